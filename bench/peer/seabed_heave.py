#!/usr/bin/env python3
"""A fairlead heaving a line that lies partly on the seabed: MoorDyn v2 (PyPI `moordyn`) and xcable.

bench/peer, not part of `make test`. Results: docs/theory/seabed.md ("Peer, dynamic").

Scene: that of seabed.py (imported from it): a 100 m line (diameter 0.1 m, 2000 kg/m^3,
EA 1e8 N, no bending stiffness to speak of) in still sea water (surface at z = 0), from an
anchor on a flat bottom 50 m down to a fairlead at x = 80 m, z = -10 m; MoorDyn's default
bottom in both codes (kBot 3e6 Pa, cBot 3e5 Pa s/m on the diameter), no friction. Drag and
added mass alike in both: Cd normal 1.2, tangential 0.008, Ca normal 1, tangential 0 (xcable
has no tangential added mass). From the static state the fairlead heaves:
    z_b(t) = z_b0 + A w(t) sin(2 pi t / T),  w = sin^2(pi t / (2 T)) for t < T, then 1,
xcable's `motion = 'harmonic'` with `ramp_time = T` (src/xcable/ends/motion.f90:
w = 1 - cos^2(pi t / (2 t_r))), run for --periods periods. Default A = 1.5 m, T = 12 s: the
line stays taut in xcable (3.4 to 6.2 kN at the fairlead). At 3 m and 12 s the fairlead drops at
up to 1.57 m/s, faster than the line sinks through the water (its normal terminal speed is about
1.1 m/s): the line goes slack and snaps (xcable at 41 nodes: up to 150 kN), not a case to
converge two codes on.

xcable: the executable on a namelist, nodes = segments + 1, a fixed step --xdt (implicit,
its statics start the run); /history/end_b/tension (the end cell's tension carried to the end)
and /history/grounded_length (sum of ds phi, phi the fraction of a cell under the bottom).

MoorDyn (RK4, dtM = --courant ds / sqrt(EA / m)): point 1 Fixed (anchor), point 2 Coupled
(fairlead), BA = --ba (default 0: no internal damping, as xcable's; a line that cannot push, as xcable's compression =
'none'). Its initial state is not found by its own dynamic relaxation (TmaxIC 10000 s in
seabed.py, minutes): xcable's static state on the same nodes (nodes = segments + 1, the same
arc lengths) is written as a MoorDyn state file and loaded after Init_NoIC, then settled for
--settle seconds with the fairlead held in a copy of the line with critical axial damping
(BA = -1) and 1000 times the drag (neither changes a static state); the settled state is
loaded into the undamped line and t = 0 is its start. The settled fairlead tension and its drift
over the last 10 % of the settling are printed. The fairlead is moved
once per dtM: the exact position at the start of the step and the chord to its end as the
velocity (MoorDyn moves a coupled point at the given velocity within a step). Fairlead tension:
1.5 T_N - 0.5 T_(N-1) from the last two segments' EA strain (carried half a segment to the end,
as xcable's); grounded length: the same sum of ds phi from MoorDyn's node heights.

Compared, every --sample s: the fairlead tension over the last period (max, min), the largest
difference between the codes' tension histories over the last two periods relative to xcable's
tension range there, raw and after a centred --smooth s moving average (which removes the
axial ringing that MoorDyn's tension carries, see seabed.md), the largest difference of the
grounded lengths, run times (CPU of the xcable process; CPU of MoorDyn's heave loop, then of its
settling, Python calls included), and each code's convergence (the same differences between
successive grids, relative to the finer grid's range). MoorDyn's extrapolated tension can go
below zero while its top segment is slack.

Usage: python3 bench/peer/seabed_heave.py [--segments 20 40 80 160 320] [--amplitude 1.5]
           [--period 12] [--periods 4] [--xdt 0.005] [--courant 0.5] [--settle 20] [--smooth 0.5]
           [--ba 0] [--exe bin/xcable] [--tsv DIR]
(about 2 minutes; --ba gives both codes the same axial internal damping, N s; --tsv writes
each run's t, T_b and grounded length.)
"""

import argparse
import math
import os
import resource
import subprocess
import sys
import tempfile
import time
from importlib import metadata

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import seabed as sc  # noqa: E402  (the scene of the static comparison)
import peer_common as pc  # noqa: E402  (MoorDyn's state file and start from it)

import moordyn  # noqa: E402

CDN, CDT, CAN, CAT = 1.2, 0.008, 1.0, 0.0
KBOT, CBOT = 3.0e6, 3.0e5          # MoorDyn's defaults; --cbot changes CBOT in both codes


def heave(t, amp, period):
    """Fairlead height above its static height (m) at time t: xcable's harmonic motion end."""
    if t <= 0:
        return 0.0
    w = math.sin(0.5 * math.pi * t / period) ** 2 if t < period else 1.0
    return amp * w * math.sin(2 * math.pi * t / period)


def grounded(z, segments):
    """Sum over the segments of ds times the fraction of the straight segment under the bottom."""
    d = -sc.DEPTH - np.asarray(z)          # depth under the bottom, > 0 in contact
    da, db = d[:-1], d[1:]
    phi = np.where((da > 0) & (db > 0), 1.0, 0.0)
    cross = (da > 0) != (db > 0)
    phi[cross] = np.maximum(da, db)[cross] / np.abs(da - db)[cross]
    return sc.LENGTH / segments * float(phi.sum())


def cpu_children():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


# ------------------------------------------------------------------ xcable
def xcable_namelist(segments, out, dt, t_end, amp, period, ba):
    motion = (f"kind = 'motion', x = {sc.FAIRLEAD[0]}, z = {sc.FAIRLEAD[1]}, motion = 'harmonic', "
              f"amplitude = {amp!r}, period = {period!r}, direction_x = 0, direction_z = 1, ramp_time = {period!r}")
    return f"""&cable length = {sc.LENGTH}, diameter = {sc.DIAMETER}, density = {sc.DENSITY}, gravity = {sc.G}, bending_stiffness = 1e-3 /
&material law = 'linear', ea = {sc.EA:.12g}, compression = 'none', damping = {ba!r} /
&fluid density = {sc.RHO}, cd_normal = {CDN}, cd_tangential = {CDT}, ca_normal = {CAN}, surface_z = 0 /
&seabed depth = {sc.DEPTH}, stiffness = {KBOT:.12g}, damping = {CBOT:.12g} /
&end_a kind = 'fixed', x = {sc.ANCHOR[0]}, z = {sc.ANCHOR[1]} /
&end_b {motion} /
&rupture enabled = .false. /
&numerics nodes = {segments + 1}, dt = {dt!r}, t_end = {t_end!r} /
&output file = '{out}', interval = 0, quiet = .true., fields = 'x z tension' /
"""


def xcable_run(exe, segments, dt, t_end, amp, period, ba, ts, work):
    nml, out = os.path.join(work, f"x{segments}.nml"), os.path.join(work, f"x{segments}.h5")
    with open(nml, "w") as f:
        f.write(xcable_namelist(segments, out, dt, t_end, amp, period, ba))
    c0 = cpu_children()
    run = subprocess.run([exe, nml], capture_output=True, text=True)
    cpu = cpu_children() - c0
    if run.returncode != 0:
        sys.exit(f"xcable failed on {nml}: {run.stderr.strip()}")
    with h5py.File(out) as f:
        h = f["history"]
        t, tb, g = h["time"][:], h["end_b/tension"][:], h["grounded_length"][:]
        static = np.column_stack([f["static/x"][:], np.zeros(segments + 1), f["static/z"][:]])
        a = f["summary"].attrs
        info = {"static_tension_b": float(a["static_tension_b"]), "rejected": int(a["rejected_steps"]),
                "warnings": str(a.get("warnings", ""))}
    os.remove(out)
    return np.column_stack([ts, np.interp(ts, t, tb), np.interp(ts, t, g)]), static, cpu, info


# ------------------------------------------------------------------ MoorDyn
def md_input(path, segments, dtm, ba, cd_factor):
    txt = f"""MoorDyn v2 input: a fairlead heaving a line on the seabed (bench/peer/seabed_heave.py)
---------------------- LINE TYPES -----------------------------------
TypeName   Diam    Mass/m     EA      BA/-zeta     EI    Cd     Ca    CdAx    CaAx
(name)     (m)     (kg/m)     (N)     (N-s/-)    (N-m^2) (-)   (-)   (-)     (-)
rope       {sc.DIAMETER:.10g}  {sc.MASS:.15g}  {sc.EA:.12g}  {ba!r}  0.0  {CDN * cd_factor!r}  {CAN}  {CDT * cd_factor!r}  {CAT}
---------------------------- POINTS -------------------------------------------
ID  Attachment  X       Y     Z      Mass   Volume  CdA    CA
(#)   (-)       (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
1     Fixed     {sc.ANCHOR[0]:.12g}     0.0   {sc.ANCHOR[1]:.12g}    0.0    0.0     0.0    0.0
2     Coupled   {sc.FAIRLEAD[0]:.12g}     0.0   {sc.FAIRLEAD[1]:.12g}    0.0    0.0     0.0    0.0
---------------------- LINES ----------------------------------------
ID   LineType AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)  (name)   (#)      (#)      (m)       (-)      (-)
1    rope      1        2       {sc.LENGTH:.12g}      {segments}      -
---------------------- OPTIONS -----------------------------------------
0        writeLog
{dtm!r}   dtM
RK4      tScheme
{sc.G}      g
{sc.RHO}    rho
{sc.DEPTH}  WtrDpth
{KBOT:.12g}    kBot
{CBOT:.12g}    cBot
1        disableOutput
1        disableOutTime
---------------------- OUTPUTS -----------------------------------------
------------------------- need this line -------------------------------------
"""
    with open(path, "w") as f:
        f.write(txt)


def md_system(work, name, segments, dtm, ba, cd_factor, state):
    inp = os.path.join(work, name)
    md_input(inp, segments, dtm, ba, cd_factor)
    return pc.moordyn_from_state(inp, [sc.FAIRLEAD[0], 0.0, sc.FAIRLEAD[1]], state)


def md_run(segments, static, courant, settle, sample, t_end, amp, period, ba, work):
    ds = sc.LENGTH / segments
    h = courant * ds / math.sqrt(sc.EA / sc.MASS)
    k = int(math.ceil(sample / h - 1e-9))   # steps per sample
    h = sample / k
    pc.moordyn_state(os.path.join(work, "start.state"), static[1:-1],
                       [(*static[0], 0.0, 0.0, 0.0), (*static[-1], 0.0, 0.0, 0.0)])
    xb = [sc.FAIRLEAD[0], 0.0, sc.FAIRLEAD[1]]

    def measure(sysm):
        line = moordyn.GetLine(sysm, 1)
        p = np.array([moordyn.GetLineNodePos(line, i) for i in range(segments + 1)])
        ten = sc.EA * np.maximum(np.linalg.norm(np.diff(p, axis=0), axis=1) / ds - 1, 0.0)
        return 1.5 * ten[-1] - 0.5 * ten[-2], grounded(p[:, 2], segments)

    c0 = time.process_time()
    sysm = md_system(work, "settle.txt", segments, h, -1.0, 1000.0, os.path.join(work, "start.state"))
    t, hist = -settle, []
    for _ in range(int(round(settle / sample))):
        for _ in range(k):
            moordyn.Step(sysm, xb, [0.0, 0.0, 0.0], t, h)
            t += h
        last = measure(sysm)
        hist.append(last[0])
    moordyn.SaveState(sysm, os.path.join(work, "settled.state"))
    moordyn.Close(sysm)
    cpu_settle = time.process_time() - c0
    hist = np.array(hist)
    tail = hist[-max(2, len(hist) // 10):]

    c0 = time.process_time()
    sysm = md_system(work, "heave.txt", segments, h, ba, 1.0, os.path.join(work, "settled.state"))
    rows = [(0.0,) + last]   # the settled state (MoorDyn gives the nodes of a loaded state after a step)
    for i in range(int(round(t_end / sample))):
        for j in range(k):
            t0 = i * sample + j * h
            z0, z1 = heave(t0, amp, period), heave(t0 + h, amp, period)
            moordyn.Step(sysm, [xb[0], 0.0, xb[2] + z0], [0.0, 0.0, (z1 - z0) / h], t0, h)
        rows.append(((i + 1) * sample,) + measure(sysm))
    cpu = time.process_time() - c0
    moordyn.Close(sysm)
    info = {"dtm": h, "cpu_settle": cpu_settle, "settled_tension_b": float(hist[-1]),
            "settle_drift": float(np.ptp(tail))}
    return np.array(rows), cpu, info


# ------------------------------------------------------------------ comparison
def window(rows, t0):
    return rows[rows[:, 0] >= t0 - 1e-9]


def stats(rows, period, t_end):
    last = window(rows, t_end - period)
    return last[:, 1].max(), last[:, 1].min(), last[:, 2].min(), last[:, 2].max()


def smooth(rows, width):
    """Centred moving average of the tension over `width` seconds, where the whole window lies in
    the run (the times and the averaged tensions)."""
    k = max(1, int(round(width / (rows[1, 0] - rows[0, 0])))) | 1
    return rows[k // 2:len(rows) - k // 2, 0], np.convolve(rows[:, 1], np.ones(k) / k, "valid")


def diff(a, b, period, t_end, width):
    """Over the last two periods: the largest |T_a - T_b| relative to b's tension range there, the
    same of the tensions averaged over `width` seconds, and the largest |grounded_a - grounded_b| (m)."""
    wa, wb = window(a, t_end - 2 * period), window(b, t_end - 2 * period)
    rng = np.ptp(wb[:, 1])
    (ta, sa), (_, sb) = smooth(a, width), smooth(b, width)
    w = ta >= t_end - 2 * period - 1e-9
    return (np.abs(wa[:, 1] - wb[:, 1]).max() / rng, np.abs(sa[w] - sb[w]).max() / rng,
            np.abs(wa[:, 2] - wb[:, 2]).max())


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--segments", type=int, nargs="+", default=[20, 40, 80, 160, 320])
    ap.add_argument("--amplitude", type=float, default=1.5)
    ap.add_argument("--period", type=float, default=12.0)
    ap.add_argument("--periods", type=int, default=4)
    ap.add_argument("--xdt", type=float, default=0.005, help="xcable's time step, s")
    ap.add_argument("--courant", type=float, default=0.5, help="MoorDyn's dtM in units of ds / c")
    ap.add_argument("--settle", type=float, default=20.0, help="MoorDyn's settling time, s")
    ap.add_argument("--sample", type=float, default=0.01, help="comparison interval, s")
    ap.add_argument("--smooth", type=float, default=0.5, help="moving-average width of the smoothed difference, s")
    ap.add_argument("--ba", type=float, default=0.0, help="axial internal damping of both codes, N s")
    ap.add_argument("--exe", default=os.path.join(HERE, "..", "..", "bin", "xcable"))
    ap.add_argument("--tsv", default="", help="directory: write each run's t, T_b, grounded length there")
    args = ap.parse_args()
    amp, period, width = args.amplitude, args.period, args.smooth
    t_end = args.periods * period
    ts = np.round(np.arange(0.0, t_end + 1e-9, args.sample), 10)
    print(f"heave {amp} m, period {period} s, ramp {period} s, to {t_end} s; axial damping {args.ba} N s; "
          f"xcable dt {args.xdt} s; MoorDyn {metadata.version('moordyn')} RK4, dtM at Courant {args.courant}, "
          f"settled {args.settle} s. Last period: T_b and grounded length range; last two periods: "
          f"differences relative to the other code's (or the finer grid's) tension range, raw and "
          f"{width} s moving average", flush=True)
    runs = {"xcable": {}, "MoorDyn": {}}
    print("| segments | code | T_b max N | T_b min N | grounded min m | grounded max m | MoorDyn - xcable: "
          "max dT / range | smoothed | max d grounded m | CPU s | notes |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for n in args.segments:
        with tempfile.TemporaryDirectory() as work:
            x, static, xcpu, xinfo = xcable_run(args.exe, n, args.xdt, t_end, amp, period, args.ba, ts, work)
            m, mcpu, minfo = md_run(n, static, args.courant, args.settle, args.sample, t_end, amp, period,
                                    args.ba, work)
        runs["xcable"][n], runs["MoorDyn"][n] = x, m
        if args.tsv:
            os.makedirs(args.tsv, exist_ok=True)
            for code, r in (("xcable", x), ("moordyn", m)):
                np.savetxt(os.path.join(args.tsv, f"{code}_{n}.tsv"), r, fmt="%.10g", delimiter="\t",
                           header="t\ttension_b\tgrounded_length", comments="")
        d = diff(m, x, period, t_end, width)
        s = stats(x, period, t_end)
        print(f"| {n} | xcable | {s[0]:.1f} | {s[1]:.1f} | {s[2]:.2f} | {s[3]:.2f} | | | | {xcpu:.1f} | "
              f"static T_b {xinfo['static_tension_b']:.2f} N, {xinfo['rejected']} rejected steps |")
        s = stats(m, period, t_end)
        print(f"| {n} | MoorDyn | {s[0]:.1f} | {s[1]:.1f} | {s[2]:.2f} | {s[3]:.2f} | {d[0]:.3f} | {d[1]:.4f} | "
              f"{d[2]:.2f} | {mcpu:.1f} (+{minfo['cpu_settle']:.1f}) | dtM {minfo['dtm']:.3g} s; settled T_b "
              f"{minfo['settled_tension_b']:.2f} N, its drift over the last 10 % of the settling "
              f"{minfo['settle_drift']:.2g} N |", flush=True)
    ns = sorted(args.segments)
    print("\nconvergence of each code: coarse against fine grid, over the last two periods")
    print("| code | segments | max dT / range | smoothed | max d grounded m |")
    print("|---|---|---|---|---|")
    for code in runs:
        for a, b in zip(ns[:-1], ns[1:]):
            d = diff(runs[code][a], runs[code][b], period, t_end, width)
            print(f"| {code} | {a} / {b} | {d[0]:.3f} | {d[1]:.4f} | {d[2]:.2f} |")


if __name__ == "__main__":
    sys.exit(main())
