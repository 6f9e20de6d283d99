#!/usr/bin/env python3
"""A three-line spread meeting at a subsurface buoy: xcable's network solver (driver/network.f90,
example/network_spread) against MoorDyn v2 (PyPI `moordyn`), statics and a heave of one anchor.

bench/peer, not part of `make test`. Results: network.md.

Scene (example/network_spread/network_spread.f90 has the same): sea water 1025 kg/m^3,
g = 9.81 m/s^2, bottom at z = -100 m (MoorDyn's WtrDpth 100; no line comes near it, and xcable
has no seabed here). Three lines of 160 mm polyester (16.6 kg/m, EA 2.79e7 N, diameter
0.1376 m, no bending stiffness: xcable 1e-3 N m^2, MoorDyn 0; neither pushes), 106 m each,
from anchors at radius 80 m, azimuths 0, 120, 240 degrees (end a, MoorDyn's AttachA) to a buoy
(end b): 2000 kg, 8 m^3, Ca 0.5, Cd 0.6 on 4 m^2 (MoorDyn: a Free point, CdA 2.4). Line drag
and added mass: Cd 1.2 normal, 0.008 tangential (both codes on pi d per length), Ca 1 normal,
0 tangential. Anchor 1 moves along x: x = 80 + A w(t) sin(2 pi t / T), A = 2 m, T = 10 s,
w = sin^2(pi t / (2 T)) for t < T, then 1 (MoorDyn: a Coupled point given its exact position at
each step's start and the chord's velocity over the step).

xcable: the example program (nodes per line, dt; implicit midpoint, lumped mass), run as a
subprocess; its columns are read. MoorDyn: RK4 at dtM = --courant ds / sqrt(EA / m) rounded down
to divide the sample (0.1 s); NumSegs = nodes - 1.

MoorDyn's static state: its own, from an independent start (straight lines from the anchors to a
buoy guessed at GUESS, 0.7 m off), settled for --settle s in a copy with critical axial damping
(BA = -1) and 10 times the drag (line and buoy), neither of which changes a static state; the
drift of the buoy and of the tensions over the last 20 % of the settling is printed. The settled
state is loaded (MoorDyn's state file) into the undamped system and the heave starts from it.

End tensions of both codes alike: each end cell's tension vector (EA strain along the cell)
carried linearly to the end node, |1.5 T_1 - 0.5 T_2| (the example does the same on xcable's
nodes).

--fairlead: the anchors stay fixed and a fourth line of the same rope, FAIR_LEN = 25.2 m, runs from
the buoy (its end a, MoorDyn's AttachA) up to a fairlead at FAIR_POS = (0.5, 0, -5) m (MoorDyn's
Coupled point 5), which surges along x by the same motion. Every line has the same number of
nodes, so MoorDyn's dtM is set by the short line's segments.

Usage (from bench/peer; --fairlead with any command):
  python3 network.py statics [--nodes 21 41 81]
  python3 network.py heave   [--nodes 21 41 81] [--xdt 0.01 0.005] [--courant 0.5] [--tsv DIR]
  python3 network.py timing  [--repeat 3] [--xruns 21:0.01 41:0.01 ...] [--mruns 21 41 81]
(--exe the example program; default: the newest build/gfortran_*/example/network_spread.)
"""

import argparse
import glob
import math
import os
import resource
import statistics
import struct
import subprocess
import sys
import tempfile
import time
from importlib import metadata

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import peer_common as pc  # noqa: E402

import moordyn  # noqa: E402

G, RHO, DEPTH = 9.81, 1025.0, 100.0
LENGTH, RADIUS = 106.0, 80.0
MASS, EA, DIAM = 16.6, 2.79e7, 0.1376
CDN, CDT, CAN = 1.2, 0.008, 1.0
BUOY = dict(mass=2000.0, volume=8.0, ca=0.5, cda=0.6 * 4.0)
AMP, PERIOD, T_END, SAMPLE = 2.0, 10.0, 60.0, 0.1
GUESS = (0.5, 0.3, -29.6)
# --fairlead: the anchors fixed, a fourth line from the buoy (AttachA) up to a fairlead that surges
FAIR, FAIR_POS, FAIR_LEN = False, (0.5, 0.0, -5.0), 25.2
SETTLE, SETTLE_GUESS, SETTLE_CD = 20.0, 200.0, 10.0
NAMES = ("buoy_x", "buoy_y", "buoy_z", "Ttop1", "Tbot1", "Ttop2", "Tbot2", "Ttop3", "Tbot3")


def nlines():
    return 4 if FAIR else 3


def lengths():
    return [LENGTH] * 3 + ([FAIR_LEN] if FAIR else [])


def coupled():
    """The coupled point's rest position: anchor 1, or the fairlead."""
    return np.array(FAIR_POS) if FAIR else anchor(0)


def anchor(k):
    if k == 3:
        return np.array(FAIR_POS)
    a = 2 * math.pi / 3 * k
    return np.array([RADIUS * math.cos(a), RADIUS * math.sin(a), -DEPTH])


def motion(t):
    if t <= 0:
        return 0.0
    w = math.sin(0.5 * math.pi * t / PERIOD) ** 2 if t < PERIOD else 1.0
    return AMP * w * math.sin(2 * math.pi * t / PERIOD)


def default_exe():
    c = sorted(glob.glob(os.path.join(HERE, "..", "..", "build", "gfortran_*", "example", "network_spread")),
               key=os.path.getmtime)
    return os.path.abspath(c[-1]) if c else "network_spread"


# ------------------------------------------------------------------ xcable
def xcable_run(exe, nodes, dt, t_end=T_END):
    """static (buoy xyz, T_top 1..3, T_bottom 1..3), history (t, buoy xyz, (T_top, T_bottom) per line),
    times: wall and CPU of the process, and the program's own (statics, steps)."""
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    w0 = time.perf_counter()
    run = subprocess.run([exe, f"nodes={nodes}", f"dt={dt!r}", f"t_end={t_end!r}", f"sample={SAMPLE!r}",
                          f"fairlead={int(FAIR)}", f"fairlead_length={FAIR_LEN!r}"],
                         capture_output=True, text=True)
    wall = time.perf_counter() - w0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    if run.returncode != 0:
        sys.exit("xcable failed: " + run.stderr.strip())
    rows = [line.split() for line in run.stdout.splitlines() if line.strip() and not line.startswith("#")]
    static = np.array(rows[0], dtype=float)
    hist = np.array(rows[1:], dtype=float)
    inner = [line for line in run.stdout.splitlines() if line.startswith("# time")][0]
    cpu = (r1.ru_utime + r1.ru_stime) - (r0.ru_utime + r0.ru_stime)
    return static, hist, {"wall": wall, "cpu": cpu, "own": inner}


# ------------------------------------------------------------------ MoorDyn
def md_input(path, nodes, dtm, ba=0.0, cdf=1.0):
    a = [[float(v) for v in anchor(k)] for k in range(4)]
    b = BUOY
    kinds = ("Fixed", "Fixed", "Fixed") if FAIR else ("Coupled", "Fixed", "Fixed")
    fair = (f"5     Coupled   {a[3][0]!r}  {a[3][1]!r}  {a[3][2]!r}  0.0  0.0  0.0  0.0\n" if FAIR else "")
    line4 = f"4    poly     4        5       {FAIR_LEN!r}      {nodes - 1}      -\n" if FAIR else ""
    txt = f"""MoorDyn v2 input: three lines meeting at a buoy (bench/peer/network.py)
---------------------- LINE TYPES -----------------------------------
TypeName   Diam    Mass/m     EA      BA/-zeta     EI    Cd     Ca    CdAx    CaAx
(name)     (m)     (kg/m)     (N)     (N-s/-)    (N-m^2) (-)   (-)   (-)     (-)
poly  {DIAM!r}  {MASS!r}  {EA!r}  {ba!r}  0.0  {CDN * cdf!r}  {CAN}  {CDT * cdf!r}  0.0
---------------------------- POINTS -------------------------------------------
ID  Attachment  X       Y     Z      Mass   Volume  CdA    CA
(#)   (-)       (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
1     {kinds[0]}   {a[0][0]!r}  {a[0][1]!r}  {a[0][2]!r}  0.0  0.0  0.0  0.0
2     {kinds[1]}     {a[1][0]!r}  {a[1][1]!r}  {a[1][2]!r}  0.0  0.0  0.0  0.0
3     {kinds[2]}     {a[2][0]!r}  {a[2][1]!r}  {a[2][2]!r}  0.0  0.0  0.0  0.0
4     Free      {GUESS[0]!r}  {GUESS[1]!r}  {GUESS[2]!r}  {b['mass']!r}  {b['volume']!r}  {b['cda'] * cdf!r}  {b['ca']!r}
{fair}---------------------- LINES ----------------------------------------
ID   LineType AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)  (name)   (#)      (#)      (m)       (-)      (-)
1    poly     1        4       {LENGTH!r}      {nodes - 1}      -
2    poly     2        4       {LENGTH!r}      {nodes - 1}      -
3    poly     3        4       {LENGTH!r}      {nodes - 1}      -
{line4}---------------------- OPTIONS -----------------------------------------
0        writeLog
{dtm!r}   dtM
RK4      tScheme
{G}      g
{RHO}    rho
{DEPTH}  WtrDpth
1        disableOutput
1        disableOutTime
---------------------- OUTPUTS -----------------------------------------
------------------------- need this line -------------------------------------
"""
    with open(path, "w") as f:
        f.write(txt)


def md_start_state(path, nodes, start=None):
    """MoorDyn's state file (its SaveState layout: the four points, each x y z vx vy vz, then each
    line's inner nodes) at rest: the nodes start (3 n, 3: lines 1, 2, 3 from the anchor to the
    buoy, xcable's static nodes), or without start straight lines from the anchors to the buoy at
    GUESS."""
    if start is None:
        buoy = np.array(GUESS)
        lines = [[anchor(k) + (buoy - anchor(k)) * i / (nodes - 1) for i in range(nodes)] for k in range(3)]
        if FAIR:
            lines.append([buoy + (anchor(3) - buoy) * i / (nodes - 1) for i in range(nodes)])
    else:
        buoy = start[nodes - 1]
        lines = [start[k * nodes:(k + 1) * nodes] for k in range(nlines())]
    pts = [(0.0,) * 6, (0.0,) * 6, (0.0,) * 6, tuple(buoy) + (0.0, 0.0, 0.0)] + ([(0.0,) * 6] if FAIR else [])
    data = b""
    for ps in pts:
        data += struct.pack("<QQ", 1, 6) + struct.pack("<6d", *ps)
    for k in range(nlines()):
        inner = lines[k][1:nodes - 1]
        data += struct.pack("<QQ", len(inner), 6)
        for p in inner:
            data += struct.pack("<6d", *p, 0.0, 0.0, 0.0)
    with open(path, "wb") as f:
        f.write(b"MoorDyn" + struct.pack("<BB", 2, 7))
        f.write(struct.pack("<QQ", len(data) // 8 + 1, len(pts) + nlines()))
        f.write(data)


def md_nodes(sysm, nodes):
    return np.vstack([np.array([moordyn.GetLineNodePos(moordyn.GetLine(sysm, k), i) for i in range(nodes)])
                      for k in range(1, nlines() + 1)])


def md_measure(sysm, nodes):
    """buoy xyz, then per line (T_top, T_bottom): the end cells' EA strain vectors carried to the end."""
    out = list(moordyn.GetPointPos(moordyn.GetPoint(sysm, 4)))
    for k in range(1, nlines() + 1):
        ds = lengths()[k - 1] / (nodes - 1)
        line = moordyn.GetLine(sysm, k)
        p = np.array([moordyn.GetLineNodePos(line, i) for i in (0, 1, 2, nodes - 3, nodes - 2, nodes - 1)])
        d = np.diff(p, axis=0)[[0, 1, 3, 4]]
        ln = np.linalg.norm(d, axis=1)
        tv = (EA * np.maximum(ln / ds - 1, 0.0) / ln)[:, None] * d
        ends = [np.linalg.norm(1.5 * tv[3] - 0.5 * tv[2]), np.linalg.norm(1.5 * tv[0] - 0.5 * tv[1])]
        out += ends[::-1] if k == 4 else ends   # line 4: the buoy is its end A
    return np.array(out)


def md_dtm(nodes, courant):
    k = int(math.ceil(SAMPLE / (courant * min(lengths()) / (nodes - 1) / math.sqrt(EA / MASS)) - 1e-9))
    return SAMPLE / k, k


def md_statics(nodes, courant, work, settle=SETTLE, start=None):
    """MoorDyn's static state: from start (xcable's static nodes) or from the straight lines to the
    buoy at GUESS, settled for `settle` s in the damped copy; returns the path of the settled
    state, the static measure, the drift over the last 20 % of the settling (buoy m, tension N),
    the largest move of a node from start (None without), and the CPU time."""
    dtm, _ = md_dtm(nodes, courant)
    inp = os.path.join(work, "md_ic.txt")
    md_input(inp, nodes, dtm, ba=-1.0, cdf=SETTLE_CD)
    md_start_state(os.path.join(work, "start.state"), nodes, start)
    xa = [float(v) for v in coupled()]
    c0 = time.process_time()
    sysm = pc.moordyn_from_state(inp, xa, os.path.join(work, "start.state"))
    hist = []
    n = int(round(settle / SAMPLE))
    for i in range(n):
        moordyn.Step(sysm, xa, [0.0, 0.0, 0.0], i * SAMPLE, SAMPLE)
        if i >= 0.8 * n:
            hist.append(md_measure(sysm, nodes))
    hist = np.array(hist)
    state = os.path.join(work, "ic.state")
    moordyn.SaveState(sysm, state)
    static = md_measure(sysm, nodes)
    moved = None if start is None else float(np.abs(md_nodes(sysm, nodes) - start).max())
    moordyn.Close(sysm)
    drift = (float(np.linalg.norm(np.ptp(hist[:, :3], axis=0))), float(np.ptp(hist[:, 3:], axis=0).max()))
    return state, static, drift, moved, time.process_time() - c0


def xcable_nodes(exe, nodes, work):
    path = os.path.join(work, "nodes.txt")
    run = subprocess.run([exe, f"nodes={nodes}", "t_end=0", f"nodes_file={path}", f"fairlead={int(FAIR)}",
                          f"fairlead_length={FAIR_LEN!r}"], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit("xcable failed: " + run.stderr.strip())
    return np.loadtxt(path)


def md_heave(nodes, courant, work, state, t_end=T_END):
    """The heave from MoorDyn's static state: history rows as xcable's; CPU and wall of the stepping."""
    dtm, k = md_dtm(nodes, courant)
    inp = os.path.join(work, "md.txt")
    md_input(inp, nodes, dtm)
    xa = [float(v) for v in coupled()]
    sysm = pc.moordyn_from_state(inp, xa, state)
    # (a loaded state shows in the nodes only after a step: row 0 is the static measure)
    rows = []
    c0, w0 = time.process_time(), time.perf_counter()
    for i in range(int(round(t_end / SAMPLE))):
        for j in range(k):
            t0 = i * SAMPLE + j * dtm
            x0, x1 = motion(t0), motion(t0 + dtm)
            moordyn.Step(sysm, [xa[0] + x0, xa[1], xa[2]], [(x1 - x0) / dtm, 0.0, 0.0], t0, dtm)
        rows.append(np.concatenate(([(i + 1) * SAMPLE], md_measure(sysm, nodes))))
    cpu, wall = time.process_time() - c0, time.perf_counter() - w0
    moordyn.Close(sysm)
    return np.array(rows), {"dtm": dtm, "cpu": cpu, "wall": wall}


def static_cols(s):
    """xcable's static row (xyz, top of each line, bottom of each line) in the history's order (xyz,
    top and bottom per line)."""
    m = nlines()
    return np.concatenate((s[:3], np.ravel(np.column_stack((s[3:3 + m], s[3 + m:3 + 2 * m])))))


def by_end(s):
    """A row in the history's order (xyz, top and bottom per line) as xyz, the tops, the bottoms."""
    return np.concatenate((s[:3], s[3::2], s[4::2]))


# ------------------------------------------------------------------ commands
def closed_form():
    """The continuum's static state: three elastic catenaries, each carrying a third of the buoy's
    net buoyancy at its top; the horizontal force H by Newton on the span (RADIUS). Returns the
    buoy's z, the tension at the top and at the anchor, and the span's residual."""
    w = (MASS - RHO * math.pi * DIAM ** 2 / 4) * G
    vtop = (BUOY["volume"] * RHO - BUOY["mass"]) * G / 3
    va = vtop - w * LENGTH

    def walk(h):
        return (h * LENGTH / EA + h / w * (math.asinh(vtop / h) - math.asinh(va / h)),
                (va * LENGTH + 0.5 * w * LENGTH ** 2) / EA
                + h / w * (math.sqrt(1 + (vtop / h) ** 2) - math.sqrt(1 + (va / h) ** 2)))

    h = vtop
    for _ in range(60):
        r = walk(h)[0] - RADIUS
        dh = 1e-6 * h
        h -= r / ((walk(h + dh)[0] - walk(h - dh)[0]) / (2 * dh))
    return -DEPTH + walk(h)[1], math.hypot(h, vtop), math.hypot(h, va), walk(h)[0] - RADIUS


def cmd_statics(args):
    print(f"MoorDyn {metadata.version('moordyn')}; nodes per line n (MoorDyn n - 1 segments)")
    if not FAIR:
        zc, tt, ta, res = closed_form()
        print(f"closed form (continuum): buoy z {zc:.7f} m, tension at the buoy {tt:.3f} N, at the anchor {ta:.3f} N "
              f"(span missed by {res:.1e} m)")
    m = nlines()
    print("\n| code | nodes | buoy x m | buoy y m | buoy z m | " + " | ".join(f"T top {k} N" for k in range(1, m + 1))
          + " | " + " | ".join(f"T bottom {k} N" for k in range(1, m + 1)) + " | notes |")
    print("|---" * (2 * m + 6) + "|")
    res = {}
    with tempfile.TemporaryDirectory() as work:
        for n in args.nodes:
            s, _, info = xcable_run(args.exe, n, 0.01, 0.0)
            res[("xcable", n)] = static_cols(s)
            if not FAIR:
                print(f"| xcable - closed form | {n} | | | {s[2] - zc:.2e} | {s[3] - tt:.4f} | | | {s[6] - ta:.4f} "
                      "| | | |")
            print(f"| xcable | {n} | {s[0]:.2e} | {s[1]:.2e} | {s[2]:.7f} | " + " | ".join(f"{v:.3f}" for v in s[3:])
                  + f" | {info['own'].split(';')[0][2:]} |", flush=True)
        for n in args.nodes:
            start = xcable_nodes(args.exe, n, work)
            for how in ("xcable", "guess"):
                if how == "xcable":
                    _, s, drift, moved, cpu = md_statics(n, args.courant, work, args.settle, start)
                    note = (f"xcable's nodes held {args.settle:g} s: largest node move {moved:.1e} m")
                    res[("MoorDyn", n)] = s
                else:
                    _, s, drift, moved, cpu = md_statics(n, args.courant, work, args.settle_guess)
                    note = f"from straight lines, the buoy at {GUESS}, settled {args.settle_guess:g} s"
                    res[("MoorDyn own", n)] = s
                sx = by_end(s)
                print(f"| MoorDyn | {n} | {sx[0]:.2e} | {sx[1]:.2e} | {sx[2]:.7f} | "
                      + " | ".join(f"{v:.3f}" for v in sx[3:])
                      + f" | {note}; over the last 20 %: buoy moves {drift[0]:.1e} m, tensions {drift[1]:.1e} N; "
                      f"{cpu:.1f} s CPU |", flush=True)
    print("\n| a | b | buoy position m | largest tension difference N |")
    print("|---|---|---|---|")
    for code in ("xcable", "MoorDyn", "MoorDyn own"):
        for a, b in zip(args.nodes[:-1], args.nodes[1:]):
            d = res[(code, a)] - res[(code, b)]
            print(f"| {code} {a} | {code} {b} | {np.linalg.norm(d[:3]):.2e} | {np.abs(d[3:]).max():.4f} |")
    for n in args.nodes:
        for tag in ("MoorDyn", "MoorDyn own"):
            d = res[(tag, n)] - res[("xcable", n)]
            print(f"| {tag} {n} | xcable {n} | {np.linalg.norm(d[:3]):.2e} | {np.abs(d[3:]).max():.4f} |")


def differences(a, b):
    """rms and largest difference of the six tensions (N) and of the buoy position (m), samples 1..."""
    n = min(len(a), len(b))
    a, b = a[:n], b[:n]
    assert np.allclose(a[:, 0], b[:, 0])
    dt = a[:, 4:] - b[:, 4:]
    dp = np.linalg.norm(a[:, 1:4] - b[:, 1:4], axis=1)
    return math.sqrt(np.mean(dt ** 2)), np.abs(dt).max(), math.sqrt(np.mean(dp ** 2)), dp.max()


def label(k):
    return f"{k[0]} {k[1]} nodes, {'dt' if k[0] == 'xcable' else 'dtM'} {k[2]:.3g} s"


def cmd_heave(args):
    print(f"MoorDyn {metadata.version('moordyn')} RK4 at Courant {args.courant}; "
          f"{'the fairlead of line 4' if FAIR else 'anchor 1'} moves {AMP} m along x, "
          f"period {PERIOD} s (ramp {PERIOD} s), {T_END} s, sampled every {SAMPLE} s")
    runs = {}
    with tempfile.TemporaryDirectory() as work:
        for n in args.nodes:
            for dt in args.xdt:
                _, h, info = xcable_run(args.exe, n, dt)
                runs[("xcable", n, dt)] = h[1:]
                print(f"xcable {n} nodes dt {dt}: {info['wall']:.2f} s wall, {info['cpu']:.2f} s CPU; "
                      f"T_top1 {h[:, 4].min():.1f} .. {h[:, 4].max():.1f} N; buoy x {h[:, 1].min():.3f} .. "
                      f"{h[:, 1].max():.3f} m ({info['own'][2:]})", flush=True)
        for n in args.md_nodes or args.nodes:
            state, _, drift, _, _ = md_statics(n, args.courant, work, args.settle, xcable_nodes(args.exe, n, work))
            h, info = md_heave(n, args.courant, work, state)
            runs[("MoorDyn", n, info["dtm"])] = h
            print(f"MoorDyn {n} nodes dtM {info['dtm']:.3g}: {info['wall']:.2f} s wall, {info['cpu']:.2f} s CPU; "
                  f"T_top1 {h[:, 4].min():.1f} .. {h[:, 4].max():.1f} N; buoy x {h[:, 1].min():.3f} .. "
                  f"{h[:, 1].max():.3f} m (settling drift {drift[0]:.1e} m, {drift[1]:.1e} N)", flush=True)
    if args.tsv:
        os.makedirs(args.tsv, exist_ok=True)
        for (code, n, dt), h in runs.items():
            np.savetxt(os.path.join(args.tsv, f"network_{code.lower()}_{n}_{dt:.6g}.tsv"), h, fmt="%.10g",
                       delimiter="\t", header="t\t" + "\t".join(NAMES), comments="")
    print("\n| a | b | rms dT N | max dT N | rms d buoy m | max d buoy m |")
    print("|---|---|---|---|---|---|")
    keys = sorted(runs, key=lambda k: (k[0], k[1], -k[2]))
    xs = [k for k in keys if k[0] == "xcable"]
    ms = [k for k in keys if k[0] == "MoorDyn"]
    # xcable: the step's change on each grid, then the grid's change at each step; MoorDyn: its grids
    pairs = [(a, b) for a in xs for b in xs if a[1] == b[1] and a[2] > b[2]]
    pairs += [(a, b) for a in xs for b in xs if a[2] == b[2] and a[1] < b[1]
              and not any(a[1] < k[1] < b[1] for k in xs)]
    pairs += list(zip(ms[:-1], ms[1:]))
    for a, b in pairs:
        d = differences(runs[a], runs[b])
        print(f"| {label(a)} | {label(b)} | {d[0]:.3f} | {d[1]:.3f} | {d[2]:.2e} | {d[3]:.2e} |")
    fx = max(xs, key=lambda k: (k[1], -k[2]))
    for m in ms:
        d = differences(runs[m], runs[fx])
        print(f"| {label(m)} | {label(fx)} | {d[0]:.3f} | {d[1]:.3f} | {d[2]:.2e} | {d[3]:.2e} |")
    rx, rm = extrapolated(runs)
    if rx is not None and rm is not None:
        d = differences(rx, rm)
        print(f"| xcable extrapolated | MoorDyn extrapolated | {d[0]:.3f} | {d[1]:.3f} | {d[2]:.2e} | {d[3]:.2e} |")
        for k in keys:
            for tag, r in (("xcable extrapolated", rx), ("MoorDyn extrapolated", rm)):
                d = differences(runs[k], r)
                print(f"| {label(k)} | {tag} | {d[0]:.3f} | {d[1]:.3f} | {d[2]:.2e} | {d[3]:.2e} |")


def extrapolated(runs):
    """Richardson's extrapolation of each code's histories (both second order): xcable from its two
    finest grids at its finest step plus the change of step at the finest grid; MoorDyn (dtM tied
    to ds) from its two finest grids. None where the runs are missing."""
    xs = sorted(k for k in runs if k[0] == "xcable")
    ms = sorted(k for k in runs if k[0] == "MoorDyn")
    rx = rm = None
    grids = sorted({k[1] for k in xs})
    steps = sorted({k[2] for k in xs})
    if len(grids) >= 2 and len(steps) >= 2:
        f, c = runs[("xcable", grids[-1], steps[0])], runs[("xcable", grids[-2], steps[0])]
        fc = runs[("xcable", grids[-1], steps[1])]
        rx = f.copy()
        rx[:, 1:] += (f[:, 1:] - c[:, 1:]) / 3 + (f[:, 1:] - fc[:, 1:]) * (steps[0] ** 2 / (steps[1] ** 2 - steps[0] ** 2))
    if len(ms) >= 2:
        f, c = runs[ms[-1]], runs[ms[-2]]
        rm = f.copy()
        rm[:, 1:] += (f[:, 1:] - c[:, 1:]) / 3
    return rx, rm


def cmd_timing(args):
    """Medians of --repeat runs of wall and CPU time, xcable (the whole process: statics, the 60 s,
    the output) and MoorDyn (the stepping of the 60 s with the measures every sample; its settling
    not counted), with each run's rms and largest tension error against both codes'
    extrapolations (as in heave: the runs must include xcable's 41 and 81 nodes at dt 0.005 and
    0.01 and MoorDyn's 41 and 81)."""
    runs, times = {}, {}
    for spec in args.xruns:
        n, dt = spec.split(":")
        walls, cpus = [], []
        for _ in range(args.repeat):
            _, h, info = xcable_run(args.exe, int(n), float(dt))
            walls.append(info["wall"])
            cpus.append(info["cpu"])
        runs[("xcable", int(n), float(dt))] = h[1:]
        times[("xcable", int(n), float(dt))] = (statistics.median(walls), statistics.median(cpus))
    with tempfile.TemporaryDirectory() as work:
        for n in args.mruns:
            n = int(n)
            state = md_statics(n, args.courant, work, args.settle, xcable_nodes(args.exe, n, work))[0]
            walls, cpus = [], []
            for _ in range(args.repeat):
                h, info = md_heave(n, args.courant, work, state)
                walls.append(info["wall"])
                cpus.append(info["cpu"])
            runs[("MoorDyn", n, info["dtm"])] = h
            times[("MoorDyn", n, info["dtm"])] = (statistics.median(walls), statistics.median(cpus))
    rx, rm = extrapolated(runs)
    print(f"MoorDyn {metadata.version('moordyn')}, RK4 at Courant {args.courant}; medians of {args.repeat} runs")
    print("\n| code | nodes | step s | wall s | CPU s | rms dT to xcable extr. N | max N | "
          "rms dT to MoorDyn extr. N | max N |")
    print("|---|---|---|---|---|---|---|---|---|")
    for k in sorted(runs, key=lambda k: (k[0] != "xcable", k[1], -k[2])):
        dx, dm = differences(runs[k], rx), differences(runs[k], rm)
        print(f"| {k[0]} | {k[1]} | {k[2]:.3g} | {times[k][0]:.3f} | {times[k][1]:.3f} | {dx[0]:.3f} | {dx[1]:.3f} | "
              f"{dm[0]:.3f} | {dm[1]:.3f} |")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("what", choices=["statics", "heave", "timing"])
    ap.add_argument("--exe", default=default_exe())
    ap.add_argument("--nodes", type=int, nargs="+", default=[21, 41, 81])
    ap.add_argument("--md-nodes", type=int, nargs="+", default=None)
    ap.add_argument("--xdt", type=float, nargs="+", default=[0.01, 0.005])
    ap.add_argument("--courant", type=float, default=0.5)
    ap.add_argument("--fairlead", action="store_true", help="the fourth line to a surging fairlead")
    ap.add_argument("--settle", type=float, default=SETTLE, help="MoorDyn's settling from xcable's nodes, s")
    ap.add_argument("--settle-guess", type=float, default=SETTLE_GUESS, help="MoorDyn's own settling, s")
    ap.add_argument("--tsv", default="")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--xruns", nargs="+", default=["21:0.01", "41:0.01", "41:0.005", "81:0.01", "81:0.005"])
    ap.add_argument("--mruns", nargs="+", default=["21", "41", "81"])
    args = ap.parse_args()
    args.exe = os.path.abspath(args.exe)
    globals()["FAIR"] = args.fairlead
    return {"statics": cmd_statics, "heave": cmd_heave, "timing": cmd_timing}[args.what](args)


if __name__ == "__main__":
    sys.exit(main())
