#!/usr/bin/env python3
"""Speed of xcable builds on fast_180kN, and MoorDyn's stepping time (docs/measurements/data/speed_rounds.md).

    python3 bench/speed.py NAME=BIN [NAME=BIN ...] [--rounds 7] [--no-callgrind]
                           [--no-moordyn] [--work DIR]

For each build (a label and the path of its xcable executable; the first is
the baseline of the ratios):

* instruction counts (valgrind --tool=callgrind) of fast_180kN as shipped
  (input/fast_180kN.nml: 241 nodes, Courant 1, HDF5 with all fields, the
  gnuplot text and the energy ledger), split into parts by inclusive cost;
* whole-process wall and CPU times, medians over interleaved rounds, of
  fast_180kN as shipped and of lean runs (no gnuplot text, no ledger) on 241
  and 961 nodes, and per round the ratio of each build to the first;
* ns per node-step of the lean runs (CPU time of the process, and the
  dynamics' own wall time from /summary, over nodes x steps), and the
  marginal cost: the lean run's CPU time less that of the same run stopped
  at 0.1 ms (start-up, statics, the HDF5 file: what every run costs), over
  the node-steps between the two;
* whether the results are the same: largest difference of the tension
  snapshots, end-b history and summary figures against the first build;
* MoorDyn's stepping time on the same scene (N = 400 segments, RK4, time
  step 0.5 ds / c_max of its table: bench/peer/moordyn_run.py's set-up),
  timed around its Step calls only, in the same rounds.

Prints a markdown report. Needs valgrind, h5py, numpy and (for MoorDyn) the
PyPI package moordyn.
"""
import argparse
import math
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

# Inclusive-cost functions that make up the parts of a run (callgrind symbol names).
PARTS = [
    ("residual and Jacobian", ["__xcable_model_rod_MOD_rod_problem_evaluate"]),
    ("factorisation", ["__xcable_solver_banded_MOD_band_factor"]),
    ("substitution", ["__xcable_solver_banded_MOD_band_solve"]),
    ("output (HDF5, gnuplot text, interpolation)", ["__xcable_rod_run_MOD_emit_snapshots", "__xcable_io_output_MOD_result_write_history",
                                                    "__xcable_io_output_MOD_result_write_summary",
                                                    "__xcable_io_output_MOD_result_create",
                                                    "__xcable_io_output_MOD_result_finish"]),
    ("of which gnuplot text (formatting)", ["_gfortran_transfer_real", "__xcable_io_number_text_MOD_put_es"]),
    ("step bookkeeping (ledger, history, accept)", ["__xcable_rod_run_MOD_record", "__xcable_rod_run_MOD_accept"]),
    ("statics", ["__xcable_rod_statics_MOD_solve_rod_statics"]),
]


def namelist(nodes, lean, path, out, short=False):
    """fast_180kN as shipped, or lean (no gnuplot text, no ledger), on `nodes` nodes; short: the
    lean run stopped at t = 0.1 ms (one or two steps, before the break), which costs what a run
    costs whatever its length (start-up, statics, the HDF5 file)."""
    text = open(os.path.join(ROOT, "input", "fast_180kN.nml")).read()
    text = text.replace("results/fast_180kN.h5", out)
    text = text.replace("nodes = 241", "nodes = %d" % nodes)
    if lean:
        text = text.replace("gnuplot = .true., energy = .true.", "gnuplot = .false., energy = .false.")
    if short:
        text = text.replace("t_end = 0.14", "t_end = 0.0001").replace("interval = 0.01", "interval = 0")
    with open(path, "w") as f:
        f.write(text)


def run_timed(cmd):
    """Wall and CPU (user + system) time of a child process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def callgrind(exe, nml, work, label):
    out = os.path.join(work, "callgrind.%s.out" % label)
    subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + out, exe, nml], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    text = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", out], check=True,
                          capture_output=True, text=True).stdout
    total = None
    inclusive = {}
    for line in text.splitlines():
        if "PROGRAM TOTALS" in line:
            total = int(line.split()[0].replace(",", ""))
            continue
        m = re.match(r"^\s*([\d,]+)\s+\(\s*[\d.]+%\)\s+(\S+)", line)
        if not m:
            continue
        value = int(m.group(1).replace(",", ""))
        name = m.group(2).split(":", 1)[-1]
        # keep the largest entry of a name (the file:function line, not a caller line)
        inclusive[name] = max(inclusive.get(name, 0), value)
    return total, inclusive


def part_value(inclusive, names):
    value = 0
    for name in names:
        value += sum(v for k, v in inclusive.items() if k == name or k.startswith(name + "."))
    return value


def compare(ref_h5, h5):
    a = h5py.File(ref_h5, "r")
    b = h5py.File(h5, "r")
    out = {}
    ts = max(abs(float(x)) for x in a["/static/tension"][:])
    out["tension snapshots, max |dT| / T_s"] = float(np.max(np.abs(a["tension"][:] - b["tension"][:]))) / ts
    for q in ("vx", "vz"):
        out["end b %s, max |d|" % q] = float(np.max(np.abs(a["history/end_b/%s" % q][:] - b["history/end_b/%s" % q][:])))
    for k in ("peak_end_speed", "front_arrival_time", "newton_iterations", "steps"):
        out["summary %s, difference" % k] = float(b["summary"].attrs[k]) - float(a["summary"].attrs[k])
    return out


def summary(h5):
    f = h5py.File(h5, "r")
    return int(f["summary"].attrs["steps"]), float(f["summary"].attrs["wall_time"])


MOORDYN_SCRIPT = r'''
import math, os, sys, time, tempfile
sys.path.insert(0, %(peer)r)
import moordyn
import peer_common as pc
from moordyn_run import write_table, write_input, write_state
tension, t_end, n, courant, sample = 180e3, 0.14, %(n)d, 0.5, 1e-3
law = pc.TanhLaw()
xs, ys = pc.moordyn_table(law, 1.3 * law.strain(tension))
tab = pc.TableLaw(xs, ys)
r0, _ = pc.discrete_catenary(tab, tension, n)
span = float(r0[-1, 0])
ds = pc.LENGTH / n
c_max = math.sqrt(tab.stiffness_max / pc.MASS)
nsub = max(1, int(math.ceil(sample / (courant * ds / c_max) - 1e-9)))
h = sample / nsub
work = tempfile.mkdtemp(prefix="md_speed_")
write_table(os.path.join(work, "ea_table.txt"), xs, ys)
inp = os.path.join(work, "cable.txt")
write_input(inp, "ea_table.txt", n, span, h)
write_state(os.path.join(work, "static.state"), r0, [[0.0] * 6, [span, 0.0, 0.0, 0.0, 0.0, 0.0]])
saved = os.dup(1); devnull = os.open(os.devnull, os.O_WRONLY); os.dup2(devnull, 1)
s = moordyn.Create(inp)
moordyn.SetVerbosity(s, moordyn.LEVEL_ERR)
moordyn.Init_NoIC(s, [span, 0.0, 0.0], [0.0, 0.0, 0.0])
moordyn.LoadState(s, os.path.join(work, "static.state"))
os.dup2(saved, 1)
t = 0.0
spent = 0.0
cpu = 0.0
for k in range(int(round(t_end / sample))):
    c0 = time.process_time(); w0 = time.perf_counter()
    moordyn.Step(s, [span, 0.0, 0.0], [0.0, 0.0, 0.0], t, sample)
    spent += time.perf_counter() - w0; cpu += time.process_time() - c0
    t += sample
moordyn.Close(s)
print(spent, cpu, nsub * int(round(t_end / sample)), h)
'''


def moordyn_stepping(n=400):
    """MoorDyn's stepping wall and CPU time on fast_180kN's scene (held end b: the cost per step does not
    depend on the motion), its number of steps and its step."""
    script = MOORDYN_SCRIPT % {"peer": os.path.join(HERE, "peer"), "n": n}
    out = subprocess.run([sys.executable, "-c", script], check=True, capture_output=True, text=True).stdout
    wall, cpu, steps, h = out.split()
    return float(wall), float(cpu), int(steps), float(h)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("builds", nargs="+", help="NAME=PATH of an xcable executable; the first is the baseline")
    ap.add_argument("--rounds", type=int, default=7)
    ap.add_argument("--no-callgrind", action="store_true")
    ap.add_argument("--no-moordyn", action="store_true")
    ap.add_argument("--work")
    a = ap.parse_args()
    builds = [b.split("=", 1) for b in a.builds]
    work = a.work or tempfile.mkdtemp(prefix="xcable_speed_")
    os.makedirs(work, exist_ok=True)
    os.environ["OMP_NUM_THREADS"] = "1"
    os.environ["OPENBLAS_NUM_THREADS"] = "1"
    configs = [("fast_180kN as shipped, 241 nodes", 241, False), ("lean, 241 nodes", 241, True),
               ("lean, 961 nodes", 961, True), ("lean to 0.1 ms, 241 nodes", 241, True),
               ("lean to 0.1 ms, 961 nodes", 961, True)]
    nml = {}
    for label, _ in builds:
        for i, (name, nodes, lean) in enumerate(configs):
            path = os.path.join(work, "%s_%d.nml" % (label, i))
            namelist(nodes, lean, path, os.path.join(work, "%s_%d.h5" % (label, i)), short=i >= 3)
            nml[label, i] = path

    print("# xcable speed, fast_180kN\n")
    print("Work directory %s; load average at the start %s.\n" % (work, " ".join("%.2f" % x for x in os.getloadavg())))

    if not a.no_callgrind:
        print("## Instructions (callgrind), fast_180kN as shipped\n")
        counts = {}
        for label, exe in builds:
            counts[label] = callgrind(exe, nml[label, 0], work, label)
        print("| part | " + " | ".join("%s: instructions, share" % label for label, _ in builds) + " |")
        print("|---|" + "---:|" * len(builds))
        print("| whole process | " + " | ".join("%.3e, 100 %%" % counts[l][0] for l, _ in builds) + " |")
        for part, names in PARTS:
            cells = []
            for label, _ in builds:
                total, inc = counts[label]
                v = part_value(inc, names)
                cells.append("%.3e, %.1f %%" % (v, 100.0 * v / total))
            print("| %s | %s |" % (part, " | ".join(cells)))
        cells = []
        for label, _ in builds:
            total, inc = counts[label]
            v = part_value(inc, ["__xcable_solver_newton_MOD_newton_solve"]) - sum(
                part_value(inc, names) for _, names in PARTS[:3])
            cells.append("%.3e, %.1f %%" % (v, 100.0 * v / total))
        print("| Newton's own work (updates, norms; statics included) | %s |" % " | ".join(cells))
        cells = []
        for label, _ in builds:
            total, inc = counts[label]
            v = total - part_value(inc, ["MAIN__"])
            cells.append("%.3e, %.1f %%" % (v, 100.0 * v / total))
        print("| process start-up and exit (outside the program) | %s |" % " | ".join(cells))
        print()

    # Interleaved timing rounds.
    times = {}
    md = []
    for r in range(a.rounds):
        for i in range(len(configs)):
            for label, exe in builds:
                times.setdefault((label, i), []).append(run_timed([exe, nml[label, i]]))
        if not a.no_moordyn:
            md.append(moordyn_stepping())
    print("## Times (%d interleaved rounds, medians; load average at the end %s)\n" %
          (a.rounds, " ".join("%.2f" % x for x in os.getloadavg())))
    print("| run | build | wall s | CPU s | CPU ratio to %s (median of rounds) | steps | dynamics wall s (/summary) | "
          "ns per node-step (process CPU) | ns per node-step (dynamics wall) |" % builds[0][0])
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|")
    for i, (name, nodes, lean) in enumerate(configs):
        for label, exe in builds:
            t = times[label, i]
            wall = statistics.median(x[0] for x in t)
            cpu = statistics.median(x[1] for x in t)
            ratio = statistics.median(x[1] / y[1] for x, y in zip(t, times[builds[0][0], i]))
            steps, dyn_wall = summary(os.path.join(work, "%s_%d.h5" % (label, i)))
            print("| %s | %s | %.3f | %.3f | %.3f | %d | %.3f | %.0f | %.0f |" %
                  (name, label, wall, cpu, ratio, steps, dyn_wall, 1e9 * cpu / (nodes * steps),
                   1e9 * dyn_wall / (nodes * steps)))
    print()
    # The marginal cost: the lean run less the short one (the costs every run has), per node-step
    # of the difference, CPU times paired within a round.
    print("Marginal cost of a node-step (lean run less the run to 0.1 ms, process CPU, median of the rounds' "
          "differences, over nodes x the difference of the steps):\n")
    print("| build | " + " | ".join("%d nodes: fixed CPU ms, marginal ns per node-step" % configs[i][1]
                                   for i in (1, 2)) + " |")
    print("|---|" + "---:|" * 2)
    for label, _ in builds:
        cells = []
        for i, j in ((1, 3), (2, 4)):
            nodes = configs[i][1]
            steps = summary(os.path.join(work, "%s_%d.h5" % (label, i)))[0]
            steps_short = summary(os.path.join(work, "%s_%d.h5" % (label, j)))[0]
            fixed = statistics.median(x[1] for x in times[label, j])
            marginal = statistics.median(x[1] - y[1] for x, y in zip(times[label, i], times[label, j]))
            cells.append("%.1f, %.0f" % (1e3 * fixed, 1e9 * marginal / (nodes * (steps - steps_short))))
        print("| %s | %s |" % (label, " | ".join(cells)))
    print()
    if md:
        wall = statistics.median(x[0] for x in md)
        cpu = statistics.median(x[1] for x in md)
        print("MoorDyn (N = 400, RK4, dt = %.4g s, %d steps), stepping only: wall %.3f s, CPU %.3f s (medians).\n" %
              (md[0][3], md[0][2], wall, cpu))
        print("| build | fast_180kN as shipped, process wall / MoorDyn stepping wall | process CPU / MoorDyn stepping CPU "
              "(median of rounds) |")
        print("|---|---:|---:|")
        for label, _ in builds:
            t = times[label, 0]
            rw = statistics.median(x[0] / m[0] for x, m in zip(t, md))
            rc = statistics.median(x[1] / m[1] for x, m in zip(t, md))
            print("| %s | %.3f | %.3f |" % (label, rw, rc))
        print()
    if len(builds) > 1:
        print("## Results against %s\n" % builds[0][0])
        for i, (name, nodes, lean) in enumerate(configs):
            for label, _ in builds[1:]:
                diff = compare(os.path.join(work, "%s_%d.h5" % (builds[0][0], i)),
                               os.path.join(work, "%s_%d.h5" % (label, i)))
                print("- %s, %s: %s" % (name, label, ", ".join("%s %.3g" % kv for kv in diff.items())))
        print()


if __name__ == "__main__":
    main()
