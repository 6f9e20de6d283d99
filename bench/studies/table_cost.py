#!/usr/bin/env python3
"""Cost of the tabulated law against the tanh law (issue 13: at most 10 %).

Runs the paper's fast 180 kN break (or --case) with the tanh law and with the
tanh law tabulated at several row counts, at equal nodes and steps, and prints
a table: the median wall time of --repeats runs (the run's own /summary
wall_time, which excludes start-up and output), its ratio to tanh, and, when
valgrind is installed, the instruction count of one run (callgrind; does not
drift with the machine's load) and its ratio.

    python3 bench/studies/table_cost.py [--exe bin/xcable] [--nodes 241] [--repeats 7] [--rows 14,105,1000]

Needs h5py and numpy; valgrind optional. Not part of make test.
"""
import argparse, math, os, shutil, statistics, subprocess, sys, tempfile
import h5py

P = (2.703e5, 10.2, -2.128, 2.627e5, 135.5)


def tanh_law(eps):
    return P[0] * math.tanh(P[1] * eps + P[2]) + P[3] + P[4] * eps


def namelist(path, h5, law, rows, nodes):
    with open(path, "w") as f:
        if law == "table":
            strain = [-0.9 + 1.3 * k / (rows - 1) for k in range(rows)]
            def column(values):  # four values a line (the reader takes lines of up to 1024 characters)
                return ",\n    ".join(", ".join(f"{v:.17g}" for v in values[i:i + 4]) for i in range(0, len(values), 4))
            f.write("&material law = 'table',\n  table_strain = " + column(strain) + ",\n"
                    "  table_tension = " + column([tanh_law(e) for e in strain]) + " /\n")
        f.write("&static tension = 180000 /\n&rupture t_break = 0.005 /\n"
                f"&numerics nodes = {nodes}, t_end = 0.14 /\n"
                f"&output file = '{h5}', interval = 0.14, quiet = .true. /\n")


def wall(exe, nml, h5):
    subprocess.run([exe, nml], check=True, capture_output=True)
    with h5py.File(h5, "r") as h:
        return float(h["summary"].attrs["wall_time"]), int(h["summary"].attrs["steps"])


def instructions(exe, nml, work, only=None):
    """Instructions of one run (callgrind), of the whole process or only inside the function `only`."""
    out = os.path.join(work, "callgrind.out")
    cmd = ["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}"]
    if only:
        cmd.append(f"--toggle-collect={only}")
    subprocess.run(cmd + [exe, nml], check=True, capture_output=True)
    with open(out) as f:
        for line in f:
            if line.startswith("summary:") or line.startswith("totals:"):
                return int(line.split()[1])
    return None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", default="bin/xcable")
    ap.add_argument("--nodes", type=int, default=241)
    ap.add_argument("--repeats", type=int, default=7)
    ap.add_argument("--rows", default="14,105,1000")
    a = ap.parse_args()
    work = tempfile.mkdtemp(prefix="xcable_table_cost_")
    exe = os.path.join(work, "xcable")
    shutil.copy(a.exe, exe)
    grind = shutil.which("valgrind") is not None
    cases = [("tanh", 0)] + [("table", int(r)) for r in a.rows.split(",")]
    results = []
    for law, rows in cases:
        nml, h5 = os.path.join(work, f"{law}{rows}.nml"), os.path.join(work, f"{law}{rows}.h5")
        namelist(nml, h5, law, rows, a.nodes)
        runs = [wall(exe, nml, h5) for _ in range(a.repeats)]
        results.append((law, rows, statistics.median(w for w, _ in runs), runs[0][1],
                        instructions(exe, nml, work, "*sim_run*") if grind else None,
                        instructions(exe, nml, work) if grind else None))
    base = results[0]
    print(f"fast 180 kN, {a.nodes} nodes, t_end 0.14 s; wall: median of {a.repeats} runs of the dynamics;")
    print("instructions (callgrind): of the dynamics (sim_run) and of the whole process (reading, statics, output)")
    print(f"{'law':>6} {'rows':>6} {'steps':>6} {'wall s':>8} {'ratio':>6} {'dynamics':>14} {'ratio':>6} "
          f"{'process':>14} {'ratio':>6}")
    for law, rows, t, steps, ins, total in results:
        def ratio(x, y):
            return x / y if x and y else float("nan")
        print(f"{law:>6} {rows if rows else '-':>6} {steps:>6} {t:8.3f} {t / base[2]:6.3f} "
              f"{ins or '-':>14} {ratio(ins, base[4]):6.3f} {total or '-':>14} {ratio(total, base[5]):6.3f}")
    shutil.rmtree(work)


if __name__ == "__main__":
    sys.exit(main())
