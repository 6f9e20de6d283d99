#!/usr/bin/env python3
"""Derive the constants of src/xcable/numerics/tan.f90 (fast_tan).

Run:  python3 tools/tan_coefficients.py 4 9 > /tmp/tan_constants.f90
(the degrees of the three polynomials; mpmath at 60 digits; prints the Fortran
parameter declarations that the module holds, with the fit errors as comments).

With s = x^2 (or r^2) and the weighted linear Remez exchange of
tools/remez.py on a fine grid, as for tools/atan2_coefficients.py (each fit
minimises the largest error relative to the function itself, not to the
polynomial):

1. small: tan x = x + x s P(s) for |x| <= 1/16; P fits
   g(s) = (tan(sqrt s)/sqrt s - 1)/s.
2. middle, 1/16 <= |x| <= pi/4: a table of tan c_j at c_j = j/64, j = 4..50, as
   hi + lo; tan(c + u) = tan c + tan u (1 + tan^2 c)/(1 - tan c tan u)
   with |u| <= 1/128 and tan u from the polynomial of 1.
3. cot: cot r = 1/r - r P(s) for 0 < r <= pi/4; P fits (1/r - cot r)/r, whose
   nearest pole is at r = pi (a factor D - s, D = pi^2, as in 2., measured worse:
   the rounding of D - s, about 9, is a tenth of a unit of the result).
   tan x = cot(pi/2 - x) for pi/4 < x <= pi/2.

The coefficients are rounded to double and the error of the rounded fit is
measured again on a finer grid (printed); half_pi as hi + lo (two doubles)
for the reduction r = pi/2 - x.
"""
import sys

import mpmath as mp

from remez import fortran, remez, rounded_error

mp.mp.dps = 60


def h(s):
    """tan(x)/x, x = sqrt(s)."""
    r = mp.sqrt(s)
    return mp.tan(r) / r


def g(s):
    return (h(s) - 1) / s


def cot_rest(s):
    """(1/r - cot r)/r, r = sqrt(s)."""
    r = mp.sqrt(s)
    return (1 / r - mp.cot(r)) / r


def fit(name, what, smin, smax, degree, target, weight):
    p, emax, _ = remez(degree, smin, smax, target, weight)
    worst, pd = rounded_error(p, smin, smax, target, weight)
    print(f'   ! {name}: {what}, P of degree {degree}: relative error of the fit {mp.nstr(emax, 3)},')
    print(f'   ! with the coefficients rounded to double {mp.nstr(worst, 3)} '
          f'(2^{mp.nstr(mp.log(worst, 2), 4)})')
    body = ', &\n      '.join(fortran(c) for c in pd)
    print(f'   real(dp), parameter :: {name}(0:{degree}) = [ &\n      {body}]')


def table():
    """tan c_j as hi + lo for c_j = j/64, j = 4..50."""
    his, los = [], []
    for j in range(4, 51):
        t = mp.tan(mp.mpf(j) / 64)
        hi = mp.mpf(float(t))
        his.append(hi)
        los.append(mp.mpf(float(t - hi)))
    print('   ! middle: tan c_j = hi + lo at c_j = j/64, j = 4..50')
    for name, vals in (('tan_hi', his), ('tan_lo', los)):
        items = [fortran(v) for v in vals]
        lines = ['      ' + ', '.join(items[k:k + 3]) for k in range(0, len(items), 3)]
        print(f'   real(dp), parameter :: {name}(4:50) = [ &')
        print(', &\n'.join(lines) + ']')


def main():
    small = int(sys.argv[1]) if len(sys.argv) > 1 else 4
    cot = int(sys.argv[2]) if len(sys.argv) > 2 else 9
    quarter = mp.pi / 4
    # small: relative error of tan = x s (P - g) / tan x
    fit('small', '|x| <= 1/16, tan x = x + x s P(s)', mp.mpf(0), mp.mpf(1) / 256, small,
        g, lambda s: s / h(s))
    # cot: relative error r (P - rest) / cot r = s h(s) (P - rest)
    fit('cot', '0 < r <= pi/4, cot r = 1/r - r P(s)', mp.mpf(0), quarter**2, cot,
        cot_rest, lambda s: s * h(s))
    table()
    hp = mp.pi / 2
    hi = mp.mpf(float(hp))
    lo = mp.mpf(float(hp - hi))
    print(f'   real(dp), parameter :: half_pi_hi = {fortran(hi)}, half_pi_lo = {fortran(lo)}')


if __name__ == '__main__':
    main()
