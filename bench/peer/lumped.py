#!/usr/bin/env python3
"""Lumped-mass peer reference for the cable release (bench/peer).

Model (2-D, x horizontal, z up):
  * nodes 0..N, node masses m ds (m ds / 2 at the two ends), ds = L / N;
  * segment j (nodes j, j+1) carries the tension T = f(eps_j) of its strain
    eps_j = |r_{j+1} - r_j| / ds - 1 along its own direction;
  * bending: at interior node i the turning angle theta_i between segments
    i-1 and i gives the moment M_i = EI theta_i / ds (curvature per
    unstretched length, as MoorDyn v2 uses the turning angle at interior
    nodes); the node forces are the exact gradient of the bending energy
    sum EI theta_i^2 / (2 ds), so the scheme conserves energy; no moment at
    the two (pinned) ends;
  * gravity -m_i g on every node; no fluid, no damping;
  * node 0 pinned; node N carries the end force F(t) = F_s ramp(t).
Initial state: the exact static equilibrium of this chain (no bending), with
end force F_s = (H, w0 L/2), H = sqrt(T_s^2 - (w0 L/2)^2).

Time integration: velocity Verlet (symplectic, one force evaluation per step)
by default, or classical RK4 (--integrator rk4, fixed step, a check only).
Step: dt = courant * ds / c_max with c_max = sqrt(max f' / m) over the whole
law (1110 m/s for the tanh law), rounded down so that a whole number of steps
fits in the sample interval; Verlet also keeps every step below
courant * ds l_min / (2 sqrt(EI/m)), the stability limit of the bending
modes on the shortest segment l_min (this binds only for fine chains whose
segments are strongly compressed, e.g. N = 6400 at 315 kN).

Output: one TSV row per sample (columns of peer_common.COLUMNS): released-end
position and speed, tension at end a (the support force projected on the
first segment's direction), strain, kinetic, bending, gravity energies
(gravity m_i g z_i with z = 0 at the supports), work of the end force
(trapezoid in time of F . dx_N, consistent with the integrator) and the
ledger strain + kinetic + bending + gravity - work.

Usage:
  python3 lumped.py CASE [--n 400] [--courant 0.5] [--law tanh] [--out FILE]
  python3 lumped.py --tension 5000 --t-break 0.05 --t-end 2 --sample 0.01 ...
"""

import argparse
import json
import math
import sys
import time

import numpy as np

import peer_common as pc


class Chain:
    """The lumped-mass chain: forces and energies."""

    def __init__(self, law, n, ei=pc.EI, mass=pc.MASS, g=pc.GRAVITY):
        self.law, self.n, self.ei, self.g = law, n, ei, g
        self.ds = pc.LENGTH / n
        self.m = np.full(n + 1, mass * self.ds)
        self.m[0] *= 0.5
        self.m[-1] *= 0.5
        self.kb = ei / self.ds
        self.mfull = np.zeros(n + 1)      # moments at nodes, 0 at the ends

    def forces(self, x, z, fx_end, fz_end):
        """Node forces (without the support reaction at node 0).

        Returns fx, fz and the tension at end a (support force . first
        segment direction) and the segment strains.
        """
        dx = x[1:] - x[:-1]
        dz = z[1:] - z[:-1]
        l = np.sqrt(dx * dx + dz * dz)
        np.maximum(l, 1e-12, out=l)
        qx = dx / l
        qz = dz / l
        eps = l / self.ds - 1.0
        t = self.law.tension(eps)
        # bending: theta_i = angle from q_{i-1} to q_i, i = 1..n-1
        cr = qx[:-1] * qz[1:] - qz[:-1] * qx[1:]
        dt_ = qx[:-1] * qx[1:] + qz[:-1] * qz[1:]
        theta = np.arctan2(cr, dt_)
        self.mfull[1:-1] = self.kb * theta
        gseg = (self.mfull[:-1] - self.mfull[1:]) / l   # dE/dphi_j / l_j
        # segment j pulls node j with t q_j, node j+1 with -t q_j;
        # bending: node j gets +gseg n_j, node j+1 gets -gseg n_j, n = (-qz, qx)
        sx = t * qx - gseg * qz
        sz = t * qz + gseg * qx
        fx = np.zeros_like(x)
        fz = -self.m * self.g
        fx[:-1] += sx
        fz[:-1] += sz
        fx[1:] -= sx
        fz[1:] -= sz
        fx[-1] += fx_end
        fz[-1] += fz_end
        tension_a = fx[0] * qx[0] + fz[0] * qz[0]
        return fx, fz, tension_a, eps, theta

    def energies(self, x, z, vx, vz):
        dx = x[1:] - x[:-1]
        dz = z[1:] - z[:-1]
        l = np.sqrt(dx * dx + dz * dz)
        eps = l / self.ds - 1.0
        e_strain = self.ds * float(np.sum(self.law.energy(eps)))
        e_kin = 0.5 * float(np.sum(self.m * (vx * vx + vz * vz)))
        cr = dx[:-1] * dz[1:] - dz[:-1] * dx[1:]
        dt_ = dx[:-1] * dx[1:] + dz[:-1] * dz[1:]
        theta = np.arctan2(cr, dt_)
        e_bend = 0.5 * self.kb * float(np.sum(theta * theta))
        e_grav = self.g * float(np.sum(self.m * z))
        return e_strain, e_kin, e_bend, e_grav


def run(tension, t_break, t_end, sample, n=400, courant=0.5, law=None,
        integrator="verlet", progress=False, snapshot_every=0):
    """Run one release; returns (rows, info[, snapshots]).

    snapshot_every > 0: also return the node positions and velocities every
    so many samples, as a list of (t, x, z, vx, vz).
    """
    snaps = []
    law = law or pc.TanhLaw()
    chain = Chain(law, n)
    r0, eps0 = pc.discrete_catenary(law, tension, n)
    fx_s, fz_s = pc.end_force(tension)
    c_max = math.sqrt(law.stiffness_max / pc.MASS)
    dt_target = courant * chain.ds / c_max
    nsub = max(1, int(math.ceil(sample / dt_target - 1e-9)))
    dt = sample / nsub
    nsamples = int(round(t_end / sample))
    # bending: the fastest mode of sum EI theta^2 / (2 ds) on a straight run
    # of segments of length l has omega = 4 sqrt(EI/m) / (ds l); Verlet needs
    # omega dt < 2, so dt < ds l / (2 sqrt(EI/m)); with l = ds (1 + eps) this
    # is dt_bend_unit (1 + eps), taken at the shortest segment (Verlet only)
    dt_bend_unit = chain.ds ** 2 / (2.0 * math.sqrt(chain.ei / pc.MASS))

    x = r0[:, 0].copy()
    z = r0[:, 1].copy()
    vx = np.zeros(n + 1)
    vz = np.zeros(n + 1)
    minv = 1.0 / chain.m
    minv[0] = 0.0                       # pinned end a

    def accel(x, z, t):
        k = pc.ramp(t, t_break) if t_break > 0 else (1.0 if t < 0 else 0.0)
        fx, fz, ta, eps, theta = chain.forces(x, z, k * fx_s, k * fz_s)
        return fx * minv, fz * minv, ta, k, eps, theta

    rows = []
    work = 0.0
    t = 0.0
    # at t = 0 the end force is the static one (ramp(0) = 1); with
    # t_break = 0 it is taken as already released for t > 0
    ax, az, ta, k, eps, theta = accel(x, z, 0.0)
    ta_static = ta
    t_drop = None
    eps_min = float(eps.min())
    theta_max = float(np.abs(theta).max())
    ledger0 = None
    speed_max = 0.0
    eps_low = []          # lowest strain since the previous sample
    low = [eps_min]

    def record():
        nonlocal ledger0
        es, ek, eb, eg = chain.energies(x, z, vx, vz)
        led = es + ek + eb + eg - work
        if ledger0 is None:
            ledger0 = led
        rows.append((t, x[-1], z[-1], math.hypot(vx[-1], vz[-1]), ta,
                     es, ek, eb, eg, work, led))
        eps_low.append(low[0])
        low[0] = math.inf
        if snapshot_every and (len(rows) - 1) % snapshot_every == 0:
            snaps.append((t, x.copy(), z.copy(), vx.copy(), vz.copy()))

    record()
    wall = time.time()
    ta_prev = ta
    if integrator == "verlet":
        if t_break == 0:
            # released at once: the force acting from t = 0+ on is zero
            ax, az, ta, k, eps, theta = accel(x, z, 1.0)
        fk = k
        steps = 0
        dt_min = dt
        for isamp in range(nsamples):
            t_next = (isamp + 1) * sample
            while t < t_next:
                # step: the axial limit (fixed) or the bending limit of the
                # shortest segment, whichever is smaller, landing on t_next
                h = min(dt, courant * dt_bend_unit * max(float(eps.min()) + 1.0, 1e-3))
                if t + 1.000001 * h >= t_next:
                    h = t_next - t
                else:
                    nleft = math.ceil((t_next - t) / h - 1e-9)
                    h = (t_next - t) / nleft
                dt_min = min(dt_min, h)
                vx += 0.5 * h * ax
                vz += 0.5 * h * az
                xo, zo = x[-1], z[-1]
                x += h * vx
                z += h * vz
                t = t_next if t + 1.000001 * h >= t_next else t + h
                ax, az, ta, k, eps, theta = accel(x, z, t)
                work += 0.5 * (fk + k) * (fx_s * (x[-1] - xo) + fz_s * (z[-1] - zo))
                fk = k
                vx += 0.5 * h * ax
                vz += 0.5 * h * az
                steps += 1
                if t_drop is None and ta < 0.99 * ta_static:
                    t_drop = t - h * (0.99 * ta_static - ta) / (ta_prev - ta) \
                        if ta_prev != ta else t
                ta_prev = ta
                em = float(eps.min())
                if em < eps_min:
                    eps_min = em
                if em < low[0]:
                    low[0] = em
                tm = float(np.abs(theta).max())
                if tm > theta_max:
                    theta_max = tm
            sp = math.hypot(vx[-1], vz[-1])
            speed_max = max(speed_max, sp)
            record()
            if progress and (isamp + 1) % max(1, nsamples // 20) == 0:
                print("  t = %.3f s  ledger drift %.3e J  (%.1f s)" %
                      (t, rows[-1][-1] - ledger0, time.time() - wall),
                      file=sys.stderr, flush=True)
    elif integrator == "rk4":
        # state: x, z, vx, vz and the work of the end force
        def deriv(x, z, vx, vz, t):
            ax, az, ta, k, eps, theta = accel(x, z, t)
            p = k * (fx_s * vx[-1] + fz_s * vz[-1])
            return vx, vz, ax, az, p, ta, eps, theta
        for isamp in range(nsamples):
            for _ in range(nsub):
                k1 = deriv(x, z, vx, vz, t if t > 0 else 1e-300)
                h2 = 0.5 * dt
                k2 = deriv(x + h2 * k1[0], z + h2 * k1[1], vx + h2 * k1[2],
                           vz + h2 * k1[3], t + h2)
                k3 = deriv(x + h2 * k2[0], z + h2 * k2[1], vx + h2 * k2[2],
                           vz + h2 * k2[3], t + h2)
                k4 = deriv(x + dt * k3[0], z + dt * k3[1], vx + dt * k3[2],
                           vz + dt * k3[3], t + dt)
                for i, arr in enumerate((x, z, vx, vz)):
                    arr += dt / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i])
                work += dt / 6 * (k1[4] + 2 * k2[4] + 2 * k3[4] + k4[4])
                t += dt
                _, _, ta, k, eps, theta = accel(x, z, t)
                if t_drop is None and ta < 0.99 * ta_static:
                    t_drop = t - dt * (0.99 * ta_static - ta) / (ta_prev - ta) \
                        if ta_prev != ta else t
                ta_prev = ta
                eps_min = min(eps_min, float(eps.min()))
                low[0] = min(low[0], float(eps.min()))
                theta_max = max(theta_max, float(np.abs(theta).max()))
            speed_max = max(speed_max, math.hypot(vx[-1], vz[-1]))
            record()
            if progress and (isamp + 1) % max(1, nsamples // 20) == 0:
                print("  t = %.3f s  ledger drift %.3e J  (%.1f s)" %
                      (t, rows[-1][-1] - ledger0, time.time() - wall),
                      file=sys.stderr, flush=True)
    else:
        raise ValueError("integrator must be verlet or rk4")
    wall = time.time() - wall

    led = np.array([r[-1] for r in rows])
    es0 = rows[0][5]
    info = {
        "code": "lumped.py", "law": law.name, "integrator": integrator,
        "N": n, "dt": dt, "courant": courant, "c_max": c_max,
        "tension": tension, "t_break": t_break, "t_end": t_end,
        "sample": sample, "span": float(r0[-1, 0]),
        "H": fx_s, "V": fz_s, "tension_a_static": ta_static,
        "ledger_drift_max_J": float(np.max(np.abs(led - led[0]))),
        "ledger_drift_rel_strain0": float(np.max(np.abs(led - led[0])) / es0),
        "E_strain0": es0,
        "eps_min": eps_min, "theta_max": theta_max, "speed_max_sampled": speed_max,
        "eps_min_per_sample": [round(v, 5) for v in eps_low],
        "t_drop_1pct": t_drop, "wall_s": wall,
        "steps": steps if integrator == "verlet" else nsub * nsamples,
        "dt_min": dt_min if integrator == "verlet" else dt,
    }
    if snapshot_every:
        return rows, info, snaps
    return rows, info


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("case", nargs="?", help="case name (see peer_common.cases)")
    ap.add_argument("--tension", type=float)
    ap.add_argument("--t-break", type=float)
    ap.add_argument("--t-end", type=float)
    ap.add_argument("--sample", type=float)
    ap.add_argument("--n", type=int, default=400, help="segments (400)")
    ap.add_argument("--courant", type=float, default=0.5,
                    help="dt = courant * ds / c_max (0.5)")
    ap.add_argument("--law", default="tanh",
                    help="tanh | tanh-nocomp | table:FILE (MoorDyn-style table)")
    ap.add_argument("--integrator", default="verlet", choices=("verlet", "rk4"))
    ap.add_argument("--out", help="TSV output file")
    ap.add_argument("--info", help="JSON file for the run summary")
    ap.add_argument("--progress", action="store_true")
    a = ap.parse_args(argv)

    if a.case:
        ts, tb, te, smp = pc.cases()[a.case]
    else:
        ts, tb, te, smp = a.tension, 0.0, 1.0, 0.01
    ts = a.tension if a.tension is not None else ts
    tb = a.t_break if a.t_break is not None else tb
    te = a.t_end if a.t_end is not None else te
    smp = a.sample if a.sample is not None else smp

    if a.law == "tanh":
        law = pc.TanhLaw()
    elif a.law == "tanh-nocomp":
        law = pc.NoCompressionLaw()
    elif a.law.startswith("table:"):
        d = np.loadtxt(a.law[6:], skiprows=3)
        law = pc.TableLaw(d[:, 0], d[:, 1])
    else:
        ap.error("unknown law " + a.law)

    rows, info = run(ts, tb, te, smp, n=a.n, courant=a.courant, law=law,
                     integrator=a.integrator, progress=a.progress)
    info["case"] = a.case
    if a.out:
        pc.write_tsv(a.out, rows)
    if a.info:
        with open(a.info, "w") as f:
            json.dump(info, f, indent=1)
    print(json.dumps(info))


if __name__ == "__main__":
    main()
