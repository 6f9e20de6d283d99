#!/usr/bin/env python3
"""A line through the water surface: MoorDyn v2 (PyPI `moordyn`) and xcable on the crane scene.

The scene (issue "the water has a surface"): a crane tip H m above still water (surface z = 0)
holds a 30 m line (diameter 0.1 m, 2000 kg/m^3, EA 1e8 N) with a 100 kg mass at its lower end,
in water of 1025 kg/m^3. The line hangs vertically; its top tension is the dry weight of the
length above the water, the wet weight of the length below and the weight of the mass:

    T_top = g [m H' + (m - rho A) (L - H') + M],   H' = the unstretched length above the water

(H' = H / (1 + eps) to first order; with EA = 1e8 N the stretch moves the waterline by less
than a millimetre). For H = 10 m: 4024.4 N. The tip at H = -5 m (the whole line under water)
gives g [(m - rho A) L + M].

MoorDyn: point 1 Fixed at the tip, point 2 Free with the mass (no volume), line from 2 (end A)
to 1 (end B) in N segments, its own static solver (dynamic relaxation, Init), MoorDyn's
submerged fraction of the segment that crosses the surface. The script prints, for each N,
MoorDyn's force on the tip (the top segment's tension GetLineFairTen and the net weight of
the top node's half segment, GetLineNodeWeight), the arc length from the tip at which the line crosses
z = 0, and their errors against the closed form; with --exe, xcable's static state of the same
scene (&fluid surface_z = 0) on the same number of cells.

Usage: python3 bench/peer/surface.py [--heights 10 -5] [--segments 20 40 80] [--exe bin/xcable]
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

LENGTH = 30.0
DIAMETER = 0.1
DENSITY = 2000.0
EA = 1.0e8
MASS_END = 100.0
RHO = 1025.0
G = 9.81
AREA = math.pi * DIAMETER**2 / 4
MASS = DENSITY * AREA


def closed_form(height):
    """Top tension (N) and the unstretched length above the water (m) of the hanging line."""
    bottom = MASS_END * G
    wet = (MASS - RHO * AREA) * G
    dry = MASS * G
    if height <= 0:
        return bottom + wet * LENGTH, 0.0
    # The stretch of the line below the waterline and above it (tension grows upwards).
    above = height  # first guess: unstretched = stretched
    for _ in range(50):
        t_water = bottom + wet * (LENGTH - above)
        # stretched length above the water: int_0^above (1 + T(s)/EA) ds with T = t_water + dry s
        stretched = above + (t_water * above + 0.5 * dry * above**2) / EA
        above += height - stretched
    return bottom + wet * (LENGTH - above) + dry * above, above


def moordyn_run(height, segments):
    txt = f"""MoorDyn v2 input: a crane line through the water surface (bench/peer/surface.py)
---------------------- LINE TYPES -----------------------------------
TypeName   Diam    Mass/m     EA      BA/-zeta     EI    Cd     Ca    CdAx    CaAx
(name)     (m)     (kg/m)     (N)     (N-s/-)    (N-m^2) (-)   (-)   (-)     (-)
rope       {DIAMETER:.10g}  {MASS:.12g}  {EA:.12g}  -1.0  0.0  1.2  1.0  0.008  0.0
---------------------------- POINTS -------------------------------------------
ID  Attachment  X       Y     Z      Mass   Volume  CdA    CA
(#)   (-)       (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
1     Fixed     0.0     0.0   {height:.12g}    0.0    0.0     0.0    0.0
2     Free      0.0     0.0   {height - LENGTH:.12g}   {MASS_END:.12g}    0.0     0.0    0.0
---------------------- LINES ----------------------------------------
ID   LineType AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)  (name)   (#)      (#)      (m)       (-)      (-)
1    rope      2        1       {LENGTH:.12g}      {segments}      -
---------------------- OPTIONS -----------------------------------------
0        writeLog
1.0e-4   dtM
RK4      tScheme
{G}      g
{RHO}    rho
200.0    WtrDpth
120.0    TmaxIC
4.0      CdScaleIC
1.0e-7   threshIC
------------------------- need this line -------------------------------------
"""
    with tempfile.TemporaryDirectory() as work:
        path = os.path.join(work, "crane.txt")
        with open(path, "w") as f:
            f.write(txt)
        system = moordyn.Create(path)
        moordyn.SetVerbosity(system, moordyn.LEVEL_ERR)
        moordyn.Init(system, [], [])
        line = moordyn.GetLine(system, 1)
        # The force on the fixed tip: the top segment's tension and the weight of the top node's
        # half segment (GetLineFairTen is the top segment's tension alone, w ds / 2 short).
        weight = moordyn.GetLineNodeWeight(line, segments)
        top = moordyn.GetLineFairTen(line) - weight[2]
        nodes = np.array([moordyn.GetLineNodePos(line, i) for i in range(segments + 1)])
        moordyn.Close(system)
    return top, crossing(nodes[::-1, 2], LENGTH)


def crossing(z_from_top, length):
    """Unstretched arc length from the top node at which the line crosses z = 0 (nodes equally
    spaced in unstretched length, listed from the top)."""
    n = len(z_from_top) - 1
    if z_from_top[0] <= 0:
        return 0.0
    for i in range(n):
        a, b = z_from_top[i], z_from_top[i + 1]
        if a > 0 >= b:
            return length * (i + a / (a - b)) / n
    return length


def xcable_run(exe, height, segments):
    with tempfile.TemporaryDirectory() as work:
        nml = os.path.join(work, "crane.nml")
        out = os.path.join(work, "crane.h5")
        with open(nml, "w") as f:
            f.write(f"""&cable length = {LENGTH}, diameter = {DIAMETER}, density = {DENSITY}, bending_stiffness = 1e-3 /
&material law = 'linear', ea = {EA:.12g} /
&fluid density = {RHO}, surface_z = 0 /
&end_a kind = 'fixed', x = 0, z = {height} /
&end_b kind = 'mass', mass = {MASS_END} /
&numerics nodes = {segments + 1}, t_end = 1e-3, newton_tol = 1e-12 /
&output file = '{out}', interval = 0, quiet = .true. /
""")
        run = subprocess.run([exe, nml], capture_output=True, text=True)
        if run.returncode != 0:
            return None, None, run.stderr.strip().splitlines()[-1]
        with h5py.File(out) as f:
            top = float(f["static"].attrs["tension_a"])
            z = f["static/z"][:]
        return top, crossing(z, LENGTH), ""


# The catenary through the surface: the same line, 90 m, from a fairlead 5 m above the water to an
# anchor 70 m away and 40 m under it (no seabed: MoorDyn's depth 200 m).
CAT_LENGTH = 90.0
FAIRLEAD = (0.0, 5.0)
ANCHOR = (70.0, -40.0)


def moordyn_catenary(segments):
    """MoorDyn's static catenary: the force of the line on the fairlead (x, z, N) and the arc
    length from the fairlead to the waterline (m)."""
    txt = f"""MoorDyn v2 input: a catenary through the water surface (bench/peer/surface.py)
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
1    rope      1        2       {CAT_LENGTH:.12g}      {segments}      -
---------------------- OPTIONS -----------------------------------------
0        writeLog
5.0e-5   dtM
RK4      tScheme
{G}      g
{RHO}    rho
200.0    WtrDpth
10000.0  TmaxIC
4.0      CdScaleIC
1.0e-9   threshIC
------------------------- need this line -------------------------------------
"""
    with tempfile.TemporaryDirectory() as work:
        path = os.path.join(work, "catenary.txt")
        with open(path, "w") as f:
            f.write(txt)
        system = moordyn.Create(path)
        moordyn.SetVerbosity(system, moordyn.LEVEL_ERR)
        moordyn.Init(system, [], [])
        line = moordyn.GetLine(system, 1)
        # The top segment's tension (from its strain) pulls the fairlead towards the line, and
        # the top node carries its half segment's net weight: the force the line puts on the
        # fairlead.
        weight = np.array(moordyn.GetLineNodeWeight(line, segments))
        nodes = np.array([moordyn.GetLineNodePos(line, i) for i in range(segments + 1)])
        moordyn.Close(system)
    top = nodes[-1] - nodes[-2]
    tension = EA * (np.linalg.norm(top) / (CAT_LENGTH / segments) - 1)
    force = -tension * top / np.linalg.norm(top) + weight
    return (float(force[0]), float(force[2])), crossing(nodes[::-1, 2], CAT_LENGTH)


def xcable_catenary(exe, segments):
    with tempfile.TemporaryDirectory() as work:
        nml = os.path.join(work, "catenary.nml")
        out = os.path.join(work, "catenary.h5")
        with open(nml, "w") as f:
            f.write(f"""&cable length = {CAT_LENGTH}, diameter = {DIAMETER}, density = {DENSITY}, bending_stiffness = 1e-3 /
&material law = 'linear', ea = {EA:.12g} /
&fluid density = {RHO}, surface_z = 0 /
&end_a kind = 'fixed', x = {FAIRLEAD[0]}, z = {FAIRLEAD[1]} /
&end_b kind = 'fixed', x = {ANCHOR[0]}, z = {ANCHOR[1]} /
&rupture enabled = .false. /
&numerics nodes = {segments + 1}, t_end = 1e-3, newton_tol = 1e-12 /
&output file = '{out}', interval = 0, quiet = .true. /
""")
        run = subprocess.run([exe, nml], capture_output=True, text=True)
        if run.returncode != 0:
            return None, None, run.stderr.strip().splitlines()[-1]
        with h5py.File(out) as f:
            # The support's reaction at end a, the fairlead: minus the line's force on it.
            fx = -float(f["history/end_a/force_x"][0])
            fz = -float(f["history/end_a/force_z"][0])
            z = f["static/z"][:]
        return (fx, fz), crossing(z, CAT_LENGTH), ""


def catenary_table(exe, segment_counts):
    print("\nCatenary from a fairlead 5 m above the water to an anchor 70 m away, 40 m down (90 m line):")
    print("| segments | MoorDyn F_x N | MoorDyn F_z N | MoorDyn waterline m | xcable F_x N | xcable F_z N "
          "| xcable waterline m |")
    print("|---|---|---|---|---|---|---|")
    for n in segment_counts:
        (mx, mz), mwl = moordyn_catenary(n)
        row = f"| {n} | {mx:.4f} | {mz:.4f} | {mwl:.4f} |"
        if exe:
            xf, xwl, why = xcable_catenary(exe, n)
            row += f" failed: {why} | | |" if xf is None else f" {xf[0]:.4f} | {xf[1]:.4f} | {xwl:.4f} |"
        else:
            row += " | | |"
        print(row, flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--heights", type=float, nargs="+", default=[10.0, -5.0])
    ap.add_argument("--segments", type=int, nargs="+", default=[20, 40, 80])
    ap.add_argument("--exe", default="")
    ap.add_argument("--catenary", action="store_true", help="also the inclined catenary through the surface")
    args = ap.parse_args()
    print("| tip height m | segments | closed form T_top N | MoorDyn T_top N | rel. error | waterline from tip m "
          "(exact) | MoorDyn | xcable T_top N | rel. error | xcable waterline m |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for h in args.heights:
        exact, above = closed_form(h)
        for n in args.segments:
            top, wl = moordyn_run(h, n)
            row = f"| {h:g} | {n} | {exact:.4f} | {top:.4f} | {(top - exact) / exact:.2e} | {above:.4f} | {wl:.4f} |"
            if args.exe:
                xt, xwl, why = xcable_run(args.exe, h, n)
                if xt is None:
                    row += f" failed: {why} | | |"
                else:
                    row += f" {xt:.4f} | {(xt - exact) / exact:.2e} | {xwl:.4f} |"
            else:
                row += " | | |"
            print(row, flush=True)
    if args.catenary:
        catenary_table(args.exe, args.segments)


if __name__ == "__main__":
    sys.exit(main())
