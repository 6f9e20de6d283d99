#!/usr/bin/env python3
"""xcable against MoorDyn v2 under water (&fluid): bench/peer, not part of `make test`.

Results and discussion: fluid.md (this directory).

Scene `pendulum`: the paper's cable (L = 60 m, d = 0.05 m, rho_c = 1140
kg/m^3, EI = E pi d^4/64 = 70.56 N m^2) with the linear law T = EA eps
(EA = E pi d^2/4 = 451.6 kN) and no compression (MoorDyn cannot push; xcable
`compression = 'none'`, which changes nothing here: the strain stays near
0.011), a point mass M = 500 kg at end b (its weight only: no volume, no drag,
no added mass), hanging from end a in sea water (rho_f = 1025, Cdn 1.2,
Cdt 0.008, Can 1.0, Cat 0), no seabed, no surface. End a is moved by
DX = 6 m horizontally and DZ = 3 m up along X(t) = D (1 - cos(pi t / TM)) / 2,
TM = 6 s, then held: the mass and the cable swing through the water until
t_end (30 s). Neither code has damping besides the water.

Scene `current`: the same line and mass held still at end a in a uniform
current U = (current_x, 0): the state at rest (xcable: its statics; MoorDyn:
its dynamics from the still-water hang, 300 s, by when the drag has settled
it; MoorDyn's own initial-condition solver runs without the current).

xcable: a namelist run of the executable (XCABLE, default
/tmp/fluidpeer/bin/xcable); its end motion is a 'table' of X(t) every 10 ms
(cubic Hermite between rows). MoorDyn (PyPI `moordyn`, 2.7.2): point 1
Coupled (moved by this script, at constant velocity within each coupling step
of one dtM, so that it is exactly at X(t) at the end of every step), point 2
Free (mass M), a line of N segments, RK4; the initial state, the straight
vertical hang of the same chain (segment j carries M g + w' (L - s_j),
w' = (rho_c - rho_f) A g: MoorDyn's exact discrete equilibrium), written as a
MoorDyn state file and loaded with LoadState after Init_NoIC, as in
moordyn_run.py. MoorDyn's z is shifted by Z0 = -50 m (its water surface is at
z = 0); results are given relative to end a's starting point.

Conventions, as read in MoorDyn's source (Line.cpp, Point.cpp, v2.7.1):
  * weight and buoyancy per node: -g (m_i - rho_w A l_i), A = pi d^2 / 4 and
    l_i the node's share of the *unstretched* length (xcable: the same);
    a point: g (V rho_w - M) with V = 0 here (xcable's mass end: M g);
  * added mass: rho_w A l_i (Can (I - q q^T) + Cat q q^T) on the node, also
    unstretched (xcable: Can rho A on the normal acceleration, the same);
  * drag: 1/2 rho_w d l_i Cdn |V_n| V_n and 1/2 rho_w pi d l_i Cdt |V_t| V_t
    with the *unstretched* d and l_i. xcable puts Cdn on the stretched
    diameter over the stretched length, d sqrt(1 + eps) per unstretched
    length: at the strain of this scene (0.011) xcable's drag is
    sqrt(1.011) = 1.0055 times MoorDyn's. --md-cd-scale 1.00553 multiplies
    MoorDyn's Cdn and Cdt by that factor, as a check of this explanation;
  * tension: EA (l/l0 - 1) along each segment, 0 when it is shorter than l0.

Compared: end b's position (x, z) and the tension at end a (xcable:
/history/end_a/tension, the end cell's tension extrapolated half a cell;
MoorDyn: the same extrapolation from its first two segments, 1.5 T_0 - 0.5 T_1).

Usage:
  python3 fluid_swing.py pendulum [--xn 61 121 241 481] [--xdt 0.01 ... 0.000625]
                                  [--mn 60 120 240 480] [--courant 0.5]
                                  [--md-cd-scale 1.00553 --skip-x]
  python3 fluid_swing.py current --u 1.0 [--xn ...] [--mn ...] [--md-t-end 300]
  python3 fluid_swing.py summarize [--work DIR] [--out DIR]
      (the tables of fluid.md on stdout; data/fluid_*.tsv, fluid_pendulum.png)
  python3 fluid_swing.py report REF.tsv OTHER.tsv ...   (differences over the run)
Writes a TSV and a JSON summary per run into --work (default /tmp/fluidpeer_runs).
"""

import argparse
import json
import math
import os
import re
import subprocess
import sys
import time

import numpy as np

import peer_common as pc  # the MoorDyn state file

XCABLE = os.environ.get("XCABLE", "/tmp/fluidpeer/bin/xcable")

# the paper's cable (xcable's defaults)
LENGTH = 60.0
DIAM = 0.05
RHO_C = 1140.0
YOUNG = 2.3e8
AREA = math.pi * DIAM ** 2 / 4
MASS = RHO_C * AREA                      # kg/m
EA = YOUNG * AREA                        # N (xcable's linear law default)
EI = YOUNG * math.pi * DIAM ** 4 / 64    # N m^2 (xcable's default)
G = 9.81
# the fluid
RHO_F = 1025.0
CDN, CDT, CAN, CAT = 1.2, 0.008, 1.0, 0.0
W_SUB = (RHO_C - RHO_F) * AREA * G       # submerged weight per length
# the scene
M_END = 500.0
DX, DZ, TM = 6.0, 3.0, 6.0
T_END = 30.0
SAMPLE = 0.05
Z0 = -50.0                               # MoorDyn: end a's depth
# diagnostics (fluid.md): EA of both codes times EA_SCALE; MoorDyn's Cd, CdAx
# times MD_CD_SCALE (to test the sqrt(1 + eps) of xcable's drag); 1 = the scene
EA_SCALE = 1.0
MD_CD_SCALE = 1.0
# xcable's &material compression: 'none' blends the law to zero over
# |eps| < 1e-3 (src/xcable/material/tension_only.f90), so a diagnostic with a
# stiffer EA (strains inside that band) uses 'law' (the cable stays in tension)
X_COMPRESSION = "none"


def _text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def motion(t):
    """Displacement and velocity of end a."""
    t = np.asarray(t, dtype=float)
    ph = np.clip(t / TM, 0.0, 1.0)
    s = 0.5 * (1 - np.cos(math.pi * ph))
    ds = np.where((t > 0) & (t < TM), 0.5 * math.pi / TM * np.sin(math.pi * ph), 0.0)
    return s * DX, s * DZ, ds * DX, ds * DZ


# ------------------------------------------------------------------ xcable
def xcable_run(n, dt, work, scene="pendulum", u=0.0, t_end=T_END):
    os.makedirs(work, exist_ok=True)
    tag = f"x_{scene}_n{n}_dt{dt:g}_ea{EA_SCALE:g}_{X_COMPRESSION}" + (f"_u{u:g}" if scene == "current" else "")
    nml = os.path.join(work, tag + ".nml")
    h5 = os.path.join(work, tag + ".h5")
    if scene == "pendulum":
        tt = np.round(np.arange(0.0, TM + 1e-9, 0.01), 10)
        mx, mz, _, _ = motion(tt)
        tab = os.path.join(work, "motion_a.txt")
        with open(tab, "w") as f:
            f.write("# t x z: displacement of end a\n")
            f.write("\n".join("%.12g %.15g %.15g" % r for r in zip(tt, mx, mz)) + "\n")
        end_a = (f"&end_a kind = 'motion', x = 0, z = 0, motion = 'table',\n"
                 f"  table_file = '{tab}' /\n")
        cur = ""
    else:
        end_a = "&end_a kind = 'fixed', x = 0, z = 0 /\n"
        cur = f", current_x = {u:.12g}"
    txt = (f"&cable length = {LENGTH}, diameter = {DIAM}, density = {RHO_C}, gravity = {G} /\n"
           f"&material law = 'linear', ea = {EA * EA_SCALE:.15g}, compression = '{X_COMPRESSION}' /\n"
           f"&fluid density = {RHO_F}, cd_normal = {CDN}, cd_tangential = {CDT}, "
           f"ca_normal = {CAN}{cur}, surface_z = {-Z0:.15g} /\n" + end_a +
           f"&end_b kind = 'mass', mass = {M_END} /\n"
           f"&rupture enabled = .false. /\n"
           f"&numerics nodes = {n}, dt = {dt:.12g}, t_end = {t_end:.12g} /\n"
           f"&output file = '{h5}', interval = {SAMPLE}, quiet = .true., energy = .true., "
           f"fields = 'x z tension' /\n")
    with open(nml, "w") as f:
        f.write(txt)
    w0 = time.time()
    p = subprocess.run([XCABLE, nml], capture_output=True, text=True)
    wall = time.time() - w0
    import h5py
    with h5py.File(h5, "r") as f:
        status = f.attrs["status"]
        st = f["static"]
        static = {"xb": float(st["x"][-1]), "zb": float(st["z"][-1]),
                  "ta": float(st.attrs["tension_a"]), "tb": float(st.attrs["tension_b"]),
                  "x": st["x"][:].tolist(), "z": st["z"][:].tolist()}
        h = f["history"]
        t = h["time"][:]
        xb, zb = h["end_b/x"][:], h["end_b/z"][:]
        xa, za = h["end_a/x"][:], h["end_a/z"][:]
        ta = h["end_a/tension"][:]
        summ = dict(f["summary"].attrs)
    info = {"code": "xcable", "N": n, "dt": dt,
            "status": status.decode() if isinstance(status, bytes) else str(status), "rc": p.returncode,
            "stderr": p.stderr.strip()[-400:], "wall_s": wall,
            "wall_time_attr": float(summ.get("wall_time", -1)),
            "energy_drift": float(summ.get("energy_drift", -1)),
            "min_strain": float(summ.get("min_strain", 0)),
            "max_strain": float(summ.get("max_strain", 0)),
            "warnings": _text(summ.get("warnings", "")), "static": static}
    # history is per accepted step: resample on the common grid
    ts = np.arange(0.0, t[-1] + 1e-9, SAMPLE)
    rows = np.column_stack([ts] + [np.interp(ts, t, a) for a in (xb, zb, ta, xa, za)])
    return rows, info


# ------------------------------------------------------------------ MoorDyn
def md_write_input(path, n, zb, dtm, u=0.0):
    cur = "1        Currents\n" if u else ""
    txt = f"""MoorDyn v2 input: xcable fluid peer (bench/peer/fluid_swing.py)
---------------------- LINE TYPES -----------------------------------
TypeName   Diam    Mass/m     EA      BA/-zeta     EI    Cd     Ca    CdAx    CaAx
(name)     (m)     (kg/m)     (N)     (N-s/-)    (N-m^2) (-)   (-)   (-)     (-)
rope  {DIAM:.12g}  {MASS:.15g}  {EA * EA_SCALE:.15g}  0.0  {EI:.15g}  {CDN * MD_CD_SCALE:.15g}  {CAN}  {CDT * MD_CD_SCALE:.15g}  {CAT}
---------------------------- POINTS -------------------------------------------
ID  Attachment  X       Y     Z      Mass   Volume  CdA    CA
(#)   (-)       (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
1     Coupled   0.0     0.0   {Z0:.15g}    0.0    0.0     0.0    0.0
2     Free      0.0     0.0   {zb:.15g}    {M_END}  0.0     0.0    0.0
---------------------- LINES ----------------------------------------
ID   LineType AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)  (name)   (#)      (#)      (m)       (-)      (-)
1    rope     1        2       {LENGTH:.12g}      {n}      -
---------------------- OPTIONS -----------------------------------------
0        writeLog
{dtm!r}  dtM
RK4      tScheme
{G}     g
{RHO_F}     rho
1000     WtrDpth
{cur}1        disableOutput
1        disableOutTime
---------------------- OUTPUTS -----------------------------------------
------------------------- need this line -------------------------------------
"""
    with open(path, "w") as f:
        f.write(txt)


def md_write_current(workdir, u):
    # steady current profile, grid approach (Currents 1): depths and velocities
    with open(os.path.join(workdir, "current_profile.txt"), "w") as f:
        f.write("--------------------- MoorDyn steady currents File ----------------------------------\n")
        f.write("Tabulated file with the water currents components\n")
        f.write("z (m), ux (m/s), uy (m/s), uz (m/s)\n")
        rows = [(-1000.0, u), (-500.0, u), (-100.0, u), (0.0, u)]
        f.write("\n".join("%g %.12g 0.0 0.0" % r for r in rows))


def vertical_hang(n):
    """Exact static state of MoorDyn's chain hanging straight down: z of nodes."""
    ds = LENGTH / n
    s_mid = (np.arange(n) + 0.5) * ds
    ten = M_END * G + W_SUB * (LENGTH - s_mid)
    l = ds * (1 + ten / (EA * EA_SCALE))
    z = Z0 - np.concatenate([[0.0], np.cumsum(l)])
    return np.column_stack([np.zeros(n + 1), z])


def md_run(n, courant, work, scene="pendulum", u=0.0, t_end=T_END):
    import moordyn
    tag = f"md_{scene}_n{n}_c{courant:g}_ea{EA_SCALE:g}_cd{MD_CD_SCALE:g}" + (f"_u{u:g}" if scene == "current" else "")
    wd = os.path.join(work, tag)
    os.makedirs(wd, exist_ok=True)
    ds = LENGTH / n
    c_ax = math.sqrt(EA * EA_SCALE / MASS)
    h = courant * ds / c_ax
    nsub = int(math.ceil(SAMPLE / h - 1e-9))
    h = SAMPLE / nsub
    r0 = vertical_hang(n)
    inp = os.path.join(wd, "swing.txt")
    md_write_input(inp, n, r0[-1, 1], h, u=u)
    if u:
        md_write_current(wd, u)
    pc.moordyn_state(os.path.join(wd, "static.state"), [(x, 0.0, z) for x, z in r0[1:-1]],
                   [[0.0, 0.0, Z0, 0.0, 0.0, 0.0], [0.0, 0.0, r0[-1, 1], 0.0, 0.0, 0.0]])
    cwd = os.getcwd()
    os.chdir(wd)              # MoorDyn reads current_profile.txt next to the input
    saved = os.dup(1)
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, 1)
    try:
        sysm = moordyn.Create(inp)
        moordyn.SetVerbosity(sysm, moordyn.LEVEL_ERR)
        moordyn.Init_NoIC(sysm, [0.0, 0.0, Z0], [0.0, 0.0, 0.0])
        moordyn.LoadState(sysm, os.path.join(wd, "static.state"))
    finally:
        os.dup2(saved, 1)
        os.close(devnull)
        os.close(saved)
        os.chdir(cwd)
    line = moordyn.GetLine(sysm, 1)
    pt2 = moordyn.GetPoint(sysm, 2)

    def ends():
        p0 = np.array(moordyn.GetLineNodePos(line, 0))
        p1 = np.array(moordyn.GetLineNodePos(line, 1))
        p2 = np.array(moordyn.GetLineNodePos(line, 2))
        pb = np.array(moordyn.GetPointPos(pt2))
        t0 = EA * EA_SCALE * max(np.linalg.norm(p1 - p0) / ds - 1, 0.0)
        t1 = EA * EA_SCALE * max(np.linalg.norm(p2 - p1) / ds - 1, 0.0)
        return pb, p0, 1.5 * t0 - 0.5 * t1

    ten0 = M_END * G + W_SUB * (LENGTH - np.array([0.5, 1.5]) * ds)
    rows = [(0.0, 0.0, r0[-1, 1] - Z0, 1.5 * ten0[0] - 0.5 * ten0[1], 0.0, 0.0)]
    t = 0.0
    wall = time.time()
    k = 0
    for _ in range(int(round(t_end / SAMPLE))):
        for _ in range(nsub):
            k += 1
            t1 = k * h
            if scene == "pendulum":
                x0, z0, _, _ = motion(t)
                x1, z1, _, _ = motion(t1)
                xa = [float(x0), 0.0, Z0 + float(z0)]
                va = [float(x1 - x0) / h, 0.0, float(z1 - z0) / h]
            else:
                xa, va = [0.0, 0.0, Z0], [0.0, 0.0, 0.0]
            moordyn.Step(sysm, xa, va, t, h)
            t = t1
        pb, pa, ta = ends()
        rows.append((t, pb[0], pb[2] - Z0, ta, pa[0], pa[2] - Z0))
    wall = time.time() - wall
    nodes = np.array([moordyn.GetLineNodePos(line, i) for i in range(n + 1)])
    moordyn.Close(sysm)
    info = {"code": "MoorDyn " + md_version(), "N": n, "dtM": h, "courant": courant,
            "wall_s": wall, "final_nodes_xz": nodes[:, [0, 2]].tolist()}
    return np.array(rows), info


def md_version():
    try:
        from importlib.metadata import version
        return version("moordyn")
    except Exception:
        return "?"


def write_tsv(path, rows):
    with open(path, "w") as f:
        f.write("t\tend_b_x\tend_b_z\ttension_a\tend_a_x\tend_a_z\n")
        for r in rows:
            f.write("\t".join("%.9g" % v for v in r) + "\n")


def write_info(path, info):
    """The run's summary (wall time, status, ...) beside its TSV, without the node lists."""
    with open(path, "w") as f:
        json.dump({k: v for k, v in info.items() if k not in ("static", "final_nodes_xz")},
                  f, indent=1)


def diff(a, b):
    m = min(len(a), len(b))
    dr = np.hypot(a[:m, 1] - b[:m, 1], a[:m, 2] - b[:m, 2])
    dT = np.abs(a[:m, 3] - b[:m, 3])
    return dr, dT


def read_tsv(path):
    return np.loadtxt(path, skiprows=1)


def report(argv):
    """report REF OTHER [OTHER ...] [--times ...]: differences to REF over the run.

    Per file: max over all samples of |r_b - r_b,REF| (m) and |T_a - T_a,REF| (N),
    the same on [0, 6] and (6, 30] s, and the values at the chosen times."""
    ap = argparse.ArgumentParser(prog="fluid_swing.py report")
    ap.add_argument("files", nargs="+")
    ap.add_argument("--times", type=float, nargs="+", default=[2, 4, 6, 8, 10, 15, 20, 25, 30])
    a = ap.parse_args(argv)
    ref = read_tsv(a.files[0])
    print("reference", os.path.basename(a.files[0]))
    print("| run | max dr (m) | max dr t<=6 | max dT (N) | max dT t<=6 | max dT t>6 |")
    print("|---|---|---|---|---|---|")
    for f in a.files[1:]:
        b = read_tsv(f)
        dr, dT = diff(ref, b)
        t = ref[:len(dr), 0]
        e = t <= 6 + 1e-9
        print("| %s | %.2e | %.2e | %.2f | %.2f | %.2f |" % (
            os.path.basename(f), dr.max(), dr[e].max(), dT.max(), dT[e].max(), dT[~e].max()))
    print()
    print("| run | " + " | ".join("t=%g" % t for t in a.times) + " |")
    print("|---|" + "---|" * len(a.times))
    for f in a.files:
        b = read_tsv(f)
        cells = []
        for t in a.times:
            i = int(round(t / SAMPLE))
            cells.append("%.4f, %.4f; %.1f" % tuple(b[i, 1:4]) if i < len(b) else "")
        print("| %s | " % os.path.basename(f) + " | ".join(cells) + " |")


def current_table(runs):
    """Static state in the current: xcable's statics (and where its dynamics
    ends) against MoorDyn's settled state: the mean over the last 10 s (the
    axial mode of the mass on the line is not damped: T_a still rings), its
    change from the 10 s before (drift) and the tension's spread; shapes
    compared node by node where the grids coincide."""
    print("| run | end b x (m) | end b z (m) | T_a (N) | note |")
    print("|---|---|---|---|---|")
    for k, (rows, info) in runs.items():
        if info["code"] == "xcable":
            st = info["static"]
            print("| %s statics | %.5f | %.5f | %.2f | dynamics to %.1f s moves end b by %.1e m |" % (
                k, st["xb"], st["zb"], st["ta"], rows[-1, 0],
                float(np.max(np.hypot(rows[:, 1] - st["xb"], rows[:, 2] - st["zb"])))))
        else:
            j = int(round(10.0 / SAMPLE))
            last, prev = rows[-j:], rows[-2 * j:-j]
            m1, m0 = last.mean(axis=0), prev.mean(axis=0)
            drift = float(np.hypot(*(m1[1:3] - m0[1:3])))
            print("| %s, mean of the last 10 s to %.0f s | %.5f | %.5f | %.2f | 10 s means moved %.1e m, %.2f N; T_a spread +-%.2f N |" % (
                k, rows[-1, 0], m1[1], m1[2], m1[3], drift, m1[3] - m0[3],
                0.5 * float(np.ptp(last[:, 3]))))
    xs = {info["N"]: np.column_stack([info["static"]["x"], info["static"]["z"]])
          for _, info in runs.values() if info["code"] == "xcable"}
    for _, info in runs.values():
        if info["code"] == "xcable":
            continue
        mdn = np.array(info["final_nodes_xz"])
        mdn[:, 1] -= Z0
        for nx, xz in xs.items():
            if nx - 1 == info["N"]:
                print("shape: MoorDyn N=%d vs xcable nodes=%d: max node distance %.2e m" % (
                    info["N"], nx, float(np.max(np.hypot(*(mdn - xz).T)))))

# ------------------------------------------------------------------ the page
_RUN = {
    "x": re.compile(r"^(pendulum|current)_x_n(\d+)_dt([0-9.e-]+)\.tsv$"),
    "md": re.compile(r"^(pendulum|current)_md_n(\d+)_c([0-9.e-]+)\.tsv$"),
    "mdcd": re.compile(r"^(pendulum|current)_cd([0-9.e-]+)_md_n(\d+)_c([0-9.e-]+)\.tsv$"),
}


def find_runs(work):
    """{(scene, kind): {(N, step): path}} of the TSVs in work (kind x, md or
    mdcd; for mdcd the key is (N, courant, cd scale))."""
    out = {}
    for name in sorted(os.listdir(work)):
        for kind, rx in _RUN.items():
            m = rx.match(name.replace("_ea1_cd", "_cd"))
            if not m:
                continue
            g = m.groups()
            if kind == "mdcd":
                key = (int(g[2]), float(g[3]), float(g[1]))
            else:
                key = (int(g[1]), float(g[2]))
            out.setdefault((g[0], kind), {})[key] = os.path.join(work, name)
    return out


def stats(a, b):
    """max and RMS over the common samples of a - b: dx, dz, |dr| (m), dT (N)."""
    m = min(len(a), len(b))
    d = a[:m, 1:4] - b[:m, 1:4]
    dr = np.hypot(d[:, 0], d[:, 1])
    rms = lambda v: float(np.sqrt(np.mean(v * v)))
    return {"dx_max": float(np.abs(d[:, 0]).max()), "dz_max": float(np.abs(d[:, 1]).max()),
            "dr_max": float(dr.max()), "dr_rms": rms(dr),
            "dT_max": float(np.abs(d[:, 2]).max()), "dT_rms": rms(d[:, 2])}


def _info(path, key):
    try:
        with open(path[:-4] + ".json") as f:
            return float(json.load(f)[key])
    except (OSError, KeyError, ValueError):
        return float("nan")


def _wall(path):
    try:
        with open(path[:-4] + ".json") as f:
            return float(json.load(f)["wall_s"])
    except (OSError, KeyError, ValueError):
        return float("nan")


def summarize(argv):
    """summarize [--work DIR] [--out DIR]: the tables of fluid.md (stdout),
    data/fluid_*.tsv and fluid_pendulum.png from the runs in --work."""
    ap = argparse.ArgumentParser(prog="fluid_swing.py summarize")
    ap.add_argument("--work", default="/tmp/fluidpeer_runs")
    ap.add_argument("--out", default=os.path.dirname(os.path.abspath(__file__)))
    ap.add_argument("--pairs", nargs="+", default=["121:0.00125:120:0.5", "241:0.000625:240:0.5"],
                    help="xcable N:dt and MoorDyn N:courant compared besides the finest runs")
    a = ap.parse_args(argv)
    runs = find_runs(a.work)
    xr, mr = runs.get(("pendulum", "x"), {}), runs.get(("pendulum", "md"), {})
    if not xr or not mr:
        sys.exit("summarize: no pendulum runs of both codes in " + a.work)
    xk = max(xr, key=lambda k: (k[0], -k[1]))
    mk = max(mr, key=lambda k: (k[0], -k[1]))
    X, M = read_tsv(xr[xk]), read_tsv(mr[mk])
    t_lo, t_hi = float(M[:, 3].min()), float(M[:, 3].max())
    t_range = t_hi - t_lo
    conv = []
    print("Tension at end a (MoorDyn N = %d): %.1f to %.1f N, range %.1f N\n" % (mk[0], t_lo, t_hi, t_range))
    print("xcable, against N = %d, dt = %g s: max |dr_b| (mm) / max |dT_a| (N)\n" % xk)
    dts = sorted({k[1] for k in xr}, reverse=True)
    print("| nodes | " + " | ".join("dt = %g s" % d for d in dts) + " |")
    print("|---|" + "---|" * len(dts))
    for n in sorted({k[0] for k in xr}):
        cells = []
        for d in dts:
            if (n, d) in xr and (n, d) != xk:
                st = stats(read_tsv(xr[(n, d)]), X)
                conv.append(("xcable", n, d, "", st, _wall(xr[(n, d)])))
                cells.append("%.3f / %.2f" % (1e3 * st["dr_max"], st["dT_max"]))
            elif (n, d) == xk:
                conv.append(("xcable", n, d, "", stats(X, X), _wall(xr[xk])))
                cells.append("reference")
            else:
                cells.append("")
        print("| %d | " % n + " | ".join(cells) + " |")
    print("\nMoorDyn, against N = %d, Courant %g\n" % mk)
    print("| segments | Courant | dtM (s) | max / RMS \\|dr_b\\| (mm) | max / RMS \\|dT_a\\| (N) | wall (s) |")
    print("|---|---|---|---|---|---|")
    for k in sorted(mr):
        st = stats(read_tsv(mr[k]), M)
        conv.append(("MoorDyn", k[0], _info(mr[k], "dtM"), k[1], st, _wall(mr[k])))
        print("| %d | %g | %.3g | %.4f / %.4f | %.2f / %.2f | %.0f |" % (
            k[0], k[1], conv[-1][2], 1e3 * st["dr_max"], 1e3 * st["dr_rms"],
            st["dT_max"], st["dT_rms"], conv[-1][5]))
    # agreement
    pairs = [(xk, mk, mr)]
    for p in a.pairs:
        n1, d1, n2, c2 = p.split(":")
        k1, k2 = (int(n1), float(d1)), (int(n2), float(c2))
        if k1 in xr and k2 in mr and (k1, k2) != (xk, mk):
            pairs.append((k1, k2, mr))
    for k, path in sorted(runs.get(("pendulum", "mdcd"), {}).items()):
        pairs.append((xk, k, runs[("pendulum", "mdcd")]))
    print("\nxcable - MoorDyn over 0-30 s (every %g s); %% of the tension range %.0f N\n" % (SAMPLE, t_range))
    print("| xcable | MoorDyn | max \\|dx_b\\| (mm) | max \\|dz_b\\| (mm) | max / RMS \\|dr_b\\| (mm) | max \\|dT_a\\| N (%) | RMS dT_a N (%) |")
    print("|---|---|---|---|---|---|---|")
    agree = []
    for k1, k2, src in pairs:
        st = stats(read_tsv(xr[k1]), read_tsv(src[k2]))
        lab = "N = %d, C = %g" % k2[:2] + (", Cd x %g" % k2[2] if len(k2) > 2 else "")
        agree.append(("%d nodes, dt %g" % k1, lab, st))
        print("| %d nodes, dt = %g s | %s | %.2f | %.2f | %.2f / %.2f | %.2f (%.2f) | %.2f (%.3f) |" % (
            k1 + (lab, 1e3 * st["dx_max"], 1e3 * st["dz_max"], 1e3 * st["dr_max"], 1e3 * st["dr_rms"],
                  st["dT_max"], 100 * st["dT_max"] / t_range, st["dT_rms"], 100 * st["dT_rms"] / t_range)))
    print("\nEnd b (x, z in m) and T_a (N) at a few times, finest runs\n")
    print("| t (s) | xcable x_b | MoorDyn x_b | xcable z_b | MoorDyn z_b | xcable T_a | MoorDyn T_a |")
    print("|---|---|---|---|---|---|---|")
    for t in (2, 4, 6, 8, 10, 15, 20, 25, 30):
        i = int(round(t / SAMPLE))
        print("| %g | %.4f | %.4f | %.4f | %.4f | %.1f | %.1f |" % (
            t, X[i, 1], M[i, 1], X[i, 2], M[i, 2], X[i, 3], M[i, 3]))
    # data
    os.makedirs(os.path.join(a.out, "data"), exist_ok=True)
    cd = runs.get(("pendulum", "mdcd"), {})
    ck = max(cd) if cd else None
    C = read_tsv(cd[ck]) if ck else None
    step = int(round(0.1 / SAMPLE))
    with open(os.path.join(a.out, "data", "fluid_pendulum.tsv"), "w") as f:
        f.write("# bench/peer/fluid_swing.py pendulum: end b (m) and tension at end a (N) every 0.1 s;"
                " xcable %d nodes dt %g s; MoorDyn %d segments Courant %g" % (xk + mk))
        f.write((", MoorDyn with Cd x %g (%d segments)\n" % (ck[2], ck[0])) if ck else "\n")
        f.write("t\txcable_x\txcable_z\txcable_T\tmoordyn_x\tmoordyn_z\tmoordyn_T" +
                ("\tmoordyn_cd_x\tmoordyn_cd_z\tmoordyn_cd_T" if ck else "") + "\n")
        for i in range(0, min(len(X), len(M)), step):
            r = [X[i, 0]] + list(X[i, 1:4]) + list(M[i, 1:4]) + (list(C[i, 1:4]) if ck else [])
            f.write("\t".join("%.8g" % v for v in r) + "\n")
    with open(os.path.join(a.out, "data", "fluid_convergence.tsv"), "w") as f:
        f.write("# bench/peer/fluid_swing.py pendulum: each run against its own code's finest run, over 0-30 s\n")
        f.write("code\tN\tdt_s\tcourant\tdr_max_m\tdr_rms_m\tdT_max_N\tdT_rms_N\twall_s\n")
        for code, n, d, c, st, w in conv:
            f.write("%s\t%d\t%.6g\t%s\t%.3e\t%.3e\t%.3f\t%.3f\t%.1f\n" % (
                code, n, d, c, st["dr_max"], st["dr_rms"], st["dT_max"], st["dT_rms"], w))
        for xl, ml, st in agree:
            f.write("xcable-MoorDyn\t%s | %s\t\t\t%.3e\t%.3e\t%.3f\t%.3f\t\n" % (
                xl, ml, st["dr_max"], st["dr_rms"], st["dT_max"], st["dT_rms"]))
    current_summary(runs, a.out)
    plot_pendulum(X, M, C, xk, mk, ck, os.path.join(a.out, "fluid_pendulum.png"))


def current_summary(runs, out):
    xr, mr = runs.get(("current", "x"), {}), runs.get(("current", "md"), {})
    if not xr or not mr:
        return
    cd = runs.get(("current", "mdcd"), {})
    print("\nScene current: end b and T_a at rest (xcable: statics; MoorDyn: mean of its last 10 s)\n")
    print("| code | N | end b x (m) | end b z (m) | T_a (N) |")
    print("|---|---|---|---|---|")
    rows = []
    j = int(round(10.0 / SAMPLE))
    for k in sorted(xr):
        r = read_tsv(xr[k])[0]
        rows.append(("xcable statics", k[0], r[1], r[2], r[3]))
    for k in sorted(mr):
        r = read_tsv(mr[k])[-j:].mean(axis=0)
        rows.append(("MoorDyn", k[0], r[1], r[2], r[3]))
    for k in sorted(cd):
        r = read_tsv(cd[k])[-j:].mean(axis=0)
        rows.append(("MoorDyn Cd x %g" % k[2], k[0], r[1], r[2], r[3]))
    for r in rows:
        print("| %s | %d | %.5f | %.5f | %.2f |" % r)
    with open(os.path.join(out, "data", "fluid_current.tsv"), "w") as f:
        f.write("# bench/peer/fluid_swing.py current: end b (m) and T_a (N) at rest; N: xcable's nodes, MoorDyn's segments\n")
        f.write("code\tN\tend_b_x\tend_b_z\ttension_a\n")
        for r in rows:
            f.write("%s\t%d\t%.7f\t%.7f\t%.3f\n" % r)


def plot_pendulum(X, M, C, xk, mk, ck, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("no matplotlib: no figure", file=sys.stderr)
        return
    m = min(len(X), len(M))
    t = X[:m, 0]
    fig, ax = plt.subplots(4, 1, figsize=(7.5, 9), sharex=True)
    lx = "xcable (%d nodes, dt %g s)" % xk
    lm = "MoorDyn (%d segments)" % mk[0]
    ax[0].plot(t, X[:m, 1], "b-", lw=1.6, label=lx + " x")
    ax[0].plot(t, M[:m, 1], "r--", lw=1.2, label=lm + " x")
    ax[0].plot(t, X[:m, 2] - X[0, 2], "b-", lw=1.0, alpha=0.6, label="z - z(0)")
    ax[0].plot(t, M[:m, 2] - M[0, 2], "r--", lw=0.8, alpha=0.6)
    ax[0].set_ylabel("end b (m)")
    ax[0].legend(fontsize=7, loc="lower right")
    ax[1].plot(t, 1e3 * (X[:m, 1] - M[:m, 1]), "k-", lw=1, label="x: xcable - MoorDyn")
    ax[1].plot(t, 1e3 * (X[:m, 2] - M[:m, 2]), "g-", lw=1, label="z: xcable - MoorDyn")
    if C is not None:
        mc = min(m, len(C))
        ax[1].plot(t[:mc], 1e3 * (X[:mc, 1] - C[:mc, 1]), "k:", lw=1,
                   label="x: against MoorDyn with Cd x %g" % ck[2])
    ax[1].set_ylabel("end b difference (mm)")
    ax[1].legend(fontsize=7)
    ax[2].plot(t, X[:m, 3], "b-", lw=1.2, label="xcable")
    ax[2].plot(t, M[:m, 3], "r--", lw=0.9, label="MoorDyn")
    ax[2].set_ylabel("tension at end a (N)")
    ax[2].legend(fontsize=7)
    ax[3].plot(t, X[:m, 3] - M[:m, 3], "k-", lw=0.8)
    ax[3].set_ylabel("T_a: xcable - MoorDyn (N)")
    ax[3].set_xlabel("t (s)")
    for a_ in ax:
        a_.grid(alpha=0.3)
        a_.axvline(TM, color="0.6", lw=0.8)
    fig.suptitle("500 kg on the 60 m line in sea water, top moved 6 m across and 3 m up in 6 s", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=90)


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if argv and argv[0] == "report":
        return report(argv[1:])
    if argv and argv[0] == "summarize":
        return summarize(argv[1:])
    ap = argparse.ArgumentParser()
    ap.add_argument("scene", choices=["pendulum", "current"])
    ap.add_argument("--xn", type=int, nargs="+", default=[61, 121, 241, 481])
    ap.add_argument("--xdt", type=float, nargs="+", default=[0.01, 0.005, 0.0025, 0.00125, 0.000625])
    ap.add_argument("--mn", type=int, nargs="+", default=[60, 120, 240, 480])
    ap.add_argument("--courant", type=float, nargs="+", default=[0.5])
    ap.add_argument("--u", type=float, default=1.0)
    ap.add_argument("--t-end", type=float, default=None,
                    help="end time (pendulum: 30 s; current: 2 s for xcable, whose statics are compared)")
    ap.add_argument("--md-t-end", type=float, default=None,
                    help="MoorDyn's end time (current: 300 s, to settle from the still-water hang)")
    ap.add_argument("--work", default="/tmp/fluidpeer_runs")
    ap.add_argument("--skip-md", action="store_true")
    ap.add_argument("--ea-scale", type=float, default=1.0,
                    help="diagnostic: EA of both codes times this")
    ap.add_argument("--x-compression", default="none", choices=["none", "law"],
                    help="xcable's &material compression ('law' for --ea-scale > 1)")
    ap.add_argument("--md-cd-scale", type=float, default=1.0,
                    help="diagnostic: MoorDyn's Cdn and Cdt times this")
    ap.add_argument("--skip-x", action="store_true")
    a = ap.parse_args(argv)
    if a.scene == "pendulum":
        a.u = 0.0
        a.t_end = a.t_end or T_END
        a.md_t_end = a.md_t_end or a.t_end
    else:
        a.t_end = a.t_end or 2.0
        a.md_t_end = a.md_t_end or 300.0
    global EA_SCALE, MD_CD_SCALE, X_COMPRESSION
    EA_SCALE, MD_CD_SCALE, X_COMPRESSION = a.ea_scale, a.md_cd_scale, a.x_compression
    sfx = "" if (EA_SCALE, MD_CD_SCALE) == (1.0, 1.0) else f"_ea{EA_SCALE:g}_cd{MD_CD_SCALE:g}"
    sfx += "" if X_COMPRESSION == "none" else "_" + X_COMPRESSION
    os.makedirs(a.work, exist_ok=True)
    runs = {}
    if not a.skip_x:
        for n in a.xn:
            for dt in a.xdt:
                rows, info = xcable_run(n, dt, a.work, a.scene, a.u, a.t_end)
                key = f"xcable N={n} dt={dt:g}"
                runs[key] = (rows, info)
                write_tsv(os.path.join(a.work, f"{a.scene}{sfx}_x_n{n}_dt{dt:g}.tsv"), rows)
                write_info(os.path.join(a.work, f"{a.scene}{sfx}_x_n{n}_dt{dt:g}.json"), info)
                print(key, "wall %.2f s" % info["wall_s"], info["status"], info["stderr"][:200],
                      "drift", info["energy_drift"], file=sys.stderr)
    if not a.skip_md:
        for n in a.mn:
            for c in a.courant:
                rows, info = md_run(n, c, a.work, a.scene, a.u, a.md_t_end)
                key = f"MoorDyn N={n} C={c:g}"
                runs[key] = (rows, info)
                write_tsv(os.path.join(a.work, f"{a.scene}{sfx}_md_n{n}_c{c:g}.tsv"), rows)
                write_info(os.path.join(a.work, f"{a.scene}{sfx}_md_n{n}_c{c:g}.json"), info)
                print(key, "wall %.2f s" % info["wall_s"], "dtM %.3g" % info["dtM"], file=sys.stderr)
    summary = {k: {kk: vv for kk, vv in v[1].items() if kk not in ("static", "final_nodes_xz")}
               for k, v in runs.items()}
    for k, v in runs.items():
        if "static" in v[1]:
            summary[k]["static_end_b"] = (v[1]["static"]["xb"], v[1]["static"]["zb"],
                                          v[1]["static"]["ta"])
    with open(os.path.join(a.work, f"{a.scene}{sfx}_summary.json"), "w") as f:
        json.dump(summary, f, indent=1)
    if a.scene == "current":
        current_table(runs)
        return
    # table
    times = [0, 2, 4, 6, 8, 10, 15, 20, 25, 30]
    print("%-24s" % "run" + "".join("%30s" % ("t=%g" % t) for t in times))
    for k, (rows, _) in runs.items():
        line = "%-24s" % k
        for t in times:
            i = int(round(t / SAMPLE))
            if i < len(rows):
                line += "%30s" % ("%.4f %.4f %.2f" % tuple(rows[i, 1:4]))
        print(line)


if __name__ == "__main__":
    main()
