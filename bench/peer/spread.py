#!/usr/bin/env python3
"""A three-line spread mooring, 600 s of prescribed fairlead motion: xcable against MoorDyn v2
at equal accuracy (issue 31, "Moorings", its performance item).

bench/peer, not part of `make test`. Results and discussion: spread.md (this directory).

Scene. Three identical lines at azimuths 0, 120 and 240 degrees around a floating body whose
motion is prescribed (no coupling). Each line, from its anchor: 120 m of 76 mm studless chain,
300 m of polyester, 30 m of the same chain (the segments of input/polyester_mooring_break.nml:
chain d 0.1368 m, 7860 kg/m^3, EA 4.945e8 N, Cdn 2.4, Cdt 1.15; polyester d 0.1376 m,
1115 kg/m^3, EA 1e8 N, Cdn 1.2, Cdt 0.1; Can 1, Cat 0 everywhere), in sea water (1025 kg/m^3,
surface z = 0), on a flat seabed 150 m down with MoorDyn's default contact (kBot 3e6 Pa,
cBot 3e5 Pa s/m) and no friction. Fairleads on the body at radius 20 m, z = -10 m; anchors at
radius 440 m on the bottom (the statics of segments_statics.py: 420 m of horizontal span, about
100 m of chain on the bottom). No bending stiffness to speak of (xcable 1e-3 N m^2, MoorDyn 0),
a rope that cannot push in both, no internal damping unless --damping (N s, both codes).

The body translates (no rotation), so the three fairleads share one displacement d(t) from
their static places:
    x = w(t) (5 sin(2 pi t / 100) + 1.5 sin(2 pi t / 10))        surge: slow drift + wave
    y = w(t)  3 sin(2 pi t / 150)                                  sway: slow drift
    z = w(t)  1 cos(2 pi t / 10)                                   heave: wave (an orbit with the surge)
    w = sin^2(pi t / (2 * 20 s)) for t < 20 s, then 1   (a start from rest)
The motion is a table of rows every TABLE_DT = 0.625 s (961 rows, within xcable's 1000) and
both codes follow the same curve: xcable's `motion = 'table'` interpolates it by a cubic
Hermite with centred-difference slopes (src/xcable/ends/table.f90), and this script evaluates
that very cubic for MoorDyn.

xcable: one process per line (the lines meet only at the prescribed body, so they are
independent), `&numerics model = '3d'` (the sway takes every line out of its plane), the
segments as &segment_1..3 with their node counts given, a fixed step dt (implicit, its statics
start the run). Fairlead and anchor tension: /history/end_b/tension, /history/end_a/tension.

MoorDyn (PyPI `moordyn`, RK4): the whole spread in one system: per line a Fixed anchor, two
Free joint points (no mass, no volume) and a Coupled fairlead, three lines (chain, polyester,
chain) with the same segment counts as xcable's cells; dtM = courant * ds_min / c_max (c_max =
sqrt(EA / m) of the polyester, 2456 m/s; ds_min the shortest segment). The script moves the three
coupled points every COUPLE = 0.01 s (MoorDyn divides the call into equal steps of at most dtM)
or, with --every-step, once per step (dtM rounded down to divide SAMPLE): the exact position at
the start and the chord to the end as the velocity. MoorDyn starts from xcable's statics on the same nodes (a state
file), settled with the fairleads held for --settle s in a copy with critical axial damping
(BA = -1) and 100 times the drag; that settled state is loaded into the real system and t = 0
starts from it. Tensions at the fairlead and the anchor: the tension of the end segment and of
its neighbour (EA strain + BA strain rate) extrapolated to the end, 1.5 T_1 - 0.5 T_2.

Compared, every SAMPLE = 0.1 s over 0-600 s: the six tension histories (three fairleads, three
anchors). Error of a run: the rms over the six histories and all samples of its difference to
a reference run. Times: wall and CPU time of the 600 s of dynamics (xcable: the sum of its three
processes, statics included; MoorDyn: the stepping loop, the settling not counted).

Usage (from bench/peer; XCABLE or --exe, default ../../bin/xcable):
  python3 spread.py xcable  --nodes 100 --dt 0.05 [--repeat 3] [--work DIR]
  python3 spread.py moordyn --nodes 100 --courant 1.4 --every-step [--repeat 3] [--work DIR]
  python3 spread.py ladder  [--work DIR]        (the runs of spread.md, one at a time)
  python3 spread.py summarize [--work DIR] [--no-figure]   (the tables; data/spread*.tsv, spread.png)
Each run writes WORK/<tag>.tsv (t, T_fair 1..3, T_anchor 1..3) and WORK/<tag>.json (times);
default WORK /tmp/spread_runs. A run already there is not repeated (--force reruns).
"""

import argparse
import json
import math
import os
import resource
import statistics
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))

G, RHO = 9.81, 1025.0
DEPTH = 150.0
KBOT, CBOT = 3.0e6, 3.0e5
R_FAIR, Z_FAIR, R_ANCHOR = 20.0, -10.0, 440.0
AZIMUTHS = (0.0, 120.0, 240.0)
T_END, SAMPLE, COUPLE = 600.0, 0.1, 0.01
TABLE_DT, T_RAMP = 0.625, 20.0
# (name, length m, diameter m, density kg/m^3, EA N, Cdn, Cdt), from the anchor
CHAIN = dict(d=0.1368, rho=7860.0, ea=4.945e8, cdn=2.4, cdt=1.15)
POLY = dict(d=0.1376, rho=1115.0, ea=1.0e8, cdn=1.2, cdt=0.1)
SEGMENTS = (("chain", 120.0, CHAIN), ("poly", 300.0, POLY), ("chain", 30.0, CHAIN))
LENGTH = sum(s[1] for s in SEGMENTS)
CAN = 1.0


def mass(p):
    return p["rho"] * math.pi * p["d"] ** 2 / 4


def cells(nodes):
    """Cells of each segment for a line of `nodes` nodes (shared by length, at least 2 each)."""
    n = nodes - 1
    c = [max(2, int(round(n * s[1] / LENGTH))) for s in SEGMENTS]
    c[1] += n - sum(c)
    return c


# ------------------------------------------------------------------ the motion
def motion_rows():
    t = np.round(np.arange(0.0, T_END + 1e-9, TABLE_DT), 10)
    w = np.where(t < T_RAMP, np.sin(0.5 * np.pi * t / T_RAMP) ** 2, 1.0)
    x = w * (5.0 * np.sin(2 * np.pi * t / 100.0) + 1.5 * np.sin(2 * np.pi * t / 10.0))
    y = w * 3.0 * np.sin(2 * np.pi * t / 150.0)
    z = w * 1.0 * np.cos(2 * np.pi * t / 10.0)
    return t, np.column_stack([x, y, z])


class Hermite:
    """xcable's table motion (src/xcable/ends/table.f90): cubic Hermite between rows, slopes the
    centred differences (one-sided at the first and last row); the first/last row outside."""

    def __init__(self, t, v):
        self.t, self.v = t, v
        m = np.empty_like(v)
        m[1:-1] = (v[2:] - v[:-2]) / (t[2:] - t[:-2])[:, None]
        m[0] = (v[1] - v[0]) / (t[1] - t[0])
        m[-1] = (v[-1] - v[-2]) / (t[-1] - t[-2])
        self.m = m

    def __call__(self, t):
        """Values at the times t (an array, inside the table)."""
        t = np.asarray(t, dtype=float)
        i = np.clip(np.searchsorted(self.t, t, side="right") - 1, 0, len(self.t) - 2)
        h = self.t[i + 1] - self.t[i]
        u = np.clip((t - self.t[i]) / h, 0.0, 1.0)[:, None]
        h = h[:, None]
        h00, h10 = (1 + 2 * u) * (1 - u) ** 2, u * (1 - u) ** 2
        h01, h11 = u * u * (3 - 2 * u), u * u * (u - 1)
        return h00 * self.v[i] + h10 * h * self.m[i] + h01 * self.v[i + 1] + h11 * h * self.m[i + 1]


def fairlead(k):
    a = math.radians(AZIMUTHS[k])
    return np.array([R_FAIR * math.cos(a), R_FAIR * math.sin(a), Z_FAIR], dtype=float)


def anchor(k):
    a = math.radians(AZIMUTHS[k])
    return np.array([R_ANCHOR * math.cos(a), R_ANCHOR * math.sin(a), -DEPTH])


def cpu_children():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def samples():
    return np.round(np.arange(0.0, T_END + 1e-9, SAMPLE), 10)


# ------------------------------------------------------------------ xcable
def xcable_namelist(k, nodes, dt, out, table, damping, t_end=T_END):
    a, b = [float(v) for v in anchor(k)], [float(v) for v in fairlead(k)]
    txt = f"&cable length = {LENGTH!r}, bending_stiffness = 1e-3, gravity = {G} /\n"
    txt += f"&material law = 'linear', compression = 'none', damping = {damping!r} /\n"
    txt += f"&fluid density = {RHO}, ca_normal = {CAN}, surface_z = 0 /\n"
    txt += f"&seabed depth = {DEPTH}, stiffness = {KBOT:.12g}, damping = {CBOT:.12g} /\n"
    for j, ((_, length, p), c) in enumerate(zip(SEGMENTS, cells(nodes)), 1):
        txt += (f"&segment_{j} length = {length!r}, diameter = {p['d']!r}, density = {p['rho']!r}, "
                f"ea = {p['ea']!r}, cd_normal = {p['cdn']!r}, cd_tangential = {p['cdt']!r}, nodes = {c + 1} /\n")
    txt += f"&end_a kind = 'fixed', x = {a[0]!r}, y = {a[1]!r}, z = {a[2]!r} /\n"
    txt += (f"&end_b kind = 'motion', x = {b[0]!r}, y = {b[1]!r}, z = {b[2]!r}, motion = 'table', "
            f"table_file = '{table}' /\n")
    txt += "&rupture enabled = .false. /\n"
    txt += f"&numerics model = '3d', dt = {dt!r}, t_end = {t_end!r} /\n"
    txt += f"&output file = '{out}', interval = 0, quiet = .true., fields = 'x' /\n"
    return txt


def write_table(path):
    t, d = motion_rows()
    with open(path, "w") as f:
        f.write("# bench/peer/spread.py: t (s), fairlead displacement x, y, z (m)\n")
        for ti, di in zip(t, d):
            f.write(f"{ti:.4f} {di[0]:.12f} {di[1]:.12f} {di[2]:.12f}\n")


def xcable_run(exe, nodes, dt, work, damping, t_end=T_END):
    """The three lines, one process each: ((t, 6 columns) at the samples, wall s, CPU s, statics)."""
    import h5py
    table = os.path.join(work, "spread_motion.dat")
    if not os.path.exists(table):
        write_table(table)
    ts = samples()
    ts = ts[ts <= t_end + 1e-9]
    cols = [None] * 6
    wall = cpu = 0.0
    statics = []
    for k in range(3):
        nml, out = os.path.join(work, f"x_{k}.nml"), os.path.join(work, f"x_{k}.h5")
        with open(nml, "w") as f:
            f.write(xcable_namelist(k, nodes, dt, out, table, damping, t_end))
        c0, w0 = cpu_children(), time.perf_counter()
        run = subprocess.run([exe, nml], capture_output=True, text=True)
        wall += time.perf_counter() - w0
        cpu += cpu_children() - c0
        if run.returncode != 0:
            sys.exit(f"xcable failed on {nml}: {run.stderr.strip()[-2000:]}")
        with h5py.File(out) as f:
            h = f["history"]
            t = h["time"][:]
            cols[k] = np.interp(ts, t, h["end_b/tension"][:])
            cols[3 + k] = np.interp(ts, t, h["end_a/tension"][:])
            statics.append(np.column_stack([f["static/x"][:], f["static/y"][:], f["static/z"][:]]))
            a = f["summary"].attrs
            if int(a.get("rejected_steps", 0)):
                print(f"  line {k}: {int(a['rejected_steps'])} rejected steps", file=sys.stderr)
        os.remove(out)
    return np.column_stack([ts] + cols), wall, cpu, statics


# ------------------------------------------------------------------ MoorDyn
def md_input(path, nodes, dtm, damping, drag=1.0):
    c = cells(nodes)
    ba = damping
    lines = ["MoorDyn v2 input: a three-line spread (bench/peer/spread.py)",
             "---------------------- LINE TYPES -----------------------------------",
             "TypeName   Diam    Mass/m     EA      BA/-zeta     EI    Cd     Ca    CdAx    CaAx",
             "(name)     (m)     (kg/m)     (N)     (N-s/-)    (N-m^2) (-)   (-)   (-)     (-)"]
    for name, p in (("chain", CHAIN), ("poly", POLY)):
        lines.append(f"{name} {p['d']!r} {mass(p)!r} {p['ea']!r} {ba!r} 0.0 {p['cdn'] * drag!r} {CAN!r} "
                     f"{p['cdt'] * drag!r} 0.0")
    lines += ["---------------------------- POINTS -------------------------------------------",
              "ID  Attachment  X       Y     Z      Mass   Volume  CdA    CA",
              "(#)   (-)       (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)"]
    pid = 0
    for k in range(3):
        a, b = anchor(k), fairlead(k)
        for kind, p in (("Fixed", a), ("Free", a + (b - a) * 120 / LENGTH),
                        ("Free", a + (b - a) * 420 / LENGTH), ("Coupled", b)):
            pid += 1
            lines.append(f"{pid} {kind} {p[0]:.12g} {p[1]:.12g} {p[2]:.12g} 0 0 0 0")
    lines += ["---------------------- LINES ----------------------------------------",
              "ID   LineType AttachA  AttachB  UnstrLen  NumSegs  LineOutputs",
              "(#)  (name)   (#)      (#)      (m)       (-)      (-)"]
    lid = 0
    for k in range(3):
        for j, (name, length, _) in enumerate(SEGMENTS):
            lid += 1
            lines.append(f"{lid} {name} {4 * k + j + 1} {4 * k + j + 2} {length!r} {c[j]} -")
    lines += ["---------------------- OPTIONS -----------------------------------------",
              "0 writeLog", f"{dtm!r} dtM", "RK4 tScheme", f"{G} g", f"{RHO} rho", f"{DEPTH} WtrDpth",
              f"{KBOT:.12g} kBot", f"{CBOT:.12g} cBot", "1 disableOutput", "1 disableOutTime",
              "---------------------- OUTPUTS -----------------------------------------",
              "------------------------- need this line -------------------------------------"]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def md_state(path, nodes, statics):
    """A MoorDyn state file (SaveState's layout: the points by ID, x y z vx vy vz each; then each
    line's inner nodes) from xcable's static node positions of the three lines."""
    import struct
    c = cells(nodes)
    joints = [c[0], c[0] + c[1]]
    data = b""
    for k in range(3):
        s = statics[k]
        for p in (s[0], s[joints[0]], s[joints[1]], s[-1]):
            data += struct.pack("<QQ", 1, 6) + struct.pack("<6d", *p, 0.0, 0.0, 0.0)
    for k in range(3):
        s = statics[k]
        starts = [0, joints[0], joints[1]]
        for j in range(3):
            inner = s[starts[j] + 1:starts[j] + c[j]]
            data += struct.pack("<QQ", len(inner), 6)
            for p in inner:
                data += struct.pack("<6d", *p, 0.0, 0.0, 0.0)
    with open(path, "wb") as f:
        f.write(b"MoorDyn" + struct.pack("<BB", 2, 7))
        f.write(struct.pack("<QQ", len(data) // 8 + 1, 21))
        f.write(data)


def md_system(inp, state):
    import moordyn
    saved = os.dup(1)
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, 1)
    try:
        sysm = moordyn.Create(inp)
        moordyn.SetVerbosity(sysm, moordyn.LEVEL_ERR)
        moordyn.Init_NoIC(sysm, list(np.concatenate([fairlead(k) for k in range(3)])), [0.0] * 9)
        moordyn.LoadState(sysm, state)
    finally:
        os.dup2(saved, 1)
        os.close(devnull)
        os.close(saved)
    return sysm


def md_tensions(sysm, nodes, damping):
    """Fairlead and anchor tension of each line: end segment and its neighbour, extrapolated."""
    import moordyn
    c = cells(nodes)
    out = []

    def seg(line, i, ea, ds):
        p0, p1 = np.array(moordyn.GetLineNodePos(line, i)), np.array(moordyn.GetLineNodePos(line, i + 1))
        dr = p1 - p0
        l = np.linalg.norm(dr)
        t = ea * (l / ds - 1.0) if l > ds else 0.0
        if damping:
            v0, v1 = np.array(moordyn.GetLineNodeVel(line, i)), np.array(moordyn.GetLineNodeVel(line, i + 1))
            t += damping * float(np.dot(v1 - v0, dr / l)) / ds
        return t

    fair, anch = [], []
    for k in range(3):
        top = moordyn.GetLine(sysm, 3 * k + 3)
        ds = SEGMENTS[2][1] / c[2]
        n = c[2]
        fair.append(1.5 * seg(top, n - 1, CHAIN["ea"], ds) - 0.5 * seg(top, n - 2, CHAIN["ea"], ds))
        bot = moordyn.GetLine(sysm, 3 * k + 1)
        ds = SEGMENTS[0][1] / c[0]
        anch.append(1.5 * seg(bot, 0, CHAIN["ea"], ds) - 0.5 * seg(bot, 1, CHAIN["ea"], ds))
    return fair + anch


def md_dtm(nodes, courant):
    c = cells(nodes)
    ds = min(s[1] / n for s, n in zip(SEGMENTS, c))
    cmax = max(math.sqrt(p["ea"] / mass(p)) for _, _, p in SEGMENTS)
    return courant * ds / cmax


def md_run(exe, nodes, courant, work, damping, settle, t_end=T_END, every_step=False):
    import moordyn
    dtm = md_dtm(nodes, courant)
    # xcable's statics on the same nodes: a run of one step
    _, _, _, statics = xcable_run(exe, nodes, 1e-3, work, damping, t_end=1e-3)
    md_state(os.path.join(work, "start.state"), nodes, statics)
    xb = np.concatenate([fairlead(k) for k in range(3)])
    zero = [0.0] * 9
    md_input(os.path.join(work, "settle.txt"), nodes, dtm, -1.0, drag=100.0)
    sysm = md_system(os.path.join(work, "settle.txt"), os.path.join(work, "start.state"))
    t = -settle
    hist = []
    nset = int(round(settle / COUPLE))
    for i in range(nset):
        moordyn.Step(sysm, list(xb), zero, t, COUPLE)
        t += COUPLE
        if i % 100 == 99:
            hist.append(md_tensions(sysm, nodes, 0.0))
    moordyn.SaveState(sysm, os.path.join(work, "settled.state"))
    moordyn.Close(sysm)
    hist = np.array(hist)
    drift = float(np.abs(hist[-1] - hist[-max(2, len(hist) // 10)]).max())

    md_input(os.path.join(work, "run.txt"), nodes, dtm, damping)
    sysm = md_system(os.path.join(work, "run.txt"), os.path.join(work, "settled.state"))
    # coupling: every COUPLE s (MoorDyn subdivides a call into steps of at most dtM), or with
    # every_step once per MoorDyn step (dtM rounded down to divide SAMPLE)
    per = int(math.ceil(SAMPLE / dtm - 1e-9)) if every_step else int(round(SAMPLE / COUPLE))
    hc = SAMPLE / per
    nsamp = int(round(t_end / SAMPLE))
    # the fairleads' path at every coupling time, before the clock starts
    tc = np.arange(nsamp * per + 1) * hc
    d = Hermite(*motion_rows())(tc)
    xs = xb + np.tile(d, 3)
    vs = np.tile(np.diff(d, axis=0) / hc, 3)
    rows = [[0.0] + list(hist[-1])]
    c0, w0 = time.process_time(), time.perf_counter()
    for i in range(nsamp):
        for j in range(per):
            m = i * per + j
            moordyn.Step(sysm, xs[m].tolist(), vs[m].tolist(), float(tc[m]), hc)
        rows.append([(i + 1) * SAMPLE] + md_tensions(sysm, nodes, damping))
    cpu, wall = time.process_time() - c0, time.perf_counter() - w0
    moordyn.Close(sysm)
    return np.array(rows), wall, cpu, {"dtM": hc if every_step else dtm, "coupling_s": hc,
                                       "settle_drift_N": drift, "settled": list(hist[-1])}


# ------------------------------------------------------------------ runs
def tag(code, nodes, step):
    return f"{code}_n{nodes}_{step:g}"


def do_run(args, code, nodes, step, repeat=None):
    os.makedirs(args.work, exist_ok=True)
    name = tag(code, nodes, step) + (f"_c{args.damping:g}" if args.damping else "") + \
        ("_es" if code == "moordyn" and args.every_step else "")
    tsv, js = os.path.join(args.work, name + ".tsv"), os.path.join(args.work, name + ".json")
    if os.path.exists(js) and not args.force:
        print(f"{name}: there already", flush=True)
        return
    exe = os.path.abspath(args.exe)
    walls, cpus, info = [], [], {}
    for r in range(repeat or args.repeat):
        if code == "xcable":
            rows, wall, cpu, _ = xcable_run(exe, nodes, step, args.work, args.damping)
        else:
            rows, wall, cpu, info = md_run(exe, nodes, step, args.work, args.damping, args.settle,
                                           every_step=args.every_step)
        walls.append(wall)
        cpus.append(cpu)
        print(f"{name}: run {r + 1}: wall {wall:.1f} s, CPU {cpu:.1f} s", flush=True)
    np.savetxt(tsv, rows, fmt="%.10g", delimiter="\t", comments="",
               header="t\tT_fair_0\tT_fair_120\tT_fair_240\tT_anchor_0\tT_anchor_120\tT_anchor_240")
    info.update({"code": code, "nodes": nodes, "step": step, "damping": args.damping, "walls": walls,
                 "cpus": cpus, "wall": statistics.median(walls), "cpu": statistics.median(cpus),
                 "load": os.getloadavg()})
    if code == "moordyn":
        info["courant"] = step
        info["every_step"] = bool(args.every_step)
    with open(js, "w") as f:
        json.dump(info, f, indent=1)


# (nodes per line, xcable's dt or MoorDyn's Courant, repeats[, MoorDyn moved at every step])
LADDER_X = [(25, 0.1, 3), (50, 0.1, 3), (50, 0.05, 3), (100, 0.1, 3), (100, 0.05, 3), (100, 0.025, 1),
            (200, 0.05, 1), (200, 0.025, 1), (200, 0.0125, 1), (400, 0.025, 1), (400, 0.0125, 1)]
LADDER_M = [(25, 1.0, 3, False), (50, 1.0, 3, False), (50, 1.4, 3, True), (100, 1.0, 3, False),
            (100, 1.4, 3, True), (100, 0.5, 1, False), (200, 1.0, 1, False), (200, 1.4, 1, True),
            (400, 1.0, 1, False)]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("what", choices=["xcable", "moordyn", "ladder", "summarize"])
    ap.add_argument("--nodes", type=int, default=100)
    ap.add_argument("--dt", type=float, default=0.05, help="xcable's step, s")
    ap.add_argument("--courant", type=float, default=1.0, help="MoorDyn's dtM in ds_min / c_max")
    ap.add_argument("--damping", type=float, default=0.0, help="axial Kelvin-Voigt damping, N s (both)")
    ap.add_argument("--settle", type=float, default=30.0, help="MoorDyn's settling, s")
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--every-step", action="store_true", help="MoorDyn: move the fairleads at every step")
    ap.add_argument("--work", default="/tmp/spread_runs")
    ap.add_argument("--exe", default=os.environ.get("XCABLE", os.path.join(HERE, "..", "..", "bin", "xcable")))
    ap.add_argument("--force", action="store_true")
    ap.add_argument("--no-figure", action="store_true")
    args = ap.parse_args()
    if args.what == "xcable":
        do_run(args, "xcable", args.nodes, args.dt)
    elif args.what == "moordyn":
        do_run(args, "moordyn", args.nodes, args.courant)
    elif args.what == "ladder":
        for n, dt, rep in LADDER_X:
            do_run(args, "xcable", n, dt, rep)
        for n, c, rep, every in LADDER_M:
            args.every_step = every
            do_run(args, "moordyn", n, c, rep)
    else:
        summarize(args)
    return 0


def load_runs(work):
    runs = {}
    for name in sorted(os.listdir(work)):
        if not name.endswith(".json"):
            continue
        with open(os.path.join(work, name)) as f:
            info = json.load(f)
        info["rows"] = np.loadtxt(os.path.join(work, name[:-5] + ".tsv"), skiprows=1)
        runs[name[:-5]] = info
    return runs


EDGE = 5.0      # s: the slow tensions are compared over [EDGE, T_END - EDGE] (the filter's ends)
LOWPASS = 0.5   # Hz: the cut-off of the 'slow' tensions (4th-order Butterworth, forward and back)


def lowpass(rows):
    from scipy.signal import butter, filtfilt
    b, a = butter(4, LOWPASS, fs=1.0 / SAMPLE)
    out = rows.copy()
    out[:, 1:] = filtfilt(b, a, rows[:, 1:], axis=0)
    return out[(out[:, 0] >= EDGE - 1e-9) & (out[:, 0] <= T_END - EDGE + 1e-9)]


def rms(a, b):
    return float(np.sqrt(np.mean((a[:, 1:] - b[:, 1:]) ** 2)))


def frontier(points):
    """The runs no other run beats on both error and time, by error (largest first)."""
    pts = sorted(points)
    out, best = [], float("inf")
    for t, e in pts:
        if e < best:
            out.append((t, e))
            best = e
    return sorted(out, key=lambda p: -p[1])


def time_at(front, err):
    """Time at the error err on a frontier, log-log interpolation; None outside its range."""
    for (t0, e0), (t1, e1) in zip(front[:-1], front[1:]):
        if e1 <= err <= e0:
            u = math.log(err / e0) / math.log(e1 / e0) if e1 != e0 else 0.0
            return math.exp(math.log(t0) + u * math.log(t1 / t0))
    return None


def summarize(args):
    runs = load_runs(args.work)
    for r in runs.values():
        r["raw"] = r["rows"]
    for metric in ("slow", "raw"):
        print(f"\n## {metric} tensions" + (f" (low-passed at {LOWPASS} Hz)" if metric == "slow" else " (as sampled)"))
        for r in runs.values():
            r["rows"] = lowpass(r["raw"]) if metric == "slow" else r["raw"]
        summarize_metric(args, runs, metric)


def summarize_metric(args, runs, metric):
    xs = {k: r for k, r in runs.items() if r["code"] == "xcable" and not r["damping"]}
    ms = {k: r for k, r in runs.items() if r["code"] == "moordyn" and not r["damping"]}
    xref = min(xs.values(), key=lambda r: (-r["nodes"], r["step"]))
    mref = min(ms.values(), key=lambda r: (-r["nodes"], -r["step"]))
    common = xref["rows"].copy()
    common[:, 1:] = 0.5 * (xref["rows"][:, 1:] + mref["rows"][:, 1:])
    dyn = float(np.sqrt(np.mean((common[:, 1:] - common[:, 1:].mean(axis=0)) ** 2)))
    print(f"references: xcable {xref['nodes']} nodes dt {xref['step']} s; MoorDyn {mref['nodes']} nodes "
          f"Courant {mref['step']} (dtM {mref['dtM']:.3g} s); common reference: their mean")
    d = xref["rows"][:, 1:] - mref["rows"][:, 1:]
    print(f"the two references: rms difference {np.sqrt(np.mean(d ** 2)) / 1e3:.3f} kN over the six histories "
          f"(fairleads {np.sqrt(np.mean(d[:, :3] ** 2)) / 1e3:.3f}, anchors {np.sqrt(np.mean(d[:, 3:] ** 2)) / 1e3:.3f}), "
          f"max {np.abs(d).max() / 1e3:.3f} kN; rms of the tensions' variation about their means {dyn / 1e3:.2f} kN")
    for j, name in enumerate(["fairlead 0", "fairlead 120", "fairlead 240", "anchor 0", "anchor 120", "anchor 240"]):
        c = common[:, 1 + j]
        print(f"  {name}: mean {c.mean() / 1e3:.1f} kN, min {c.min() / 1e3:.1f}, max {c.max() / 1e3:.1f}; "
              f"refs rms diff {np.sqrt(np.mean(d[:, j] ** 2)) / 1e3:.3f} kN, max {np.abs(d[:, j]).max() / 1e3:.3f}")
    print("\n| code | nodes per line | step (s) | rms error, kN | % of the variation | against its own "
          "reference, kN | wall (s) | CPU (s) | repeats |")
    print("|---|---|---|---|---|---|---|---|---|")
    table = []
    for code, group, ref in (("xcable", xs, xref), ("MoorDyn", ms, mref)):
        for r in sorted(group.values(), key=lambda r: (r["nodes"], -r["step"])):
            e = rms(r["rows"], common)
            own = rms(r["rows"], ref["rows"]) if r is not ref else float("nan")
            if code == "xcable":
                step = r["step"]
                label = f"{step:g}"
            else:   # the step MoorDyn took: dtM, or the coupling interval divided into steps of at most dtM
                step = r["dtM"] if r.get("every_step") else COUPLE / math.ceil(COUPLE / r["dtM"] - 1e-9)
                c = r["step"] * step / r["dtM"]
                label = f"{step:.3g} (Courant {c:.2f}{', every step' if r.get('every_step') else ''})"
            print(f"| {code} | {r['nodes']} | {label} | {e / 1e3:.3f} | {100 * e / dyn:.2f} | "
                  f"{own / 1e3:.3f} | {r['wall']:.1f} | {r['cpu']:.1f} | {len(r['walls'])} |")
            table.append((code, r["nodes"], step, r["step"], e, own, r["wall"], r["cpu"], min(r["walls"]),
                          max(r["walls"]), len(r["walls"])))
    os.makedirs(os.path.join(HERE, "data"), exist_ok=True)
    with open(os.path.join(HERE, "data", f"spread_{metric}.tsv"), "w") as f:
        f.write("code\tnodes_per_line\tstep_s\tcourant_or_dt\trms_error_N\terror_own_ref_N\twall_s\tcpu_s"
                "\twall_min_s\twall_max_s\trepeats\n")
        for row in table:
            f.write("\t".join(f"{v:.6g}" if isinstance(v, float) else str(v) for v in row) + "\n")
    print("\nequal error (log-log interpolation along each code's frontier of error against time):")
    print("| at the error of | error kN | xcable wall s | MoorDyn wall s | MoorDyn / xcable | xcable CPU s | "
          "MoorDyn CPU s | MoorDyn / xcable (CPU) |")
    print("|---|---|---|---|---|---|---|---|")
    fr = {}
    for code in ("xcable", "MoorDyn"):
        for col, key in ((6, "wall"), (7, "cpu")):
            fr[code, key] = frontier([(row[col], row[4]) for row in table if row[0] == code
                                      and not (row[0] == "xcable" and row[1] == xref["nodes"] and row[3] == xref["step"])
                                      and not (row[0] == "MoorDyn" and row[1] == mref["nodes"] and row[3] == mref["step"])])
    for row in table:
        out = []
        for key in ("wall", "cpu"):
            tx = time_at(fr["xcable", key], row[4]) if row[0] == "MoorDyn" else row[6 if key == "wall" else 7]
            tm = time_at(fr["MoorDyn", key], row[4]) if row[0] == "xcable" else row[6 if key == "wall" else 7]
            if tx is None or tm is None:
                out.append(None)
            else:
                out.append((tx, tm))
        if out[0] is None and out[1] is None:
            continue
        cells_ = []
        for o in out:
            cells_ += ["-", "-", "-"] if o is None else [f"{o[0]:.1f}", f"{o[1]:.1f}", f"{o[1] / o[0]:.2f}"]
        step = f"dt {row[3]:g}" if row[0] == "xcable" else f"Courant {row[3]:g}"
        print(f"| {row[0]} {row[1]} nodes, {step} | {row[4] / 1e3:.3f} | {cells_[0]} | {cells_[1]} | {cells_[2]} | "
              f"{cells_[3]} | {cells_[4]} | {cells_[5]} |")
    if not args.no_figure and metric == "slow":
        figure(table, xref, mref, common)


def figure(table, xref, mref, common):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.2))
    for code, mk, colour in (("xcable", "o", "C0"), ("MoorDyn", "s", "C3")):
        for col, lab in ((6, "wall"), (7, "CPU")):
            pts = [(row[4], row[col], row[1], row[3]) for row in table if row[0] == code and not math.isnan(row[5])]
            ax.loglog([p[1] for p in pts], [p[0] / 1e3 for p in pts], mk, color=colour, label=f"{code} ({lab})",
                      mfc="none" if lab == "CPU" else colour, linestyle="none")
            if lab == "wall":
                for e, t, n, st in pts:
                    text = f"{n}/{st:g}" if code == "xcable" else (f"{n}" if st == 1 else f"{n}/C{st:g}")
                    ax.annotate(text, (t, e / 1e3), fontsize=7, xytext=(3, 3), textcoords="offset points")
    floor = rms(xref["rows"], mref["rows"]) / 1e3
    ax.axhline(floor, linestyle=":", color="grey", label="the two finest runs differ by")
    ax.set_xlabel("time for 600 s of the spread (s)")
    ax.set_ylabel("rms tension error (kN)")
    ax.set_title("slow tensions: error against time\n(labels: nodes per line / xcable's dt, s; MoorDyn Courant 1 "
                 "unless C)", fontsize=9)
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    t = xref["raw"][:, 0]
    w = (t >= 400) & (t <= 450)
    bx.plot(t[w], xref["raw"][w, 3] / 1e3, "-", label=f"xcable {xref['nodes']} nodes, fairlead 240")
    bx.plot(t[w], mref["raw"][w, 3] / 1e3, "--", label=f"MoorDyn {mref['nodes']} nodes, fairlead 240")
    bx.plot(t[w], xref["raw"][w, 1] / 1e3, "-", label="xcable, fairlead 0")
    bx.plot(t[w], mref["raw"][w, 1] / 1e3, "--", label="MoorDyn, fairlead 0")
    bx.set_xlabel("t (s)")
    bx.set_ylabel("tension (kN)")
    bx.set_title("the two references, 400-450 s", fontsize=10)
    bx.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "spread.png"), dpi=110)


if __name__ == "__main__":
    sys.exit(main())
