"""Shared pieces of the peer reference solutions (bench/peer).

The scene: the paper's 60 m nylon cable in a vertical plane (x horizontal,
z up), pinned at end a = (0, 0), hanging as a static catenary with the same
height at both ends and the end tension T_s, then released at end b by
ramping the static end force F_s to zero as cos^2(pi t / (2 t_break)).

This module holds what both peer codes (lumped.py and moordyn_run.py) share:
the cable data, the tension-strain laws (the tanh law and its variants), the
discrete static catenary of a chain of N segments, the continuum catenary by
quadrature, the theoretical plateau speed of the released end, the case list
and the writer of the reference data files.
"""

import math
import struct

import numpy as np

# ---------------------------------------------------------------- cable data
LENGTH = 60.0                              # unstretched length L, m
DIAMETER = 0.05                            # m
AREA = math.pi * DIAMETER ** 2 / 4         # m^2
DENSITY = 1140.0                           # kg/m^3
MASS = DENSITY * AREA                      # mass per unstretched length m, kg/m
GRAVITY = 9.81                             # m/s^2
WEIGHT = MASS * GRAVITY                    # w0, N/m
YOUNG = 230e6                              # Pa (used only for EI)
EI = YOUNG * math.pi * DIAMETER ** 4 / 64  # N m^2 (about 70.6)
P = (2.703e5, 10.2, -2.128, 2.627e5, 135.5)  # p1..p5 of the tanh law

COLUMNS = ("t", "end_x", "end_z", "end_speed", "tension_a", "E_strain",
           "E_kinetic", "E_bending", "E_gravity", "W_end", "ledger")


def _logcosh(x):
    """log(cosh(x)) without overflow."""
    ax = np.abs(x)
    return ax + np.log1p(np.exp(-2.0 * ax)) - math.log(2.0)


# ---------------------------------------------------------------- laws
class TanhLaw:
    """T = p1 tanh(p2 eps + p3) + p4 + p5 eps, used for all eps (compression too).

    W(eps) = integral_0^eps T is the strain energy per unstretched length.
    f, fp, w are the formula itself; tension, slope, energy are what the
    dynamics use (the same here, cut at T = 0 in NoCompressionLaw).
    """

    name = "tanh"

    def __init__(self, p=P):
        self.p = tuple(float(v) for v in p)
        p1, p2, p3, p4, p5 = self.p
        # largest slope (at p2 eps + p3 = 0) bounds the axial wave speed
        self.stiffness_max = p1 * p2 + p5

    def f(self, eps):
        p1, p2, p3, p4, p5 = self.p
        return p1 * np.tanh(p2 * eps + p3) + p4 + p5 * eps

    def fp(self, eps):
        p1, p2, p3, p4, p5 = self.p
        return p1 * p2 / np.cosh(p2 * eps + p3) ** 2 + p5

    def w(self, eps):
        p1, p2, p3, p4, p5 = self.p
        return (p1 / p2 * (_logcosh(p2 * eps + p3) - _logcosh(p3))
                + p4 * eps + 0.5 * p5 * eps ** 2)

    tension = f
    slope = fp
    energy = w

    def strain(self, tension):
        """Inverse of f (vectorised bisection + Newton polish)."""
        t = np.atleast_1d(np.asarray(tension, dtype=float))
        lo = np.full_like(t, -1.0)
        hi = np.full_like(t, 1.0)
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            above = self.f(mid) > t
            hi = np.where(above, mid, hi)
            lo = np.where(above, lo, mid)
        e = 0.5 * (lo + hi)
        for _ in range(3):
            e = e - (self.f(e) - t) / self.fp(e)
        return e if np.ndim(tension) else float(e[0])


class NoCompressionLaw(TanhLaw):
    """The tanh law cut at T = 0: T = max(f(eps), 0) (a cable that cannot push).

    This is what MoorDyn does in compression; it is used to separate the
    effect of the compressive branch from the rest of the MoorDyn comparison.
    """

    name = "tanh-nocomp"

    def __init__(self, p=P):
        super().__init__(p)
        self.eps_zero = self.strain(0.0)
        self._w_zero = self.w(self.eps_zero)

    def tension(self, eps):
        return np.maximum(self.f(eps), 0.0)

    def slope(self, eps):
        return np.where(eps > self.eps_zero, self.fp(eps), 0.0)

    def energy(self, eps):
        return np.where(eps > self.eps_zero, self.w(eps) - self._w_zero, 0.0)


class TableLaw:
    """Piecewise-linear strain-tension table read the way MoorDyn reads it.

    T = 0 for eps < 0 (MoorDyn: a line cannot push); linear interpolation
    between the points; clamped (constant tension) beyond the last point.
    The first point must be at eps = 0.
    """

    name = "table"

    def __init__(self, xs, ys):
        self.xs = np.asarray(xs, dtype=float)
        self.ys = np.asarray(ys, dtype=float)
        assert self.xs[0] == 0.0 and np.all(np.diff(self.xs) > 0)
        assert np.all(np.diff(self.ys) >= 0)
        seg = 0.5 * (self.ys[1:] + self.ys[:-1]) * np.diff(self.xs)
        self.cum = np.concatenate(([0.0], np.cumsum(seg)))
        self.stiffness_max = float(np.max(np.diff(self.ys) / np.diff(self.xs)))

    def tension(self, eps):
        return np.where(eps < 0.0, 0.0, np.interp(eps, self.xs, self.ys))

    def slope(self, eps):
        k = np.searchsorted(self.xs, eps, side="right") - 1
        k = np.clip(k, 0, len(self.xs) - 2)
        s = (self.ys[k + 1] - self.ys[k]) / (self.xs[k + 1] - self.xs[k])
        return np.where((eps < 0.0) | (eps > self.xs[-1]), 0.0, s)

    def energy(self, eps):
        e = np.clip(eps, 0.0, None)
        k = np.clip(np.searchsorted(self.xs, e, side="right") - 1, 0,
                    len(self.xs) - 1)
        t = np.interp(e, self.xs, self.ys)
        return self.cum[k] + 0.5 * (self.ys[k] + t) * (e - self.xs[k])

    def strain(self, tension):
        t = np.asarray(tension, dtype=float)
        if np.any(t > self.ys[-1]) or np.any(t < 0):
            raise ValueError("tension outside the table")
        return np.interp(t, self.ys, self.xs)


def moordyn_table(law, eps_max, npts=30):
    """A strain-tension table of npts points (MoorDyn's limit is 30).

    Points at eps = 0 (T = 0), at eps0 = f^-1(0) (T = 0; f(0) is about -42 N,
    which MoorDyn could not use anyway) and npts - 2 points between eps0 and
    eps_max spread so that each interval carries the same share of
    integral sqrt(|f''|) (equal interpolation error), T = f(eps) there.
    """
    eps0 = law.strain(0.0)
    e = np.linspace(eps0, eps_max, 4001)
    p1, p2, p3, _, _ = law.p
    th = np.tanh(p2 * e + p3)
    f2 = np.abs(-2 * p1 * p2 ** 2 * th * (1 - th ** 2))
    dens = np.sqrt(f2 + 0.05 * f2.max())
    cum = np.concatenate(([0.0], np.cumsum(0.5 * (dens[1:] + dens[:-1]) * np.diff(e))))
    target = np.linspace(0.0, cum[-1], npts - 1)
    xs = np.interp(target, cum, e)
    xs[0], xs[-1] = eps0, eps_max
    ys = law.f(xs)
    ys[0] = 0.0
    return np.concatenate(([0.0], xs)), np.concatenate(([0.0], ys))


# ---------------------------------------------------------------- statics
def end_force(tension):
    """Static force that holds end b: (H, w0 L / 2), N (x right, z up)."""
    v = WEIGHT * LENGTH / 2
    if tension <= v:
        raise ValueError("end tension must exceed w0 L / 2 = %.1f N" % v)
    return math.sqrt(tension ** 2 - v ** 2), v


def discrete_catenary(law, tension, n):
    """Exact static equilibrium of the chain of n segments (no bending).

    Node masses m ds (half at the ends). The force that segment j carries is
    (H, w0 (s_j - L/2)) with s_j = (j + 1/2) ds its midpoint, exactly as in the
    continuum, so the end force is F_s = (H, w0 L/2) and the force on end a
    has magnitude T_s. Returns node positions (n+1, 2) and segment strains.
    """
    h, _ = end_force(tension)
    ds = LENGTH / n
    s_mid = (np.arange(n) + 0.5) * ds
    v = WEIGHT * (s_mid - LENGTH / 2)
    t = np.hypot(h, v)
    eps = law.strain(t)
    dr = np.empty((n, 2))
    dr[:, 0] = ds * (1 + eps) * h / t
    dr[:, 1] = ds * (1 + eps) * v / t
    r = np.zeros((n + 1, 2))
    r[1:] = np.cumsum(dr, axis=0)
    return r, eps


def continuum_catenary(law, tension):
    """Span and sag of the extensible catenary by quadrature in s."""
    from scipy.integrate import quad
    h, _ = end_force(tension)

    def t_of(s):
        return math.hypot(h, WEIGHT * (s - LENGTH / 2))

    def dx(s):
        t = t_of(s)
        return (1 + float(law.strain(t))) * h / t

    def dz(s):
        t = t_of(s)
        return (1 + float(law.strain(t))) * WEIGHT * (s - LENGTH / 2) / t

    span = quad(dx, 0, LENGTH, epsabs=1e-12, epsrel=1e-12, limit=200)[0]
    sag = -quad(dz, 0, LENGTH / 2, epsabs=1e-12, epsrel=1e-12, limit=200)[0]
    return span, sag


def plateau_speed(law, tension):
    """Theory: speed of the released end = integral of c(eps) from f^-1(0) to eps_s."""
    from scipy.integrate import quad
    e0 = float(law.strain(0.0))
    es = float(law.strain(tension))
    return quad(lambda e: math.sqrt(float(law.fp(e)) / MASS), e0, es,
                epsabs=1e-10, limit=200)[0]


def ramp(t, t_break):
    """cos^2(pi t / (2 t_break)) for t < t_break, else 0 (1 before t = 0)."""
    if t <= 0.0:
        return 1.0
    if t >= t_break:
        return 0.0
    return math.cos(0.5 * math.pi * t / t_break) ** 2


# ---------------------------------------------------------------- cases
def cases():
    """name -> (T_s, t_break, t_end, sample interval)."""
    out = {}
    for ts in (2000, 5000, 20000, 50000):
        for tag, tb in (("fast", 0.005), ("slow", 0.05)):
            out["slack_%dkN_%s" % (ts // 1000, tag)] = (float(ts), tb, 2.0, 0.01)
    for name, ts, tb, te in (("fast_180kN", 180e3, 0.005, 0.14),
                             ("fast_315kN", 315e3, 0.005, 0.13),
                             ("slow_180kN", 180e3, 0.05, 0.17),
                             ("slow_315kN", 315e3, 0.05, 0.16)):
        out[name] = (ts, tb, te, 0.001)
    return out


# ---------------------------------------------------------------- output
def write_tsv(path, rows):
    """rows: sequence of 11-tuples in COLUMNS order; one header line."""
    fmt = ("%.5f", "%.6f", "%.6f", "%.7g", "%.7g", "%.7g", "%.7g", "%.5g",
           "%.7g", "%.7g", "%.8g")
    with open(path, "w") as f:
        f.write("\t".join(COLUMNS) + "\n")
        for row in rows:
            f.write("\t".join(fm % v for fm, v in zip(fmt, row)) + "\n")


def read_tsv(path):
    """Structured array with the COLUMNS names."""
    return np.genfromtxt(path, names=True, delimiter="\t")


def moordyn_state(path, inner, points):
    """A MoorDyn v2 state file (the layout of its SaveState) of one line at rest: the points'
    states first (each x, y, z, vx, vy, vz), then the line's inner nodes (x, y, z each)."""
    moordyn_state_lines(path, [inner], points)


def moordyn_state_lines(path, lines, points):
    """A MoorDyn v2 state file of several lines at rest: the points' states first (each x, y, z,
    vx, vy, vz), then each line's inner nodes (x, y, z each), in MoorDyn's order of the lines."""
    data = b""
    for ps in points:
        data += struct.pack("<QQ", 1, 6) + struct.pack("<6d", *ps)
    for inner in lines:
        data += struct.pack("<QQ", len(inner), 6)
        for p in inner:
            data += struct.pack("<6d", *p, 0.0, 0.0, 0.0)
    with open(path, "wb") as f:
        f.write(b"MoorDyn" + struct.pack("<BB", 2, 7))
        f.write(struct.pack("<QQ", len(data) // 8 + 1, len(points) + len(lines)))
        f.write(data)


def moordyn_from_state(inp, coupled, state):
    """A MoorDyn v2 system from its input file, started from a state file (moordyn_state), the
    coupled point at coupled (x, y, z) and at rest; MoorDyn's banner kept off the terminal."""
    import os
    import moordyn
    saved = os.dup(1)
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, 1)
    try:
        sysm = moordyn.Create(inp)
        moordyn.SetVerbosity(sysm, moordyn.LEVEL_ERR)
        moordyn.Init_NoIC(sysm, list(coupled), [0.0, 0.0, 0.0])
        moordyn.LoadState(sysm, state)
    finally:
        os.dup2(saved, 1)
        os.close(devnull)
        os.close(saved)
    return sysm

