#!/usr/bin/env python3
"""Friction in the statics: xcable against NREL's MoorPy (PyPI `moorpy`), a quasi-static
mooring code whose catenary solver takes the seabed friction coefficient CB.

Two scenes, each a line from an anchor on a flat bottom (end a) to a fixed fairlead (end b), with
`&seabed static_friction = 'end_a'` in xcable (the friction fully mobilised towards the anchor,
as MoorPy's CB assumes):
  catenary  the scene of test seabed/catenary_with_static_friction_closed_form: 100 m line,
            d 0.1 m, 2000 kg/m^3, EA 1e8 N, in sea water, span 80 m, drop 40 m;
  chain     the chain of input/chain_mooring_heave.nml on a flat bottom 60 m down: 250 m of
            76 mm R4 studless chain (MoorPy's coefficients), fairlead 10 m under the surface,
            230 m from the anchor.
Printed per friction coefficient and resolution: the anchor's tension, the fairlead's horizontal
and vertical force, the grounded length (xcable: /summary@static_grounded_length), and MoorPy's.

Usage: python3 bench/peer/static_friction.py [--exe bin/xcable] [--nodes 201 401 801]
"""

import argparse
import math
import os
import subprocess
import sys
import tempfile

import h5py
from moorpy.Catenary import catenary

G, RHO = 9.81, 1025.0


def scenes():
    """(name, length, EA, wet weight N/m, span, drop, namelist head with %MU% and %NODES%)."""
    d = 0.1
    area = math.pi * d * d / 4
    w_cat = (2000.0 - RHO) * area * G
    cat = ("&cable length = 100, diameter = 0.1, density = 2000, bending_stiffness = 1e-3 /\n"
           "&material law = 'linear', ea = 1e8 /\n"
           "&fluid density = 1025, surface_z = 10 /\n"
           "&seabed depth = 40, stiffness = 1e10, mu_axial = %MU%, static_friction = 'end_a' /\n"
           "&end_a kind = 'fixed', x = 0, z = -40 /\n"
           "&end_b kind = 'fixed', x = 80, z = 0 /\n")
    dc = 0.076
    mass = 20.01e3 * dc * dc
    ea = 85.61e9 * dc * dc - 3.927e7 * dc ** 3
    dvol = 1.801 * dc
    w_chain = (mass - RHO * math.pi * dvol * dvol / 4) * G
    density = mass / (math.pi * dvol * dvol / 4)
    chain = ("&cable length = 250, diameter = %r, density = %r, bending_stiffness = 0 /\n"
             "&material law = 'linear', ea = %r /\n"
             "&fluid density = 1025, surface_z = 0 /\n"
             "&seabed depth = 60, mu_axial = %%MU%%, static_friction = 'end_a' /\n"
             "&end_a kind = 'fixed', x = 0, z = -60 /\n"
             "&end_b kind = 'fixed', x = 230, z = -10 /\n") % (dvol, density, ea)
    return [("catenary", 100.0, 1.0e8, w_cat, 80.0, 40.0, cat),
            ("chain", 250.0, ea, w_chain, 230.0, 50.0, chain)]


def run_xcable(exe, head, mu, nodes, work):
    path = os.path.join(work, "case.nml")
    with open(path, "w") as f:
        text = head.replace("%MU%", repr(mu))
        if mu == 0:
            text = text.replace("static_friction = 'end_a'", "static_friction = 'none'")
        f.write(text)
        f.write("&rupture enabled = .false. /\n")
        f.write("&numerics nodes = %d, dt = 1e-3, t_end = 1e-3, newton_tol = 1e-12 /\n" % nodes)
        f.write("&output file = '%s', interval = 0, quiet = .true. /\n" % os.path.join(work, "r.h5"))
    out = subprocess.run([exe, path], capture_output=True, text=True)
    if out.returncode != 0:
        return None, out.stderr.strip().splitlines()[-1]
    with h5py.File(os.path.join(work, "r.h5")) as f:
        s = f["summary"].attrs
        st = f["static"].attrs
        return (float(s["static_tension_a"]), float(s["static_tension_b"]),
                float(s["static_grounded_length"]), float(st["end_angle_b"])), ""


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--exe", default="bin/xcable")
    ap.add_argument("--nodes", type=int, nargs="+", default=[201, 401, 801])
    args = ap.parse_args()
    exe = os.path.abspath(args.exe)
    with tempfile.TemporaryDirectory() as work:
        for name, length, ea, w, span, drop, head in scenes():
            print("\n## %s: L %g m, EA %.4g N, w %.2f N/m, span %g m, drop %g m\n" % (name, length, ea, w, span, drop))
            print("| mu | code | anchor tension N | fairlead tension N | grounded length m |")
            print("|---|---|---|---|---|")
            for mu in (0.0, 0.5, 1.0):
                ha, va, hf, vf, info = catenary(span, drop, length, ea, w, CB=mu, Tol=1e-12, MaxIter=500)
                print("| %g | MoorPy | %.2f | %.2f | %.3f |" % (mu, math.hypot(ha, va), math.hypot(hf, vf),
                                                            info["LBot"]))
                for n in args.nodes:
                    res, why = run_xcable(exe, head, mu, n, work)
                    if res is None:
                        print("| %g | xcable %d nodes | failed: %s | | |" % (mu, n, why))
                        continue
                    print("| %g | xcable %d nodes | %.2f | %.2f | %.3f |" % (mu, n, res[0], res[1], res[2]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
