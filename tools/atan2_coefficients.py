#!/usr/bin/env python3
"""Derive the constants of src/xcable/numerics/atan2.f90 (fast_atan2).

Run:  python3 tools/atan2_coefficients.py 4 2 > /tmp/atan2_constants.f90
(the degrees of the two polynomials P; mpmath at 60 digits; prints the Fortran
parameter declarations that the module holds, and the fit errors as comments).

1. Two odd polynomials for atan on a small interval, atan(t) = t + t s P(s),
   s = t^2, found by a weighted linear Remez exchange on a fine grid: P of
   degree n minimises max |(t + t s P(s) - atan t) / atan t| over t in [0, T],
   that is max |w(s) (P(s) - g(s))| with g(s) = (atan(sqrt s)/sqrt s - 1)/s and
   w(s) = s / (atan(sqrt s)/sqrt s).  The coefficients are then rounded to
   double and the error of the rounded polynomial is measured again (printed). The
   exchange itself is tools/remez.py's, shared with tools/tan_coefficients.py.
   - the direct range, t = |y|/|x| in [0, 1/16]   (T = 1/16),
   - the reduced argument u = (t - c)/(1 + t c), |u| <= 2^-6 (T = 2^-6).
2. The table: for each interval of t = 2^e (1 + m/16 .. 1 + (m+1)/16),
   e = -4..-1, m = 0..15, and the one interval starting at t = 1, its mid
   point c = 2^e (1 + (m + 1/2)/16) and the four angles the quadrants need,
   atan(c), pi/2 - atan(c), pi - atan(c), pi/2 + atan(c), each as hi + lo
   (hi the double nearest the angle, lo the double nearest the rest).
"""
import mpmath as mp

from remez import fortran, remez, rounded_error

mp.mp.dps = 60


def g(s):
    r = mp.sqrt(s)
    return (mp.atan(r) / r - 1) / s


def h(s):
    r = mp.sqrt(s)
    return mp.atan(r) / r


def weight(s):
    return s / h(s)


def fit(name, tmax, degree):
    smax = mp.mpf(tmax) ** 2
    p, emax, lev = remez(degree, 0, smax, g, weight, iterations=30)
    worst, pd = rounded_error(p, 0, smax, g, weight)
    print(f'   ! {name}: t in [0, {tmax}], P of degree {degree}: relative error of the fit '
          f'{mp.nstr(emax, 3)},')
    print(f'   ! with the coefficients rounded to double {mp.nstr(worst, 3)} '
          f'(2^{mp.nstr(mp.log(worst, 2), 4)})')
    body = ', &\n      '.join(fortran(c) for c in pd)
    print(f'   real(dp), parameter :: {name}({0}:{degree}) = [ &\n      {body}]')


def split(v):
    hi = mp.mpf(float(v))
    lo = mp.mpf(float(v - hi))
    return hi, lo


def table():
    cs = []
    for e in range(-4, 0):
        for m in range(16):
            cs.append(mp.ldexp(1 + (mp.mpf(m) + mp.mpf(1) / 2) / 16, e))
    cs.append(1 + mp.mpf(1) / 32)
    pi = mp.pi
    hi = []
    lo = []
    for c in cs:
        a = mp.atan(c)
        for v in (a, pi / 2 - a, pi - a, pi / 2 + a):
            x, y = split(v)
            hi.append(x)
            lo.append(y)
    n = len(cs) - 1
    print(f'   ! quadrant angles K(o, j) = hi + lo for the mid points c_j of the intervals of t,')
    print(f'   ! o = 0: atan(c), 1: pi/2 - atan(c), 2: pi - atan(c), 3: pi/2 + atan(c)')
    for name, vals in (('angle_hi', hi), ('angle_lo', lo)):
        items = [fortran(v) for v in vals]
        lines = []
        for k in range(0, len(items), 4):
            lines.append('      ' + ', '.join(items[k:k + 4]))
        print(f'   real(dp), parameter :: {name}(0:3, 0:{n}) = reshape([ &')
        print(', &\n'.join(lines) + '], [4, {}])'.format(n + 1))


if __name__ == '__main__':
    import sys
    direct = int(sys.argv[1]) if len(sys.argv) > 1 else 6
    reduced = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    fit('direct', mp.mpf(1) / 16, direct)
    fit('reduced', mp.mpf(1) / 64, reduced)
    pi = mp.pi
    for name, v in (('pi', pi), ('half_pi', pi / 2)):
        x, y = split(v)
        print(f'   real(dp), parameter :: {name}_hi = {fortran(x)}, {name}_lo = {fortran(y)}')
    table()
