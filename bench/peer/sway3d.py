#!/usr/bin/env python3
"""Out-of-plane dynamics: xcable's 3-D model against MoorDyn v2 (issue 15).

bench/peer, not part of `make test`. Results and discussion: sway3d.md (this directory).

Scene. The line and the water of fluid_swing.py: the paper's cable (L = 60 m,
d = 0.05 m, rho_c = 1140 kg/m^3, EI = 70.56 N m^2) with the linear law
EA = 451.6 kN, in sea water (rho_f 1025, Cdn 1.2, Cdt 0.008, Can 1, Cat 0), no
seabed, no surface. End a (the anchor) is fixed at (0, 0, 0), end b (the
fairlead) at (XB, 0, ZB) = (48, 0, 24) m, so the chord (53.7 m) lies in the
x-z plane and the line sags below it. A uniform current U = 0.25 m/s along y,
across that plane, blows the line about 8 m sideways (the static state is
3-D). From t = 0 the fairlead moves across the plane, along y:
    y_b(t) = A w(t) sin(2 pi t / P),  w = sin^2(pi t / (2 P)) until t = P, then 1,
A = 2 m, P = 15 s (xcable's `motion = 'harmonic'` with `direction_y = 1` and
`ramp_time = P`; MoorDyn gets the same path). Run to T_END = 45 s (three
periods). The line stays in tension throughout (the smallest tension anywhere is
about 20 N), so xcable's linear law continued into compression (`compression =
'law'`) and MoorDyn's rope that cannot push model the same thing; the script
reports each code's smallest tension to show it.

Compared, every SAMPLE = 0.05 s over 0-45 s: the fairlead tension T_b (xcable:
/history/end_b/tension, the end cell's tension carried half a cell to the end;
MoorDyn: 1.5 T_{N-1} - 0.5 T_{N-2} from its last two segments) and the position
of the middle node (s = 30 m), in particular its out-of-plane component y_mid
(xcable: the snapshots `x`, `y`, `z` at node (n - 1) / 2; MoorDyn: node N / 2).

xcable: the executable (XCABLE, default bin/xcable of this tree) on a namelist,
`&numerics model = '3d'`, fixed dt; wall time and CPU time of the child process.
Its statics start the run.

MoorDyn (PyPI `moordyn` 2.7.2, RK4): point 1 Fixed (anchor), point 2 Coupled
(fairlead), one line of N segments, dtM = Courant ds / sqrt(EA / m). MoorDyn's
own initial-condition solver ignores the current (fluid.md), so the script
starts it from xcable's static state (241 nodes, interpolated by a cubic spline
in s onto MoorDyn's nodes, written as a state file and loaded after
Init_NoIC) and lets it settle with the fairlead held for T_SETTLE = 40 s, in
a copy of the line with critical axial damping (and, in still water, 1000
times the drag); the settled state, MoorDyn's own static state, is loaded into
the undamped line (the script reports how far the middle node still moves
over the last 10 s of the settling and how far the settling moved it from
xcable's statics). t = 0 is the end of the settling. The
fairlead is then moved once per dtM: MoorDyn moves a coupled point from the
given position at the given velocity, and the script passes the exact position
at the start of the step and the chord to its end. MoorDyn's z is shifted by
Z0 = -100 m (its surface is at z = 0); results are relative to the anchor.

Conventions (MoorDyn's source, see fluid.md): both take buoyancy and added mass
on the unstretched volume; MoorDyn takes the drag on the unstretched diameter
and length, xcable on the stretched ones, a factor sqrt(1 + eps) on xcable's
drag, here 1.00014 on average over the line and the run (strain 5e-5 to
7e-4). Small as it is, it is the one systematic difference found: about 0.3 mm
at the middle node (sway3d.md); --md-cd-scale 1.00014 multiplies MoorDyn's Cdn
and Cdt by it, as a check of that explanation. MoorDyn's bending is at
interior nodes with pinned ends, from the turning angle over the stretched
segment length; xcable's rod has pinned ends and the turning angle over the
unstretched length; the difference is of the order of the strain.

Usage (from bench/peer):
  python3 sway3d.py run [--xn 61 121 241] [--xdt 0.02 0.01 0.005] [--mn 60 120 240]
                        [--courant 0.5] [--work DIR] [--skip-x] [--skip-md]
                        [--u 0.25] [--md-cd-scale 1] [--force]
  python3 sway3d.py summarize [--work DIR] [--out DIR] [--name sway3d] [--no-figure]
      (the tables of sway3d.md on stdout; data/NAME.tsv, data/NAME_convergence.tsv, NAME.png)
Each run writes WORK/<tag>.tsv (t, T_b, mid x, y, z, fairlead y) and
WORK/<tag>.json (times, static state, smallest tension); default WORK
/tmp/sway3d_runs. A run already there is not repeated (--force reruns).
"""

import argparse
import json
import math
import os
import resource
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import fluid_swing as fs  # noqa: E402  (the line and the water, MoorDyn's version)
import peer_common as pc  # noqa: E402  (the MoorDyn state file)

XCABLE = os.environ.get("XCABLE", os.path.join(HERE, "..", "..", "bin", "xcable"))
XB, ZB = 48.0, 24.0          # fairlead (end b), m; anchor (end a) at the origin
U = 0.25                     # current along y, m/s
AMP, PERIOD = 2.0, 15.0      # fairlead motion along y, m and s; ramp over one period
RAMP = PERIOD
T_END = 45.0
SAMPLE = 0.05
SETTLE_CD_STILL = 1000.0     # MoorDyn's settling in still water: drag coefficients times this
T_SETTLE = 40.0              # MoorDyn's settling in the current before t = 0
Z0 = -100.0                  # MoorDyn: the anchor's depth
X_STATIC_N = 241             # xcable statics that start MoorDyn
WORK = "/tmp/sway3d_runs"
MD_CD_SCALE = 1.0            # diagnostic: MoorDyn's Cdn and Cdt times this (the drag's stretch factor)
COLS = ["t", "tension_b", "mid_x", "mid_y", "mid_z", "end_b_y"]


def motion_y(t):
    """Fairlead displacement along y (m) and its rate (m/s) at time t (scalar)."""
    if t <= 0:
        return 0.0, 0.0
    if t < RAMP:
        w = math.sin(0.5 * math.pi * t / RAMP) ** 2
        dw = 0.5 * math.pi / RAMP * math.sin(math.pi * t / RAMP)
    else:
        w, dw = 1.0, 0.0
    om = 2 * math.pi / PERIOD
    return AMP * w * math.sin(om * t), AMP * (dw * math.sin(om * t) + w * om * math.cos(om * t))


def _cpu_children():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


# ------------------------------------------------------------------ xcable
def x_tag(n, dt):
    return f"x_n{n}_dt{dt:g}"


def xcable_namelist(n, dt, t_end, h5, interval):
    return (f"&cable length = {fs.LENGTH}, diameter = {fs.DIAM}, density = {fs.RHO_C}, gravity = {fs.G} /\n"
            f"&material law = 'linear', ea = {fs.EA:.15g}, compression = 'law' /\n"
            f"&fluid density = {fs.RHO_F}, cd_normal = {fs.CDN}, cd_tangential = {fs.CDT}, "
            f"ca_normal = {fs.CAN}, current_y = {U}, surface_z = {-Z0:.15g} /\n"
            f"&end_a kind = 'fixed', x = 0, z = 0 /\n"
            f"&end_b kind = 'motion', x = {XB}, z = {ZB}, motion = 'harmonic', amplitude = {AMP}, "
            f"period = {PERIOD}, ramp_time = {RAMP}, direction_x = 0, direction_y = 1, direction_z = 0 /\n"
            f"&rupture enabled = .false. /\n"
            f"&numerics model = '3d', nodes = {n}, dt = {dt:.12g}, t_end = {t_end:.12g} /\n"
            f"&output file = '{h5}', interval = {interval:.12g}, quiet = .true., energy = .true., "
            f"fields = 'x z tension' /\n")


def xcable_run(n, dt, work, t_end=T_END):
    import h5py
    tag = x_tag(n, dt)
    nml, h5 = os.path.join(work, tag + ".nml"), os.path.join(work, tag + ".h5")
    with open(nml, "w") as f:
        f.write(xcable_namelist(n, dt, t_end, h5, SAMPLE))
    c0, w0 = _cpu_children(), time.time()
    p = subprocess.run([XCABLE, nml], capture_output=True, text=True)
    wall, cpu = time.time() - w0, _cpu_children() - c0
    if p.returncode != 0:
        sys.exit(f"xcable failed on {nml} (exit {p.returncode}): {p.stderr.strip()}")
    with h5py.File(h5, "r") as f:
        status = fs._text(f.attrs["status"])
        tsnap = f["time"][:]
        mid = (n - 1) // 2
        x, y, z = f["x"][:, mid], f["y"][:, mid], f["z"][:, mid]
        yb = f["y"][:, -1]
        ten = f["tension"][:]
        h = f["history"]
        th, tb = h["time"][:], h["end_b/tension"][:]
        summ = dict(f["summary"].attrs)
    ts = np.round(np.arange(0.0, t_end + 1e-9, SAMPLE), 10)
    if len(tsnap) != len(ts) or np.abs(tsnap - ts).max() > 1e-9:
        sys.exit(f"xcable {tag}: snapshot times are not every {SAMPLE} s")
    rows = np.column_stack([ts, np.interp(ts, th, tb), x, y, z, yb])
    info = {"code": "xcable", "N": n, "dt": dt, "u": U, "status": status, "wall_s": wall, "cpu_s": cpu,
            "energy_drift": float(summ.get("energy_drift", -1)),
            "min_tension": float(ten.min()), "max_tension": float(ten.max()),
            "static_tension_b": float(tb[0]), "static_mid": [float(x[0]), float(y[0]), float(z[0])],
            "warnings": fs._text(summ.get("warnings", ""))}
    os.remove(h5)
    return rows, info


def x_static(work, n=X_STATIC_N):
    """xcable's static state on n nodes: s and (x, y, z) per node."""
    import h5py
    h5 = os.path.join(work, f"static_n{n}.h5")
    nml = h5[:-3] + ".nml"
    with open(nml, "w") as f:
        f.write(xcable_namelist(n, 0.01, 0.01, h5, 0.0))
    p = subprocess.run([XCABLE, nml], capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"xcable statics failed on {nml}: {p.stderr.strip()}")
    with h5py.File(h5, "r") as f:
        return f["s"][:], np.column_stack([f["x"][0], f["y"][0], f["z"][0]])


# ------------------------------------------------------------------ MoorDyn
def md_tag(n, c):
    return f"md_n{n}_c{c:g}" + ("" if MD_CD_SCALE == 1 else f"_cd{MD_CD_SCALE:g}")


def md_write_input(path, n, dtm, ba=0.0, cd_factor=1.0):
    txt = f"""MoorDyn v2 input: xcable 3-D peer (bench/peer/sway3d.py)
---------------------- LINE TYPES -----------------------------------
TypeName   Diam    Mass/m     EA      BA/-zeta     EI    Cd     Ca    CdAx    CaAx
(name)     (m)     (kg/m)     (N)     (N-s/-)    (N-m^2) (-)   (-)   (-)     (-)
rope  {fs.DIAM:.12g}  {fs.MASS:.15g}  {fs.EA:.15g}  {ba!r}  {fs.EI:.15g}  {fs.CDN * MD_CD_SCALE * cd_factor!r}  {fs.CAN}  {fs.CDT * MD_CD_SCALE * cd_factor!r}  {fs.CAT}
---------------------------- POINTS -------------------------------------------
ID  Attachment  X       Y     Z      Mass   Volume  CdA    CA
(#)   (-)       (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
1     Fixed     0.0     0.0   {Z0:.15g}    0.0    0.0     0.0    0.0
2     Coupled   {XB:.15g}  0.0   {Z0 + ZB:.15g}    0.0    0.0     0.0    0.0
---------------------- LINES ----------------------------------------
ID   LineType AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)  (name)   (#)      (#)      (m)       (-)      (-)
1    rope     1        2       {fs.LENGTH:.12g}      {n}      -
---------------------- OPTIONS -----------------------------------------
0        writeLog
{dtm!r}  dtM
RK4      tScheme
{fs.G}     g
{fs.RHO_F}     rho
1000     WtrDpth
1        Currents
1        disableOutput
1        disableOutTime
---------------------- OUTPUTS -----------------------------------------
------------------------- need this line -------------------------------------
"""
    with open(path, "w") as f:
        f.write(txt)
    # steady uniform current along y (MoorDyn's "Currents 1": a table of depth and ux, uy, uz)
    with open(os.path.join(os.path.dirname(path), "current_profile.txt"), "w") as f:
        f.write("--------------------- MoorDyn steady currents File ----------------------------------\n")
        f.write("Tabulated file with the water currents components\n")
        f.write("z (m), ux (m/s), uy (m/s), uz (m/s)\n")
        f.write("\n".join("%g 0.0 %.12g 0.0" % (z, U) for z in (-1000.0, -500.0, -100.0, 0.0)))


def md_run(n, courant, work, static, t_end=T_END):
    import moordyn
    from scipy.interpolate import CubicSpline
    wd = os.path.join(work, md_tag(n, courant))
    os.makedirs(wd, exist_ok=True)
    ds = fs.LENGTH / n
    h = courant * ds / math.sqrt(fs.EA / fs.MASS)
    k = int(math.ceil(SAMPLE / h - 1e-9))      # steps per sample
    h = SAMPLE / k
    s_x, r_x = static
    r0 = CubicSpline(s_x, r_x, axis=0)(np.linspace(0.0, fs.LENGTH, n + 1))
    r0[0], r0[-1] = [0.0, 0.0, 0.0], [XB, 0.0, ZB]
    r0[:, 2] += Z0
    pc.moordyn_state(os.path.join(wd, "start.state"), r0[1:-1], [(*r0[0], 0.0, 0.0, 0.0), (*r0[-1], 0.0, 0.0, 0.0)])

    def system(name, ba, state, cd_factor=1.0):
        inp = os.path.join(wd, name)
        md_write_input(inp, n, h, ba, cd_factor)
        cwd = os.getcwd()
        os.chdir(wd)              # MoorDyn reads current_profile.txt beside the input
        saved = os.dup(1)
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, 1)
        try:
            sysm = moordyn.Create(inp)
            moordyn.SetVerbosity(sysm, moordyn.LEVEL_ERR)
            moordyn.Init_NoIC(sysm, [XB, 0.0, Z0 + ZB], [0.0, 0.0, 0.0])
            moordyn.LoadState(sysm, state)
        finally:
            os.dup2(saved, 1)
            os.close(devnull)
            os.close(saved)
            os.chdir(cwd)
        return sysm

    mid = n // 2
    min_t = [math.inf]

    def sample(sysm, t):
        line = moordyn.GetLine(sysm, 1)
        p = np.array([moordyn.GetLineNodePos(line, i) for i in range(n + 1)])
        seg = fs.EA * np.maximum(np.linalg.norm(np.diff(p, axis=0), axis=1) / ds - 1, 0.0)
        min_t[0] = min(min_t[0], float(seg.min()))
        pm = p[mid]
        return (t, 1.5 * seg[-1] - 0.5 * seg[-2], pm[0], pm[1], pm[2] - Z0, p[-1, 1])

    xb = [XB, 0.0, Z0 + ZB]
    c0, w0 = time.process_time(), time.time()
    # settling with the fairlead held, in a copy of the line with critical axial
    # damping (BA = -1: a damping ratio of 1 for each segment's axial mode), which
    # does not change the static state but quenches the axial ringing that the
    # start from xcable's statics excites; its end state is MoorDyn's own static
    # state in the current, saved and loaded into the undamped line. In still
    # water (--u 0) the drag is quadratic in a small velocity and would leave the
    # slow in-plane swing ringing for minutes, so the copy also has its drag
    # coefficients SETTLE_CD_STILL times larger (at rest the drag is zero, so the
    # static state is the same; MoorDyn's own initial-condition solver raises the
    # drag in the same way).
    sysm = system("settle.txt", -1.0, os.path.join(wd, "start.state"),
                  1.0 if U != 0 else SETTLE_CD_STILL)
    t = -T_SETTLE
    hist = []
    for j in range(int(round(T_SETTLE / SAMPLE))):
        for _ in range(k):
            moordyn.Step(sysm, xb, [0.0, 0.0, 0.0], t, h)
            t += h
        hist.append(sample(sysm, t))
    moordyn.SaveState(sysm, os.path.join(wd, "settled.state"))
    moordyn.Close(sysm)
    hist = np.array(hist)
    last10 = hist[-int(round(10.0 / SAMPLE)):]
    settle = {"mid_moved_from_xcable_static_m": float(np.linalg.norm(hist[-1, 2:5] - (r0[mid] - [0, 0, Z0]))),
              "mid_range_last_10s_m": float(np.linalg.norm(last10[:, 2:5].max(0) - last10[:, 2:5].min(0))),
              "tension_b_range_last_10s_N": float(np.ptp(last10[:, 1]))}
    sysm = system("sway.txt", 0.0, os.path.join(wd, "settled.state"))
    min_t[0] = math.inf
    rows = [(0.0,) + tuple(hist[-1, 1:])]
    nsamp = int(round(t_end / SAMPLE))
    for i in range(nsamp):
        for j in range(k):
            t0 = i * SAMPLE + j * h
            y0, _ = motion_y(t0)
            y1, _ = motion_y(t0 + h)
            moordyn.Step(sysm, [XB, y0, Z0 + ZB], [0.0, (y1 - y0) / h, 0.0], t0, h)
        rows.append(sample(sysm, (i + 1) * SAMPLE))
    cpu, wall = time.process_time() - c0, time.time() - w0
    moordyn.Close(sysm)
    rows = np.array(rows)
    info = {"code": "MoorDyn " + fs.md_version(), "N": n, "courant": courant, "dtM": h, "u": U,
            "cd_scale": MD_CD_SCALE,
            "cpu_s": cpu, "wall_s": wall, "min_tension": min_t[0], "settle": settle,
            "static_tension_b": float(rows[0, 1]), "static_mid": [float(v) for v in rows[0, 2:5]]}
    return rows, info


# ------------------------------------------------------------------ files
def write_run(work, tag, rows, info):
    with open(os.path.join(work, tag + ".tsv"), "w") as f:
        f.write("\t".join(COLS) + "\n")
        for r in rows:
            f.write("\t".join("%.10g" % v for v in r) + "\n")
    with open(os.path.join(work, tag + ".json"), "w") as f:
        json.dump(info, f, indent=1)


def read_run(work, tag):
    rows = np.loadtxt(os.path.join(work, tag + ".tsv"), skiprows=1)
    with open(os.path.join(work, tag + ".json")) as f:
        return rows, json.load(f)


def run(argv):
    global U, MD_CD_SCALE
    ap = argparse.ArgumentParser(prog="sway3d.py run")
    ap.add_argument("--xn", type=int, nargs="*", default=[61, 121, 241])
    ap.add_argument("--xdt", type=float, nargs="*", default=[0.02, 0.01, 0.005])
    ap.add_argument("--mn", type=int, nargs="*", default=[60, 120, 240])
    ap.add_argument("--courant", type=float, nargs="*", default=[0.5])
    ap.add_argument("--work", default=WORK)
    ap.add_argument("--skip-x", action="store_true")
    ap.add_argument("--skip-md", action="store_true")
    ap.add_argument("--force", action="store_true")
    ap.add_argument("--u", type=float, default=U, help="current along y (m/s); 0.25 is the scene")
    ap.add_argument("--md-cd-scale", type=float, default=1.0,
                    help="diagnostic: MoorDyn's Cdn and Cdt times this (e.g. sqrt(1 + mean strain))")
    a = ap.parse_args(argv)
    U, MD_CD_SCALE = a.u, a.md_cd_scale
    os.makedirs(a.work, exist_ok=True)
    todo = []
    if not a.skip_x:
        todo += [("x", n, d, x_tag(n, d)) for n in a.xn for d in a.xdt]
    if not a.skip_md:
        todo += [("md", n, c, md_tag(n, c)) for n in a.mn for c in a.courant]
    static = None
    for kind, n, p, tag in todo:
        if not a.force and os.path.exists(os.path.join(a.work, tag + ".json")):
            continue
        if kind == "x":
            rows, info = xcable_run(n, p, a.work)
        else:
            if static is None:
                static = x_static(a.work)
            rows, info = md_run(n, p, a.work, static)
        write_run(a.work, tag, rows, info)
        print("%-16s wall %6.1f s  cpu %6.1f s  T_b(0) %.3f N  y_mid(0) %.4f m  min T %.1f N" % (
            tag, info["wall_s"], info["cpu_s"], rows[0, 1], rows[0, 3], info["min_tension"]),
            (" settle " + json.dumps(info["settle"])) if "settle" in info else "", file=sys.stderr)


# ------------------------------------------------------------------ summary
def diff(a, b):
    """max and RMS of a - b over the common samples: T_b (N), y_mid and |r_mid| (m)."""
    m = min(len(a), len(b))
    dT = a[:m, 1] - b[:m, 1]
    dy = a[:m, 3] - b[:m, 3]
    dr = np.linalg.norm(a[:m, 2:5] - b[:m, 2:5], axis=1)
    rms = lambda v: float(np.sqrt(np.mean(v * v)))
    return {"dT_max": float(np.abs(dT).max()), "dT_rms": rms(dT), "dy_max": float(np.abs(dy).max()),
            "dy_rms": rms(dy), "dr_max": float(dr.max())}


def find(work):
    """xcable runs {(N, dt): tag}, MoorDyn runs {(N, courant): tag} and the
    Cd-scaled MoorDyn runs {(N, courant, scale): tag} in work."""
    xr, mr, cr = {}, {}, {}
    for name in os.listdir(work):
        if not name.endswith(".json") or name.startswith("static"):
            continue
        tag = name[:-5]
        if tag.startswith("x_n"):
            n, d = tag[3:].split("_dt")
            xr[(int(n), float(d))] = tag
        elif tag.startswith("md_n"):
            parts = tag[4:].split("_")
            n, c = int(parts[0]), float(parts[1][1:])
            if len(parts) == 2:
                mr[(n, c)] = tag
            else:
                cr[(n, c, float(parts[2][2:]))] = tag
    return xr, mr, cr


def summarize(argv):
    ap = argparse.ArgumentParser(prog="sway3d.py summarize")
    ap.add_argument("--work", default=WORK)
    ap.add_argument("--out", default=HERE)
    ap.add_argument("--name", default="sway3d", help="stem of the data files and the figure")
    ap.add_argument("--no-figure", action="store_true")
    a = ap.parse_args(argv)
    xr, mr, cr = find(a.work)
    if not xr or not mr:
        sys.exit("summarize: no runs of both codes in " + a.work)
    xk = max(xr, key=lambda k: (k[0], -k[1]))
    mk = max(mr, key=lambda k: (k[0], -k[1]))
    X, xi = read_run(a.work, xr[xk])
    M, mi = read_run(a.work, mr[mk])
    u = xi.get("u", U)
    print("Current %g m/s. Fairlead tension T_b: xcable %.1f to %.1f N, MoorDyn %.1f to %.1f N; "
          "y_mid %.3f to %.3f m\n" % (u, X[:, 1].min(), X[:, 1].max(), M[:, 1].min(), M[:, 1].max(),
                                     X[:, 3].min(), X[:, 3].max()))
    conv = []
    print("xcable, against %d nodes, dt = %g s: max |dT_b| (N) / max |dy_mid| (mm) / max |dr_mid| (mm); wall (s)\n" % xk)
    dts = sorted({k[1] for k in xr}, reverse=True)
    print("| nodes | " + " | ".join("dt = %g s" % d for d in dts) + " |")
    print("|---|" + "---|" * len(dts))
    for n in sorted({k[0] for k in xr}):
        cells = []
        for d in dts:
            if (n, d) not in xr:
                cells.append("")
                continue
            R, ri = read_run(a.work, xr[(n, d)])
            st = diff(R, X)
            conv.append(("xcable", n, d, st, ri))
            cells.append("reference; %.0f s" % ri["wall_s"] if (n, d) == xk else
                         "%.3f / %.3f / %.3f; %.0f s" % (st["dT_max"], 1e3 * st["dy_max"], 1e3 * st["dr_max"], ri["wall_s"]))
        print("| %d | " % n + " | ".join(cells) + " |")
    print("\nMoorDyn, against %d segments, Courant %g\n" % mk)
    print("| segments | Courant | dtM (ms) | max / RMS \\|dT_b\\| (N) | max / RMS \\|dy_mid\\| (mm) | max \\|dr_mid\\| (mm) | wall (s) |")
    print("|---|---|---|---|---|---|---|")
    for k in sorted(mr):
        R, ri = read_run(a.work, mr[k])
        st = diff(R, M)
        conv.append(("MoorDyn", k[0], ri["dtM"], st, ri))
        print("| %d | %g | %.3f | %.3f / %.3f | %.3f / %.3f | %.3f | %.0f |" % (
            k[0], k[1], 1e3 * ri["dtM"], st["dT_max"], st["dT_rms"], 1e3 * st["dy_max"], 1e3 * st["dy_rms"],
            1e3 * st["dr_max"], ri["wall_s"]))
    # each code's finest step at each grid
    xbest = {n: min(d for m, d in xr if m == n) for n, _ in xr}
    mbest = {n: min(c for m, c in mr if m == n) for n, _ in mr}
    print("\nStatic state (t = 0): fairlead tension, middle node; smallest tension anywhere over the run\n")
    print("| code | N | T_b (N) | mid x (m) | mid y (m) | mid z (m) | min tension (N) |")
    print("|---|---|---|---|---|---|---|")
    for lab, rr, best in (("xcable", xr, xbest), ("MoorDyn", mr, mbest), ("MoorDyn Cd scaled", cr, None)):
        for k in sorted(rr):
            if best is not None and best[k[0]] != k[1]:
                continue
            R, ri = read_run(a.work, rr[k])
            print("| %s | %d | %.4f | %.5f | %.5f | %.5f | %.1f |" % (lab, k[0], R[0, 1], R[0, 2], R[0, 3], R[0, 4],
                                                                     ri["min_tension"]))
    for k in sorted(mr) + sorted(cr):
        ri = read_run(a.work, (mr if k in mr else cr)[k])[1]
        print("MoorDyn %s settling:" % (k,), json.dumps(ri["settle"]))
    print("\nxcable - MoorDyn over 0-%g s, every %g s\n" % (T_END, SAMPLE))
    print("| xcable | MoorDyn | max / RMS \\|dT_b\\| (N) | max / RMS \\|dy_mid\\| (mm) | max \\|dr_mid\\| (mm) |")
    print("|---|---|---|---|---|")
    pairs = [(xk, mk, mr)]
    for n in sorted(mbest):
        if (n + 1) in xbest and ((n + 1, xbest[n + 1]), (n, mbest[n])) != (xk, mk):
            pairs.append(((n + 1, xbest[n + 1]), (n, mbest[n]), mr))
    for k in sorted(cr):
        pairs.append((xk, k, cr))
    agree = []
    C = None
    for p, q, src in pairs:
        R = read_run(a.work, src[q])[0]
        if len(q) == 3:
            C, ck = R, q
        st = diff(read_run(a.work, xr[p])[0], R)
        agree.append((p, q, st))
        print("| %d nodes, dt %g s | %d segments, C %g%s | %.3f / %.3f | %.3f / %.3f | %.3f |" % (
            p + q[:2] + ((", Cd x %g" % q[2]) if len(q) == 3 else "",
                         st["dT_max"], st["dT_rms"], 1e3 * st["dy_max"], 1e3 * st["dy_rms"], 1e3 * st["dr_max"])))
    # Richardson: second order in the grid, from each code's two finest grids at its finest step
    ext = {}
    for lab, rr, best in (("xcable", xr, xbest), ("MoorDyn", mr, mbest)):
        ns = sorted(best)
        if len(ns) >= 2:
            fine = read_run(a.work, rr[(ns[-1], best[ns[-1]])])[0]
            coarse = read_run(a.work, rr[(ns[-2], best[ns[-2]])])[0]
            ext[lab] = (fine + (fine - coarse) / 3, "%d+%d" % (ns[-2], ns[-1]))
    for n, c in zip(sorted(cr)[:-1], sorted(cr)[1:]):
        if n[1:] == c[1:] and n[0] < c[0]:
            fine, coarse = read_run(a.work, cr[c])[0], read_run(a.work, cr[n])[0]
            ext["MoorDyn, Cd x %g" % c[2]] = (fine + (fine - coarse) / 3, "%d+%d" % (n[0], c[0]))
    if "xcable" in ext:
        XE = ext["xcable"][0]
        for lab in [k for k in ext if k != "xcable"]:
            st = diff(XE, ext[lab][0])
            agree.append((("Richardson", ext["xcable"][1]), (lab, ext[lab][1]), st))
            print("| Richardson %s nodes | Richardson %s segments, %s | %.3f / %.3f | %.3f / %.3f | %.3f |" % (
                ext["xcable"][1], ext[lab][1], lab, st["dT_max"], st["dT_rms"], 1e3 * st["dy_max"],
                1e3 * st["dy_rms"], 1e3 * st["dr_max"]))
        print("\nStatic state, Richardson: " + "; ".join(
            "%s T_b %.4f N, mid (%.5f, %.5f, %.5f) m" % ((k,) + tuple(v[0][0, 1:5])) for k, v in ext.items()))
    print("\nFinest runs at a few times\n")
    print("| t (s) | y_b (m) | T_b xcable (N) | T_b MoorDyn (N) | y_mid xcable (m) | y_mid MoorDyn (m) | z_mid xcable (m) | z_mid MoorDyn (m) |")
    print("|---|---|---|---|---|---|---|---|")
    for t in (0, 5, 10, 15, 20, 25, 30, 35, 40, 45):
        i = int(round(t / SAMPLE))
        print("| %g | %.4f | %.3f | %.3f | %.4f | %.4f | %.4f | %.4f |" % (
            t, X[i, 5], X[i, 1], M[i, 1], X[i, 3], M[i, 3], X[i, 4], M[i, 4]))
    os.makedirs(os.path.join(a.out, "data"), exist_ok=True)
    step = int(round(0.1 / SAMPLE))
    with open(os.path.join(a.out, "data", a.name + ".tsv"), "w") as f:
        f.write("# bench/peer/sway3d.py, current %g m/s: fairlead tension (N) and middle node (m) every 0.1 s;"
                " xcable %d nodes dt %g s; MoorDyn %d segments Courant %g\n" % ((u,) + xk + mk))
        f.write("t\ty_b\txcable_T_b\txcable_mid_x\txcable_mid_y\txcable_mid_z"
                "\tmoordyn_T_b\tmoordyn_mid_x\tmoordyn_mid_y\tmoordyn_mid_z\n")
        for i in range(0, min(len(X), len(M)), step):
            r = [X[i, 0], X[i, 5]] + list(X[i, 1:5]) + list(M[i, 1:5])
            f.write("\t".join("%.8g" % v for v in r) + "\n")
    with open(os.path.join(a.out, "data", a.name + "_convergence.tsv"), "w") as f:
        f.write("# bench/peer/sway3d.py, current %g m/s: each run against its own code's finest run, then the codes"
                " against each other, over 0-%g s\n" % (u, T_END))
        f.write("code\tN\tdt_s\tdT_max_N\tdT_rms_N\tdy_max_m\tdy_rms_m\tdr_max_m\twall_s\tcpu_s\n")
        for code, n, d, st, ri in conv:
            f.write("%s\t%d\t%.6g\t%.4f\t%.4f\t%.3e\t%.3e\t%.3e\t%.1f\t%.1f\n" % (
                code, n, d, st["dT_max"], st["dT_rms"], st["dy_max"], st["dy_rms"], st["dr_max"],
                ri["wall_s"], ri["cpu_s"]))
        for p, q, st in agree:
            f.write("xcable %s - MoorDyn %s\t\t\t%.4f\t%.4f\t%.3e\t%.3e\t%.3e\t\t\n" % (
                p, q, st["dT_max"], st["dT_rms"], st["dy_max"], st["dy_rms"], st["dr_max"]))
    if not a.no_figure:
        plot(X, M, C, xk, mk, u, os.path.join(a.out, a.name + ".png"))


def plot(X, M, C, xk, mk, u, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    m = min(len(X), len(M))
    t = X[:m, 0]
    fig, ax = plt.subplots(4, 1, figsize=(7.5, 9), sharex=True)
    lx = "xcable (%d nodes, dt %g s)" % xk
    lm = "MoorDyn (%d segments)" % mk[0]
    ax[0].plot(t, X[:m, 5], "0.5", lw=1, label="fairlead y_b")
    ax[0].plot(t, X[:m, 3], "b-", lw=1.6, label=lx)
    ax[0].plot(t, M[:m, 3], "r--", lw=1.2, label=lm)
    ax[0].set_ylabel("y (m)")
    ax[0].legend(fontsize=7, loc="lower left")
    ax[0].set_title("middle node (s = 30 m), out of plane", fontsize=8)
    ax[1].plot(t, 1e3 * (X[:m, 3] - M[:m, 3]), "k-", lw=1, label="y_mid")
    ax[1].plot(t, 1e3 * (X[:m, 2] - M[:m, 2]), "g-", lw=0.8, label="x_mid")
    ax[1].plot(t, 1e3 * (X[:m, 4] - M[:m, 4]), "m-", lw=0.8, label="z_mid")
    if C is not None:
        ax[1].plot(t, 1e3 * (X[:m, 3] - C[:m, 3]), "k:", lw=1, label="y_mid, MoorDyn's Cd scaled")
    ax[1].set_ylabel("xcable - MoorDyn (mm)")
    ax[1].legend(fontsize=7)
    ax[2].plot(t, X[:m, 1], "b-", lw=1.4, label="xcable")
    ax[2].plot(t, M[:m, 1], "r--", lw=1.0, label="MoorDyn")
    ax[2].set_ylabel("fairlead tension (N)")
    ax[2].legend(fontsize=7)
    ax[3].plot(t, X[:m, 1] - M[:m, 1], "k-", lw=0.8, label="against MoorDyn")
    if C is not None:
        ax[3].plot(t, X[:m, 1] - C[:m, 1], "k:", lw=1, label="against MoorDyn with Cd scaled")
        ax[3].legend(fontsize=7)
    ax[3].set_ylabel("T_b: xcable - MoorDyn (N)")
    ax[3].set_xlabel("t (s)")
    for a_ in ax:
        a_.grid(alpha=0.3)
        a_.axvline(RAMP, color="0.6", lw=0.8)
    fig.suptitle("60 m line in a %g m/s cross current, fairlead moved 2 m across the plane (period 15 s)" % u,
                 fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=90)


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if argv and argv[0] == "summarize":
        return summarize(argv[1:])
    if argv and argv[0] == "run":
        return run(argv[1:])
    sys.exit(__doc__)


if __name__ == "__main__":
    main()
