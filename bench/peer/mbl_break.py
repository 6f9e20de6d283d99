#!/usr/bin/env python3
"""A line that parts at its minimum breaking load (MBL): xcable against MoorDyn v2.

bench/peer, not part of `make test`. Results and discussion:
docs/theory/verification.md, section "A line that parts at its MBL".

Scene (in air, identical in both codes). The paper's cable (L = 60 m, d = 0.05 m,
rho = 1140 kg/m^3, so m = 2.238 kg/m; EI = 70.56 N m^2) with the linear law
EA = E A = 451.6 kN, a rope that cannot push (xcable `compression = 'none'`,
MoorDyn's lines). Anchor (end a, MoorDyn point 1) fixed at (0, 0); fairlead
(end b, point 2) at (56, 12) m at t = 0, where the line hangs in its static
catenary (fairlead tension about 1.43 kN). From t = 0 the fairlead moves away
horizontally: speed V w(t) along +x, w = sin^2(pi t / (2 T_RAMP)) up to T_RAMP,
then 1 (V = 0.5 m/s, T_RAMP = 2 s). The path is given to xcable as a table
(`motion = 'table'`, rows every 0.05 s); xcable interpolates it by a cubic
Hermite with centred-difference slopes, and this script evaluates the same
interpolant to drive MoorDyn, so both fairleads follow the same path. The line
parts when its tension reaches MBL = 4 kN.

xcable: `&rupture criterion = 'tension', mbl = MBL, t_break = 0` (the force
across the break drops at once; --t-break sets a ramp): the line parts at the
node of the first cell whose tension (the law at the cell's strain) reaches the
MBL, at the time found by xcable's search within the step (to 1e-4 of the MBL).
The run is made twice: once to find the break time, then again to
break_time + WINDOW (see below).

MoorDyn (PyPI `moordyn`, RK4, dtM = courant ds / sqrt(EA / m)): point 1 Fixed,
point 2 Coupled, moved once per step (the exact position at the step's start,
the chord to its end as velocity). MoorDyn-C 2.7 reads a FAILURE section but
acts only on its time column, and tests that column the wrong way round
(`failure->time < t` skips the failure, so it fires in the first step); its
tension column is read and never used ("step 2: check for tension-triggered
failures" is an empty comment in MoorDyn2.cpp). `--md-failure-check` shows both
on this scene. The detachment itself is MoorDyn's `BreakLine` (Python
`moordyn.BreakLine(system, point, line)`): the line's end is taken off the
point and put on a new free, massless point with the old point's position and
velocity. This script calls it after the first step at whose end the largest
segment tension EA (l / ds - 1) reaches the MBL, at the point of that line end
(the fairlead: the top segment carries the largest tension). MoorDyn starts
from the static state of its own chain of N segments (lumped node weights,
no bending), found here by shooting on the anchor force, and settles for
T_SETTLE with the fairlead held and critical axial damping (BA = -1) so that
its bending (EI) finds its equilibrium; the settled state is loaded into the
undamped line.

After the break both lines recoil: an unloading front runs from the fairlead
to the anchor (L / c = 0.13 s, c = sqrt(EA / m) = 449 m/s) and the released
end moves back. When the front has reflected at the anchor, the line, which
cannot push, piles up into the cells next to the anchor (a collapse both codes
meet, 0.15 to 0.34 s after the break on this scene, sooner on finer grids:
xcable stops with "the compressed zone has collapsed", MoorDyn's segments
shrink below 10 % of their length). The comparison therefore covers
WINDOW = 0.14 s after the break.

The released end of a lumped-mass line that cannot push is thrown faster than
the continuum's MBL / sqrt(EA m): its node, half a segment's mass, leaves when
the last segment goes slack and nothing pulls it back. The script shows it on a
straight 1-D chain (chain_release) and also runs xcable with
`mass_matrix = 'lumped'` (--x-lumped), which then behaves as MoorDyn does.

Printed: a markdown table per code and resolution (static fairlead tension,
break time, place, tension at the break, the released end's speed and the
anchor tension at AFTER s after the break, the released end's change of
velocity over the first 5 ms less gravity's share, the time the anchor tension
falls below half its value at the break), the 1-D chain's end speed, and the
differences between the finest runs of the codes (fairlead tension before the
break, end speed and anchor tension after it). Progress and each run's
details (collapse times, MoorDyn's settling) go to stderr.

Usage (from the repository root or bench/peer):
  python3 bench/peer/mbl_break.py [--xn 61 121 241] [--x-lumped 61 241] [--mn 60 120 240]
      [--courant 0.5] [--t-break 0] [--exe bin/xcable] [--work DIR]
  python3 bench/peer/mbl_break.py --md-failure-check
"""

import argparse
import math
import os
import subprocess
import sys
import tempfile
import time

import h5py
import numpy as np

import moordyn

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import peer_common as pc  # noqa: E402  (MoorDyn's state file and start from it)

HERE = os.path.dirname(os.path.abspath(__file__))
XCABLE = os.environ.get("XCABLE", os.path.join(HERE, "..", "..", "bin", "xcable"))

LENGTH, DIAM, RHO_C, YOUNG, G = 60.0, 0.05, 1140.0, 2.3e8, 9.81
AREA = math.pi * DIAM**2 / 4
MASS = RHO_C * AREA                      # kg/m
EA = YOUNG * AREA                        # N (xcable's linear law default)
EI = YOUNG * math.pi * DIAM**4 / 64      # N m^2 (xcable's default)
XB0, ZB0 = 56.0, 12.0                    # fairlead at t = 0; anchor at the origin
SPEED, T_RAMP = 0.5, 2.0                 # fairlead speed along +x (m/s), smooth start (s)
TABLE_DT, TABLE_END = 0.05, 30.0         # rows of the motion table
MBL = 4000.0                             # N
WINDOW = 0.14                            # compared time after the break, s
COLLAPSE_WATCH = 0.5                     # MoorDyn runs on this long after the break to find its collapse
PROBE_END = 25.0                         # t_end of the run that finds the break
T_SETTLE = 3.0                           # MoorDyn's settling before t = 0, s
AFTER = (0.01, 0.02, 0.05, 0.1, 0.14)    # times after the break where figures are taken


# ------------------------------------------------------------------ the fairlead's path
def displacement(t):
    """Exact path: x displacement of the fairlead (m) at time t (speed SPEED w(t))."""
    if t <= 0:
        return 0.0
    if t < T_RAMP:
        return SPEED * (0.5 * t - T_RAMP / (2 * math.pi) * math.sin(math.pi * t / T_RAMP))
    return SPEED * (t - 0.5 * T_RAMP)


TAB_T = np.round(np.arange(0.0, TABLE_END + 1e-9, TABLE_DT), 10)
TAB_X = np.array([displacement(t) for t in TAB_T])


def _slope(j):
    n = len(TAB_T)
    if j == 0:
        return (TAB_X[1] - TAB_X[0]) / (TAB_T[1] - TAB_T[0])
    if j == n - 1:
        return (TAB_X[-1] - TAB_X[-2]) / (TAB_T[-1] - TAB_T[-2])
    return (TAB_X[j + 1] - TAB_X[j - 1]) / (TAB_T[j + 1] - TAB_T[j - 1])


def table_x(t):
    """xcable's table interpolant (src/xcable/ends/table.f90, table_at): cubic Hermite
    with centred-difference slopes, held outside the rows."""
    if t <= TAB_T[0]:
        return float(TAB_X[0])
    if t >= TAB_T[-1]:
        return float(TAB_X[-1])
    i = int(np.searchsorted(TAB_T, t, side="right") - 1)
    h = TAB_T[i + 1] - TAB_T[i]
    u = (t - TAB_T[i]) / h
    h00 = (1 + 2 * u) * (1 - u) ** 2
    h10 = u * (1 - u) ** 2
    h01 = u * u * (3 - 2 * u)
    h11 = u * u * (u - 1)
    return float(h00 * TAB_X[i] + h10 * h * _slope(i) + h01 * TAB_X[i + 1] + h11 * h * _slope(i + 1))


# ------------------------------------------------------------------ xcable
def xcable_namelist(nodes, courant, t_break, t_end, h5, mass="averaged"):
    table = h5[:-3] + "_path.txt"
    with open(table, "w") as f:
        f.write("# t (s), x, z displacement of the fairlead (m)\n")
        f.write("".join("%.10g %.17g 0\n" % (t, x) for t, x in zip(TAB_T, TAB_X)))
    return (f"&cable length = {LENGTH}, diameter = {DIAM}, density = {RHO_C}, young = {YOUNG:.10g}, "
            f"gravity = {G} /\n"
            f"&material law = 'linear', ea = {EA:.15g}, compression = 'none' /\n"
            f"&end_a kind = 'fixed', x = 0, z = 0 /\n"
            f"&end_b kind = 'motion', x = {XB0}, z = {ZB0}, motion = 'table', table_file = '{table}' /\n"
            f"&rupture enabled = .true., criterion = 'tension', mbl = {MBL:.10g}, t_break = {t_break:.10g} /\n"
            f"&numerics nodes = {nodes}, courant = {courant:.10g}, t_end = {t_end:.12g}, "
            f"mass_matrix = '{mass}' /\n"
            f"&output file = '{h5}', interval = 0, quiet = .true., fields = 'tension' /\n")


def xcable_run(exe, nodes, courant, t_break, work, mass="averaged"):
    """Two runs: the first finds the break, the second stops WINDOW after it."""
    out = {}
    tag = f"x_n{nodes}_c{courant:g}_tb{t_break:g}_{mass}"
    t_end = PROBE_END
    for attempt in ("probe", "run"):
        nml = os.path.join(work, f"{tag}_{attempt}.nml")
        h5 = nml[:-4] + ".h5"
        with open(nml, "w") as f:
            f.write(xcable_namelist(nodes, courant, t_break, t_end, h5, mass))
        w0 = time.time()
        p = subprocess.run([exe, nml], capture_output=True, text=True)
        wall = time.time() - w0
        if not os.path.exists(h5):
            sys.exit(f"xcable gave no result for {nml} (exit {p.returncode}): {p.stderr.strip()}")
        with h5py.File(h5, "r") as f:
            s = dict(f["summary"].attrs)
            status = f.attrs["status"]
            status = status.decode() if isinstance(status, bytes) else str(status)
            reason = f.attrs.get("failure_reason", "")
            reason = reason.decode() if isinstance(reason, bytes) else str(reason)
            h = f["history"]
            hist = {"t": h["time"][:], "xb": h["end_b/x"][:], "zb": h["end_b/z"][:],
                    "vb": np.hypot(h["end_b/vx"][:], h["end_b/vz"][:]),
                    "vx": h["end_b/vx"][:], "vz": h["end_b/vz"][:],
                    "Tb": h["end_b/tension"][:], "Ta": h["end_a/tension"][:]}
        if "break_time" not in s:
            sys.exit(f"xcable {tag}: the MBL was not reached (largest tension "
                     f"{s.get('largest_tension', float('nan')):.1f} N)")
        if attempt == "probe":
            out["probe_status"] = status
            out["probe_failure_time"] = float(s.get("time_reached", np.nan)) if status != "complete" else None
            out["probe_failure"] = reason
            t_end = float(s["break_time"]) + WINDOW
        os.remove(h5)
    if status != "complete":
        sys.exit(f"xcable {tag} did not complete: {reason}")
    out.update({"code": "xcable" + ("" if mass == "averaged" else f" ({mass} mass)"),
                "res": f"{nodes} nodes, Courant {courant:g}", "n": nodes,
                "dt": float(s["dt_used"]), "t_break_ramp": t_break, "wall_s": wall,
                "static_Tb": float(s["static_tension_b"]), "break_time": float(s["break_time"]),
                "break_s": float(s["break_s"]), "break_cell_s": float(s["break_cell_s"]),
                "break_T": float(s["break_tension"]), "hist": hist})
    return out


# ------------------------------------------------------------------ MoorDyn
def md_input(path, n, dtm, ba):
    txt = f"""MoorDyn v2 input: a line that parts at its MBL (bench/peer/mbl_break.py)
---------------------- LINE TYPES -----------------------------------
TypeName   Diam    Mass/m     EA      BA/-zeta     EI    Cd     Ca    CdAx    CaAx
(name)     (m)     (kg/m)     (N)     (N-s/-)    (N-m^2) (-)   (-)   (-)     (-)
rope  {DIAM!r}  {MASS!r}  {EA!r}  {ba!r}  {EI!r}  0.0  0.0  0.0  0.0
---------------------------- POINTS -------------------------------------------
ID  Attachment  X       Y     Z      Mass   Volume  CdA    CA
(#)   (-)       (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
1     Fixed     0.0     0.0   0.0    0.0    0.0     0.0    0.0
2     Coupled   {XB0!r}  0.0   {ZB0!r}    0.0    0.0     0.0    0.0
---------------------- LINES ----------------------------------------
ID   LineType AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)  (name)   (#)      (#)      (m)       (-)      (-)
1    rope     1        2       {LENGTH!r}      {n}      -
---------------------- OPTIONS -----------------------------------------
0        writeLog
{dtm!r}  dtM
RK4      tScheme
{G}      g
0        rho
1000     WtrDpth
1        disableOutput
1        disableOutTime
------------------------- need this line -------------------------------------
"""
    with open(path, "w") as f:
        f.write(txt)


def chain_static(n):
    """Static state of MoorDyn's chain of n segments between the anchor and (XB0, ZB0):
    node weights m g ds (half at the ends), linear EA, no bending; shooting on the force
    (H, V) that segment 1 carries. Returns the n + 1 node positions (x, z)."""
    ds = LENGTH / n
    w = MASS * G * ds
    k = np.arange(n)

    def shape(hv):
        h, v = hv
        fz = v + w * k                     # segment j + 1 carries (H, V + j w)
        t = np.hypot(h, fz)
        seg = ds * (1 + t / EA)
        return np.column_stack([seg * h / t, seg * fz / t])

    hv = np.array([1000.0, 0.0])
    for _ in range(100):
        r = shape(hv).sum(0) - [XB0, ZB0]
        jac = np.empty((2, 2))
        for j in range(2):
            d = np.zeros(2)
            d[j] = 1e-6 * max(1.0, abs(hv[j]))
            jac[:, j] = (shape(hv + d).sum(0) - shape(hv - d).sum(0)) / (2 * d[j])
        step = np.linalg.solve(jac, r)
        hv -= step
        if np.abs(step).max() < 1e-12 * max(1.0, np.abs(hv).max()):
            break
    return np.vstack([[0.0, 0.0], np.cumsum(shape(hv), axis=0)])


def md_run(n, courant, work):
    wd = os.path.join(work, f"md_n{n}_c{courant:g}")
    os.makedirs(wd, exist_ok=True)
    ds = LENGTH / n
    h = courant * ds / math.sqrt(EA / MASS)
    r0 = chain_static(n)
    pc.moordyn_state(os.path.join(wd, "start.state"), [(x, 0.0, z) for x, z in r0[1:-1]],
                     [(x, 0.0, z, 0.0, 0.0, 0.0) for x, z in (r0[0], r0[-1])])
    xb0 = [XB0, 0.0, ZB0]
    md_input(os.path.join(wd, "settle.txt"), n, h, -1.0)
    md_input(os.path.join(wd, "run.txt"), n, h, 0.0)

    def seg_tension(line):
        p = np.array([moordyn.GetLineNodePos(line, i) for i in range(n + 1)])
        return EA * np.maximum(np.linalg.norm(np.diff(p, axis=0), axis=1) / ds - 1, 0.0), p

    w0 = time.time()
    sysm = pc.moordyn_from_state(os.path.join(wd, "settle.txt"), xb0, os.path.join(wd, "start.state"))
    t = -T_SETTLE
    line = moordyn.GetLine(sysm, 1)
    tb_settle = []
    for _ in range(int(round(T_SETTLE / h))):
        moordyn.Step(sysm, xb0, [0.0, 0.0, 0.0], t, h)
        t += h
        seg, _ = seg_tension(line)
        tb_settle.append(1.5 * seg[-1] - 0.5 * seg[-2])
    moordyn.SaveState(sysm, os.path.join(wd, "settled.state"))
    moordyn.Close(sysm)
    tb_settle = np.array(tb_settle)
    last = tb_settle[-int(round(0.5 / h)):]

    sysm = pc.moordyn_from_state(os.path.join(wd, "run.txt"), xb0, os.path.join(wd, "settled.state"))
    line = moordyn.GetLine(sysm, 1)
    fair = moordyn.GetPoint(sysm, 2)
    seg, p = seg_tension(line)
    rows = [(0.0, p[-1, 0], p[-1, 2], 0.0, 1.5 * seg[-1] - 0.5 * seg[-2], 1.5 * seg[0] - 0.5 * seg[1], 0.0, 0.0)]
    t, k = 0.0, 0
    broke, t_cross, brk_seg, brk_T = None, None, None, None
    prev_max = float(seg.max())
    min_strain = 0.0
    stop = None
    while True:
        t0 = k * h
        x0, x1 = table_x(t0), table_x(t0 + h)
        moordyn.Step(sysm, [XB0 + x0, 0.0, ZB0], [(x1 - x0) / h, 0.0, 0.0], t0, h)
        k += 1
        t = k * h
        seg, p = seg_tension(line)
        v = np.array(moordyn.GetLineNodeVel(line, n))
        strain = np.linalg.norm(np.diff(p, axis=0), axis=1) / ds - 1
        rows.append((t, p[-1, 0], p[-1, 2], float(np.linalg.norm(v)),
                     1.5 * seg[-1] - 0.5 * seg[-2], 1.5 * seg[0] - 0.5 * seg[1], v[0], v[2]))
        if broke is None:
            top = float(seg.max())
            if top >= MBL:
                broke = t
                t_cross = t - h * (top - MBL) / (top - prev_max)
                brk_seg, brk_T = int(seg.argmax()), top
                moordyn.BreakLine(sysm, fair, line)
            prev_max = top
            if t > PROBE_END:
                sys.exit(f"MoorDyn N {n}: the MBL was not reached by {PROBE_END} s")
        else:
            min_strain = min(min_strain, float(strain.min()))
            if strain.min() < -0.9 and stop is None:
                stop = t
            if t >= broke + WINDOW - 1e-12 and (stop is not None or t >= broke + COLLAPSE_WATCH):
                break
    wall = time.time() - w0
    moordyn.Close(sysm)
    r = np.array(rows)
    hist = {"t": r[:, 0], "xb": r[:, 1], "zb": r[:, 2], "vb": r[:, 3], "Tb": r[:, 4], "Ta": r[:, 5],
            "vx": r[:, 6], "vz": r[:, 7]}
    return {"code": "MoorDyn", "res": f"{n} segments, Courant {courant:g}", "n": n, "dt": h,
            "wall_s": wall, "static_Tb": float(r[0, 4]), "break_time": broke, "break_cross": t_cross,
            "break_s": LENGTH, "break_cell_s": (brk_seg + 0.5) * ds, "break_T": brk_T,
            "settle_Tb_range_last_0.5s": float(np.ptp(last)), "settle_Tb_change": float(tb_settle[-1] - tb_settle[0]),
            "min_strain_window": min_strain, "collapse_time": stop, "hist": hist}


def md_failure_check(work):
    """What MoorDyn-C does with a FAILURE section on this scene (60 segments): a tension
    failure (FailTime 0, FailTen MBL), and a time failure (FailTime 5 s, FailTen 0)."""
    n = 60
    h = 0.5 * (LENGTH / n) / math.sqrt(EA / MASS)
    r0 = chain_static(n)
    pc.moordyn_state(os.path.join(work, "fc.state"), [(x, 0.0, z) for x, z in r0[1:-1]],
                     [(x, 0.0, z, 0.0, 0.0, 0.0) for x, z in (r0[0], r0[-1])])
    for label, ftime, ften in (("tension", 0.0, MBL), ("time 5 s", 5.0, 0.0)):
        inp = os.path.join(work, "fc.txt")
        md_input(inp, n, h, 0.0)
        with open(inp) as f:
            txt = f.read()
        fail = ("---------------------- FAILURE ----------------------\n"
                "FailureID  Point    Line(s)   FailTime   FailTen\n"
                "()           ()       (,)      (s or 0)   (N or 0)\n"
                f"1          2        1          {ftime!r}      {ften!r}\n")
        txt = txt.replace("---------------------- OPTIONS", fail + "---------------------- OPTIONS")
        with open(inp, "w") as f:
            f.write(txt)
        sysm = pc.moordyn_from_state(inp, [XB0, 0.0, ZB0], os.path.join(work, "fc.state"))
        line = moordyn.GetLine(sysm, 1)
        npts0 = moordyn.GetNumberPoints(sysm)
        detached, t, k, top = None, 0.0, 0, 0.0
        while t < 9.0:
            x0, x1 = table_x(k * h), table_x((k + 1) * h)
            moordyn.Step(sysm, [XB0 + x0, 0.0, ZB0], [(x1 - x0) / h, 0.0, 0.0], k * h, h)
            k += 1
            t = k * h
            if detached is None and moordyn.GetNumberPoints(sysm) > npts0:
                detached = t
            p = np.array([moordyn.GetLineNodePos(line, i) for i in (n - 1, n)])
            top = max(top, EA * (np.linalg.norm(p[1] - p[0]) / (LENGTH / n) - 1))
            if detached is not None and t > detached + 0.05:
                break
        moordyn.Close(sysm)
        print(f"MoorDyn FAILURE ({label}): points {npts0} -> detached at "
              f"{'never' if detached is None else '%.4f s' % detached}; largest top-segment "
              f"tension up to {t:.3f} s: {top:.1f} N (MBL {MBL:.0f} N)")


def chain_release(n, t_end=0.02):
    """Speed of the released end of a straight 1-D lumped chain of n segments (this line's
    m and EA, node masses m ds, half at the ends, springs that cannot push), anchored at
    node 0, at rest under the tension MBL and released at t = 0 (velocity Verlet, dt 0.1 ds
    / c). The continuum's speed behind the unloading front is MBL / sqrt(EA m)."""
    ds = LENGTH / n
    x = np.arange(n + 1) * ds * (1 + MBL / EA)
    v = np.zeros(n + 1)
    mass = np.full(n + 1, MASS * ds)
    mass[-1] *= 0.5
    h = 0.1 * ds / math.sqrt(EA / MASS)

    def acc(x):
        ten = EA * np.maximum(np.diff(x) / ds - 1, 0.0)
        f = np.zeros(n + 1)
        f[:-1] += ten
        f[1:] -= ten
        a = f / mass
        a[0] = 0.0
        return a

    a = acc(x)
    for _ in range(int(round(t_end / h))):
        v += 0.5 * h * a
        x += h * v
        a = acc(x)
        v += 0.5 * h * a
    return float(-v[-1])


# ------------------------------------------------------------------ figures
def figures(r):
    """The figures of one run: values at AFTER s after the break, and the time after the
    break at which the anchor tension falls below half its value at the break."""
    hh, tb = r["hist"], r["break_time"]
    t = hh["t"]
    out = {"v": [float(np.interp(tb + a, t, hh["vb"])) for a in AFTER],
           "Ta": [float(np.interp(tb + a, t, hh["Ta"])) for a in AFTER]}
    ta0 = float(np.interp(tb, t, hh["Ta"]))
    after = (t > tb) & (hh["Ta"] < 0.5 * ta0)
    j = int(np.argmax(after)) if after.any() else None
    if j is not None:
        t1, t0 = t[j], t[j - 1]
        y1, y0 = hh["Ta"][j], hh["Ta"][j - 1]
        out["half"] = float(t0 + (t1 - t0) * (y0 - 0.5 * ta0) / (y0 - y1) - tb)
    else:
        out["half"] = float("nan")
    out["Ta_break"] = ta0
    # the released end's change of velocity from the break to 5 ms after it, less gravity's share
    dv = [float(np.interp(tb + 0.005, t, hh[k]) - np.interp(tb - 1e-7, t, hh[k])) for k in ("vx", "vz")]
    out["dv"] = math.hypot(dv[0], dv[1] + G * 0.005)
    return out


def compare(a, b, t0, t1, key):
    """max |a - b| of a history column over [t0, t1], on a's times."""
    ta = a["hist"]["t"]
    m = (ta >= t0) & (ta <= t1)
    return float(np.max(np.abs(a["hist"][key][m] - np.interp(ta[m], b["hist"]["t"], b["hist"][key]))))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--xn", type=int, nargs="*", default=[61, 121, 241])
    ap.add_argument("--xcourant", type=float, default=1.0)
    ap.add_argument("--x-lumped", type=int, nargs="*", default=[61, 241],
                    help="node counts of xcable runs with mass_matrix = 'lumped' too (none: no such runs)")
    ap.add_argument("--mn", type=int, nargs="*", default=[60, 120, 240])
    ap.add_argument("--courant", type=float, default=0.5, help="MoorDyn's dtM = courant ds / c")
    ap.add_argument("--t-break", type=float, default=0.0, help="xcable's t_break (0: at once)")
    ap.add_argument("--exe", default=XCABLE)
    ap.add_argument("--work")
    ap.add_argument("--md-failure-check", action="store_true")
    a = ap.parse_args()
    work = a.work or tempfile.mkdtemp(prefix="mbl_")
    os.makedirs(work, exist_ok=True)
    if a.md_failure_check:
        md_failure_check(work)
        return
    print(f"scene: L {LENGTH} m, m {MASS:.4f} kg/m, EA {EA:.1f} N, EI {EI:.2f} N m^2, in air; anchor (0, 0), "
          f"fairlead ({XB0}, {ZB0}) m moving along +x at {SPEED} m/s after a {T_RAMP} s start; MBL {MBL:.0f} N; "
          f"xcable t_break {a.t_break:g} s; c = {math.sqrt(EA / MASS):.1f} m/s, L / c = "
          f"{LENGTH / math.sqrt(EA / MASS):.4f} s, MBL / sqrt(EA m) = {MBL / math.sqrt(EA * MASS):.3f} m/s; "
          f"moordyn {moordyn_version()}")
    runs = []
    todo = [(n, "averaged") for n in a.xn] + [(n, "lumped") for n in a.x_lumped]
    for n, mass in todo:
        r = xcable_run(a.exe, n, a.xcourant, a.t_break, work, mass)
        runs.append(r)
        print(f"  {r['code']} {n}: break {r['break_time']:.5f} s at s = {r['break_s']:g} m; first pass "
              f"{r['probe_status']}" + (f" {r['probe_failure_time'] - r['break_time']:.4f} s after the break "
                                        f"({r['probe_failure'][:60]}...)" if r["probe_failure_time"] else "")
              + f"; {r['wall_s']:.1f} s", file=sys.stderr)
    for n in a.mn:
        r = md_run(n, a.courant, work)
        runs.append(r)
        col = "none" if r["collapse_time"] is None else "%.4f s after the break" % (r["collapse_time"] - r["break_time"])
        print(f"  MoorDyn {n}: break {r['break_time']:.5f} s (crossing {r['break_cross']:.5f} s) in segment "
              f"{r['break_cell_s']:.3f} m; settling: T_b changed {r['settle_Tb_change']:+.2f} N, range "
              f"{r['settle_Tb_range_last_0.5s']:.3f} N over its last 0.5 s; smallest strain up to "
              f"{WINDOW:g} s after the break {r['min_strain_window']:.3f}; a segment below 10 % of its length: {col}; "
              f"{r['wall_s']:.1f} s", file=sys.stderr)

    after = ", ".join("%g" % x for x in AFTER)
    print()
    print(f"| code | resolution | dt s | static T_b N | break time s | break node s m (first cell) | T at break N "
          f"| end speed m/s at +{after} s | end velocity change m/s at +0.005 s | anchor T N at +{after} s "
          f"| anchor T at half s after break |")
    print("|" + "---|" * 11)
    for r in runs:
        f = figures(r)
        bt = f"{r['break_time']:.4f}"
        if r["code"] == "MoorDyn":
            bt += f" ({r['break_cross']:.4f})"
        print(f"| {r['code']} | {r['res']} | {r['dt']:.3g} | {r['static_Tb']:.1f} | {bt} | {r['break_s']:g} "
              f"({r['break_cell_s']:g}) | {r['break_T']:.1f} | " + ", ".join("%.2f" % v for v in f["v"])
              + f" | {f['dv']:.3f} | " + ", ".join("%.0f" % v for v in f["Ta"]) + f" | {f['half']:.4f} |")
    print()
    print("straight 1-D lumped chain released from the MBL, end speed at 0.02 s: "
          + ", ".join("%d segments %.3f m/s" % (n, chain_release(n)) for n in (60, 240))
          + f" (continuum: {MBL / math.sqrt(EA * MASS):.3f} m/s)")
    ms = [r for r in runs if r["code"] == "MoorDyn"]
    if not ms:
        return
    m = ms[-1]
    for code in ("xcable", "xcable (lumped mass)"):
        xs = [r for r in runs if r["code"] == code]
        if not xs:
            continue
        x = xs[-1]
        print()
        print(f"{code} {x['res']} against MoorDyn {m['res']}:")
        print(f"  break time: xcable - MoorDyn = {x['break_time'] - m['break_time']:+.5f} s "
              f"(against MoorDyn's interpolated crossing {x['break_time'] - m['break_cross']:+.5f} s)")
        tb = min(x["break_time"], m["break_time"])
        print(f"  fairlead tension before the break, max |diff| over [0, {tb - 0.01:.2f}] s: "
              f"{compare(x, m, 0.0, tb - 0.01, 'Tb'):.1f} N (of {MBL:.0f})")
        # after the break, on the time since each code's own break
        xx = dict(x, hist=dict(x["hist"], t=x["hist"]["t"] - x["break_time"]))
        mm = dict(m, hist=dict(m["hist"], t=m["hist"]["t"] - m["break_time"]))
        front = LENGTH / math.sqrt(EA / MASS)
        print(f"  released end speed over [0.01, {WINDOW:g}] s after each break, max |diff|: "
              f"{compare(xx, mm, 0.01, WINDOW, 'vb'):.3f} m/s")
        print(f"  anchor tension over [0.01, {front - 0.01:.4f}] s after each break (until 0.01 s before "
              f"the front arrives), max |diff|: {compare(xx, mm, 0.01, front - 0.01, 'Ta'):.2f} N; "
              f"time it falls to half, xcable - MoorDyn: {figures(x)['half'] - figures(m)['half']:+.5f} s")


def moordyn_version():
    try:
        from importlib.metadata import version
        return version("moordyn")
    except Exception:
        return "unknown"


if __name__ == "__main__":
    sys.exit(main())
