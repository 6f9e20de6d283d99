#!/usr/bin/env python3
"""Run every peer computation and fill bench/peer/runs/ and bench/peer/data/.

  python3 run_all.py                 # everything (about an hour on one core)
  python3 run_all.py --only slack_5kN_slow
  python3 run_all.py --groups lumped moordyn

Groups (each run is skipped when its JSON summary already exists in runs/,
so an interrupted run_all resumes; --force reruns):
  lumped    lumped.py, tanh law, Verlet, Courant 0.5, N = 200 ... 6400
  courant   lumped.py at N = 1600 with Courant 0.25 (time-step check)
  rk4       lumped.py with RK4 (Courant 0.8) at N = 800 for two cases
  nocomp    lumped.py with the law cut at T = 0 and with MoorDyn's table
            (N = 400), the same physics as MoorDyn
  moordyn   moordyn_run.py at N = 400 and 800
  free      t_break = 0 release at 5 kN (to 0.04 s), Courant 0.5, 0.25,
            0.1: MoorDyn with a Free point vs MoorDyn with the coupled end
            vs lumped.py (table law)
Then data/: the finest lumped run of every case (data/<case>.tsv) and the
N = 800 MoorDyn run (data/moordyn_<case>.tsv, cut where MoorDyn's results
stop being meaningful), and data/manifest.tsv.
"""

import argparse
import json
import os
import shutil
import sys
import time

import numpy as np

import peer_common as pc

HERE = os.path.dirname(os.path.abspath(__file__))
RUNS = os.path.join(HERE, "runs")
DATA = os.path.join(HERE, "data")
N_LIST = (200, 400, 800, 1600, 3200, 6400)
N_FINE = N_LIST[-1]
N_MD = (400, 800)


def log(msg):
    print(time.strftime("%H:%M:%S ") + msg, flush=True)


def done(tag, force):
    return (not force) and os.path.exists(os.path.join(RUNS, tag + ".json"))


def save(tag, rows, info):
    info["tag"] = tag
    pc.write_tsv(os.path.join(RUNS, tag + ".tsv"), rows)
    with open(os.path.join(RUNS, tag + ".json"), "w") as f:
        json.dump(info, f, indent=1)
    log("%-40s wall %7.1f s  drift %.2e" % (
        tag, info["wall_s"], info.get("ledger_drift_rel_strain0", float("nan"))))


def lumped_run(tag, case, force, **kw):
    import lumped
    if done(tag, force):
        return
    ts, tb, te, smp = pc.cases()[case]
    tb = kw.pop("t_break", tb)
    te = kw.pop("t_end", te)
    rows, info = lumped.run(ts, tb, te, smp, **kw)
    info["case"] = case
    save(tag, rows, info)


def moordyn_run(tag, case, force, **kw):
    import moordyn_run as mr
    if done(tag, force):
        return
    ts, tb, te, smp = pc.cases()[case]
    tb = kw.pop("t_break", tb)
    te = kw.pop("t_end", te)
    rows, info = mr.run(ts, tb, te, smp,
                        workdir=os.path.join(RUNS, "md_" + tag), **kw)
    info["case"] = case
    save(tag, rows, info)


def table_law(case):
    ts = pc.cases()[case][0]
    law = pc.TanhLaw()
    xs, ys = pc.moordyn_table(law, 1.3 * law.strain(ts))
    return pc.TableLaw(xs, ys)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--only", nargs="*", help="case names")
    ap.add_argument("--groups", nargs="*",
                    default=["lumped", "courant", "rk4", "nocomp", "moordyn",
                             "free"])
    ap.add_argument("--force", action="store_true")
    a = ap.parse_args()
    os.makedirs(RUNS, exist_ok=True)
    os.makedirs(DATA, exist_ok=True)
    cases = list(pc.cases())
    if a.only:
        cases = [c for c in cases if c in a.only]
    # paper runs first (cheap), then slack releases, coarse to fine
    cases.sort(key=lambda c: (c.startswith("slack"), c))
    g = set(a.groups)
    if "lumped" in g:
        for n in N_LIST:
            for c in cases:
                lumped_run("lumped_%s_N%d" % (c, n), c, a.force, n=n)
    if "courant" in g:
        for c in cases:
            lumped_run("lumped_%s_N1600_c0.25" % c, c, a.force, n=1600,
                       courant=0.25)
    if "rk4" in g:
        for c in ("fast_180kN", "slack_5kN_slow"):
            if c in cases:
                lumped_run("lumped_%s_N800_rk4" % c, c, a.force, n=800,
                           courant=0.8, integrator="rk4")
    if "nocomp" in g:
        for c in cases:
            lumped_run("nocomp_%s_N400" % c, c, a.force, n=400,
                       law=pc.NoCompressionLaw())
            lumped_run("table_%s_N400" % c, c, a.force, n=400,
                       law=table_law(c))
    if "moordyn" in g:
        for n in N_MD:
            for c in cases:
                moordyn_run("moordyn_%s_N%d" % (c, n), c, a.force, n=n)
    if "free" in g and (not a.only or "slack_5kN_slow" in a.only):
        # until 0.04 s: later the end node, released at once and with no
        # compression to hold it back, overruns its neighbour in all three
        c = "slack_5kN_slow"
        for cr in (0.5, 0.25, 0.1):
            moordyn_run("moordyn_release0_free_N400_c%g" % cr, c, a.force,
                        n=400, courant=cr, t_break=0.0, t_end=0.04, free=True)
            moordyn_run("moordyn_release0_coupled_N400_c%g" % cr, c, a.force,
                        n=400, courant=cr, t_break=0.0, t_end=0.04)
            lumped_run("table_release0_N400_c%g" % cr, c, a.force, n=400,
                       courant=cr, t_break=0.0, t_end=0.04, law=table_law(c))
    collect()


def collect():
    """Copy the reference files into data/ and write data/manifest.tsv."""
    man = []
    for c in pc.cases():
        for src, dst, note in (
                ("lumped_%s_N%d" % (c, N_FINE), c, "lumped.py tanh law"),
                ("moordyn_%s_N%d" % (c, N_MD[-1]), "moordyn_" + c,
                 "MoorDyn table law, no compression")):
            js = os.path.join(RUNS, src + ".json")
            if not os.path.exists(js):
                continue
            info = json.load(open(js))
            rows = np.genfromtxt(os.path.join(RUNS, src + ".tsv"),
                                 delimiter="\t", skip_header=1)
            tv = info.get("t_valid")
            if tv is not None:
                rows = rows[rows[:, 0] <= tv + 1e-12]
            pc.write_tsv(os.path.join(DATA, dst + ".tsv"), rows)
            man.append((dst + ".tsv", info["code"], note, info["N"],
                        "%.4g" % info["dt"], "%g" % info["tension"],
                        "%g" % info["t_break"], "%.4g" % rows[-1, 0],
                        "%.6f" % info["span"],
                        "%.3g" % (info["ledger_drift_rel_strain0"]
                                  if tv is None else
                                  info.get("ledger_drift_rel_strain0_valid",
                                           float("nan"))),
                        "%.1f" % info["wall_s"]))
    with open(os.path.join(DATA, "manifest.tsv"), "w") as f:
        f.write("file\tcode\tmodel\tN\tdt\tT_s\tt_break\tt_last\tspan\t"
                "ledger_drift_rel\twall_s\n")
        for m in man:
            f.write("\t".join(str(v) for v in m) + "\n")
    log("data/: %d files" % len(man))


if __name__ == "__main__":
    main()
