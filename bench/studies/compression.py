#!/usr/bin/env python3
"""Study of the compressive branch (issue 11, item 4): the paper's four runs and
the slack releases with &material compression = 'law' (the tanh fit continued
below zero) and 'none' (a rope that cannot push), on a ladder of grids.

For each run: the ledger drift, whether the compressed zone buckles (the
largest bending energy of the run against the static one, and the largest
turning angle between neighbouring cells), the lowest tension at end a, and
the released end's position at the end of the run, so that the convergence of
the post-reflection results can be read off the ladder.

    python3 bench/studies/compression.py [--exe bin/xcable] [--work build/study] [--out docs/theory/compression.md]

Needs h5py and numpy (pip install h5py numpy); not part of make test.
"""
import argparse, os, subprocess, sys, time
import numpy as np
import h5py
from common import text_attr, write_tables

PAPER = [("fast_180kN", 180e3, 0.005, 0.14), ("fast_315kN", 315e3, 0.005, 0.13),
         ("slow_180kN", 180e3, 0.05, 0.17), ("slow_315kN", 315e3, 0.05, 0.16)]
SLACK = [(f"slack_{int(t/1e3)}kN_{'fast' if tb < 0.01 else 'slow'}", t, tb, 2.0)
         for t in (2e3, 5e3, 20e3, 50e3) for tb in (0.005, 0.05)]


def run(exe, work, name, tension, t_break, t_end, nodes, compression):
    stem = f"{name}_{compression}_{nodes}"
    nml = os.path.join(work, stem + ".nml")
    h5 = os.path.join(work, stem + ".h5")
    with open(nml, "w") as f:
        f.write(f"&material compression = '{compression}' /\n&static tension = {tension} /\n"
                f"&rupture t_break = {t_break} /\n&numerics nodes = {nodes}, t_end = {t_end} /\n"
                f"&output file = '{h5}', interval = {t_end}, energy = .true., quiet = .true. /\n")
    t0 = time.time()
    p = subprocess.run([exe, nml], capture_output=True, text=True)
    wall = time.time() - t0
    if not os.path.exists(h5):
        return dict(status="no file: " + p.stderr.strip().splitlines()[-1] if p.stderr.strip() else "no file",
                    drift=float("nan"), bend_ratio=float("nan"), bend_max=float("nan"), turn=float("nan"),
                    tmin=float("nan"), min_strain=float("nan"), end=(float("nan"), float("nan")), wall=wall,
                    rc=p.returncode)
    with h5py.File(h5, "r") as h:
        s = h["summary"].attrs
        e = h["history/energy"]
        bend = e["bending"][:]
        b = h["history/end_b"]
        return dict(status=text_attr(h.attrs["status"]),
                    drift=float(s["energy_drift"]), bend_ratio=float(bend.max() / max(bend[0], 1e-300)),
                    bend_max=float(bend.max()), turn=float(s["max_turning_angle"]),
                    tmin=float(s["end_a_min_tension"]), min_strain=float(s["min_strain"]),
                    end=(float(b["x"][-1]), float(b["z"][-1])), wall=wall, rc=p.returncode)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", default="bin/xcable")
    ap.add_argument("--work", default="build/study")
    ap.add_argument("--out", default="docs/theory/compression.md")
    ap.add_argument("--paper-nodes", default="121,241,481,961")
    ap.add_argument("--slack-nodes", default="241,481")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    # Run a copy, so that rebuilding bin/xcable during the study does not mix versions.
    exe = os.path.join(a.work, "xcable")
    subprocess.run(["cp", a.exe, exe], check=True)
    a.exe = exe
    # The columns are explained in the hand-written text of docs/theory/compression.md, above the tables.
    lines = []
    for title, cases, nodes in (("The paper's four runs", PAPER, [int(n) for n in a.paper_nodes.split(",")]),
                                ("Slack releases", SLACK, [int(n) for n in a.slack_nodes.split(",")])):
        lines += [f"## {title}", "",
                  "| case | compression | nodes | status | drift | E_b,max / E_b(0) | turn | eps_min | T_a,min kN | end b x, z at t_end | wall s |",
                  "|---|---|---|---|---|---|---|---|---|---|---|"]
        for (name, tension, t_break, t_end) in cases:
            for comp in ("law", "none"):
                for n in nodes:
                    r = run(a.exe, a.work, name, tension, t_break, t_end, n, comp)
                    lines.append(f"| {name} | {comp} | {n} | {r['status']} | {r['drift']:.1e} | {r['bend_ratio']:.3g} | "
                                 f"{r['turn']:.3f} | {r['min_strain']:.3f} | {r['tmin']/1e3:.2f} | "
                                 f"{r['end'][0]:.3f}, {r['end'][1]:.3f} | {r['wall']:.1f} |")
                    print(lines[-1], flush=True)
        lines.append("")
    write_tables(a.out, "\n".join(lines) + "\n")

if __name__ == "__main__":
    sys.exit(main())
