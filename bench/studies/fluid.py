#!/usr/bin/env python3
"""The paper's four ruptures in vacuum (the paper), in air with drag and in
water (issue 14).

For each run: the released end's peak speed and its mean speed from the end of
the break to the return of the front (of the run in vacuum); the front's
arrival at the fixed end (1 % drop); where the energy has gone at t_end, as
fractions of the initial strain energy (kinetic, strain, bending, the work done
on the cable by the fluid: negative when the fluid takes energy); the lowest
tension at the fixed end, the smallest strain and the largest turning angle
between cells (buckling); the ledger drift; the static sag.

    python3 bench/studies/fluid.py [--exe bin/xcable] [--work build/study_fluid] \
        [--out docs/theory/fluid.md] [--nodes 241]

Needs h5py and numpy; not part of make test.
"""
import argparse, os, subprocess, sys, time
import numpy as np
import h5py
from common import text_attr, write_tables

# The paper's runs and their t_end (s).
CASES = [("fast_180kN", 180e3, 0.005, 0.14), ("slow_180kN", 180e3, 0.05, 0.17),
         ("fast_315kN", 315e3, 0.005, 0.13), ("slow_315kN", 315e3, 0.05, 0.16)]
# Media: name, &fluid group ('' for vacuum). Coefficients: docs/theory/fluid.md says where they come from.
MEDIA = [("vacuum", ""),
         ("air", "&fluid air_density = 1.2, cd_normal = 1.2, cd_tangential = 0.008, ca_normal = 1.0 /\n"),
         ("water", "&fluid density = 1025, cd_normal = 1.979, cd_tangential = 0.008, ca_normal = 1.1, surface_z = 100 /\n")]


def run(exe, work, name, medium, fluid, tension, t_break, t_end, nodes, window_end=None):
    stem = f"{name}_{medium}_{nodes}"
    nml = os.path.join(work, stem + ".nml")
    h5 = os.path.join(work, stem + ".h5")
    with open(nml, "w") as f:
        f.write(fluid + f"&static tension = {tension} /\n&rupture t_break = {t_break} /\n"
                f"&numerics nodes = {nodes}, t_end = {t_end} /\n"
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
        vb = np.hypot(h["history/end_b/vx"][:], h["history/end_b/vz"][:])
        front = float(s["front_arrival_time"])
        end = window_end if window_end is not None else 2 * front - t_break
        window = (t > t_break + 0.005) & (t < end)
        mean = float(np.sum(vb[window] * step[window]) / np.sum(step[window]))
        e = h["history/energy"]
        e0 = float(e["strain"][0])
        last = {k: float(e[k][-1]) for k in ("strain", "kinetic", "bending", "gravity", "loads")}
        gravity0 = float(e["gravity"][0])
        status = text_attr(h.attrs["status"])
        return dict(status=status, peak=float(s["peak_end_speed"]), mean=mean, front=front,
                    window_end=2 * front - t_break, kinetic=last["kinetic"] / e0, strain=last["strain"] / e0,
                    bending=last["bending"] / e0, gravity=(last["gravity"] - gravity0) / e0,
                    fluid=last["loads"] / e0, tmin=float(s["end_a_min_tension"]), eps_min=float(s["min_strain"]),
                    turn=float(s["max_turning_angle"]), drift=float(s["energy_drift"]),
                    sag=float(h["static"].attrs["sag"]), wall=wall)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", default="bin/xcable")
    ap.add_argument("--work", default="build/study_fluid")
    ap.add_argument("--out", default="docs/theory/fluid.md")
    ap.add_argument("--nodes", type=int, default=241)
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    exe = os.path.join(a.work, "xcable")
    subprocess.run(["cp", a.exe, exe], check=True)
    lines = ["| case | medium | status | static sag m | peak end speed m/s | mean end speed m/s | front arrival ms | "
             "kinetic | strain | bending | gravity | work of the fluid | T_a,min kN | eps_min | turn rad | drift | wall s |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for (name, tension, t_break, t_end) in CASES:
        window_end = None
        for medium, fluid in MEDIA:
            r = run(exe, a.work, name, medium, fluid, tension, t_break, t_end, a.nodes, window_end)
            if medium == "vacuum":
                window_end = r["window_end"]
            lines.append(f"| {name} | {medium} | {r['status']} | {r['sag']:.4f} | {r['peak']:.2f} | {r['mean']:.2f} | "
                         f"{1e3 * r['front']:.2f} | {r['kinetic']:.3f} | {r['strain']:.3f} | {r['bending']:.3f} | "
                         f"{r['gravity']:+.4f} | {r['fluid']:+.3f} | {r['tmin'] / 1e3:.2f} | {r['eps_min']:.3f} | "
                         f"{r['turn']:.3f} | {r['drift']:.1e} | {r['wall']:.1f} |")
            print(lines[-1], flush=True)
    write_tables(a.out, "\n".join(lines) + "\n")

if __name__ == "__main__":
    sys.exit(main())
