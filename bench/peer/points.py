#!/usr/bin/env python3
"""Bodies on a line (`&point_k`): xcable against MoorDyn v2 (PyPI `moordyn`), statics and a heave.

bench/peer, not part of `make test`. Results: points.md.

Scene: a chain and rope line in still sea water (1025 kg/m^3, g = 9.81), no seabed (water
200 m deep in MoorDyn, none in xcable; the line stays above -110 m): end a fixed at (0, -100) m,
50 m of 76 mm studless chain (MoorPy's data: 115.6 kg/m, EA 4.945e8 N, volume-equivalent
diameter 0.1369 m), then 100 m of 160 mm polyester (16.58 kg/m, EA 2.790e7 N, 0.1376 m), to
a fairlead at (110, -10) m. No bending stiffness. A body at the joint (case):
  clump: 2000 kg displacing 0.25 m^3 (16.7 kN net down);
  buoy:  500 kg displacing 3 m^3 (25.3 kN net up), Ca 1, drag Cd A = 0.6 x 2.5 m^2.
Line drag and added mass alike in both codes: Cd normal 1.2, tangential 0.008, Ca normal 1,
tangential 0 (xcable has none).

xcable: &segment_1, &segment_2 with `nodes` each (the joint a node of both), &point_1 joint = 1.
MoorDyn: point 1 Fixed (anchor), point 2 Free with M, V, CdA, Ca (the joint), point 3 Coupled
(fairlead); line 1 chain from 1 to 2, line 2 rope from 2 to 3. MoorDyn's point buoyancy is the
full rho g V wherever the point is (Point::doRHS, no surface): the buoy stays 50 m down here.

1. statics: each code's static state (xcable's Newton statics; MoorDyn's, see below), the
   anchor's and the fairlead's tension and the joint's position, against the continuum's closed
   form (two elastic catenaries with the body's net weight as a jump of the vertical force,
   solved here by Newton on (H, V_a)).
2. dynamics: from each code's own static state, the fairlead heaves
   z_b = z_b0 + A w(t) sin(2 pi t / T), w = sin^2(pi t / (2 T)) for t < T, then 1
   (xcable's motion = 'harmonic', ramp_time = T), A = 2 m, T = 10 s, 60 s. Compared every
   --sample s: the fairlead tension and the joint's (x, z); rms and largest differences over
   the whole run, between the codes and between each code's successive grids.
   MoorDyn: RK4 at dtM <= --courant ds_min / c_max (dividing the sample); Step is called once per
   dtM with the fairlead's exact position at the step's start and the chord's velocity.
   Tensions of both codes: the end cell's tension carried to the end (MoorDyn: the vectors
   1.5 T_N - 0.5 T_N-1 of the segments' EA strain along them; carrying the magnitudes instead
   is off by 3/8 ds^2 T'' = 180 N at the anchor on 5 m chain segments).

3. free: 60 m of the polyester hanging from a fairlead at (0, -10) m that surges 2 m (10 s,
   ramped, 60 s), a clump (2000 kg, 0.25 m^3, Ca 1, Cd 1 on 0.5 m^2) on its free end b; MoorDyn:
   point 1 Coupled, point 2 Free, from xcable's static nodes. The fairlead tension and the
   clump's position compared as in 2.

MoorDyn's static state in 2: xcable's static nodes loaded into MoorDyn (its state file) and
held --settle s in a copy with critical axial damping and 10 times the drag; `statics`
shows that MoorDyn moves them by less than 3e-8 m (they are its equilibrium too), and
--relax-grids adds MoorDyn's own dynamic relaxation from its own start (slow: 15 s CPU at g 10).
In 3 xcable's static nodes (a straight hanging line) are loaded as they are.

Usage (from bench/peer; grid g: g chain and 2 g rope segments, ds = 50 / g m):
  python3 points.py statics [--grids 10 20 40 80] [--relax-grids 10 20]
  python3 points.py heave [--case buoy|clump] [--grids ...] [--xdt 0.01 0.005] [--courant 0.5] [--tsv DIR]
  python3 points.py free [--grids ...] [--xdt ...]
(--exe the xcable executable, default ../../bin/xcable.) Results: points.md.
"""

import argparse
import math
import os
import struct
import subprocess
import sys
import tempfile
import time
from importlib import metadata

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import peer_common as pc  # noqa: E402  (MoorDyn started quietly)

import moordyn  # noqa: E402

G, RHO = 9.81, 1025.0
ANCHOR, FAIRLEAD = (0.0, -100.0), (110.0, -10.0)
CDN, CDT, CAN = 1.2, 0.008, 1.0
AMP, PERIOD, T_END = 2.0, 10.0, 60.0
ICGEN, CDSCALE, THRESH, TMAXIC = 1, 5.0, 1e-12, 2000.0
SETTLE, SETTLE_CD, PERTURB = 20.0, 10.0, 0.0


def chain(dc=0.076):
    return 20.01e3 * dc * dc, 85.61e9 * dc * dc - 3.927e7 * dc ** 3, 1.801 * dc


def polyester(d=0.16):
    return 0.6476e3 * d * d, 1.09e9 * d * d, 0.86 * d


def segments():
    """(length m, mass kg/m, EA N, diameter m, wet weight N/m) from end a."""
    out = []
    for length, (mass, ea, dvol) in ((50.0, chain()), (100.0, polyester())):
        out.append((length, mass, ea, dvol, (mass - RHO * math.pi * dvol * dvol / 4) * G))
    return out


BODIES = {"clump": dict(mass=2000.0, volume=0.25, ca=0.0, cd=0.0, area=0.0),
          "buoy": dict(mass=500.0, volume=3.0, ca=1.0, cd=0.6, area=2.5)}


def heave(t):
    if t <= 0:
        return 0.0
    w = math.sin(0.5 * math.pi * t / PERIOD) ** 2 if t < PERIOD else 1.0
    return AMP * w * math.sin(2 * math.pi * t / PERIOD)


# ------------------------------------------------------------------ closed form
def closed_form(body):
    """Continuum statics: the two elastic catenaries with the jump W_p (net weight of the body)
    in the vertical force. Returns anchor tension, fairlead tension, joint (x, z)."""
    segs = segments()
    wp = (body["mass"] - RHO * body["volume"]) * G

    def walk(y):
        h, va = y
        p = np.array(ANCHOR, dtype=float)
        joint = None
        for j, (length, _, ea, _, w) in enumerate(segs):
            vb = va + w * length
            p = p + [h * length / ea + h / w * (math.asinh(vb / h) - math.asinh(va / h)),
                     (va * length + 0.5 * w * length ** 2) / ea
                     + h / w * (math.sqrt(1 + (vb / h) ** 2) - math.sqrt(1 + (va / h) ** 2))]
            if j == 0:
                joint = p.copy()
                vb += wp
            va = vb
        return p, joint, va

    y = np.array([0.5 * sum(s[0] * s[4] for s in segs), -0.2 * sum(s[0] * s[4] for s in segs)])
    for _ in range(100):
        r = walk(y)[0] - FAIRLEAD
        if np.linalg.norm(r) < 1e-11:
            break
        jac = np.empty((2, 2))
        for j in range(2):
            dy = np.zeros(2)
            dy[j] = 1e-6 * max(1.0, abs(y[j]))
            jac[:, j] = (walk(y + dy)[0] - walk(y - dy)[0]) / (2 * dy[j])
        step = np.linalg.solve(jac, r)
        for _ in range(30):
            if y[0] - step[0] > 0 and np.linalg.norm(walk(y - step)[0] - FAIRLEAD) < np.linalg.norm(r):
                break
            step *= 0.5
        y = y - step
    _, joint, vb = walk(y)
    return math.hypot(y[0], y[1]), math.hypot(y[0], vb), joint, np.linalg.norm(walk(y)[0] - FAIRLEAD)


# ------------------------------------------------------------------ xcable
def xcable_namelist(body, grid, dt, t_end, out, interval):
    segs = segments()
    n = (grid, 2 * grid)
    text = "&cable length = %r, bending_stiffness = 1e-3 /\n" % sum(s[0] for s in segs)
    text += "&material law = 'linear', compression = 'none' /\n"
    text += ("&fluid density = %r, surface_z = 0, cd_normal = %r, cd_tangential = %r, ca_normal = %r /\n"
             % (RHO, CDN, CDT, CAN))
    for k, (length, mass, ea, dvol, _) in enumerate(segs):
        area = math.pi * dvol * dvol / 4
        text += "&segment_%d length = %r, diameter = %r, density = %r, ea = %r, nodes = %d /\n" % (
            k + 1, length, dvol, mass / area, ea, n[k] + 1)
    b = body
    text += ("&point_1 joint = 1, mass = %r, volume = %r, ca = %r, cd = %r, area = %r /\n"
             % (b["mass"], b["volume"], b["ca"], b["cd"], b["area"]))
    text += "&end_a kind = 'fixed', x = %r, z = %r /\n" % ANCHOR
    if t_end > dt:
        text += ("&end_b kind = 'motion', x = %r, z = %r, motion = 'harmonic', amplitude = %r, period = %r, "
                 "direction_x = 0, direction_z = 1, ramp_time = %r /\n" % (*FAIRLEAD, AMP, PERIOD, PERIOD))
    else:
        text += "&end_b kind = 'fixed', x = %r, z = %r /\n" % FAIRLEAD
    text += "&rupture enabled = .false. /\n"
    text += "&numerics nodes = %d, dt = %r, t_end = %r, newton_tol = 1e-12 /\n" % (sum(n) + 1, dt, t_end)
    text += "&output file = '%s', interval = %r, quiet = .true., fields = 'x z' /\n" % (out, interval)
    return text


def xcable_run(exe, body, grid, dt, t_end, sample, work):
    nml, out = os.path.join(work, "x.nml"), os.path.join(work, "x.h5")
    with open(nml, "w") as f:
        f.write(xcable_namelist(body, grid, dt, t_end, out, sample))
    c0 = time.time()
    run = subprocess.run([exe, nml], capture_output=True, text=True)
    wall = time.time() - c0
    if run.returncode != 0:
        sys.exit("xcable failed: " + run.stderr.strip())
    with h5py.File(out) as f:
        a = f["summary"].attrs
        st = (float(a["static_tension_a"]), float(a["static_tension_b"]),
              np.array([f["static/x"][grid], f["static/z"][grid]]),
              np.column_stack([f["static/x"][:], f["static/z"][:]]))
        hist = None
        if t_end > dt:
            h = f["history"]
            ts = f["time"][:]
            tb = np.interp(ts, h["time"][:], h["end_b/tension"][:])
            hist = np.column_stack([ts, tb, f["x"][:, grid], f["z"][:, grid]])
        info = {"rejected": int(a["rejected_steps"]), "wall": wall}
    os.remove(out)
    return st, hist, info


# ------------------------------------------------------------------ MoorDyn
def md_input(path, body, grid, dtm, ba=0.0, cdf=1.0):
    segs = segments()
    b = body
    (l1, m1, ea1, d1, _), (l2, m2, ea2, d2, _) = segs
    txt = f"""MoorDyn v2 input: a chain and rope line with a body at the joint (bench/peer/points.py)
---------------------- LINE TYPES -----------------------------------
TypeName   Diam    Mass/m     EA      BA/-zeta     EI    Cd     Ca    CdAx    CaAx
(name)     (m)     (kg/m)     (N)     (N-s/-)    (N-m^2) (-)   (-)   (-)     (-)
chain  {d1!r}  {m1!r}  {ea1!r}  {ba!r}  0.0  {CDN * cdf!r}  {CAN}  {CDT * cdf!r}  0.0
rope   {d2!r}  {m2!r}  {ea2!r}  {ba!r}  0.0  {CDN * cdf!r}  {CAN}  {CDT * cdf!r}  0.0
---------------------------- POINTS -------------------------------------------
ID  Attachment  X       Y     Z      Mass   Volume  CdA    CA
(#)   (-)       (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
1     Fixed     {ANCHOR[0]!r}  0.0  {ANCHOR[1]!r}  0.0  0.0  0.0  0.0
2     Free      40.0  0.0  -70.0  {b['mass']!r}  {b['volume']!r}  {b['cd'] * b['area'] * cdf!r}  {b['ca']!r}
3     Coupled   {FAIRLEAD[0]!r}  0.0  {FAIRLEAD[1]!r}  0.0  0.0  0.0  0.0
---------------------- LINES ----------------------------------------
ID   LineType AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)  (name)   (#)      (#)      (m)       (-)      (-)
1    chain     1        2       {l1!r}      {grid}      -
2    rope      2        3       {l2!r}      {2 * grid}      -
---------------------- OPTIONS -----------------------------------------
0        writeLog
{dtm!r}   dtM
RK4      tScheme
{G}      g
{RHO}    rho
200.0  WtrDpth
1.0    dtIC
{TMAXIC}  TmaxIC
{THRESH}  threshIC
{ICGEN}  ICgenDynamic
{CDSCALE}  CdScaleIC
1        disableOutput
1        disableOutTime
---------------------- OUTPUTS -----------------------------------------
------------------------- need this line -------------------------------------
"""
    with open(path, "w") as f:
        f.write(txt)


def md_dtm(grid, courant):
    segs = segments()
    return courant * min(s[0] / n / math.sqrt(s[2] / s[1]) for s, n in zip(segs, (grid, 2 * grid)))


def md_measure(sysm, grid):
    segs = segments()
    out = []
    for k, n in ((1, grid), (2, 2 * grid)):
        line = moordyn.GetLine(sysm, k)
        p = np.array([moordyn.GetLineNodePos(line, i) for i in range(n + 1)])
        ds = segs[k - 1][0] / n
        d = np.diff(p, axis=0)
        ln = np.linalg.norm(d, axis=1)
        out.append((segs[k - 1][2] * np.maximum(ln / ds - 1, 0.0) / ln)[:, None] * d)
    # the segments' tension vectors carried linearly to the end (exact for a uniform static line)
    ta = np.linalg.norm(1.5 * out[0][0] - 0.5 * out[0][1])
    tb = np.linalg.norm(1.5 * out[1][-1] - 0.5 * out[1][-2])
    pj = moordyn.GetPointPos(moordyn.GetPoint(sysm, 2))
    return ta, tb, np.array([pj[0], pj[2]]), pj[1]


def perturbed(xz, grid, amp):
    """The nodes xz moved by amp sin(pi s / L) up and amp / 2 sin(2 pi s / L) across (s the node's
    arc length over the line, ends kept): MoorDyn's settling then has to find its own state."""
    s = np.concatenate([np.linspace(0, 50, grid + 1), np.linspace(50, 150, 2 * grid + 1)[1:]]) / 150
    out = np.array(xz, dtype=float)
    out[:, 1] += amp * np.sin(np.pi * s)
    out[:, 0] += 0.5 * amp * np.sin(2 * np.pi * s)
    return out


def md_state(path, xz, grid):
    """A MoorDyn state file (the layout of its SaveState for this input: the three points, each
    x, y, z, vx, vy, vz, the free one at the joint; then each line's inner nodes) from node
    positions xz (3 g + 1, 2) at rest."""
    pts = [(0.0,) * 6, (xz[grid][0], 0.0, xz[grid][1], 0.0, 0.0, 0.0), (0.0,) * 6]
    data = b""
    for ps in pts:
        data += struct.pack("<QQ", 1, 6) + struct.pack("<6d", *ps)
    for inner in (xz[1:grid], xz[grid + 1:3 * grid]):
        data += struct.pack("<QQ", len(inner), 6)
        for p in inner:
            data += struct.pack("<6d", p[0], 0.0, p[1], 0.0, 0.0, 0.0)
    with open(path, "wb") as f:
        f.write(b"MoorDyn" + struct.pack("<BB", 2, 7))
        f.write(struct.pack("<QQ", len(data) // 8 + 1, 5))
        f.write(data)


def md_create(body, grid, dtm, work, start=None, settle=SETTLE, sample=0.1):
    """MoorDyn's static state. With start (xcable's static nodes, (3 g + 1, 2)): those loaded into
    a copy of the line with critical axial damping (BA = -1) and SETTLE_CD times the drag (line
    and body; neither changes a static state), held for `settle` s; its largest change of T_b
    and of the joint's position over the last 20 % of the settling is returned as the drift.
    Without: MoorDyn's own dynamic relaxation (ICgenDynamic, drag times CdScaleIC, TmaxIC) on
    the damped copy. The settled state is saved and loaded into the undamped line."""
    inp = os.path.join(work, "md_ic.txt")
    md_input(inp, body, grid, dtm, ba=-1.0, cdf=1.0 if start is None else SETTLE_CD)
    drift = None
    xb = [FAIRLEAD[0], 0.0, FAIRLEAD[1]]
    if start is None:
        saved = os.dup(1)
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, 1)
        try:
            sysm = moordyn.Create(inp)
            moordyn.SetVerbosity(sysm, moordyn.LEVEL_ERR)
            moordyn.Init(sysm, xb, [0.0, 0.0, 0.0])
        finally:
            os.dup2(saved, 1)
            os.close(devnull)
            os.close(saved)
    else:
        md_state(os.path.join(work, "x.state"), perturbed(start, grid, PERTURB), grid)
        sysm = pc.moordyn_from_state(inp, xb, os.path.join(work, "x.state"))
        hist = []
        nsteps = int(round(settle / sample))
        for i in range(nsteps):
            moordyn.Step(sysm, xb, [0.0, 0.0, 0.0], i * sample, sample)
            if i >= 0.8 * nsteps:
                m = md_measure(sysm, grid)
                hist.append((m[1], m[2][0], m[2][1]))
        hist = np.array(hist)
        nodes = [np.array([moordyn.GetLineNodePos(moordyn.GetLine(sysm, k), i) for i in range(n + 1)])[:, [0, 2]]
                 for k, n in ((1, grid), (2, 2 * grid))]
        moved = float(np.abs(np.vstack([nodes[0], nodes[1][1:]]) - start).max())
        drift = (float(np.ptp(hist[:, 0])), float(np.hypot(np.ptp(hist[:, 1]), np.ptp(hist[:, 2]))), moved)
    moordyn.SaveState(sysm, os.path.join(work, "ic.state"))
    static = md_measure(sysm, grid)
    moordyn.Close(sysm)
    inp = os.path.join(work, "md.txt")
    md_input(inp, body, grid, dtm)
    # (a loaded state shows in the node positions only after a step: measured before)
    return pc.moordyn_from_state(inp, xb, os.path.join(work, "ic.state")), static, drift


def md_run(body, grid, courant, t_end, sample, work, start=None, settle=SETTLE):
    k = int(math.ceil(sample / md_dtm(grid, courant) - 1e-9))   # MoorDyn steps per sample
    dtm = sample / k
    c0 = time.process_time()
    sysm, (ta, tb, pj, _), drift = md_create(body, grid, dtm, work, start, settle)
    cpu_ic = time.process_time() - c0
    static = (ta, tb, pj)
    hist = None
    c0 = time.process_time()
    if t_end > 0:
        rows = [(0.0, tb, pj[0], pj[1])]
        xb = [FAIRLEAD[0], 0.0, FAIRLEAD[1]]
        for i in range(int(round(t_end / sample))):
            for j in range(k):
                # the fairlead at its exact height at the step's start, the chord's velocity: stepping
                # once per sample instead makes the velocity jump by A w^2 x sample each time, and the
                # rope rings with sqrt(EA m) times that (850 N at 0.05 s)
                t0 = i * sample + j * dtm
                z0, z1 = heave(t0), heave(t0 + dtm)
                moordyn.Step(sysm, [xb[0], 0.0, xb[2] + z0], [0.0, 0.0, (z1 - z0) / dtm], t0, dtm)
            _, tb, pj, _ = md_measure(sysm, grid)
            rows.append(((i + 1) * sample, tb, pj[0], pj[1]))
        hist = np.array(rows)
    moordyn.Close(sysm)
    return static, hist, {"dtm": dtm, "cpu_ic": cpu_ic, "cpu": time.process_time() - c0, "drift": drift}


# ------------------------------------------------------------------ comparison
def differences(a, b):
    """rms and largest |a - b| of the fairlead tension (N) and of the joint's position (m)."""
    n = min(len(a), len(b))
    a, b = a[:n], b[:n]
    assert np.allclose(a[:, 0], b[:, 0])
    dt = a[:, 1] - b[:, 1]
    dp = np.hypot(a[:, 2] - b[:, 2], a[:, 3] - b[:, 3])
    return (math.sqrt(np.mean(dt ** 2)), np.abs(dt).max(), math.sqrt(np.mean(dp ** 2)), dp.max())


def cmd_statics(args):
    print(f"MoorDyn {metadata.version('moordyn')}; grid g: g chain and 2g rope segments")
    for case in args.cases:
        body = BODIES[case]
        ta, tb, pj, res = closed_form(body)
        print(f"\n### {case}: {body}\n")
        print("| code | grid | anchor tension N | fairlead tension N | joint x m | joint z m | "
              "err T_a N | err T_b N | err joint m | notes |")
        print("|---|---|---|---|---|---|---|---|---|---|")
        print(f"| closed form | continuum | {ta:.3f} | {tb:.3f} | {pj[0]:.5f} | {pj[1]:.5f} | | | | "
              f"end b missed by {res:.1e} m |")
        with tempfile.TemporaryDirectory() as work:
            starts = {}
            for g in args.grids:
                s, _, info = xcable_run(args.exe, body, g, 1e-3, 1e-3, 0.0, work)
                starts[g] = s[3]
                print(f"| xcable | {g} | {s[0]:.3f} | {s[1]:.3f} | {s[2][0]:.5f} | {s[2][1]:.5f} | "
                      f"{s[0] - ta:.3f} | {s[1] - tb:.3f} | {np.linalg.norm(s[2] - pj):.2e} | |", flush=True)
            for g in args.grids:
                s, _, info = md_run(body, g, args.courant, 0.0, 0.1, work, starts[g], args.settle)
                d = info["drift"]
                note = (f"xcable's nodes{' moved by up to %g m' % PERTURB if PERTURB else ''} held {args.settle:g} s ({info['cpu_ic']:.1f} s CPU); over its "
                        f"last 20 %: T_b moves {d[0]:.2g} N, joint {d[1]:.2g} m; "
                        f"largest node move from the start {d[2]:.2g} m")
                print(f"| MoorDyn | {g} | {s[0]:.3f} | {s[1]:.3f} | {s[2][0]:.5f} | {s[2][1]:.5f} | "
                      f"{s[0] - ta:.3f} | {s[1] - tb:.3f} | {np.linalg.norm(s[2] - pj):.2e} | {note} |",
                      flush=True)
            for g in args.relax_grids:
                s, _, info = md_run(body, g, args.courant, 0.0, 0.1, work)
                note = f"MoorDyn's dynamic relaxation, TmaxIC {TMAXIC:g} s ({info['cpu_ic']:.1f} s CPU)"
                print(f"| MoorDyn | {g} | {s[0]:.3f} | {s[1]:.3f} | {s[2][0]:.5f} | {s[2][1]:.5f} | "
                      f"{s[0] - ta:.3f} | {s[1] - tb:.3f} | {np.linalg.norm(s[2] - pj):.2e} | {note} |",
                      flush=True)


def cmd_heave(args):
    body = BODIES[args.case]
    print(f"MoorDyn {metadata.version('moordyn')} RK4 at Courant {args.courant}; heave {AMP} m, period "
          f"{PERIOD} s, ramp {PERIOD} s, {T_END} s; case {args.case}: {body}")
    runs = {}
    with tempfile.TemporaryDirectory() as work:
        for g in args.grids:
            for dt in args.xdt:
                _, h, info = xcable_run(args.exe, body, g, dt, T_END, args.sample, work)
                runs[("xcable", g, dt)] = h
                print(f"xcable grid {g} dt {dt}: {info['wall']:.1f} s wall, {info['rejected']} rejected; "
                      f"T_b {h[:, 1].min():.1f} .. {h[:, 1].max():.1f} N; joint z {h[:, 3].min():.3f} .. "
                      f"{h[:, 3].max():.3f} m", flush=True)
        for g in args.md_grids or args.grids:
            start = xcable_run(args.exe, body, g, 1e-3, 1e-3, 0.0, work)[0][3]
            _, h, info = md_run(body, g, args.courant, T_END, args.sample, work, start, args.settle)
            runs[("MoorDyn", g, 0)] = h
            print(f"MoorDyn grid {g}: dtM {info['dtm']:.3g} s, {info['cpu']:.1f} s CPU (+{info['cpu_ic']:.1f} IC); "
                  f"T_b {h[:, 1].min():.1f} .. {h[:, 1].max():.1f} N; joint z {h[:, 3].min():.3f} .. "
                  f"{h[:, 3].max():.3f} m; settling drift T_b {info['drift'][0]:.2g} N, joint {info['drift'][1]:.2g} m",
                  flush=True)
            if args.tsv:
                np.savetxt(os.path.join(args.tsv, f"points_{args.case}_moordyn_{g}.tsv"), h, fmt="%.10g",
                           delimiter="\t", header="t\ttension_b\tjoint_x\tjoint_z", comments="")
    if args.tsv:
        for (code, g, dt), h in runs.items():
            if code == "xcable":
                np.savetxt(os.path.join(args.tsv, f"points_{args.case}_xcable_{g}_{dt}.tsv"), h, fmt="%.10g",
                           delimiter="\t", header="t\ttension_b\tjoint_x\tjoint_z", comments="")
    print("\n| a | b | rms dT_b N | max dT_b N | rms d joint m | max d joint m |")
    print("|---|---|---|---|---|---|")
    keys = sorted(runs, key=lambda k: (k[0], k[1], -k[2]))
    xs = [k for k in keys if k[0] == "xcable"]
    ms = [k for k in keys if k[0] == "MoorDyn"]
    for group in (xs, ms):
        for a, b in zip(group[:-1], group[1:]):
            d = differences(runs[a], runs[b])
            print(f"| {a} | {b} | {d[0]:.2f} | {d[1]:.2f} | {d[2]:.2e} | {d[3]:.2e} |")
    fx = max(xs, key=lambda k: (k[1], -k[2]))
    for m in ms:
        d = differences(runs[m], runs[fx])
        print(f"| {m} | {fx} | {d[0]:.2f} | {d[1]:.2f} | {d[2]:.2e} | {d[3]:.2e} |")


# ------------------------------------------------------------------ 3. a body on a free end
FREE_LEN, FREE_TOP = 60.0, (0.0, -10.0)
FREE_BODY = dict(mass=2000.0, volume=0.25, ca=1.0, cd=1.0, area=0.5)


def free_namelist(grid, dt, t_end, out, interval):
    """The polyester rope hanging from a fairlead that surges (end a, 2 m, 10 s), the clump on its
    free end b."""
    mass, ea, dvol = polyester()
    area = math.pi * dvol * dvol / 4
    b = FREE_BODY
    return f"""&cable length = {FREE_LEN!r}, diameter = {dvol!r}, density = {mass / area!r}, bending_stiffness = 1e-3 /
&material law = 'linear', ea = {ea!r}, compression = 'none' /
&fluid density = {RHO!r}, surface_z = 0, cd_normal = {CDN}, cd_tangential = {CDT}, ca_normal = {CAN} /
&point_1 joint = 1, mass = {b['mass']!r}, volume = {b['volume']!r}, ca = {b['ca']!r}, cd = {b['cd']!r}, area = {b['area']!r} /
&end_a kind = 'motion', x = {FREE_TOP[0]!r}, z = {FREE_TOP[1]!r}, motion = 'harmonic', amplitude = {AMP!r},
  period = {PERIOD!r}, direction_x = 1, direction_z = 0, ramp_time = {PERIOD!r} /
&end_b kind = 'free' /
&rupture enabled = .false. /
&numerics nodes = {grid + 1}, dt = {dt!r}, t_end = {t_end!r}, newton_tol = 1e-12 /
&output file = '{out}', interval = {interval!r}, quiet = .true., fields = 'x z' /
"""


def free_xcable(exe, grid, dt, sample, work):
    nml, out = os.path.join(work, "f.nml"), os.path.join(work, "f.h5")
    with open(nml, "w") as f:
        f.write(free_namelist(grid, dt, T_END, out, sample))
    run = subprocess.run([exe, nml], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit("xcable failed: " + run.stderr.strip())
    with h5py.File(out) as f:
        h = f["history"]
        ts = f["time"][:]
        hist = np.column_stack([ts, np.interp(ts, h["time"][:], h["end_a/tension"][:]), f["x"][:, -1], f["z"][:, -1]])
        start = np.column_stack([f["static/x"][:], f["static/z"][:]])
        st = float(f["summary"].attrs["static_tension_a"])
    os.remove(out)
    return hist, start, st


def free_md_input(path, grid, dtm):
    mass, ea, dvol = polyester()
    b = FREE_BODY
    txt = f"""MoorDyn v2 input: a rope with a clump on its free end (bench/peer/points.py)
---------------------- LINE TYPES -----------------------------------
TypeName   Diam    Mass/m     EA      BA/-zeta     EI    Cd     Ca    CdAx    CaAx
(name)     (m)     (kg/m)     (N)     (N-s/-)    (N-m^2) (-)   (-)   (-)     (-)
rope   {dvol!r}  {mass!r}  {ea!r}  0.0  0.0  {CDN}  {CAN}  {CDT}  0.0
---------------------------- POINTS -------------------------------------------
ID  Attachment  X       Y     Z      Mass   Volume  CdA    CA
(#)   (-)       (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
1     Coupled   {FREE_TOP[0]!r}  0.0  {FREE_TOP[1]!r}  0.0  0.0  0.0  0.0
2     Free      0.0  0.0  {FREE_TOP[1] - FREE_LEN!r}  {b['mass']!r}  {b['volume']!r}  {b['cd'] * b['area']!r}  {b['ca']!r}
---------------------- LINES ----------------------------------------
ID   LineType AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)  (name)   (#)      (#)      (m)       (-)      (-)
1    rope      1        2       {FREE_LEN!r}      {grid}      -
---------------------- OPTIONS -----------------------------------------
0        writeLog
{dtm!r}   dtM
RK4      tScheme
{G}      g
{RHO}    rho
200.0  WtrDpth
1        disableOutput
1        disableOutTime
---------------------- OUTPUTS -----------------------------------------
------------------------- need this line -------------------------------------
"""
    with open(path, "w") as f:
        f.write(txt)


def free_md(grid, start, courant, sample, work):
    mass, ea, _ = polyester()
    ds = FREE_LEN / grid
    k = int(math.ceil(sample / (courant * ds / math.sqrt(ea / mass)) - 1e-9))
    dtm = sample / k
    inp = os.path.join(work, "f.txt")
    free_md_input(inp, grid, dtm)
    data = struct.pack("<QQ", 1, 6) + struct.pack("<6d", *([0.0] * 6))
    data += struct.pack("<QQ", 1, 6) + struct.pack("<6d", start[-1][0], 0.0, start[-1][1], 0.0, 0.0, 0.0)
    data += struct.pack("<QQ", grid - 1, 6)
    for p in start[1:-1]:
        data += struct.pack("<6d", p[0], 0.0, p[1], 0.0, 0.0, 0.0)
    with open(os.path.join(work, "f.state"), "wb") as f:
        f.write(b"MoorDyn" + struct.pack("<BB", 2, 7) + struct.pack("<QQ", len(data) // 8 + 1, 3) + data)
    sysm = pc.moordyn_from_state(inp, [FREE_TOP[0], 0.0, FREE_TOP[1]], os.path.join(work, "f.state"))

    def measure():
        line = moordyn.GetLine(sysm, 1)
        p = np.array([moordyn.GetLineNodePos(line, i) for i in range(grid + 1)])
        d = p[1] - p[0], p[2] - p[1]
        tv = [ea * max(np.linalg.norm(x) / ds - 1, 0.0) * x / np.linalg.norm(x) for x in d]
        return np.linalg.norm(1.5 * tv[0] - 0.5 * tv[1]), p[-1][0], p[-1][2]

    def surge(t):
        if t <= 0:
            return 0.0
        w = math.sin(0.5 * math.pi * t / PERIOD) ** 2 if t < PERIOD else 1.0
        return AMP * w * math.sin(2 * math.pi * t / PERIOD)

    rows = [(0.0, np.nan, start[-1][0], start[-1][1])]   # (row 0 is left out of the comparison)
    c0 = time.process_time()
    for i in range(int(round(T_END / sample))):
        for j in range(k):
            t0 = i * sample + j * dtm
            x0, x1 = surge(t0), surge(t0 + dtm)
            moordyn.Step(sysm, [FREE_TOP[0] + x0, 0.0, FREE_TOP[1]], [(x1 - x0) / dtm, 0.0, 0.0], t0, dtm)
        rows.append(((i + 1) * sample,) + measure())
    moordyn.Close(sysm)
    return np.array(rows), dtm, time.process_time() - c0


def cmd_free(args):
    print(f"3. the clump {FREE_BODY} on the free end of {FREE_LEN} m of polyester hanging from a fairlead at "
          f"{FREE_TOP} that surges {AMP} m, {PERIOD} s (ramp {PERIOD} s), {T_END} s; "
          f"MoorDyn {metadata.version('moordyn')} from xcable's static nodes, RK4 at Courant {args.courant}")
    runs = {}
    with tempfile.TemporaryDirectory() as work:
        for g in args.grids:
            for dt in args.xdt:
                h, start, st = free_xcable(args.exe, g, dt, args.sample, work)
                runs[("xcable", g, dt)] = h
                print(f"xcable {g} segments dt {dt}: static T_a {st:.2f} N; T_a {h[1:, 1].min():.1f} .. "
                      f"{h[1:, 1].max():.1f} N; clump x {h[:, 2].min():.3f} .. {h[:, 2].max():.3f} m", flush=True)
        for g in args.md_grids or args.grids:
            start = free_xcable(args.exe, g, 1e-3, 1e-3, work)[1]
            h, dtm, cpu = free_md(g, start, args.courant, args.sample, work)
            runs[("MoorDyn", g, 0)] = h
            print(f"MoorDyn {g} segments: dtM {dtm:.3g} s, {cpu:.1f} s CPU; T_a {h[1:, 1].min():.1f} .. "
                  f"{h[1:, 1].max():.1f} N; clump x {h[:, 2].min():.3f} .. {h[:, 2].max():.3f} m", flush=True)
    table(runs)


def table(runs):
    print("\n| a | b | rms dT N | max dT N | rms d body m | max d body m |")
    print("|---|---|---|---|---|---|")
    keys = sorted(runs, key=lambda k: (k[0], k[1], -k[2]))
    xs = [k for k in keys if k[0] == "xcable"]
    ms = [k for k in keys if k[0] == "MoorDyn"]
    for group in (xs, ms):
        for a, b in zip(group[:-1], group[1:]):
            d = differences(runs[a][1:], runs[b][1:])
            print(f"| {a} | {b} | {d[0]:.2f} | {d[1]:.2f} | {d[2]:.2e} | {d[3]:.2e} |")
    fx = max(xs, key=lambda k: (k[1], -k[2]))
    for m in ms:
        d = differences(runs[m][1:], runs[fx][1:])
        print(f"| {m} | {fx} | {d[0]:.2f} | {d[1]:.2f} | {d[2]:.2e} | {d[3]:.2e} |")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("what", choices=["statics", "heave", "free"])
    ap.add_argument("--exe", default=os.path.join(HERE, "..", "..", "bin", "xcable"))
    ap.add_argument("--grids", type=int, nargs="+", default=[10, 20, 40, 80])
    ap.add_argument("--md-grids", type=int, nargs="+", default=None)
    ap.add_argument("--cases", nargs="+", default=["clump", "buoy"])
    ap.add_argument("--case", default="buoy")
    ap.add_argument("--xdt", type=float, nargs="+", default=[0.01, 0.005])
    ap.add_argument("--courant", type=float, default=0.5)
    ap.add_argument("--sample", type=float, default=0.05)
    ap.add_argument("--settle", type=float, default=SETTLE, help="MoorDyn's settling from xcable's nodes, s")
    ap.add_argument("--perturb", type=float, default=PERTURB, help="statics: move xcable's nodes by this (m) "
                    "before MoorDyn's settling")
    ap.add_argument("--relax-grids", type=int, nargs="*", default=[10],
                    help="statics: grids also solved by MoorDyn's own dynamic relaxation (slow)")
    ap.add_argument("--tsv", default="")
    args = ap.parse_args()
    args.exe = os.path.abspath(args.exe)
    globals()["PERTURB"] = args.perturb
    return {"statics": cmd_statics, "heave": cmd_heave, "free": cmd_free}[args.what](args)


if __name__ == "__main__":
    sys.exit(main())
