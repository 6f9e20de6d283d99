#!/usr/bin/env python3
"""A line of a network that parts: xcable against MoorDyn v2 (bench/peer, not part of `make test`).

Results and discussion: network_break.md.

Scene (sea water, identical in both codes): a buoy (free point: 2 t, 20 m^3, Ca 0.5, Cd 0.6 on
8 m^2) on two anchor legs of 140 m of polyester from anchors at (120, +-30, -150) m, and a 110 m
polyester hawser from the buoy to a vessel's fairlead, which starts at (-70, 0, -5) m and drifts
6 m along -x over 10 s (x = -6 (u - sin(2 pi u) / (2 pi)), u = t / 10 s, a table of rows every
0.25 s). One rope everywhere: d = 0.1376 m, 1115 kg/m^3 (16.58 kg/m), EA = 1e8 N linear, no
compression, EI = 1000 N m^2, Cd 1.2 normal, 0.1 tangential, Ca 1.0 normal, 0 tangential. No
seabed (MoorDyn's water depth 1000 m). The hawser parts at its fairlead end (a held end lets go):

  (a) --mode time: at T_A = 2.5 s in both codes;
  (b) --mode tension: xcable `&rupture criterion = 'tension'` with the hawser's segment
      mbl = 300 kN (the legs' 1e9 N, never reached); MoorDyn (whose FAILURE section does not act
      on tension in 2.7.2, see mbl_break.py) is stepped by dtM and detached after the first step at
      whose end a hawser segment's tension EA (l / ds - 1) reaches the MBL.

Both detach at once: xcable `t_break = 0`, MoorDyn `moordyn.BreakLine(system, fairlead, hawser)`
(the line's end moves to a new free massless point). xcable runs with `mass_matrix = 'lumped'`
(MoorDyn's lines are lumped masses; the averaged matrix has no term across a free point anyway).

Grids: level r has 5 / r m cells in both codes (legs 28 r + 1 nodes, hawser 22 r + 1 nodes;
MoorDyn NumSegs one less). xcable: Courant number --courant (2, so dt is about 3.8 ms / r);
MoorDyn: RK4, dtM = 0.01 s / ceil(0.01 s / (0.5 ds / c)), c = sqrt(EA / m) (about 1 ms / r).
MoorDyn starts from xcable's static nodes of the same grid (`/static/x, y, z`, written as its
state file): network.md found the two codes' static equations the same.

Compared (--window s after each code's own break, sampled every 0.01 s): the buoy's position and
velocity, the two anchor tensions (each end cell's tension vector carried linearly to the end
node in MoorDyn; xcable's /history/<end>/tension is the same extrapolation), and the anchor
tensions' differences averaged over SMOOTH = 0.5 s (the legs go slack and snatch). Before the break, the
fairlead's tension. CPU: xcable's child process (for (b) it includes xcable's own first pass that
finds the break); MoorDyn's stepping loop in Python, measurements included.

Usage (from the repository root or bench/peer; bin/xcable built by `make build`):
  python3 bench/peer/network_break.py [--mode time tension] [--levels 1 2 4] [--window 5]
      [--courant 2] [--exe bin/xcable] [--work DIR]
"""

import argparse
import json
import math
import os
import resource
import subprocess
import sys
import tempfile
import time

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import peer_common as pc  # noqa: E402

import moordyn  # noqa: E402

G, RHO = 9.81, 1025.0
DIAM, RHO_C, EA, EI = 0.1376, 1115.0, 1.0e8, 1000.0
MASS = RHO_C * math.pi * DIAM**2 / 4
CDN, CDT, CAN = 1.2, 0.1, 1.0
BUOY = dict(mass=2000.0, volume=20.0, ca=0.5, cd=0.6, area=8.0)
LEG, HAWSER = 140.0, 110.0
ANCHORS = ((120.0, 30.0, -150.0), (120.0, -30.0, -150.0))
FAIR0 = (-70.0, 0.0, -5.0)
DRIFT, T_DRIFT = 6.0, 10.0
MBL, T_A = 3.0e5, 2.5
T_B_GUESS = 3.2                          # about where (b) parts: sets its t_end
TABLE_DT, TABLE_END = 0.25, 30.0
SAMPLE = 0.01
SMOOTH = 0.5                             # running mean of the anchor tensions' differences, s


# ------------------------------------------------------------------ the fairlead's path
def drift(t):
    u = min(max(t / T_DRIFT, 0.0), 1.0)
    return -DRIFT * (u - math.sin(2 * math.pi * u) / (2 * math.pi))


TAB_T = np.round(np.arange(0.0, TABLE_END + 1e-9, TABLE_DT), 10)
TAB_X = np.array([drift(t) for t in TAB_T])


def _slope(j):
    if j == 0:
        return (TAB_X[1] - TAB_X[0]) / (TAB_T[1] - TAB_T[0])
    if j == len(TAB_T) - 1:
        return (TAB_X[-1] - TAB_X[-2]) / (TAB_T[-1] - TAB_T[-2])
    return (TAB_X[j + 1] - TAB_X[j - 1]) / (TAB_T[j + 1] - TAB_T[j - 1])


def table_x(t):
    """xcable's table interpolant (cubic Hermite, centred-difference slopes), as in mbl_break.py."""
    if t <= TAB_T[0]:
        return float(TAB_X[0])
    if t >= TAB_T[-1]:
        return float(TAB_X[-1])
    i = int(np.searchsorted(TAB_T, t, side="right") - 1)
    h = TAB_T[i + 1] - TAB_T[i]
    u = (t - TAB_T[i]) / h
    h00, h10 = (1 + 2 * u) * (1 - u) ** 2, u * (1 - u) ** 2
    h01, h11 = u * u * (3 - 2 * u), u * u * (u - 1)
    return float(h00 * TAB_X[i] + h10 * h * _slope(i) + h01 * TAB_X[i + 1] + h11 * h * _slope(i + 1))


def nodes_of(level):
    return 28 * level + 1, 22 * level + 1


# ------------------------------------------------------------------ xcable
def xcable_nml(level, courant, mode, t_end, h5, table):
    nl, nh = nodes_of(level)
    if mode == "time":
        rup = f"&rupture  line = 3, time = {T_A!r}, s_break = {HAWSER!r}, t_break = 0 /\n"
        mbl_leg, mbl_h = "", ""
    else:
        rup = "&rupture  criterion = 'tension', t_break = 0 /\n"
        mbl_leg, mbl_h = ", mbl = 1.0e9", f", mbl = {MBL!r}"
    b = BUOY
    return (f"&cable     diameter = {DIAM!r}, density = {RHO_C!r}, bending_stiffness = {EI!r}, gravity = {G!r} /\n"
            f"&material  law = 'linear', ea = {EA!r}, compression = 'none' /\n"
            f"&fluid     density = {RHO!r}, cd_normal = {CDN!r}, cd_tangential = {CDT!r}, ca_normal = {CAN!r}, "
            f"surface_z = 0.0 /\n"
            f"&segment_1 length = {LEG!r}, nodes = {nl}{mbl_leg} /\n"
            f"&segment_2 length = {HAWSER!r}, nodes = {nh}{mbl_h} /\n"
            f"&point_1   kind = 'free', x = 10.0, z = -15.0, mass = {b['mass']!r}, volume = {b['volume']!r}, "
            f"ca = {b['ca']!r}, cd = {b['cd']!r}, area = {b['area']!r} /\n"
            f"&point_2   kind = 'fixed', x = {ANCHORS[0][0]!r}, y = {ANCHORS[0][1]!r}, z = {ANCHORS[0][2]!r} /\n"
            f"&point_3   kind = 'fixed', x = {ANCHORS[1][0]!r}, y = {ANCHORS[1][1]!r}, z = {ANCHORS[1][2]!r} /\n"
            f"&point_4   kind = 'motion', x = {FAIR0[0]!r}, y = {FAIR0[1]!r}, z = {FAIR0[2]!r}, motion = 'table', "
            f"table_file = '{table}' /\n"
            "&line_1    end_a = 'point_2', end_b = 'point_1', segments = 1 /\n"
            "&line_2    end_a = 'point_3', end_b = 'point_1', segments = 1 /\n"
            "&line_3    end_a = 'point_1', end_b = 'point_4', segments = 2 /\n"
            + rup +
            f"&numerics  t_end = {t_end!r}, courant = {courant!r}, mass_matrix = 'lumped' /\n"
            f"&output    file = '{h5}', interval = 0.5, quiet = .true. /\n")


def xcable_run(exe, level, courant, mode, t_end, work):
    table = os.path.join(work, "drift.dat")
    with open(table, "w") as f:
        f.write("# t (s), x, z displacement of the fairlead (m)\n")
        f.write("".join("%.10g %.17g 0\n" % (t, x) for t, x in zip(TAB_T, TAB_X)))
    tag = f"x_{mode}_r{level}"
    nml, h5 = os.path.join(work, tag + ".nml"), os.path.join(work, tag + ".h5")
    with open(nml, "w") as f:
        f.write(xcable_nml(level, courant, mode, t_end, h5, table))
    if os.path.exists(h5):
        os.remove(h5)
    c0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    w0 = time.time()
    p = subprocess.run([exe, nml], capture_output=True, text=True)
    wall = time.time() - w0
    c1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (c1.ru_utime - c0.ru_utime) + (c1.ru_stime - c0.ru_stime)
    if not os.path.exists(h5):
        sys.exit(f"xcable gave no result for {nml} (exit {p.returncode}): {p.stderr.strip()}")
    with h5py.File(h5, "r") as f:
        s = dict(f["summary"].attrs)
        status = f.attrs["status"]
        status = status.decode() if isinstance(status, bytes) else str(status)
        reason = f.attrs.get("failure_reason", "")
        reason = reason.decode() if isinstance(reason, bytes) else str(reason)
        h = f["history"]
        hist = {"t": h["time"][:]}
        for c in ("x", "y", "z", "vx", "vy", "vz"):
            hist["b" + c] = h["line_1_b/" + c][:]
        hist["Ta1"] = h["line_1_a/tension"][:]
        hist["Ta2"] = h["line_2_a/tension"][:]
        hist["Tf"] = h["line_3_b/tension"][:]
        static = np.column_stack([f["static/x"][:], f["static/y"][:], f["static/z"][:]])
    bt = float(s["break_time"]) if "break_time" in s else (T_A if mode == "time" else None)
    if bt is None:
        sys.exit(f"xcable {tag}: no break ({status} {reason})")
    return {"code": "xcable", "level": level, "status": status, "reason": reason, "cpu": cpu, "wall": wall,
            "dt": float(s.get("dt_used", np.nan)), "break_time": bt,
            "break_s": float(s.get("break_s", np.nan)), "t_end_reached": float(hist["t"][-1]),
            "hist": hist, "static": static, "stderr": p.stderr.strip()[-400:]}


# ------------------------------------------------------------------ MoorDyn
def md_input(path, level, dtm):
    nl, nh = nodes_of(level)
    b = BUOY
    txt = f"""MoorDyn v2 input: a network line that parts (bench/peer/network_break.py)
---------------------- LINE TYPES -----------------------------------
TypeName   Diam    Mass/m     EA      BA/-zeta     EI    Cd     Ca    CdAx    CaAx
(name)     (m)     (kg/m)     (N)     (N-s/-)    (N-m^2) (-)   (-)   (-)     (-)
poly  {DIAM!r}  {MASS!r}  {EA!r}  0.0  {EI!r}  {CDN!r}  {CAN!r}  {CDT!r}  0.0
---------------------------- POINTS -------------------------------------------
ID  Attachment  X       Y     Z      Mass   Volume  CdA    CA
(#)   (-)       (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
1     Fixed     {ANCHORS[0][0]!r}  {ANCHORS[0][1]!r}  {ANCHORS[0][2]!r}  0.0  0.0  0.0  0.0
2     Fixed     {ANCHORS[1][0]!r}  {ANCHORS[1][1]!r}  {ANCHORS[1][2]!r}  0.0  0.0  0.0  0.0
3     Coupled   {FAIR0[0]!r}  {FAIR0[1]!r}  {FAIR0[2]!r}  0.0  0.0  0.0  0.0
4     Free      10.0  0.0  -15.0  {b['mass']!r}  {b['volume']!r}  {b['cd'] * b['area']!r}  {b['ca']!r}
---------------------- LINES ----------------------------------------
ID   LineType AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)  (name)   (#)      (#)      (m)       (-)      (-)
1    poly     1        4       {LEG!r}      {nl - 1}      -
2    poly     2        4       {LEG!r}      {nl - 1}      -
3    poly     4        3       {HAWSER!r}      {nh - 1}      -
---------------------- OPTIONS -----------------------------------------
0        writeLog
{dtm!r}   dtM
RK4      tScheme
{G}      g
{RHO}    rho
1000     WtrDpth
1        disableOutput
1        disableOutTime
------------------------- need this line -------------------------------------
"""
    with open(path, "w") as f:
        f.write(txt)


def md_state(path, level, static):
    """xcable's static nodes as MoorDyn's state file (points 1-4, then the lines' inner nodes)."""
    nl, nh = nodes_of(level)
    lines = [static[:nl], static[nl:2 * nl], static[2 * nl:2 * nl + nh]]
    buoy = lines[0][-1]
    pts = [(0.0,) * 6, (0.0,) * 6, (0.0,) * 6, tuple(buoy) + (0.0, 0.0, 0.0)]
    pc.moordyn_state_lines(path, [ln[1:-1] for ln in lines], pts)


def end_tension(line, idx, ds):
    """|1.5 T_1 - 0.5 T_2| of the end cells' tension vectors; idx the three nodes from the end."""
    p = np.array([moordyn.GetLineNodePos(line, i) for i in idx])
    d = np.diff(p, axis=0)
    ln = np.linalg.norm(d, axis=1)
    tv = (EA * np.maximum(ln / ds - 1, 0.0) / ln)[:, None] * d
    return float(np.linalg.norm(1.5 * tv[0] - 0.5 * tv[1]))


def md_run(level, mode, t_end, static, work):
    nl, nh = nodes_of(level)
    ds = 5.0 / level
    k_sub = int(math.ceil(SAMPLE / (0.5 * ds / math.sqrt(EA / MASS)) - 1e-9))
    h = SAMPLE / k_sub
    inp, st = os.path.join(work, f"md_{mode}_r{level}.txt"), os.path.join(work, f"md_r{level}.state")
    md_input(inp, level, h)
    md_state(st, level, static)
    fair0 = [FAIR0[0], FAIR0[1], FAIR0[2]]
    sysm = pc.moordyn_from_state(inp, fair0, st)
    l1, l2, l3 = (moordyn.GetLine(sysm, k) for k in (1, 2, 3))
    buoy, fair = moordyn.GetPoint(sysm, 4), moordyn.GetPoint(sysm, 3)

    def measure(t, broke):
        p = moordyn.GetPointPos(buoy)
        v = moordyn.GetPointVel(buoy)
        tf = np.nan if broke else end_tension(l3, (nh - 1, nh - 2, nh - 3), HAWSER / (nh - 1))
        return (t, *p, *v, end_tension(l1, (0, 1, 2), LEG / (nl - 1)), end_tension(l2, (0, 1, 2), LEG / (nl - 1)), tf)

    def hawser_max():
        p = np.array([moordyn.GetLineNodePos(l3, i) for i in range(nh)])
        return float(EA * (np.linalg.norm(np.diff(p, axis=0), axis=1) / (HAWSER / (nh - 1)) - 1).max())

    rows = []   # (MoorDyn's measures before its first Step do not see the loaded state)
    broke, t_cross, prev = None, None, hawser_max()
    k_a = int(round(T_A / h))
    c0, w0 = time.process_time(), time.time()
    k, stop_at = 0, t_end
    err = None
    while k * h < stop_at - 1e-9:
        t0 = k * h
        x0, x1 = table_x(t0), table_x(t0 + h)
        try:
            moordyn.Step(sysm, [FAIR0[0] + x0, FAIR0[1], FAIR0[2]], [(x1 - x0) / h, 0.0, 0.0], t0, h)
        except Exception as e:  # noqa: BLE001  (MoorDyn's NaN guard)
            err = f"MoorDyn stopped at {t0:.4f} s: {e}"
            break
        k += 1
        t = k * h
        if broke is None:
            hit = False
            if mode == "time":
                hit = k == k_a
            else:
                top = hawser_max()
                if top >= MBL:
                    hit = True
                    t_cross = t - h * (top - MBL) / (top - prev)
                prev = top
            if hit:
                rows.append(measure(t, False))
                moordyn.BreakLine(sysm, fair, l3)
                broke = t
                stop_at = min(t_end, broke + ARGS.window + 2 * SAMPLE)
                continue
        if k % k_sub == 0 or broke is not None:
            rows.append(measure(t, broke is not None))
    cpu, wall = time.process_time() - c0, time.time() - w0
    moordyn.Close(sysm)
    r = np.array(rows)
    hist = {"t": r[:, 0], "bx": r[:, 1], "by": r[:, 2], "bz": r[:, 3], "bvx": r[:, 4], "bvy": r[:, 5],
            "bvz": r[:, 6], "Ta1": r[:, 7], "Ta2": r[:, 8], "Tf": r[:, 9]}
    return {"code": "MoorDyn", "level": level, "dt": h, "cpu": cpu, "wall": wall, "break_time": broke,
            "break_cross": t_cross, "t_end_reached": float(r[-1, 0]), "error": err, "hist": hist}


# ------------------------------------------------------------------ comparison
def resample(run, tau):
    """The compared quantities at times tau after the run's own break (columns: bx by bz bvx bvy bvz Ta1 Ta2)."""
    hh = run["hist"]
    t = hh["t"]
    tb = run["break_time"]
    after = t >= tb - 1e-12
    # after the break only (the record at the break time is the state at the detachment)
    out = {}
    for c in ("bx", "by", "bz", "bvx", "bvy", "bvz", "Ta1", "Ta2"):
        out[c] = np.interp(tb + tau, t[after], hh[c][after])
    return out


def before(run, times):
    hh = run["hist"]
    return np.interp(times, hh["t"], hh["Tf"])


def diff(a, b, tau):
    ra, rb = resample(a, tau), resample(b, tau)
    dp = np.sqrt(sum((ra[c] - rb[c]) ** 2 for c in ("bx", "by", "bz")))
    dv = np.sqrt(sum((ra[c] - rb[c]) ** 2 for c in ("bvx", "bvy", "bvz")))
    dT = np.concatenate([ra["Ta1"] - rb["Ta1"], ra["Ta2"] - rb["Ta2"]])
    tpre = np.arange(SAMPLE, min(a["break_time"], b["break_time"]) - 0.02, SAMPLE)
    dTf = before(a, tpre) - before(b, tpre)
    rms = lambda x: float(np.sqrt(np.mean(x ** 2)))  # noqa: E731
    nav = int(round(SMOOTH / SAMPLE))
    kern = np.ones(nav) / nav
    dTs = np.concatenate([np.convolve(ra[c] - rb[c], kern, mode="valid") for c in ("Ta1", "Ta2")])
    return {"pos_rms": rms(dp), "pos_max": float(dp.max()), "vel_rms": rms(dv), "vel_max": float(dv.max()),
            "T_rms": rms(dT), "T_max": float(np.abs(dT).max()), "Ts_rms": rms(dTs), "Ts_max": float(np.abs(dTs).max()), "Tf_pre_rms": rms(dTf),
            "Tf_pre_max": float(np.abs(dTf).max()),
            "dtb": (a["break_time"] or 0) - (b["break_time"] or 0)}


def describe(run, tau):
    r = resample(run, tau)
    sp = np.sqrt(r["bvx"] ** 2 + r["bvy"] ** 2 + r["bvz"] ** 2)
    return {"peak_speed": float(sp.max()), "Ta_min": float(min(r["Ta1"].min(), r["Ta2"].min())),
            "Ta_max": float(max(r["Ta1"].max(), r["Ta2"].max())), "x_end": float(r["bx"][-1]),
            "z_end": float(r["bz"][-1]),
            "slack": float(tau[np.argmax(np.minimum(r["Ta1"], r["Ta2"]) < 1000.0)]),
            "Ta_mean": float(0.5 * (r["Ta1"].mean() + r["Ta2"].mean()))}


def main():
    global ARGS
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--mode", nargs="+", default=["time", "tension"], choices=["time", "tension"])
    ap.add_argument("--levels", nargs="+", type=int, default=[1, 2, 4])
    ap.add_argument("--window", type=float, default=5.0)
    ap.add_argument("--courant", type=float, default=2.0)
    ap.add_argument("--exe", default=os.environ.get("XCABLE", os.path.join(HERE, "..", "..", "bin", "xcable")))
    ap.add_argument("--work", default=None)
    ARGS = ap.parse_args()
    work = ARGS.work or tempfile.mkdtemp(prefix="network_break_")
    os.makedirs(work, exist_ok=True)
    exe = os.path.abspath(ARGS.exe)
    summary = {}
    for mode in ARGS.mode:
        runs = {}
        for lv in ARGS.levels:
            t_end = (T_A if mode == "time" else T_B_GUESS) + ARGS.window + 0.5
            xr = xcable_run(exe, lv, ARGS.courant, mode, t_end, work)
            print(f"[{mode}] xcable r{lv}: {xr['status']} to {xr['t_end_reached']:.3f} s, break "
                  f"{xr['break_time']}, dt {xr['dt']:.3e}, CPU {xr['cpu']:.2f} s {xr['reason']}", file=sys.stderr)
            mr = md_run(lv, mode, t_end, xr["static"], work)
            print(f"[{mode}] MoorDyn r{lv}: to {mr['t_end_reached']:.3f} s, break {mr['break_time']} "
                  f"(crossing {mr['break_cross']}), dtM {mr['dt']:.3e}, CPU {mr['cpu']:.2f} s {mr['error'] or ''}",
                  file=sys.stderr)
            runs[("x", lv)], runs[("m", lv)] = xr, mr
        # window: common to every run
        w = min(ARGS.window, *[r["t_end_reached"] - r["break_time"] for r in runs.values()])
        tau = np.arange(0.0, w + 1e-9, SAMPLE)
        print(f"\n## mode {mode}: window {w:.2f} s after each code's own break\n")
        print("| code | level | cells m | step s | break time s | crossing s | peak buoy speed m/s | anchor T min..max kN "
              "| mean anchor T kN | first slack s | buoy x, z at window end m | CPU s | wall s | reached s |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        rows = []
        for (c, lv), r in sorted(runs.items(), key=lambda kv: (kv[0][0] != "x", kv[0][1])):
            d = describe(r, tau)
            cross = r.get("break_cross")
            print(f"| {r['code']} | {lv} | {5.0 / lv:g} | {r['dt']:.3e} | {r['break_time']:.4f} | "
                  f"{'' if cross is None else '%.4f' % cross} | {d['peak_speed']:.4f} | "
                  f"{d['Ta_min'] / 1e3:.2f}..{d['Ta_max'] / 1e3:.2f} | {d['Ta_mean'] / 1e3:.2f} | {d['slack']:.3f} | {d['x_end']:.3f}, {d['z_end']:.3f} | "
                  f"{r['cpu']:.2f} | {r['wall']:.2f} | {r['t_end_reached']:.3f} |")
            rows.append({"code": r["code"], "level": lv, "dt": r["dt"], "break_time": r["break_time"],
                         "break_cross": cross, "cpu": r["cpu"], "wall": r["wall"], **d})
        pairs = []
        lv = sorted(ARGS.levels)
        for c in ("x", "m"):
            pairs += [((c, a), (c, b)) for a, b in zip(lv, lv[1:])]
        pairs += [(("m", l), ("x", l)) for l in lv]
        print("\n| a | b | d break s | d T_fairlead before, rms / max N | d buoy pos rms / max m | "
              "d buoy vel rms / max m/s | d anchor T rms / max N | d anchor T, 0.5 s means, rms / max N |")
        print("|---|---|---|---|---|---|---|---|")
        dl = []
        for a, b in pairs:
            d = diff(runs[a], runs[b], tau)
            name = lambda k: ("xcable" if k[0] == "x" else "MoorDyn") + f" r{k[1]}"  # noqa: E731
            print(f"| {name(a)} | {name(b)} | {d['dtb']:+.4f} | {d['Tf_pre_rms']:.1f} / {d['Tf_pre_max']:.1f} | "
                  f"{d['pos_rms']:.2e} / {d['pos_max']:.2e} | {d['vel_rms']:.2e} / {d['vel_max']:.2e} | "
                  f"{d['T_rms']:.1f} / {d['T_max']:.1f} | {d['Ts_rms']:.1f} / {d['Ts_max']:.1f} |")
            dl.append({"a": name(a), "b": name(b), **d})
        summary[mode] = {"window": w, "runs": rows, "diffs": dl}
        sys.stdout.flush()
    with open(os.path.join(work, "summary.json"), "w") as f:
        json.dump(summary, f, indent=1)
    print(f"\n(work files and summary.json in {work})", file=sys.stderr)


ARGS = None
if __name__ == "__main__":
    main()
