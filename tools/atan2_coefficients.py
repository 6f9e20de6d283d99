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
   double and the error of the rounded polynomial is measured again (printed).
   - the direct range, t = |y|/|x| in [0, 1/16]   (T = 1/16),
   - the reduced argument u = (t - c)/(1 + t c), |u| <= 2^-6 (T = 2^-6).
2. The table: for each interval of t = 2^e (1 + m/16 .. 1 + (m+1)/16),
   e = -4..-1, m = 0..15, and the one interval starting at t = 1, its mid
   point c = 2^e (1 + (m + 1/2)/16) and the four angles the quadrants need,
   atan(c), pi/2 - atan(c), pi - atan(c), pi/2 + atan(c), each as hi + lo
   (hi the double nearest the angle, lo the double nearest the rest).
"""
import mpmath as mp

mp.mp.dps = 60


def g(s):
    r = mp.sqrt(s)
    return (mp.atan(r) / r - 1) / s


def h(s):
    r = mp.sqrt(s)
    return mp.atan(r) / r


def weight(s):
    return s / h(s)


def remez(n, smax, grid=6000, iterations=30):
    """Coefficients p_0..p_n of P minimising max |w (P - g)| on (0, smax]."""
    m = n + 2
    ref = [smax * (1 - mp.cos(mp.pi * (k + mp.mpf(1) / 2) / m)) / 2 for k in range(m)]
    # a grid dense near both ends (Chebyshev-like), without s = 0 where w = 0
    xs = [smax * (1 - mp.cos(mp.pi * (k + mp.mpf(1) / 2) / grid)) / 2 for k in range(grid)]
    gx = [g(x) for x in xs]
    wx = [weight(x) for x in xs]
    best = None
    for _ in range(iterations):
        a = mp.matrix(m, m)
        b = mp.matrix(m, 1)
        for k, x in enumerate(ref):
            for i in range(n + 1):
                a[k, i] = x**i
            a[k, n + 1] = (-1) ** k / weight(x)
            b[k] = g(x)
        sol = mp.lu_solve(a, b)
        p = [sol[i] for i in range(n + 1)]
        lev = abs(sol[n + 1])
        err = [wx[k] * (mp.polyval(p[::-1], xs[k]) - gx[k]) for k in range(grid)]
        # alternating extrema: split the grid into runs of one sign, keep each run's largest
        runs = []
        start = 0
        for k in range(1, grid + 1):
            if k == grid or mp.sign(err[k]) != mp.sign(err[start]):
                kk = max(range(start, k), key=lambda j: abs(err[j]))
                runs.append(kk)
                start = k
        while len(runs) > m:  # drop the smallest end extremum
            if abs(err[runs[0]]) < abs(err[runs[-1]]):
                runs.pop(0)
            else:
                runs.pop()
        emax = max(abs(e) for e in err)
        best = (p, emax, lev)
        if len(runs) < m:
            break
        ref = [xs[k] for k in runs]
        if emax - lev < mp.mpf('1e-6') * emax:
            break
    return best


def rounded_error(p, smax, grid=20000):
    """Largest relative error of t + t s P(s) against atan t, P with double coefficients."""
    pd = [mp.mpf(float(c)) for c in p]
    worst = mp.mpf(0)
    for k in range(1, grid + 1):
        s = smax * mp.mpf(k) / grid
        worst = max(worst, abs(weight(s) * (mp.polyval(pd[::-1], s) - g(s))))
    return worst, pd


def fortran(x):
    return repr(float(x)) + '_dp'


def fit(name, tmax, degree):
    smax = mp.mpf(tmax) ** 2
    p, emax, lev = remez(degree, smax)
    worst, pd = rounded_error(p, smax)
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
