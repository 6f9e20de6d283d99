#!/usr/bin/env python3
"""A mooring line of three segments: xcable's statics against NREL's MoorPy (PyPI `moorpy`).

The line: 120 m of 76 mm studless chain from an anchor on a flat frictionless bottom 150 m
down, 300 m of polyester rope, 30 m of the same chain to a fixed fairlead 10 m under the
surface and 420 m from the anchor, in sea water. xcable solves it as one line of three
segments (`&segment_1` .. `&segment_3`). MoorPy has no line of segments in its catenary: the
reference here is three MoorPy catenaries (`moorpy.Catenary.catenary`, each with its own
weight and EA; the first with seabed contact) joined at two massless points whose positions
are found by balancing the forces on them (scipy's fsolve). A uniform line cut in two is
checked against one catenary first, so that the joining is known right.

Printed: the anchor's and the fairlead's tension, the joints' positions, the grounded length,
for MoorPy and for xcable at several resolutions.

Usage: python3 bench/peer/segments_statics.py [--exe bin/xcable] [--nodes 91 181 361 721]
"""

import argparse
import math
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np
from moorpy.Catenary import catenary
from scipy.optimize import fsolve

G, RHO = 9.81, 1025.0
DEPTH = 150.0
FAIRLEAD = (420.0, -10.0)


def chain(dc=0.076):
    """MoorPy's studless chain: mass (kg/m), EA (N), volume-equivalent diameter (m)."""
    return 20.01e3 * dc * dc, 85.61e9 * dc * dc - 3.927e7 * dc ** 3, 1.801 * dc


def polyester(d=0.16):
    """MoorPy's polyester: mass (kg/m), EA (N, static), volume-equivalent diameter (m)."""
    return 0.6476e3 * d * d, 1.09e9 * d * d, 0.86 * d


def segments():
    """(length, mass kg/m, EA N, diameter m, wet weight N/m) from the anchor."""
    out = []
    for length, (mass, ea, dvol) in ((120.0, chain()), (300.0, polyester()), (30.0, chain())):
        w = (mass - RHO * math.pi * dvol * dvol / 4) * G
        out.append((length, mass, ea, dvol, w))
    return out


def joined(segs, a, b, cb0):
    """MoorPy catenaries joined at massless points: (anchor tension, fairlead tension, joints,
    grounded length). a, b: end points (x, z); cb0: CB of the first segment (its end A on the
    bottom)."""
    m = len(segs)

    def forces(p):
        pts = [np.array(a)] + [np.array(p[2 * i:2 * i + 2]) for i in range(m - 1)] + [np.array(b)]
        out = []
        for i, (length, _, ea, _, w) in enumerate(segs):
            dx, dz = pts[i + 1] - pts[i]
            cb = cb0 if i == 0 else -(pts[i][1] + DEPTH)
            fah, fav, fbh, fbv, info = catenary(dx, dz, length, ea, w, CB=cb, Tol=1e-10, MaxIter=500)
            out.append((fah, fav, fbh, fbv, info))
        return out

    def residual(p):
        f = forces(p)
        r = []
        for i in range(m - 1):
            # A massless joint in balance: the pulls of segment i (on its end B) and of segment i + 1
            # (on its end A); MoorPy's catenary returns the forces the line exerts on its two ends.
            r += [f[i][2] + f[i + 1][0], f[i][3] + f[i + 1][1]]
        return r

    # The first guess of the joints: one catenary of the mean weight and EA, at their arc lengths.
    total = sum(s[0] for s in segs)
    w_mean = sum(s[0] * s[4] for s in segs) / total
    ea_mean = sum(s[0] * s[2] for s in segs) / total
    nn = int(round(total)) + 1
    _, _, _, _, info = catenary(b[0] - a[0], b[1] - a[1], total, ea_mean, w_mean, CB=cb0, Tol=1e-10,
                                MaxIter=500, nNodes=nn, plots=1)
    sg = np.linspace(0.0, total, nn)
    guess = []
    acc = 0.0
    for length, *_ in segs[:-1]:
        acc += length
        guess += [a[0] + np.interp(acc, sg, info["X"]), a[1] + np.interp(acc, sg, info["Z"])]
    p = fsolve(residual, guess, xtol=1e-13)
    f = forces(p)
    ta = math.hypot(f[0][0], f[0][1])
    tb = math.hypot(f[-1][2], f[-1][3])
    return ta, tb, p.reshape(-1, 2), f[0][4].get("LBot", 0.0), max(abs(x) for x in residual(p))


def namelist(segs, nodes, out):
    text = "&cable length = %r, bending_stiffness = 1.0e-3 /\n" % sum(s[0] for s in segs)
    text += "&material law = 'linear', compression = 'none' /\n"
    text += "&fluid density = %r, surface_z = 0 /\n" % RHO
    text += "&seabed depth = %r, stiffness = 1e10 /\n" % DEPTH
    for k, (length, mass, ea, dvol, _) in enumerate(segs, 1):
        area = math.pi * dvol * dvol / 4
        text += "&segment_%d length = %r, diameter = %r, density = %r, ea = %r /\n" % (
            k, length, dvol, mass / area, ea)
    text += "&end_a kind = 'fixed', x = 0, z = %r /\n" % -DEPTH
    text += "&end_b kind = 'fixed', x = %r, z = %r /\n" % FAIRLEAD
    text += "&numerics nodes = %d, dt = 1e-3, t_end = 1e-3, newton_tol = 1e-12 /\n" % nodes
    text += "&output file = '%s', interval = 0, quiet = .true. /\n" % out
    return text


def run_xcable(exe, segs, nodes, work):
    path = os.path.join(work, "case.nml")
    out = os.path.join(work, "r.h5")
    with open(path, "w") as f:
        f.write(namelist(segs, nodes, out))
    run = subprocess.run([exe, path], capture_output=True, text=True)
    if run.returncode != 0:
        return None, (run.stderr.strip().splitlines() or ["?"])[-1]
    with h5py.File(out) as f:
        s = f["summary"].attrs
        s_nodes = f["s"][()]
        x = f["static/x"][()]
        z = f["static/z"][()]
        joints = []
        acc = 0.0
        for length, *_ in segs[:-1]:
            acc += length
            k = int(np.argmin(abs(s_nodes - acc)))
            joints.append((x[k], z[k]))
        return (float(s["static_tension_a"]), float(s["static_tension_b"]), np.array(joints),
                float(s["static_grounded_length"])), ""


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--exe", default="bin/xcable")
    ap.add_argument("--nodes", type=int, nargs="+", default=[91, 181, 361, 721])
    args = ap.parse_args()
    exe = os.path.abspath(args.exe)
    segs = segments()
    a = (0.0, -DEPTH)

    # The joining checked: a uniform chain cut in two against one catenary.
    length, mass, ea, dvol, w = segs[0]
    whole = catenary(FAIRLEAD[0] - a[0], FAIRLEAD[1] - a[1], 450.0, ea, w, CB=0, Tol=1e-10, MaxIter=500)
    cut = joined([(200.0, mass, ea, dvol, w), (250.0, mass, ea, dvol, w)], a, FAIRLEAD, 0)
    print("joining check (450 m of chain, cut at 200 m): fairlead tension %.4f N one catenary, %.4f N two joined"
          % (math.hypot(whole[2], whole[3]), cut[1]))

    ta, tb, joints, lbot, res = joined(segs, a, FAIRLEAD, 0)
    print("\n## chain 120 m, polyester 300 m, chain 30 m; anchor on the bottom %g m down, fairlead at (%g, %g) m\n"
          % (DEPTH, FAIRLEAD[0], FAIRLEAD[1]))
    for k, (length, mass, ea, dvol, w) in enumerate(segs, 1):
        print("segment %d: %g m, %.2f kg/m, EA %.4g N, wet weight %.2f N/m" % (k, length, mass, ea, w))
    print("\n| code | anchor tension N | fairlead tension N | joint 1 (x, z) m | joint 2 (x, z) m | grounded m |")
    print("|---|---|---|---|---|---|")
    print("| MoorPy (joined, residual %.1e N) | %.2f | %.2f | %.3f, %.3f | %.3f, %.3f | %.3f |"
          % (res, ta, tb, joints[0][0], joints[0][1], joints[1][0], joints[1][1], lbot))
    with tempfile.TemporaryDirectory() as work:
        for n in args.nodes:
            r, why = run_xcable(exe, segs, n, work)
            if r is None:
                print("| xcable %d nodes | failed: %s | | | | |" % (n, why))
                continue
            print("| xcable %d nodes | %.2f | %.2f | %.3f, %.3f | %.3f, %.3f | %.3f |"
                  % (n, r[0], r[1], r[2][0][0], r[2][0][1], r[2][1][0], r[2][1][1], r[3]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
