#!/usr/bin/env python3
"""Long-duration heave: xcable against MoorDyn v2 in work-precision (issue 16).

bench/peer, not part of `make test`. Results and discussion: heave.md (this directory).

Scene. The line and the fluid of fluid_swing.py's pendulum: the paper's cable
(L = 60 m, d = 0.05 m, rho_c = 1140 kg/m^3) with the linear law EA = 451.6 kN and
no compression, a 500 kg point mass at end b (weight only), hanging from end a
in sea water (rho_f 1025, Cdn 1.2, Cdt 0.008, Can 1, Cat 0). End a, the
fairlead, moves harmonically along the direction (0.6, 0.8) (mostly heave, some
surge), amplitude A = 2 m, period T = 10 s, brought in over RAMP = 20 s:
    X(t) = A w(t) sin(2 pi t / T) (0.6, 0.8),  w = sin^2(pi t / (2 RAMP)) until RAMP, then 1
(xcable's `motion = 'harmonic'` with `ramp_time`). The line stays in tension
(4.5 to 5.5 kN at the fairlead), so the two codes' laws agree (neither pushes);
the mass swings as a pendulum through the water, damped by the line's drag.
Run to t_end (600 s, 60 periods). Stiff variant (--ea-scale 25): EA of both codes
25 times larger (axial wave speed 2245 m/s instead of 449 m/s), all else equal.

Compared: the tension at end a (xcable: /history/end_a/tension; MoorDyn:
1.5 T_0 - 0.5 T_1 from its first two segments, as in fluid_swing.py) and end b's
position, over the last WINDOW = 100 s, every SAMPLE = 0.05 s. Error of a run =
max over that window of |T_a - T_a,ref| (N) and of |r_b - r_b,ref| (m), the
reference being the code's own finest run (and, for the cross-code floor,
the other code's).

xcable: a namelist run of the executable (XCABLE, default bin/xcable of this
tree); CPU time of the child process (getrusage), whole process: start-up,
statics, stepping and the HDF5 history. MoorDyn (PyPI `moordyn` 2.7.2, RK4):
point 1 Coupled, point 2 Free (mass M), N segments, started from its exact
vertical hang (a state file, as fluid_swing.py); the script calls
moordyn.Step once per dtM (MoorDyn moves the coupled point from the given
position at the given velocity: the script passes the fairlead's exact
position at the start of the step and the chord to its end). CPU time
(process_time) of the stepping loop only; the Python overhead of the calls is
measured apart (a run with 2 segments) and quoted. Stability limit: for each N
the largest dtM = SAMPLE / k stable over the whole run (k raised by about 5 %
from Courant 1.6, then refined by 1): a run is stable when it stays finite and
within 1000 N of 5 kN at the fairlead at every sample (the reference stays
within 470 N; a run past the limit either stops on a NaN or rings at the grid
scale, bounded only because a segment cannot push).

Usage:
  python3 heave.py x N DT [N DT ...]      xcable runs (writes WORK/x_nN_dtDT.tsv/.json)
  python3 heave.py md N K [N K ...]       MoorDyn runs with dtM = SAMPLE/K
  python3 heave.py limit N [N ...]        MoorDyn: search the stability limit
  python3 heave.py time [--reps 3] [--x N:DT ...] [--md N:K ...]
                                          interleaved repeated timings (WORK/timing.tsv)
  python3 heave.py summarize [--xref N:DT] [--mref N:K] [--name heave]
                                          tables on stdout; data/heave_*.tsv, heave.png
Options: --work DIR (default /tmp/heave_runs), --t-end S (default 600), --ea-scale F
(both codes' EA times F: the stiff variant of heave.md is --ea-scale 25, in its own
--work, summarized with --name heave_stiff).
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
import fluid_swing as fs  # noqa: E402  (the line, the fluid, MoorDyn's input and state files)
import peer_common as pc  # noqa: E402  (the MoorDyn state file)

XCABLE = os.environ.get("XCABLE", os.path.join(HERE, "..", "..", "bin", "xcable"))
AMP, PERIOD, RAMP = 2.0, 10.0, 20.0
DIR = (0.6, 0.8)
T_END = 600.0
WINDOW = 100.0
SAMPLE = 0.05
WORK = "/tmp/heave_runs"
T_MEAN = 5000.0     # N, about the mean fairlead tension (the reference stays within 470 N of it)


def motion(t):
    """Fairlead displacement (x, z) and velocity (u, w) at time t (scalar)."""
    if t < RAMP:
        w = math.sin(0.5 * math.pi * t / RAMP) ** 2
        dw = 0.5 * math.pi / RAMP * math.sin(math.pi * t / RAMP)
    else:
        w, dw = 1.0, 0.0
    om = 2 * math.pi / PERIOD
    s = AMP * w * math.sin(om * t)
    ds = AMP * (dw * math.sin(om * t) + w * om * math.cos(om * t))
    return s * DIR[0], s * DIR[1], ds * DIR[0], ds * DIR[1]


# ------------------------------------------------------------------ xcable
def x_tag(n, dt):
    return f"x_n{n}_dt{dt:g}"


def xcable_run(n, dt, work, t_end):
    tag = x_tag(n, dt)
    nml, h5 = os.path.join(work, tag + ".nml"), os.path.join(work, tag + ".h5")
    # 'none' blends the law to zero for |eps| < 1e-3 (docs/theory/compression.md); a stiffer
    # line (--ea-scale) strains less than that, so it keeps the law (it stays in tension)
    comp = "none" if fs.EA_SCALE == 1 else "law"
    txt = (f"&cable length = {fs.LENGTH}, diameter = {fs.DIAM}, density = {fs.RHO_C}, gravity = {fs.G} /\n"
           f"&material law = 'linear', ea = {fs.EA * fs.EA_SCALE:.15g}, compression = '{comp}' /\n"
           f"&fluid density = {fs.RHO_F}, cd_normal = {fs.CDN}, cd_tangential = {fs.CDT}, "
           f"ca_normal = {fs.CAN}, surface_z = {-fs.Z0:.15g} /\n"
           f"&end_a kind = 'motion', x = 0, z = 0, motion = 'harmonic', amplitude = {AMP}, "
           f"period = {PERIOD}, direction_x = {DIR[0]}, direction_z = {DIR[1]}, ramp_time = {RAMP} /\n"
           f"&end_b kind = 'mass', mass = {fs.M_END} /\n"
           f"&rupture enabled = .false. /\n"
           f"&numerics nodes = {n}, dt = {dt:.12g}, t_end = {t_end:.12g} /\n"
           f"&output file = '{h5}', interval = {t_end:.12g}, quiet = .true., fields = 'x z tension' /\n")
    with open(nml, "w") as f:
        f.write(txt)
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    w0 = time.time()
    p = subprocess.run([XCABLE, nml], capture_output=True, text=True)
    wall = time.time() - w0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    import h5py
    with h5py.File(h5, "r") as f:
        status = fs._text(f.attrs["status"])
        h = f["history"]
        t = h["time"][:]
        cols = [h["end_b/x"][:], h["end_b/z"][:], h["end_a/tension"][:], h["end_a/x"][:], h["end_a/z"][:]]
        warn = fs._text(dict(f["summary"].attrs).get("warnings", ""))
    ts = np.arange(0.0, t[-1] + 1e-9, SAMPLE)
    rows = np.column_stack([ts] + [np.interp(ts, t, a) for a in cols])
    info = {"code": "xcable", "N": n, "dt": dt, "status": status, "rc": p.returncode,
            "stderr": p.stderr.strip()[-300:], "warnings": warn, "cpu_s": cpu, "wall_s": wall,
            "t_end": float(t[-1])}
    os.remove(h5)
    return rows, info


# ------------------------------------------------------------------ MoorDyn
def md_tag(n, k):
    return f"md_n{n}_k{k}"


def md_run(n, k, work, t_end, bound=None):
    """MoorDyn with N segments, dtM = SAMPLE / k, one Step call per dtM. bound: stop early (unstable)
    when |T_a - T_MEAN| exceeds bound or a value is not finite."""
    import moordyn
    wd = os.path.join(work, md_tag(n, k))
    os.makedirs(wd, exist_ok=True)
    ds = fs.LENGTH / n
    h = SAMPLE / k
    r0 = fs.vertical_hang(n)
    inp = os.path.join(wd, "heave.txt")
    fs.md_write_input(inp, n, r0[-1, 1], h)
    pc.moordyn_state(os.path.join(wd, "static.state"), [(x, 0.0, z) for x, z in r0[1:-1]],
                      [[0.0, 0.0, fs.Z0, 0.0, 0.0, 0.0], [0.0, 0.0, r0[-1, 1], 0.0, 0.0, 0.0]])
    saved = os.dup(1)
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, 1)
    try:
        sysm = moordyn.Create(inp)
        moordyn.SetVerbosity(sysm, moordyn.LEVEL_ERR)
        moordyn.Init_NoIC(sysm, [0.0, 0.0, fs.Z0], [0.0, 0.0, 0.0])
        moordyn.LoadState(sysm, os.path.join(wd, "static.state"))
    finally:
        os.dup2(saved, 1)
        os.close(devnull)
        os.close(saved)
    line = moordyn.GetLine(sysm, 1)
    pt2 = moordyn.GetPoint(sysm, 2)
    ea = fs.EA * fs.EA_SCALE

    def sample(t):
        p0 = np.array(moordyn.GetLineNodePos(line, 0))
        p1 = np.array(moordyn.GetLineNodePos(line, 1))
        p2 = np.array(moordyn.GetLineNodePos(line, 2))
        pb = np.array(moordyn.GetPointPos(pt2))
        t0 = ea * max(np.linalg.norm(p1 - p0) / ds - 1, 0.0)
        t1 = ea * max(np.linalg.norm(p2 - p1) / ds - 1, 0.0)
        return (t, pb[0], pb[2] - fs.Z0, 1.5 * t0 - 0.5 * t1, p0[0], p0[2] - fs.Z0)

    # the fairlead's path at every dtM, precomputed (not timed); within a step
    # MoorDyn moves the coupled point from the given position at the given
    # velocity, so pass the start of the step and the chord to its end
    nc = int(round(t_end / h))
    path = [motion(j * h)[:2] for j in range(nc + 1)]
    rows = [sample(0.0)]
    cpu = 0.0
    stable = True
    c0 = time.process_time()
    for j in range(1, nc + 1):
        (x0, z0), (x1, z1) = path[j - 1], path[j]
        try:
            moordyn.Step(sysm, [x0, 0.0, fs.Z0 + z0], [(x1 - x0) / h, 0.0, (z1 - z0) / h], (j - 1) * h, h)
        except RuntimeError:          # MoorDyn stops on a non-finite state
            stable = False
            break
        if j % k == 0:
            cpu += time.process_time() - c0
            r = sample(j * h)
            rows.append(r)
            c0 = time.process_time()
            if bound is not None and not (all(math.isfinite(v) for v in r) and abs(r[3] - T_MEAN) < bound):
                stable = False
                break
    cpu += time.process_time() - c0
    moordyn.Close(sysm)
    info = {"code": "MoorDyn " + fs.md_version(), "N": n, "k": k, "dtM": h,
            "courant": h * math.sqrt(fs.EA * fs.EA_SCALE / fs.MASS) / ds, "cpu_s": cpu, "stable": stable,
            "t_end": rows[-1][0]}
    return np.array(rows), info


def md_overhead(work, t_end, reps=3):
    """CPU time per Step call of the Python loop and the call itself (2 segments,
    dtM = 1 ms, where MoorDyn's own work is negligible), s."""
    return float(np.median([md_run(2, 50, work, t_end)[1]["cpu_s"] for _ in range(reps)])) / (t_end / 1e-3)


# ------------------------------------------------------------------ files
def save(work, tag, rows, info):
    fs.write_tsv(os.path.join(work, tag + ".tsv"), rows)
    with open(os.path.join(work, tag + ".json"), "w") as f:
        json.dump(info, f)


def load(work, tag):
    p = os.path.join(work, tag)
    if not os.path.exists(p + ".tsv"):
        return None, None
    with open(p + ".json") as f:
        return fs.read_tsv(p + ".tsv"), json.load(f)


def err(a, b, t_end):
    """max |dT_a| (N) and max |dr_b| (m) over the last WINDOW s."""
    m = min(len(a), len(b))
    if m < len(b) or a[m - 1, 0] < t_end - 1e-6:
        return float("inf"), float("inf")
    sel = a[:m, 0] >= t_end - WINDOW - 1e-9
    d = a[:m][sel] - b[:m][sel]
    return float(np.abs(d[:, 3]).max()), float(np.hypot(d[:, 1], d[:, 2]).max())


# ------------------------------------------------------------------ commands
def cmd_x(a):
    for n, dt in zip(a.args[::2], a.args[1::2]):
        rows, info = xcable_run(int(n), float(dt), a.work, a.t_end)
        save(a.work, x_tag(int(n), float(dt)), rows, info)
        print("xcable", n, dt, "cpu %.2f s" % info["cpu_s"], info["status"], info["warnings"][:100],
              info["stderr"][:200], flush=True)


def cmd_md(a):
    for n, k in zip(a.args[::2], a.args[1::2]):
        rows, info = md_run(int(n), int(k), a.work, a.t_end, bound=1e5)
        save(a.work, md_tag(int(n), int(k)), rows, info)
        print("MoorDyn", n, k, "dtM %.4g Courant %.3f cpu %.2f s stable %s" % (
            info["dtM"], info["courant"], info["cpu_s"], info["stable"]), flush=True)


def cmd_limit(a):
    """Smallest k (largest dtM = SAMPLE/k) stable over the run, starting from
    Courant 1.6 and raising k by about 5 %, then refining by 1."""
    for n in map(int, a.args):
        ds = fs.LENGTH / n
        c = math.sqrt(fs.EA * fs.EA_SCALE / fs.MASS)
        k = max(1, int(math.ceil(SAMPLE / (1.6 * ds / c))))
        last_bad, fine = k - 1, False
        done = {}
        while True:
            rows, info = done[k] if k in done else md_run(n, k, a.work, a.t_end, bound=1000.0)
            print("limit N %d k %d dtM %.4g Courant %.3f stable %s (to %.1f s) cpu %.2f" % (
                n, k, info["dtM"], info["courant"], info["stable"], info["t_end"], info["cpu_s"]),
                flush=True)
            if info["stable"]:
                if k - 1 > last_bad:       # refine between the last unstable k and this one
                    done[k] = (rows, info)
                    k = last_bad + 1
                    fine = True
                    continue
                save(a.work, md_tag(n, k), rows, info)
                break
            last_bad = k
            k = k + 1 if fine else max(k + 1, int(math.ceil(k * 1.05)))


def cmd_time(a):
    """Interleaved repeats: each configuration once per round, a.reps rounds."""
    out = os.path.join(a.work, "timing.tsv")
    jobs = [("x", s) for s in a.x] + [("md", s) for s in a.md]
    for r in range(a.reps):
        for kind, s in jobs:
            n, v = s.split(":")
            if kind == "x":
                _, info = xcable_run(int(n), float(v), a.work, a.t_end)
            else:
                _, info = md_run(int(n), int(v), a.work, a.t_end)
            with open(out, "a") as f:
                f.write("%s\t%s\t%s\t%d\t%.4f\n" % (kind, n, v, r, info["cpu_s"]))
            print(kind, s, "round", r, "cpu %.3f" % info["cpu_s"], flush=True)
        ov = md_overhead(a.work, a.t_end, reps=1)
        with open(out, "a") as f:
            f.write("overhead\t2\t50\t%d\t%.4g\n" % (r, ov))


def timings(work):
    """{(kind, n, v): median cpu} from timing.tsv."""
    p = os.path.join(work, "timing.tsv")
    out = {}
    if os.path.exists(p):
        for line in open(p):
            kind, n, v, _, c = line.split("\t")
            out.setdefault((kind, n, v), []).append(float(c))
    return {k: float(np.median(v)) for k, v in out.items()}


def front(ladder):
    """The work-precision front of [(err, cpu)]: the runs no other run beats in both."""
    pts = sorted((x, c) for x, c in ladder if math.isfinite(x) and x > 0)
    return [p for p in pts if not any(q[0] <= p[0] and q[1] < p[1] for q in pts if q != p)]


def interp_cost(ladder, e):
    """CPU time at error e on the front of a ladder [(err, cpu)], log-log between neighbours."""
    pts = front(ladder)
    for (e1, c1), (e2, c2) in zip(pts, pts[1:]):
        if e1 <= e <= e2:
            f = (math.log(e) - math.log(e1)) / (math.log(e2) - math.log(e1))
            return math.exp(math.log(c1) + f * (math.log(c2) - math.log(c1)))
    return float("nan")


def cmd_summarize(a):
    work, t_end = a.work, a.t_end
    names = sorted(os.listdir(work))
    xs = sorted({(int(m.split("_")[1][1:]), float(m.split("_")[2][2:-4]))
                 for m in names if m.startswith("x_n") and m.endswith(".tsv")})
    mds = sorted({(int(m.split("_")[1][1:]), int(m.split("_")[2][1:-4]))
                  for m in names if m.startswith("md_n") and m.endswith(".tsv")})
    tm = timings(work)
    xref = (int(a.xref.split(":")[0]), float(a.xref.split(":")[1])) if a.xref else max(xs, key=lambda k: (k[0], -k[1]))
    mref = (int(a.mref.split(":")[0]), int(a.mref.split(":")[1])) if a.mref else max(mds, key=lambda k: (k[0], k[1]))
    X, _ = load(work, x_tag(*xref))
    M, _ = load(work, md_tag(*mref))
    sel = X[:, 0] >= t_end - WINDOW - 1e-9
    rng = float(X[sel, 3].max() - X[sel, 3].min())
    print("window %g-%g s; xcable reference %s, T_a %.1f to %.1f N (range %.1f N)" % (
        t_end - WINDOW, t_end, xref, X[sel, 3].min(), X[sel, 3].max(), rng))
    print("cross-code floor (xcable ref vs MoorDyn ref %s): dT %.3f N, dr %.5f m\n" % (
        (mref,) + err(M, X, t_end)))
    rows = []
    print("| code | configuration | step (s) | Courant | error T_a own ref (N) | error r_b own ref (mm) | "
          "error T_a / r_b vs xcable ref (N / mm) | CPU (s) |")
    print("|---|---|---|---|---|---|---|---|")
    c_ax = math.sqrt(fs.EA * fs.EA_SCALE / fs.MASS)
    for n, dt in xs:
        R, info = load(work, x_tag(n, dt))
        eT, er = err(R, X, t_end)
        cpu = tm.get(("x", str(n), "%g" % dt), info["cpu_s"])
        cour = dt * c_ax / (fs.LENGTH / (n - 1))
        rows.append(("xcable", n, dt, cour, eT, er, eT, er, cpu))
    for n, k in mds:
        R, info = load(work, md_tag(n, k))
        eT, er = err(R, M, t_end)
        xT, xr_ = err(R, X, t_end)
        cpu = tm.get(("md", str(n), str(k)), info["cpu_s"])
        rows.append(("MoorDyn", n, info["dtM"], info["courant"], eT, er, xT, xr_, cpu))
    for r in rows:
        ref = (r[0] == "xcable" and (r[1], r[2]) == xref) or (r[0] == "MoorDyn" and (r[1], r[2]) == (mref[0], SAMPLE / mref[1]))
        print("| %s | %d %s | %.4g | %.3g | %s | %s | %s | %.2f |" % (
            r[0], r[1], "nodes" if r[0] == "xcable" else "segments", r[2], r[3],
            "reference" if ref else "%.3g" % r[4], "reference" if ref else "%.3g" % (1e3 * r[5]),
            "%.2f / %.3g" % (r[6], 1e3 * r[7]), r[8]))
    ov = tm.get(("overhead", "2", "50"))
    if ov:
        print("\nMoorDyn: Python loop and call overhead %.2f us per Step call (2 segments, dtM 1 ms)" % (1e6 * ov))
        for r in rows:
            if r[0] == "MoorDyn":
                print("  N %d: %.0f calls, overhead %.2f s of %.2f s" % (r[1], t_end / r[2], ov * t_end / r[2], r[8]))
    os.makedirs(os.path.join(HERE, "data"), exist_ok=True)
    with open(os.path.join(HERE, "data", a.name + "_ladders.tsv"), "w") as f:
        f.write("# bench/peer/heave.py: error over %g-%g s against the code's own finest run "
                "(xcable %d nodes dt %g s; MoorDyn %d segments dtM %g s) and against xcable's; "
                "median CPU time\n" % ((t_end - WINDOW, t_end) + xref + (mref[0], SAMPLE / mref[1])))
        f.write("code\tN\tstep_s\tcourant\tdT_own_N\tdr_own_m\tdT_vs_xcable_N\tdr_vs_xcable_m\tcpu_s\n")
        for r in rows:
            f.write("%s\t%d\t%.6g\t%.4g\t%.4g\t%.4g\t%.4g\t%.4g\t%.4f\n" % r)
    with open(os.path.join(HERE, "data", a.name + "_reference.tsv"), "w") as f:
        f.write("# bench/peer/heave.py: last %g s every 0.25 s; xcable %d nodes dt %g s; MoorDyn %d segments dtM %g s\n"
                % ((WINDOW,) + xref + (mref[0], SAMPLE / mref[1])))
        f.write("t\txcable_x_b\txcable_z_b\txcable_T_a\tmoordyn_x_b\tmoordyn_z_b\tmoordyn_T_a\n")
        m = min(len(X), len(M))
        for i in range(0, m, 5):
            if X[i, 0] >= t_end - WINDOW - 1e-9:
                f.write("\t".join("%.7g" % v for v in [X[i, 0]] + list(X[i, 1:4]) + list(M[i, 1:4])) + "\n")
    # ratio at equal accuracy (own references), on the tension error
    for what, j, unit, f in (("T_a", 4, "N", 1.0), ("r_b", 5, "mm", 1e3)):
        xl = [(r[j], r[8]) for r in rows if r[0] == "xcable" and r[j] > 0 and math.isfinite(r[j])]
        ml = [(r[j], r[8]) for r in rows if r[0] == "MoorDyn" and r[j] > 0 and math.isfinite(r[j])]
        print("\nxcable's front (%s): " % what + ", ".join("%.3g %s %.3g s" % (f * e, unit, c) for e, c in front(xl)))
        print("CPU ratio MoorDyn / xcable at equal %s error (own references):" % what)
        for e, c in sorted(ml):
            cx, ge = interp_cost(xl, e), ""
            if cx != cx and e > front(xl)[-1][0]:     # above xcable's cheapest run: a lower bound
                cx, ge = front(xl)[-1][1], ">= "
            print("  error %.3g %s: MoorDyn %.2f s, xcable %.3g s, ratio %s%.3g" % (
                f * e, unit, c, cx, ge, c / cx if cx == cx else float("nan")))
    plot(rows, X, M, xref, mref, t_end, os.path.join(HERE, a.name + ".png"), fs.EA_SCALE)


def plot(rows, X, M, xref, mref, t_end, path, ea_scale=1.0):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for code, sty in (("xcable", "bo-"), ("MoorDyn", "rs-")):
        rr = sorted([r for r in rows if r[0] == code and r[4] > 0 and math.isfinite(r[4])], key=lambda r: r[8])
        # one curve per N for xcable (step ladder), one for MoorDyn (segment ladder at its limit)
        if code == "xcable":
            for n in sorted({r[1] for r in rr}):
                s = sorted([r for r in rr if r[1] == n], key=lambda r: r[8])
                ax[0].loglog([r[8] for r in s], [r[4] for r in s], "o-", ms=4, label="xcable %d nodes (dt ladder)" % n)
        else:
            ax[0].loglog([r[8] for r in rr], [r[4] for r in rr], sty, ms=5, label="MoorDyn at its stability limit")
            for r in rr:
                ax[0].annotate("N=%d" % r[1], (r[8], r[4]), fontsize=7)
    ax[0].set_xlabel("CPU time (s) for %g s" % t_end)
    ax[0].set_ylabel("max |T_a - T_a,ref| over the last %g s (N)" % WINDOW)
    ax[0].grid(alpha=0.3, which="both")
    ax[0].legend(fontsize=7)
    sel = X[:, 0] >= t_end - 3 * PERIOD - 1e-9
    m = min(len(X), len(M))
    selm = sel[:m]
    ax[1].plot(X[sel, 0], X[sel, 3] / 1e3, "b-", lw=1.4, label="xcable %d nodes, dt %g s" % xref)
    ax[1].plot(M[:m][selm, 0], M[:m][selm, 3] / 1e3, "r--", lw=1, label="MoorDyn %d segments" % mref[0])
    ax[1].set_xlabel("t (s)")
    ax[1].set_ylabel("tension at the fairlead (kN)")
    ax[1].legend(fontsize=7)
    ax[1].grid(alpha=0.3)
    fig.suptitle("500 kg on 60 m in sea water, fairlead moved 2 m along (0.6, 0.8), period 10 s, 600 s"
                 + ("" if ea_scale == 1 else "; EA x %g" % ea_scale), fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=90)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("cmd", choices=["x", "md", "limit", "time", "summarize"])
    ap.add_argument("args", nargs="*")
    ap.add_argument("--work", default=WORK)
    ap.add_argument("--t-end", type=float, default=T_END)
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--name", default="heave", help="summarize: data/NAME_*.tsv and NAME.png")
    ap.add_argument("--ea-scale", type=float, default=1.0,
                    help="both codes' EA times this (a stiffer line: wave speed times its square root)")
    ap.add_argument("--x", nargs="*", default=[])
    ap.add_argument("--md", nargs="*", default=[])
    ap.add_argument("--xref", help="summarize: xcable reference N:DT (default: most nodes, smallest step)")
    ap.add_argument("--mref", help="summarize: MoorDyn reference N:K (default: most segments)")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    fs.EA_SCALE = a.ea_scale
    {"x": cmd_x, "md": cmd_md, "limit": cmd_limit, "time": cmd_time, "summarize": cmd_summarize}[a.cmd](a)


if __name__ == "__main__":
    main()
