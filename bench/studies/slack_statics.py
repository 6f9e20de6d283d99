#!/usr/bin/env python3
"""Robustness of the planar statics of a slack line: a sweep over the span.

The paper's cable (L = 60 m, its law and bending stiffness EI = 70.6 N m^2,
dry) held at end a = (0, 0) and end b = (f L, 0) for span ratios f = 0.05 ..
0.95, on 31 .. 481 nodes, with compression = 'law' and 'none'. Only the static
state is used (t_end = one step of 1 ms).

Each static state is compared with REF's (default: the binary under test)
961-node state of the same span and compression at the common nodes (961 - 1
is a multiple of every n - 1): err = the largest distance between the nodes /
L. Classes:
  right     exit 0 and err <= 4 (ds / L)^2, four times the second-order
            error of a unit-curvature scale;
  wrong     exit 0 and err above that;
  unjudged  exit 0, no reference;
  refused   exit 1, no result file.
Usage: python3 slack_statics.py BIN [--ref REFBIN] [--ei EI] [--out TSV]
Prints one line per run and a table per (compression, f).
"""
import argparse
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

LENGTH = 60.0
RATIOS = [0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9, 0.95]
NODES = [31, 61, 121, 241, 481]
REF_NODES = 961
CLASSES = ("right", "wrong", "unjudged", "refused")


def static(binary, n, f, comp, work, ei):
    tag = f"{n}_{f}_{comp}_{os.path.basename(binary)}"
    nml, h5 = os.path.join(work, tag + ".nml"), os.path.join(work, tag + ".h5")
    with open(nml, "w") as fh:
        fh.write(f"&cable bending_stiffness = {ei} /\n&material compression = '{comp}' /\n"
                 f"&end_a kind = 'fixed', x = 0, z = 0 /\n&end_b kind = 'fixed', x = {f * LENGTH}, z = 0 /\n"
                 f"&rupture enabled = .false. /\n&numerics nodes = {n}, dt = 0.001, t_end = 0.001 /\n"
                 f"&output file = '{h5}', interval = 0, quiet = .true. /\n")
    if os.path.exists(h5):
        os.remove(h5)
    p = subprocess.run([binary, nml], capture_output=True, text=True)
    out = {"rc": p.returncode, "msg": p.stderr.strip().splitlines()[-1] if p.stderr.strip() else ""}
    if p.returncode == 0:
        with h5py.File(h5, "r") as fh:
            out["r"] = np.stack([fh["static/x"][:], fh["static/z"][:]], 1)
            out["tension"] = fh["static/tension"][:]
            out["iterations"] = int(fh["static"].attrs["newton_iterations"])
        os.remove(h5)
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("binary")
    ap.add_argument("--ref")
    ap.add_argument("--ei", default="0")
    ap.add_argument("--out")
    a = ap.parse_args()
    ref_bin = a.ref or a.binary
    work = tempfile.mkdtemp(prefix="slack_statics_")
    rows, table = [], {}
    for comp in ("law", "none"):
        for f in RATIOS:
            ref = static(ref_bin, REF_NODES, f, comp, work, a.ei)
            for n in NODES:
                r = static(a.binary, n, f, comp, work, a.ei)
                err = float("nan")
                if r["rc"] != 0:
                    cls = "refused"
                elif ref["rc"] != 0:
                    cls = "unjudged"
                else:
                    step = (REF_NODES - 1) // (n - 1)
                    err = float(np.max(np.linalg.norm(r["r"] - ref["r"][::step], axis=1))) / LENGTH
                    cls = "right" if err <= 4 * (1.0 / (n - 1)) ** 2 else "wrong"
                table.setdefault((comp, f), dict.fromkeys(CLASSES, 0))[cls] += 1
                line = (f"{comp}\t{f}\t{n}\t{cls}\t{r['rc']}\t{err:.2e}\t{r.get('iterations', -1)}\t"
                        f"{float(np.min(r['tension'])) if 'tension' in r else float('nan'):.3f}\t"
                        f"{r['msg'][:160] if r['rc'] else ''}")
                print(line, flush=True)
                rows.append(line)
    if a.out:
        with open(a.out, "w") as fh:
            fh.write("compression\tspan_ratio\tnodes\tclass\texit\terr_over_L\tnewton_iterations\tmin_tension\tmessage\n")
            fh.write("\n".join(rows) + "\n")
    print("\n| compression | span / L | " + " | ".join(CLASSES) + " |\n|---|---|" + "---|" * len(CLASSES))
    for (comp, f), v in table.items():
        print(f"| {comp} | {f} | " + " | ".join(str(v[c]) for c in CLASSES) + " |")
    print("| all | | " + " | ".join(str(sum(v[c] for v in table.values())) for c in CLASSES) + " |")


if __name__ == "__main__":
    sys.exit(main())
