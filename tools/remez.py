"""Weighted linear Remez exchange in mpmath, shared by the scripts that derive
the constants of our own elementary-function kernels
(tools/atan2_coefficients.py, tools/tan_coefficients.py).

remez() finds the coefficients p_0..p_n of the polynomial P of degree n that
minimises max |weight(s) (P(s) - target(s))| over [smin, smax]: it solves for
P and the levelled error on n + 2 reference points, then moves the reference
to the alternating extrema of the error on a fine grid (Chebyshev-like, dense
at both ends, never on an end point itself, where a weight may vanish), until
the largest error is within 1e-6 of the levelled one. rounded_error() measures
the fit again with the coefficients rounded to double, on a uniform grid.
The callers set mpmath's working precision (mp.mp.dps).
"""
import mpmath as mp


def remez(n, smin, smax, target, weight, grid=6000, iterations=40):
    """(p, largest error, levelled error) of P minimising max |weight (P - target)| on [smin, smax]."""
    m = n + 2

    def node(k, count):
        return smin + (smax - smin) * (1 - mp.cos(mp.pi * (k + mp.mpf(1) / 2) / count)) / 2

    ref = [node(k, m) for k in range(m)]
    xs = [node(k, grid) for k in range(grid)]
    tx = [target(x) for x in xs]
    wx = [weight(x) for x in xs]
    best = None
    for _ in range(iterations):
        a = mp.matrix(m, m)
        b = mp.matrix(m, 1)
        for k, x in enumerate(ref):
            for i in range(n + 1):
                a[k, i] = x**i
            a[k, n + 1] = (-1) ** k / weight(x)
            b[k] = target(x)
        sol = mp.lu_solve(a, b)
        p = [sol[i] for i in range(n + 1)]
        lev = abs(sol[n + 1])
        err = [wx[k] * (mp.polyval(p[::-1], xs[k]) - tx[k]) for k in range(grid)]
        # The alternating extrema: the grid split into runs of one sign, each run's largest.
        runs = []
        start = 0
        for k in range(1, grid + 1):
            if k == grid or mp.sign(err[k]) != mp.sign(err[start]):
                runs.append(max(range(start, k), key=lambda j: abs(err[j])))
                start = k
        while len(runs) > m:  # drop the smaller end extremum
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


def rounded_error(p, smin, smax, target, weight, grid=20000):
    """(largest weighted error, coefficients) with the coefficients of p rounded to double."""
    pd = [mp.mpf(float(c)) for c in p]
    worst = mp.mpf(0)
    for k in range(1, grid + 1):
        s = smin + (smax - smin) * mp.mpf(k) / grid
        worst = max(worst, abs(weight(s) * (mp.polyval(pd[::-1], s) - target(s))))
    return worst, pd


def fortran(x):
    """x as a Fortran double literal."""
    return repr(float(x)) + '_dp'
