#!/usr/bin/env python3
"""Study of internal (Kelvin-Voigt) damping on the paper's runs (issue 13).

The paper's four runs to their t_end, with &material damping c = 0, values
around the realistic one (docs/theory/laws.md) and a large one. For each: the
released end's peak speed and its mean speed from the end of the break to the
return of the (undamped) front; the front's arrival at the fixed end (1 % drop)
and its width (1 % to 50 % drop); the fastest fall of the tension there during
the first unloading (how abrupt the break is felt there: the paper's argument
for slow breaks being less destructive); the lowest tension at the fixed end, the smallest strain and the
largest turning angle between cells (buckling); the energy dissipated over the
initial strain energy, the ledger drift and the number of warnings.

    python3 bench/studies/damping.py [--exe bin/xcable] [--work build/study_damping] \
        [--out docs/theory/damping.md] [--nodes 481] [--damping 0,1.5e3,4.5e3,1.4e4,4.5e4]

Needs h5py and numpy (pip install h5py numpy); not part of make test.
"""
import argparse, os, subprocess, sys, time
import numpy as np
import h5py
from common import crossing, text_attr, write_tables

# The paper's runs and their t_end (s).
CASES = [("fast_180kN", 180e3, 0.005, 0.14), ("slow_180kN", 180e3, 0.05, 0.17),
         ("fast_315kN", 315e3, 0.005, 0.13), ("slow_315kN", 315e3, 0.05, 0.16)]


def run(exe, work, name, tension, t_break, nodes, damping, t_end, window_end=None):
    stem = f"{name}_c{damping:g}_{nodes}"
    nml = os.path.join(work, stem + ".nml")
    h5 = os.path.join(work, stem + ".h5")
    with open(nml, "w") as f:
        f.write(f"&material damping = {damping} /\n&static tension = {tension} /\n"
                f"&rupture t_break = {t_break} /\n&numerics nodes = {nodes}, t_end = {t_end} /\n"
                f"&output file = '{h5}', interval = {t_end}, energy = .true., quiet = .true. /\n")
    t0 = time.time()
    p = subprocess.run([exe, nml], capture_output=True, text=True)
    wall = time.time() - t0
    if not os.path.exists(h5):
        raise RuntimeError(f"{stem}: no result file\n{p.stderr}")
    with h5py.File(h5, "r") as h:
        s = h["summary"].attrs
        t = h["history/time"][:]
        step = h["history/dt"][:]
        ta = h["history/end_a/tension"][:]
        vb = np.hypot(h["history/end_b/vx"][:], h["history/end_b/vz"][:])
        front = float(s["front_arrival_time"])
        # Mean speed of the released end from the end of the break to the return of the front
        # (of the undamped run: damping brings a diffuse precursor forward).
        end = window_end if window_end is not None else 2 * front - t_break
        window = (t > t_break + 0.005) & (t < end)
        mean_speed = float(np.sum(vb[window] * step[window]) / np.sum(step[window]))
        # How abrupt the unloading is at the fixed end: the fastest fall of its tension.
        first = t < end
        rate = float(np.max(-np.diff(ta[first]) / np.diff(t[first])))
        warnings = text_attr(s["warnings"])
        status = text_attr(h.attrs["status"])
        return dict(status=status, peak=float(s["peak_end_speed"]), mean=mean_speed, front=front, window_end=2 * front - t_break,
                    width=crossing(t, ta, 0.5 * ta[0]) - crossing(t, ta, 0.99 * ta[0]), rate=rate,
                    tmin=float(s["end_a_min_tension"]), eps_min=float(s["min_strain"]),
                    turn=float(s["max_turning_angle"]),
                    dissipated=float(s["dissipated"]) / float(h["history/energy/strain"][0]),
                    drift=float(s["energy_drift"]), warnings=len([w for w in warnings.splitlines() if w]), wall=wall)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", default="bin/xcable")
    ap.add_argument("--work", default="build/study_damping")
    ap.add_argument("--out", default="docs/theory/damping.md")
    ap.add_argument("--nodes", type=int, default=481)
    ap.add_argument("--damping", default="0,1.5e3,4.5e3,1.4e4,4.5e4")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    exe = os.path.join(a.work, "xcable")
    subprocess.run(["cp", a.exe, exe], check=True)
    values = [float(c) for c in a.damping.split(",")]
    lines = ["| case | c (N s) | status | peak end speed m/s | mean end speed m/s | front arrival ms | front width ms | "
             "fastest fall of T_a kN/ms | T_a,min kN | eps_min | turn rad | "
             "dissipated / E_s(0) | drift | warnings | wall s |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for (name, tension, t_break, t_end) in CASES:
        window_end = None
        for c in values:
            r = run(exe, a.work, name, tension, t_break, a.nodes, c, t_end, window_end)
            if c == 0:
                window_end = r["window_end"]
            lines.append(f"| {name} | {c:g} | {r['status']} | {r['peak']:.2f} | {r['mean']:.2f} | {1e3 * r['front']:.2f} | "
                         f"{1e3 * r['width']:.2f} | {r['rate'] / 1e6:.1f} | {r['tmin'] / 1e3:.2f} | "
                         f"{r['eps_min']:.3f} | {r['turn']:.3f} | {r['dissipated']:.3f} | {r['drift']:.1e} | "
                         f"{r['warnings']} | {r['wall']:.1f} |")
            print(lines[-1], flush=True)
    write_tables(a.out, "\n".join(lines) + "\n")

if __name__ == "__main__":
    sys.exit(main())
