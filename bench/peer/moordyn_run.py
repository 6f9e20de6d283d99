#!/usr/bin/env python3
"""MoorDyn v2 (PyPI package `moordyn`) on the cable release scenes (bench/peer).

What MoorDyn is asked to do, and how:
  * one line of N segments between point 1 (Fixed, end a at the origin) and
    point 2 (end b), 60 m unstretched, diameter 0.05 m, mass 2.2384 kg/m,
    EI = 70.56 N m^2, internal damping BA = 0;
  * the tanh law as a strain-tension lookup table (EA column = file name),
    at most 30 points (MoorDyn's nCoef); MoorDyn interpolates linearly,
    clamps beyond the last point and gives T = 0 for eps < 0 (a MoorDyn line
    cannot push): the compressive branch of the law cannot be expressed;
  * no fluid: water density `rho 0` (no buoyancy), Cd = Ca = CdAx = CaAx = 0
    (no drag, no added mass), water depth 1000 m (no seabed contact);
  * the initial state: the discrete static catenary of the same chain with
    the table law (nodes written into a MoorDyn state file and loaded with
    LoadState after Init_NoIC, so MoorDyn's own IC solver is not used);
  * the ramped end force: MoorDyn-C has no time-varying external force on a
    point (a point's force column is a constant; the EXTERNAL LOADS section is
    MoorDyn-F only). Point 2 is therefore a Coupled point and this script
    integrates the end node: MoorDyn returns the line force on point 2
    (tension, bending and the weight of the end node) and the mass of the
    end node; velocity Verlet on the end node with F(t) = F_s ramp(t) added,
    MoorDyn moving the point at the mid-step velocity during each coupling
    step (one MoorDyn step per coupling step, MoorDyn's RK4 inside);
  * --free: t_break = 0 only: point 2 is a plain Free point (no coupling
    loop), released at t = 0, as a check of the coupling loop.

The energies are computed here from the node positions and velocities with
the same formulas as lumped.py (table-law strain energy, bending energy
sum EI theta^2 / (2 ds), which MoorDyn's bending forces approximate but are
not the exact gradient of).

Usage: python3 moordyn_run.py CASE [--n 400] [--courant 0.5] [--out FILE]
"""

import argparse
import json
import math
import os
import struct
import sys
import tempfile
import time

import numpy as np

import peer_common as pc

import moordyn


def write_table(path, xs, ys):
    # three header lines; no newline after the last point (MoorDyn reads a
    # trailing empty line as a bad curve point)
    with open(path, "w") as f:
        f.write("Strain Tension\n(-) (N)\n--------\n")
        f.write("\n".join("%.12g %.12g" % (a, b) for a, b in zip(xs, ys)))


def write_input(path, table_name, n, span, dtm, free=False):
    kind = "Free" if free else "Coupled"
    txt = f"""MoorDyn v2 input: peer reference of the xcable release (bench/peer)
---------------------- LINE TYPES -----------------------------------
TypeName   Diam    Mass/m     EA      BA/-zeta     EI    Cd     Ca    CdAx    CaAx
(name)     (m)     (kg/m)     (N)     (N-s/-)    (N-m^2) (-)   (-)   (-)     (-)
nylon      {pc.DIAMETER:.10g}  {pc.MASS:.12g}  {table_name}  0.0  {pc.EI:.12g}  0.0  0.0  0.0  0.0
---------------------------- POINTS -------------------------------------------
ID  Attachment  X       Y     Z      Mass   Volume  CdA    CA
(#)   (-)       (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
1     Fixed     0.0     0.0   0.0    0.0    0.0     0.0    0.0
2     {kind}    {span:.15g}  0.0   0.0    0.0    0.0     0.0    0.0
---------------------- LINES ----------------------------------------
ID   LineType AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)  (name)   (#)      (#)      (m)       (-)      (-)
1    nylon     1        2       {pc.LENGTH:.12g}      {n}      -
---------------------- OPTIONS -----------------------------------------
0        writeLog
{dtm:.12g}  dtM
RK4      tScheme
{pc.GRAVITY}     g
0        rho
1000     WtrDpth
1        disableOutput
1        disableOutTime
---------------------- OUTPUTS -----------------------------------------
------------------------- need this line -------------------------------------
"""
    with open(path, "w") as f:
        f.write(txt)


def write_state(path, r, point_states):
    """MoorDyn v2 state file: the line's interior nodes at rest.

    Layout (as written by MoorDyn's SaveState): 'MoorDyn', 2 version bytes,
    uint64 count, uint64 instances, then per instance uint64 rows, cols and
    rows x cols doubles. Here: one 1x6 block per point (position and
    velocity; zeros are read back for Fixed and Coupled points), then the line's
    N-1 interior nodes (x, y, z, vx, vy, vz).
    """
    data = b""
    ninst = 0
    for ps in point_states:
        data += struct.pack("<QQ", 1, 6) + struct.pack("<6d", *ps)
        ninst += 1
    inner = r[1:-1]
    data += struct.pack("<QQ", len(inner), 6)
    for x, z in inner:
        data += struct.pack("<6d", x, 0.0, z, 0.0, 0.0, 0.0)
    ninst += 1
    with open(path, "wb") as f:
        f.write(b"MoorDyn" + struct.pack("<BB", 2, 7))
        f.write(struct.pack("<QQ", len(data) // 8 + 1, ninst))
        f.write(data)


def run(tension, t_break, t_end, sample, n=400, courant=0.5, eps_max=None,
        free=False, workdir=None, quiet=True, drift_limit=0.02):
    law = pc.TanhLaw()
    eps_s = law.strain(tension)
    eps_max = eps_max or 1.3 * eps_s
    xs, ys = pc.moordyn_table(law, eps_max)
    tab = pc.TableLaw(xs, ys)
    r0, _ = pc.discrete_catenary(tab, tension, n)
    fx_s, fz_s = pc.end_force(tension)
    span = float(r0[-1, 0])
    ds = pc.LENGTH / n
    c_max = math.sqrt(tab.stiffness_max / pc.MASS)
    nsub = max(1, int(math.ceil(sample / (courant * ds / c_max) - 1e-9)))
    h = sample / nsub
    nsamples = int(round(t_end / sample))
    if free and t_break != 0:
        raise ValueError("--free needs t_break = 0")

    workdir = workdir or tempfile.mkdtemp(prefix="md_")
    os.makedirs(workdir, exist_ok=True)
    write_table(os.path.join(workdir, "ea_table.txt"), xs, ys)
    inp = os.path.join(workdir, "cable.txt")
    write_input(inp, "ea_table.txt", n, span, h, free=free)
    write_state(os.path.join(workdir, "static.state"), r0,
                [[0.0] * 6, [span, 0.0, 0.0, 0.0, 0.0, 0.0]])

    # MoorDyn prints a banner on stdout: keep it out of ours
    saved = os.dup(1)
    if quiet:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, 1)
    try:
        sysm = moordyn.Create(inp)
        moordyn.SetVerbosity(sysm, moordyn.LEVEL_ERR)
        xb = np.array([span, 0.0, 0.0])
        vb = np.zeros(3)
        if free:
            moordyn.Init_NoIC(sysm, [], [])
        else:
            moordyn.Init_NoIC(sysm, list(xb), list(vb))
        moordyn.LoadState(sysm, os.path.join(workdir, "static.state"))
    finally:
        if quiet:
            os.dup2(saved, 1)
            os.close(devnull)
        os.close(saved)
    line = moordyn.GetLine(sysm, 1)
    point_b = moordyn.GetPoint(sysm, 2)

    chain_m = np.full(n + 1, pc.MASS * ds)
    chain_m[0] *= 0.5
    chain_m[-1] *= 0.5
    m_end = chain_m[-1]

    def nodes():
        p = np.array([moordyn.GetLineNodePos(line, i) for i in range(n + 1)])
        v = np.array([moordyn.GetLineNodeVel(line, i) for i in range(n + 1)])
        return p, v

    r_a = np.array([0.0, 0.0, 0.0])

    def tension_a(p1=None):
        if p1 is None:
            p1 = np.array(moordyn.GetLineNodePos(line, 1))
        d = p1 - r_a
        l = float(np.linalg.norm(d))
        t0 = float(tab.tension(l / ds - 1.0))
        # bending acts normal to the first segment; weight of node 0 projected
        return t0 - chain_m[0] * pc.GRAVITY * d[2] / l

    def energies(p, v):
        d = p[1:] - p[:-1]
        l = np.linalg.norm(d, axis=1)
        e_strain = ds * float(np.sum(tab.energy(l / ds - 1.0)))
        e_kin = 0.5 * float(np.sum(chain_m * np.sum(v * v, axis=1)))
        cr = d[:-1, 0] * d[1:, 2] - d[:-1, 2] * d[1:, 0]
        dt_ = d[:-1, 0] * d[1:, 0] + d[:-1, 2] * d[1:, 2]
        th = np.arctan2(cr, dt_)
        e_bend = 0.5 * pc.EI / ds * float(np.sum(th * th))
        e_grav = pc.GRAVITY * float(np.sum(chain_m * p[:, 2]))
        return (e_strain, e_kin, e_bend, e_grav, float(np.max(l / ds - 1.0)),
                float(np.min(l / ds - 1.0)))

    rows = []
    work = 0.0
    t = 0.0
    t_drop = None
    eps_top = 0.0
    eps_low = [0.0]

    # MoorDyn's node positions are refreshed from the loaded state only when
    # a step starts: the record at t = 0 is made from the state written
    p_static = np.zeros((n + 1, 3))
    p_static[:, 0] = r0[:, 0]
    p_static[:, 2] = r0[:, 1]
    ta0 = tension_a(p_static[1])
    ta_prev = ta0

    def record(vend):
        nonlocal eps_top
        if t == 0.0:
            p, v = p_static.copy(), np.zeros((n + 1, 3))
            ta = ta0
        else:
            p, v = nodes()
            ta = tension_a()
        if not free and vend is not None:
            v[-1] = vend          # the end node's full-step velocity
        es, ek, eb, eg, emax, emin = energies(p, v)
        eps_top = max(eps_top, emax)
        eps_low.append(emin)
        rows.append((t, p[-1, 0], p[-1, 2], float(np.linalg.norm(v[-1])),
                     ta, es, ek, eb, eg, work, es + ek + eb + eg - work))

    record(vb)
    fs = np.array([fx_s, 0.0, fz_s])
    # the end node's mass (MoorDyn's node mass A rho l / 2; its point mass
    # matrix is filled only once a step has been made); at t = 0 the line
    # force on point 2 balances F_s (static state), so the acceleration is 0
    m_b = m_end
    k_prev = 1.0
    acc = np.zeros(3)
    failure = None
    t_valid = None
    es0 = rows[0][5]
    wall = time.time()
    try:
        for _ in range(nsamples):
            for _ in range(nsub):
                if free:
                    moordyn.Step(sysm, [], [], t, h)
                    t += h
                else:
                    vhalf = vb + 0.5 * h * acc
                    f_line = np.asarray(moordyn.Step(sysm, list(xb), list(vhalf), t, h))
                    xn = xb + h * vhalf
                    t += h
                    k = pc.ramp(t, t_break)
                    work += 0.5 * (k_prev + k) * float(np.dot(fs, xn - xb))
                    k_prev = k
                    acc = (f_line + k * fs) / m_b
                    vb = vhalf + 0.5 * h * acc
                    xb = xn
                ta = tension_a()
                if t_drop is None and ta < 0.99 * ta0:
                    t_drop = t - h * (0.99 * ta0 - ta) / (ta_prev - ta)
                ta_prev = ta
            record(None if free else vb)
            drift = rows[-1][-1] - rows[0][-1]
            if t_valid is None and (drift > drift_limit * es0 or
                                    abs(drift) > 10 * drift_limit * es0 or
                                    eps_low[-1] < -0.9):
                # a segment has collapsed (MoorDyn lines cannot push: nothing
                # stops a segment shrinking to nothing) or the energy is no
                # longer conserved: the results stop being meaningful here
                t_valid = rows[-2][0]
            if t_valid is not None and len(rows) > 1 and \
                    rows[-1][0] > t_valid + 20 * sample:
                failure = ("segment collapse (strain < -0.9), energy created "
                           "(ledger up by 2 % of E_strain(0)) or lost (20 %)")
                break
    except RuntimeError as exc:
        failure = "MoorDyn error at t = %.5f s: %s" % (t, exc)
        if t_valid is None:
            t_valid = rows[-1][0]
    wall = time.time() - wall
    moordyn.Close(sysm)

    led = np.array([row[-1] for row in rows])
    info = {
        "code": "moordyn_run.py", "moordyn": moordyn_version(),
        "coupling": "free point" if free else "coupled point, Verlet end node",
        "N": n, "dt": h, "courant": courant, "c_max_table": c_max,
        "table_points": len(xs), "table_eps_max": float(xs[-1]),
        "table_max_error_N": table_error(law, tab),
        "tension": tension, "t_break": t_break, "t_end": t_end,
        "sample": sample, "span": span, "end_mass": m_end,
        "tension_a_static": ta0,
        "ledger_drift_max_J": float(np.max(np.abs(led - led[0]))),
        "ledger_drift_rel_strain0": float(np.max(np.abs(led - led[0])) / es0),
        "eps_max_sampled": eps_top, "eps_min_sampled": float(min(eps_low)),
        "t_drop_1pct": t_drop,
        "t_valid": t_valid, "stopped": failure,
        "steps_per_sample": nsub, "wall_s": wall, "workdir": workdir,
    }
    if t_valid is not None:
        keep = [r for r in rows if r[0] <= t_valid + 1e-12]
        v = np.array([r[-1] for r in keep])
        info["ledger_drift_rel_strain0_valid"] = float(np.max(np.abs(v - v[0])) / es0)
    if eps_top > xs[-1]:
        info["warning"] = "strain beyond the table (tension clamped)"
    return rows, info



def table_error(law, tab):
    e = np.linspace(0.0, tab.xs[-1], 20001)
    return float(np.max(np.abs(tab.tension(e) - np.maximum(law.f(e), 0.0))))


def moordyn_version():
    try:
        from importlib.metadata import version
        return version("moordyn")
    except Exception:
        return "unknown"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("case")
    ap.add_argument("--t-break", type=float)
    ap.add_argument("--t-end", type=float)
    ap.add_argument("--n", type=int, default=400)
    ap.add_argument("--courant", type=float, default=0.5,
                    help="dt = courant * ds / c_max of the table (0.5)")
    ap.add_argument("--eps-max", type=float,
                    help="last table strain (default 1.3 x static strain)")
    ap.add_argument("--free", action="store_true",
                    help="t_break = 0 release with a Free point 2")
    ap.add_argument("--workdir")
    ap.add_argument("--out")
    ap.add_argument("--info")
    a = ap.parse_args(argv)
    ts, tb, te, smp = pc.cases()[a.case]
    tb = a.t_break if a.t_break is not None else tb
    te = a.t_end if a.t_end is not None else te
    rows, info = run(ts, tb, te, smp, n=a.n, courant=a.courant,
                     eps_max=a.eps_max, free=a.free, workdir=a.workdir)
    info["case"] = a.case
    if a.out:
        if info.get("t_valid") is not None:
            rows = [r for r in rows if r[0] <= info["t_valid"] + 1e-12]
        pc.write_tsv(a.out, rows)
    if a.info:
        with open(a.info, "w") as f:
            json.dump(info, f, indent=1)
    print(json.dumps(info))


if __name__ == "__main__":
    main()
