#!/usr/bin/env python3
"""Robustness of the statics under a strong current (issue 15): a sweep.

The line of bench/peer/sway3d.py (the paper's cable in sea water, end a at the
origin, end b at (48, 0, 24) m, linear law EA = 451.6 kN) in a uniform current
of U = 0.25 .. 3 m/s, on 31 .. 161 nodes, with compression = 'law' and 'none'.
Only the static state is used (t_end = one step of 0.01 s).

  3d:     &numerics model = '3d', current across the chord's plane (current_y = U)
  planar: &numerics model = '2d', current in the plane (current_x = +U and -U)

Each run is classed against a reference, REF's (default: the binary under
test) 161-node static state of the same current and compression, taken as
valid when it is unfolded and agrees with REF's 121-node state (as below):
  right     exit 0, no fold, the end tensions within 1 % of the larger
            reference end tension and the middle node within 0.1 % of L;
  folded    exit 0 with a turning angle between neighbouring cells above pi/2;
  wrong     exit 0, no fold, but off the (valid) reference;
  unjudged  exit 0, no fold, no valid reference;
  refused   exit 1, no result file.
Usage: python3 statics_sweep.py BIN [--ref REFBIN] [--kind 3d|planar] [--out TSV]
Prints one line per run and a table of the classes per (U, compression).
"""
import argparse
import math
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

EA = 451603.943953533   # the linear law of sway3d.py (E = 2.3e8 Pa on d = 0.05 m)
CURRENTS = [0.25, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0]
NODES = [31, 41, 61, 81, 121, 161]
LENGTH = 60.0


def namelist(n, u, comp, kind, h5):
    cur = f"current_y = {u}" if kind == "3d" else f"current_x = {u}"
    model = "3d" if kind == "3d" else "2d"
    endb = ("kind = 'motion', x = 48.0, z = 24.0, motion = 'harmonic', amplitude = 2.0, period = 15.0, "
            "ramp_time = 15.0, direction_x = 0, direction_y = 1, direction_z = 0" if kind == "3d"
            else "kind = 'fixed', x = 48.0, z = 24.0")
    return (f"&cable length = {LENGTH}, diameter = 0.05, density = 1140.0, gravity = 9.81 /\n"
            f"&material law = 'linear', ea = {EA}, compression = '{comp}' /\n"
            f"&fluid density = 1025.0, cd_normal = 1.2, cd_tangential = 0.008, ca_normal = 1.0, {cur}, surface_z = 1000 /\n"
            f"&end_a kind = 'fixed', x = 0, z = 0 /\n&end_b {endb} /\n&rupture enabled = .false. /\n"
            f"&numerics model = '{model}', nodes = {n}, dt = 0.01, t_end = 0.01 /\n"
            f"&output file = '{h5}', interval = 0, quiet = .true., fields = 'x z tension' /\n")


def static(binary, n, u, comp, kind, work):
    tag = f"{kind}_{n}_{u}_{comp}_{os.path.basename(binary)}"
    nml, h5 = os.path.join(work, tag + ".nml"), os.path.join(work, tag + ".h5")
    with open(nml, "w") as f:
        f.write(namelist(n, u, comp, kind, h5))
    if os.path.exists(h5):
        os.remove(h5)
    p = subprocess.run([binary, nml], capture_output=True, text=True)
    out = {"rc": p.returncode, "msg": p.stderr.strip().splitlines()[-1] if p.stderr.strip() else ""}
    if p.returncode != 0:
        out["file"] = os.path.exists(h5)
        return out
    with h5py.File(h5, "r") as f:
        x, z = f["x"][0], f["z"][0]
        y = f["y"][0] if "y" in f else np.zeros_like(x)
        t = f["tension"][0]
        out["status"] = f.attrs["status"]
    r = np.stack([x, y, z], 1)
    e = np.diff(r, axis=0)
    c = (e[1:] * e[:-1]).sum(1) / np.linalg.norm(e[1:], axis=1) / np.linalg.norm(e[:-1], axis=1)
    out["turn"] = float(np.arccos(np.clip(c, -1, 1)).max())
    out["ta"], out["tb"], out["mid"] = float(t[0]), float(t[-1]), r[(n - 1) // 2]
    os.remove(h5)
    return out


def close(r, ref):
    """Whether r agrees with ref: end tensions within 1 % of ref's larger one, middle node within 0.1 % of L."""
    scale = max(abs(ref["ta"]), abs(ref["tb"]))
    dev = max(abs(r["ta"] - ref["ta"]), abs(r["tb"] - ref["tb"])) / scale
    dpos = float(np.linalg.norm(r["mid"] - ref["mid"])) / LENGTH
    return dev < 0.01 and dpos < 1e-3, dev


CLASSES = ("right", "folded", "wrong", "unjudged", "refused")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("binary")
    ap.add_argument("--ref")
    ap.add_argument("--kind", default="3d", choices=["3d", "planar"])
    ap.add_argument("--out")
    a = ap.parse_args()
    ref_bin = a.ref or a.binary
    currents = CURRENTS if a.kind == "3d" else CURRENTS + [-u for u in CURRENTS]
    work = tempfile.mkdtemp(prefix="statics_sweep_")
    rows, table = [], {}
    for u in currents:
        for comp in ("law", "none"):
            ref = static(ref_bin, NODES[-1], u, comp, a.kind, work)
            ref2 = static(ref_bin, NODES[-2], u, comp, a.kind, work)
            ok_ref = (ref["rc"] == 0 and ref["turn"] < math.pi / 2 and ref2["rc"] == 0
                      and ref2["turn"] < math.pi / 2 and close(ref2, ref)[0])
            for n in NODES:
                r = static(a.binary, n, u, comp, a.kind, work)
                dev = float("nan")
                if r["rc"] != 0:
                    cls = "refused"
                elif r["turn"] >= math.pi / 2:
                    cls = "folded"
                elif not ok_ref:
                    cls = "unjudged"
                else:
                    good, dev = close(r, ref)
                    cls = "right" if good else "wrong"
                key = (u, comp)
                table.setdefault(key, dict.fromkeys(CLASSES, 0))[cls] += 1
                line = (f"{a.kind}\t{u}\t{comp}\t{n}\t{cls}\t{r['rc']}\t{r.get('turn', float('nan')):.3f}\t"
                        f"{r.get('ta', float('nan')):.3f}\t{r.get('tb', float('nan')):.3f}\t{dev:.2e}\t"
                        f"{r['msg'][:150] if r['rc'] else ''}")
                print(line, flush=True)
                rows.append(line)
    if a.out:
        with open(a.out, "w") as f:
            f.write("kind\tU\tcompression\tnodes\tclass\texit\tmax_turn_rad\tT_a\tT_b\trel_dev_T\tmessage\n")
            f.write("\n".join(rows) + "\n")
    print("\n| U m/s | compression | " + " | ".join(CLASSES) + " |\n|---|---|" + "---|" * len(CLASSES))
    for (u, comp), v in table.items():
        print(f"| {u} | {comp} | " + " | ".join(str(v[c]) for c in CLASSES) + " |")
    print("| all | | " + " | ".join(str(sum(v[c] for v in table.values())) for c in CLASSES) + " |")

if __name__ == "__main__":
    sys.exit(main())
