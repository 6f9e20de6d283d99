#!/usr/bin/env python3
"""The slack releases of bench/peer with compression = 'none' against MoorDyn.

MoorDyn cuts its law at zero tension with no band (README, B). xcable's
compression = 'none' was a blend over +-1e-3 of strain around the strain of
zero tension before version 0.6 and is the exact cut since (issue 37). This
script runs the eight slack_*kN scenes of peer_common.cases() with 'none' on
one or more xcable executables, up to MoorDyn's last valid time (t_last of
data/manifest.tsv), and prints per case and executable: the status, the
largest distance between xcable's and MoorDyn's released end over MoorDyn's
samples (10 ms), that distance at MoorDyn's last sample, the Newton iterations
per accepted step and the rejected steps.

  python3 slack_none.py --exe OLD NEW [--nodes 241] [--work /tmp/slack_none]

Needs numpy and h5py. Not part of make test.
"""

import argparse
import os
import subprocess
import sys

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True
sys.path.insert(0, HERE)
import peer_common as pc  # noqa: E402


def namelist(case, nodes, t_end, h5name):
    ts, tb, _, sample = pc.cases()[case]
    p = ", ".join(repr(float(v)) for v in pc.P)
    return "\n".join([
        "&cable    length = %r, diameter = %r, density = %r, young = %r," % (
            pc.LENGTH, pc.DIAMETER, pc.DENSITY, pc.YOUNG),
        "          gravity = %r, area = %r, bending_stiffness = %r /" % (pc.GRAVITY, pc.AREA, pc.EI),
        "&material law = 'tanh', p = %s, compression = 'none' /" % p,
        "&static   tension = %r /" % float(ts),
        "&end_a    kind = 'fixed', x = 0.0, z = 0.0 /",
        "&end_b    kind = 'fixed' /",
        "&rupture  enabled = .true., s_break = %r, t_break = %r, time = 0.0 /" % (pc.LENGTH, tb),
        "&numerics nodes = %d, t_end = %r /" % (nodes, t_end),
        "&output   file = '%s', interval = %r, fields = 'x z', energy = .true., quiet = .true. /" % (h5name, sample),
        ""])


def manifest():
    out = {}
    with open(os.path.join(HERE, "data", "manifest.tsv")) as f:
        head = f.readline().rstrip("\n").split("\t")
        for ln in f:
            c = ln.rstrip("\n").split("\t")
            out[c[0]] = dict(zip(head, c))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", nargs="+", required=True)
    ap.add_argument("--nodes", type=int, default=241)
    ap.add_argument("--work", default="/tmp/slack_none")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    man = manifest()
    cases = [c for c in pc.cases() if c.startswith("slack_")]
    print("| case | t_valid s | exe | status | max distance m | at t_valid m | Newton / step | rejected | drift |")
    print("|---|---|---|---|---|---|---|---|---|")
    for case in cases:
        md = pc.read_tsv(os.path.join(HERE, "data", "moordyn_%s.tsv" % case))
        t_valid = float(man["moordyn_%s.tsv" % case]["t_last"])
        for k, exe in enumerate(a.exe):
            stem = "%s_%d" % (case, k)
            with open(os.path.join(a.work, stem + ".nml"), "w") as f:
                f.write(namelist(case, a.nodes, t_valid, stem + ".h5"))
            subprocess.run([os.path.abspath(exe), stem + ".nml"], cwd=a.work, capture_output=True, text=True)
            with h5py.File(os.path.join(a.work, stem + ".h5"), "r") as f:
                status = f.attrs["status"]
                status = status.decode() if isinstance(status, bytes) else str(status)
                s = f["summary"].attrs
                t = f["time"][:]
                x = f["x"][:, -1]
                z = f["z"][:, -1]
                its = int(s["newton_iterations"])
                acc = int(s["steps"])
                rej = int(s["rejected_steps"]) if "rejected_steps" in s else -1
                drift = float(s["energy_drift"])
            dist = []
            for tm, xm, zm in zip(md["t"], md["end_x"], md["end_z"]):
                i = np.argmin(abs(t - tm))
                if abs(t[i] - tm) < 1e-6:
                    dist.append(np.hypot(x[i] - xm, z[i] - zm))
            print("| %s | %.2f | %s | %s | %.3g | %.3g | %.3f | %d | %.1e |" % (
                case, t_valid, exe, status, max(dist), dist[-1], its / max(acc, 1), rej, drift))


if __name__ == "__main__":
    main()
