#!/usr/bin/env python3
"""A catenary partly on the seabed: MoorDyn v2 (PyPI `moordyn`) and xcable, static state.

The scene of the test seabed/catenary_on_a_frictionless_bottom, lowered 10 m so that all of it
is under water: a 100 m line (diameter 0.1 m, 2000 kg/m^3, EA 1e8 N) in sea water from an anchor
on a flat bottom 50 m down to a fairlead 80 m away at z = -10 m. Both codes use MoorDyn's default
bottom (kBot 3e6 Pa, cBot 3e5 Pa s/m on the diameter), no friction. MoorDyn finds its static
state by dynamic relaxation (TmaxIC 10000 s: it settles slowly, a stiff line on a soft bottom),
xcable by Newton. Printed: the horizontal tension at the anchor's segment, the force on the fairlead,
the arc length of the last node within 1 mm of the bottom (both codes alike), and the elastic
catenary's closed form for a rigid bottom.

Usage: python3 bench/peer/seabed.py [--segments 20 40] [--exe bin/xcable]
"""

import argparse
import math
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

import moordyn

LENGTH, DIAMETER, DENSITY, EA = 100.0, 0.1, 2000.0, 1.0e8
RHO, G, DEPTH = 1025.0, 9.81, 50.0
ANCHOR, FAIRLEAD = (0.0, -DEPTH), (80.0, -10.0)
AREA = math.pi * DIAMETER**2 / 4
MASS = DENSITY * AREA
WET = (MASS - RHO * AREA) * G


def closed_form():
    """H, grounded length, fairlead tension of the elastic catenary on a rigid, frictionless bottom."""
    span, drop = FAIRLEAD[0] - ANCHOR[0], FAIRLEAD[1] - ANCHOR[1]

    def res(v):
        h, lb = v
        ls = LENGTH - lb
        vv = WET * ls
        return np.array([lb * (1 + h / EA) + h / WET * math.asinh(vv / h) + h * ls / EA - span,
                         h / WET * (math.sqrt(1 + (vv / h) ** 2) - 1) + WET * ls**2 / (2 * EA) - drop])

    v = np.array([1800.0, 40.0])
    for _ in range(60):
        jac = np.zeros((2, 2))
        for j in range(2):
            dv = np.zeros(2)
            dv[j] = 1e-6 * max(1.0, abs(v[j]))
            jac[:, j] = (res(v + dv) - res(v - dv)) / (2 * dv[j])
        v = v - np.linalg.solve(jac, res(v))
    return v[0], v[1], math.hypot(v[0], WET * (LENGTH - v[1]))


def moordyn_run(segments):
    txt = f"""MoorDyn v2 input: a catenary on the seabed (bench/peer/seabed.py)
---------------------- LINE TYPES -----------------------------------
TypeName   Diam    Mass/m     EA      BA/-zeta     EI    Cd     Ca    CdAx    CaAx
(name)     (m)     (kg/m)     (N)     (N-s/-)    (N-m^2) (-)   (-)   (-)     (-)
rope       {DIAMETER:.10g}  {MASS:.12g}  {EA:.12g}  -1.0  0.0  1.2  1.0  0.008  0.0
---------------------------- POINTS -------------------------------------------
ID  Attachment  X       Y     Z      Mass   Volume  CdA    CA
(#)   (-)       (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
1     Fixed     {ANCHOR[0]:.12g}     0.0   {ANCHOR[1]:.12g}    0.0    0.0     0.0    0.0
2     Fixed     {FAIRLEAD[0]:.12g}     0.0   {FAIRLEAD[1]:.12g}    0.0    0.0     0.0    0.0
---------------------- LINES ----------------------------------------
ID   LineType AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)  (name)   (#)      (#)      (m)       (-)      (-)
1    rope      1        2       {LENGTH:.12g}      {segments}      -
---------------------- OPTIONS -----------------------------------------
0        writeLog
5.0e-5   dtM
RK4      tScheme
{G}      g
{RHO}    rho
{DEPTH}  WtrDpth
3.0e6    kBot
3.0e5    cBot
10000.0  TmaxIC
4.0      CdScaleIC
1.0e-9   threshIC
------------------------- need this line -------------------------------------
"""
    with tempfile.TemporaryDirectory() as work:
        path = os.path.join(work, "seabed.txt")
        with open(path, "w") as f:
            f.write(txt)
        system = moordyn.Create(path)
        moordyn.SetVerbosity(system, moordyn.LEVEL_ERR)
        moordyn.Init(system, [], [])
        line = moordyn.GetLine(system, 1)
        nodes = np.array([moordyn.GetLineNodePos(line, i) for i in range(segments + 1)])
        weight = np.array(moordyn.GetLineNodeWeight(line, segments))
        moordyn.Close(system)
    seg = np.diff(nodes, axis=0)
    lens = np.linalg.norm(seg, axis=1)
    ten = EA * (lens / (LENGTH / segments) - 1)
    h = ten[0] * seg[0, 0] / lens[0]
    # The force on the fairlead: the top segment's pull and the top node's half-segment weight.
    fair = np.linalg.norm(-ten[-1] * seg[-1] / lens[-1] + weight)
    return h, fair, last_grounded(nodes[:, 2], segments)


def last_grounded(z, segments):
    """Arc length of the last node within 1 mm of the bottom (from the anchor)."""
    off = np.nonzero(z + DEPTH > 1e-3)[0]
    return LENGTH * (off[0] - 1) / segments if len(off) else LENGTH


def xcable_run(exe, segments):
    with tempfile.TemporaryDirectory() as work:
        nml = os.path.join(work, "seabed.nml")
        out = os.path.join(work, "seabed.h5")
        with open(nml, "w") as f:
            f.write(f"""&cable length = {LENGTH}, diameter = {DIAMETER}, density = {DENSITY}, bending_stiffness = 1e-3 /
&material law = 'linear', ea = {EA:.12g} /
&fluid density = {RHO} /
&seabed depth = {DEPTH} /
&end_a kind = 'fixed', x = {ANCHOR[0]}, z = {ANCHOR[1]} /
&end_b kind = 'fixed', x = {FAIRLEAD[0]}, z = {FAIRLEAD[1]} /
&rupture enabled = .false. /
&numerics nodes = {segments + 1}, t_end = 1e-3, newton_tol = 1e-12 /
&output file = '{out}', interval = 0, quiet = .true. /
""")
        run = subprocess.run([exe, nml], capture_output=True, text=True)
        if run.returncode != 0:
            return None
        with h5py.File(out) as f:
            a = f["summary"].attrs
            return (-float(f["history/end_a/force_x"][0]), float(a["static_tension_b"]),
                    last_grounded(f["static/z"][:], segments))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--segments", type=int, nargs="+", default=[20, 40])
    ap.add_argument("--exe", default="")
    args = ap.parse_args()
    h, lb, tf = closed_form()
    print(f"closed form, rigid bottom: H {h:.4f} N, grounded {lb:.4f} m, fairlead {tf:.4f} N")
    print("| segments | MoorDyn H N | MoorDyn fairlead N | MoorDyn last grounded node m | xcable H N | xcable fairlead N "
          "| xcable last grounded node m |")
    print("|---|---|---|---|---|---|---|")
    for n in args.segments:
        mh, mf, mg = moordyn_run(n)
        row = f"| {n} | {mh:.4f} | {mf:.4f} | {mg:.3f} |"
        x = xcable_run(args.exe, n) if args.exe else None
        row += " | | |" if x is None else f" {x[0]:.4f} | {x[1]:.4f} | {x[2]:.3f} |"
        print(row, flush=True)


if __name__ == "__main__":
    sys.exit(main())
