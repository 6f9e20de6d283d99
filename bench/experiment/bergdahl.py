#!/usr/bin/env python3
"""Bergdahl et al. (2016): a 33 m chain on a tank floor, its fairlead moved on a circle; xcable
against the measured top tension.

bench/experiment, not part of `make test`. Report: bench/experiment/bergdahl.md.

Source. L. Bergdahl, J. Palm, C. Eskilsson, J. Lindahl, "Dynamically Scaled Model Experiment of
a Mooring Cable", J. Mar. Sci. Eng. 4(1), 5 (2016), doi:10.3390/jmse4010005 (CC BY 4.0): Jan
Lindahl's 1984 experiment at Chalmers. Measured tension histories: the article's supplement
`expData.dat` as shipped with Moody's tutorial T1 (github.com/Qxp-git/MoodyAPI,
moodyCore-3.0.0-Linux/.../tutorials/T1_singleCatenary/), columns t (s), T (N) at T = 1.25 s
R = 0.2 m, T (N) at T = 3.5 s R = 0.2 m; a copy is bench/experiment/data/expData.dat. The
table of measured mean cycle maxima (30 cases): the article's table as carried in
github.com/SMI-Lab-Inha/CableDyn validation/experiments/bergdahl/prepare_bergdahl_cases.py
(MEASURED_MAXIMUM_N), see MEASURED below.

Scene (x along the line, z up, still water level z = 0, tank floor z = -3 m):
  * chain 33 m, 0.0818 kg/m, steel 7800 kg/m^3 (so the steel's cross-section is
    A = 0.0818 / 7800 = 1.0487e-5 m^2 and the submerged weight 0.699 N/m), nominal diameter
    d = 2.2 mm, EA = 1e4 N, no compression (`compression = 'none'`), no bending stiffness to speak
    of (`bending_stiffness` at the schema's floor, 1e-6 N m^2), no material damping;
  * &cable diameter = d (drag and the seabed's per-diameter coefficients), area = A (mass,
    buoyancy, added mass), density 7800;
  * water 1000 kg/m^3 up to z = 0, no air (Moody's airDensity 0): the top 0.3 m is dry;
  * Cd normal 2.5 on d; Cd tangential 0.5 on d (Moody's f_D = 1/2 rho d (Cdt |v_t| v_t + ...),
    manual eq. A.31), so xcable's cd_tangential (on pi d) is 0.5 / pi; Ca normal 3.8 on the
    nominal section pi d^2 / 4 (Moody's A_c, the circular section of its diameter), so xcable's
    ca_normal (on A) is 3.8 (pi d^2 / 4) / A = 1.377; `--ca-volume` puts 3.8 on A instead
    (CableDyn's reading, added mass 2.8 times larger);
  * anchor (end a) fixed at (0, -3); fairlead (end b) about (32.554, 0.3);
  * seabed at z = -3: stiffness 3e9 Pa per metre of penetration and per metre of diameter
    (Moody's Kg on d: 6.6e6 N/m per metre of chain), damping at the critical ratio of Moody's
    input (dampingCoeff = 1): 2 sqrt(Kg d m) / d = 6.68e5 Pa s/m on d, friction 0.3 along the
    line with slip speed 0.01 m/s (Moody's frictionCoeff, frictionVelocity). These are the
    settings of Moody's input (lindahl125.m, lindahl35.m), not measured.
  * motion, as Moody's (mode 'sine', amplitude [R; 0; -R], phase [90; 0; 0] deg, rampTime
    t_r): x = x0 + Q(t) R cos(w t), z = z0 - Q(t) R sin(w t), Q = (1 - cos(pi t / t_r)) / 2
    for t < t_r, then 1; t_r = 2 T (Moody: 2.5 s at T = 1.25 s, 7 s at 3.5 s). xcable has one
    direction per harmonic motion, so the circle is a `motion = 'table'` file of displacements
    (at most 1000 rows: cubic Hermite between them). Moody's phase shifts to the measurement
    (post.py: -0.649 s at 1.25 s, -2.945 s at 3.5 s) then hold for xcable as well.

xcable's top tension is /history/end_b/tension (the end cell's tension carried to the end).

Usage:
  python3 bergdahl.py wave  [--period 1.25 3.5] [--resolution NODES:DT ...]   (each resolution)
  python3 bergdahl.py table [--periods ...] [--radii ...] [--resolution NODES:DT]  (the last one)
  cd bench/experiment && gnuplot bergdahl.gp   (figures from the --tsv data)
Common options: --exe bin/xcable, --work DIR (runs kept there, reused when present; default
bench/experiment/runs), --jobs N (2), --settle N (2 cycles after the start), --assess N (5 cycles
compared), --tsv DIR (figure data). Sensitivities (not the scene): --ca-volume,
--seabed-stiffness PA, --friction MU, --damping C (material, N s; Moody's input has 2).
"""

import argparse
import concurrent.futures
import json
import math
import os
import resource
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
EXP_DATA = os.path.join(HERE, 'data', 'expData.dat')

# The scene (see the docstring).
LENGTH = 33.0
MASS = 0.0818                     # kg/m
STEEL = 7800.0                    # kg/m^3
AREA = MASS / STEEL               # m^2, steel section: mass, buoyancy, added mass
DIAM = 0.0022                     # m, nominal chain diameter: drag, seabed coefficients
EA = 1.0e4                        # N
RHO_W = 1000.0
G = 9.81                          # Moody's gravity
CDN = 2.5
CDT = 0.5 / math.pi               # 0.5 on d (Moody) expressed on pi d (xcable)
CA_NOMINAL = 3.8 * (math.pi * DIAM**2 / 4) / AREA   # 3.8 on pi d^2 / 4, expressed on A
CA_VOLUME = 3.8                   # 3.8 on A (CableDyn's reading)
DEPTH = 3.0
KBOT = 3.0e9                      # Pa (per m of penetration, per m of diameter)
CBOT = 2.0 * math.sqrt(KBOT * DIAM * MASS) / DIAM   # critical ratio 1, per m of diameter
MU = 0.3
VSLIP = 0.01
DAMPING = 0.0                     # N s, material (Kelvin-Voigt); Moody's input has xi = 2 N s
ANCHOR = (0.0, -3.0)
FAIRLEAD = (32.554, 0.3)

PERIODS = (1.25, 1.50, 2.00, 2.50, 3.00, 3.50)
RADII = (0.075, 0.100, 0.125, 0.150, 0.200)
# Measured mean cycle maximum of the top tension (N), rows PERIODS, columns RADII: the article's
# table, as carried in CableDyn's prepare_bergdahl_cases.py (MEASURED_MAXIMUM_N).
MEASURED = {
    1.25: (42.5, 46.8, 54.1, 60.4, 70.3),
    1.50: (41.0, 45.3, 51.5, 59.0, 68.0),
    2.00: (36.0, 39.5, 47.5, 54.1, 62.3),
    2.50: (31.1, 35.4, 42.5, 49.0, 57.3),
    3.00: (29.5, 33.1, 39.3, 45.8, 54.0),
    3.50: (27.8, 31.5, 37.5, 42.5, 50.1),
}
# Moody's time shift onto the measured record (its tutorial's post.py): t_exp = t_sim + shift.
MOODY_SHIFT = {1.25: -0.649, 3.5: -2.945}
# Column of each measured history in expData.dat.
EXP_COLUMN = {1.25: 1, 3.5: 2}


def motion(t, period, radius, ramp):
    """Fairlead displacement (dx, dz) at times t: Moody's 'sine' mode of lindahl125.m / 35.m."""
    t = np.asarray(t, dtype=float)
    q = np.where(t < ramp, 0.5 * (1.0 - np.cos(np.pi * np.clip(t, 0, ramp) / ramp)), 1.0)
    w = 2 * np.pi / period
    return q * radius * np.cos(w * t), -q * radius * np.sin(w * t)


def write_case(work, name, period, radius, nodes, dt, t_end, ca, ramp_cycles=2.0, rows=1000):
    """Namelist and motion table of one run; returns the namelist path."""
    ramp = ramp_cycles * period
    t = np.linspace(0.0, t_end, rows)
    dx, dz = motion(t, period, radius, ramp)
    table = os.path.join(work, name + '.motion')
    with open(table, 'w') as f:
        f.write(f'# Bergdahl et al. (2016) fairlead circle: T = {period} s, R = {radius} m, '
                f'start {ramp} s (Moody rampTime); t, dx, dz\n')
        for row in zip(t, dx, dz):
            f.write('%.9f %.12e %.12e\n' % row)
    nml = os.path.join(work, name + '.nml')
    with open(nml, 'w') as f:
        f.write(f"""! Bergdahl et al. (2016), doi:10.3390/jmse4010005: Lindahl's 33 m chain, T = {period} s, R = {radius} m
&cable    length = {LENGTH}, diameter = {DIAM}, density = {STEEL}, area = {AREA:.10e},
          bending_stiffness = 1e-6, gravity = {G} /
&material law = 'linear', ea = {EA}, compression = 'none', damping = {DAMPING} /
&fluid    density = {RHO_W}, cd_normal = {CDN}, cd_tangential = {CDT:.10f}, ca_normal = {ca:.10f},
          surface_z = 0, air_density = 0 /
&seabed   depth = {DEPTH}, stiffness = {KBOT}, damping = {CBOT:.6e}, mu_axial = {MU}, mu_lateral = {MU},
          slip_velocity = {VSLIP} /
&end_a    kind = 'fixed', x = {ANCHOR[0]}, z = {ANCHOR[1]} /
&end_b    kind = 'motion', motion = 'table', x = {FAIRLEAD[0]}, z = {FAIRLEAD[1]},
          table_file = '{os.path.basename(table)}' /
&numerics nodes = {nodes}, dt = {dt}, t_end = {t_end} /
&output   file = '{name}.h5', interval = 0, fields = 'tension', quiet = .true. /
""")
    return nml


def run_case(args):
    """One run (in a worker process): (namelist, CPU seconds of xcable, wall seconds)."""
    exe, nml = args
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.time()
    proc = subprocess.run([os.path.abspath(exe), os.path.basename(nml)], cwd=os.path.dirname(nml),
                          capture_output=True, text=True)
    if proc.returncode != 0:
        raise RuntimeError(f'{nml}: xcable exit {proc.returncode}\n{proc.stderr[-3000:]}')
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    with open(nml[:-4] + '.cpu', 'w') as f:
        f.write(f'{cpu:.3f} {time.time() - t0:.3f}\n')
    return nml


def load(h5):
    """Times, top tension, Newton iterations and rejected attempts of a run."""
    import h5py
    with h5py.File(h5, 'r') as f:
        h = f['history']
        return (h['time'][:], h['end_b/tension'][:], int(h['newton_iterations'][:].sum()),
                int(h['rejected'][:].sum()))


def cycle_extrema(t, y, start, period, cycles):
    """Maxima and minima of y over the cycles [start + k T, start + (k + 1) T), k < cycles."""
    mx, mn = [], []
    for k in range(cycles):
        m = (t >= start + k * period) & (t < start + (k + 1) * period)
        mx.append(y[m].max())
        mn.append(y[m].min())
    return np.array(mx), np.array(mn)


def phase_average(t, y, start, period, cycles, phases):
    """Mean of y(start + k T + phase) over k < cycles, interpolated linearly, and the cycles."""
    rows = np.array([np.interp(start + k * period + phases, t, y) for k in range(cycles)])
    return rows.mean(axis=0), rows


class Case:
    """One run: its name, scene, resolution and files."""

    def __init__(self, work, period, radius, nodes, dt, ca, settle, assess, tag=''):
        self.period, self.radius, self.nodes, self.dt = period, radius, nodes, dt
        self.ramp = 2.0 * period
        self.start = self.ramp + settle * period        # first assessed cycle
        self.assess = assess
        self.t_end = self.start + assess * period
        self.ca = ca
        self.name = (f'{tag}T{period:.2f}_R{radius:.3f}_n{nodes}_dt{dt:.4g}'
                     + ('_cavol' if ca == CA_VOLUME else '')
                     + (f'_k{KBOT:.0e}' if KBOT != 3.0e9 else '')
                     + (f'_mu{MU:g}' if MU != 0.3 else '')
                     + (f'_c{DAMPING:g}' if DAMPING != 0 else '')).replace('.', 'p')
        self.nml = os.path.join(work, self.name + '.nml')
        self.h5 = os.path.join(work, self.name + '.h5')

    def prepare(self):
        write_case(os.path.dirname(self.nml), self.name, self.period, self.radius, self.nodes,
                   self.dt, self.t_end, self.ca)

    def done(self):
        return os.path.exists(self.h5) and os.path.exists(self.nml[:-4] + '.cpu')

    def cpu(self):
        with open(self.nml[:-4] + '.cpu') as f:
            return float(f.read().split()[0])


def run_all(cases, exe, jobs):
    """Runs the cases not yet done, jobs at a time."""
    todo = [c for c in cases if not c.done()]
    for c in todo:
        c.prepare()
    with concurrent.futures.ProcessPoolExecutor(jobs) as pool:
        for nml in pool.map(run_case, [(exe, c.nml) for c in todo]):
            print(f'  ran {os.path.basename(nml)}', file=sys.stderr, flush=True)


def summary(case):
    """Figures of one run over its assessed cycles."""
    t, y, iters, rejected = load(case.h5)
    mx, mn = cycle_extrema(t, y, case.start, case.period, case.assess)
    m = (t >= case.start) & (t < case.t_end)
    return dict(max=mx.mean(), max_sd=mx.std(), min=mn.mean(), mean=np.trapezoid(y[m], t[m]) / (t[m][-1] - t[m][0]),
                steps=len(t) - 1, iterations=iters, rejected=rejected, cpu=case.cpu())


def measured(period):
    """The measured history at this period (R = 0.2 m): times and tension."""
    d = np.loadtxt(EXP_DATA)
    return d[:, 0], d[:, EXP_COLUMN[period]]


def compare_wave(case, shift=None):
    """xcable's assessed cycles against the measured history (same period, R = 0.2 m).

    Both are phase-averaged on a 1 ms grid of the period: the measurement over all its full
    cycles, xcable over its assessed cycles. The measured time is t_exp = t_sim + shift; the
    shift is Moody's (post.py) and, apart, the one that minimises the rms difference of the
    phase averages (searched at 1 ms)."""
    te, ye = measured(case.period)
    period = case.period
    nphase = int(round(period / 1e-3))
    phases = np.arange(nphase) * 1e-3
    exp_cycles = int((te[-1] - te[0]) // period)
    exp_pa, exp_rows = phase_average(te, ye, te[0], period, exp_cycles, phases)
    t, y, _, _ = load(case.h5)
    sim_pa, _ = phase_average(t, y, case.start, period, case.assess, phases)
    # sim phase psi (from case.start) lands on the measured phase (psi + case.start + shift) mod T.
    def rms_at(shift):
        k = int(round(((case.start + shift) % period) / 1e-3)) % nphase
        return math.sqrt(np.mean((sim_pa - np.roll(exp_pa, -k)) ** 2)), k
    rms = [rms_at(j * 1e-3)[0] for j in range(nphase)]
    best = int(np.argmin(rms)) * 1e-3
    moody = MOODY_SHIFT.get(period)
    emx, emn = cycle_extrema(te, ye, te[0] + ((case.start + (moody or best)) % period), period, exp_cycles - 1)
    out = dict(exp_max=emx.mean(), exp_max_sd=emx.std(), exp_min=emn.mean(), exp_mean=ye.mean(),
               exp_cycles=exp_cycles - 1, best_shift=best, rms_best=min(rms),
               exp_scatter=math.sqrt(np.mean((exp_rows - exp_pa) ** 2)), range=exp_pa.max() - exp_pa.min())
    if moody is not None:
        out.update(moody_shift=moody, rms_moody=rms_at(moody)[0])
    out['_curves'] = (phases, sim_pa, exp_pa, rms_at(best)[1])
    return out


RESOLUTIONS = ['101:1e-3', '201:5e-4', '201:2.5e-4', '401:2.5e-4', '401:1.25e-4', '801:1.25e-4']


def parse_resolution(text):
    n, dt = text.split(':')
    return int(n), float(dt)


def cmd_wave(args):
    """The two measured histories (R = 0.2 m) at each resolution."""
    cases = [Case(args.work, p, 0.2, *parse_resolution(r), args.ca, args.settle, args.assess, 'wave_')
             for p in args.period for r in args.resolution]
    run_all(cases, args.exe, args.jobs)
    print('| T (s) | nodes | dt (ms) | Courant | CPU (s) | steps (rejected) | mean max (N) | sd | mean min | mean | '
          'rms, Moody shift (N) | best shift (s) | rms, best (N) |')
    print('|---|---|---|---|---|---|---|---|---|---|---|---|---|')
    c_axial = math.sqrt(EA / MASS)
    for p in args.period:
        for c in [c for c in cases if c.period == p]:
            s, w = summary(c), compare_wave(c)
            courant = c_axial * c.dt / (LENGTH / (c.nodes - 1))
            print(f'| {p} | {c.nodes} | {c.dt * 1e3:g} | {courant:.2f} | {s["cpu"]:.0f} | {s["steps"]} ({s["rejected"]}) | '
                  f'{s["max"]:.2f} | {s["max_sd"]:.2f} | {s["min"]:.2f} | {s["mean"]:.2f} | '
                  f'{w.get("rms_moody", float("nan")):.2f} | {w["best_shift"]:.3f} | {w["rms_best"]:.2f} |')
        print(f'| {p} | measured ({w["exp_cycles"]} cycles) | | | | | {w["exp_max"]:.2f} | {w["exp_max_sd"]:.2f} | '
              f'{w["exp_min"]:.2f} | {w["exp_mean"]:.2f} | cycle scatter {w["exp_scatter"]:.2f} | '
              f'Moody {w.get("moody_shift", float("nan")):.3f} | range {w["range"]:.1f} |')
        print(f'| {p} | article table | | | | | {MEASURED[p][-1]:.1f} | | | | | | |')
    if args.tsv:
        write_wave_tsv(args, [c for c in cases if (c.nodes, c.dt) == parse_resolution(args.resolution[-1])])


def write_wave_tsv(args, cases):
    """Phase averages and three raw cycles of each code, on the measured time, for the figure."""
    os.makedirs(args.tsv, exist_ok=True)
    for c in cases:
        w = compare_wave(c)
        phases, sim_pa, exp_pa, k = w['_curves']
        te, ye = measured(c.period)
        t, y, _, _ = load(c.h5)
        # Three measured cycles from the end of the record, and xcable's last three cycles moved onto them.
        shift = w['best_shift']
        t0 = te[-1] - 3 * c.period
        ts = np.arange(t0, te[-1], 1e-3)
        # A measured time t_e is xcable's time t_e - shift, less whole periods to land in its last cycles.
        back = math.ceil((ts[-1] - shift - c.t_end) / c.period + 1e-9) * c.period
        with open(os.path.join(args.tsv, f'bergdahl_wave_T{c.period:.2f}.tsv'.replace('.', 'p', 1)), 'w') as f:
            f.write(f'# Bergdahl et al. (2016) T = {c.period} s, R = 0.2 m: time on the measured record (s), measured '
                    f'tension (N), xcable (nodes {c.nodes}, dt {c.dt} s) at its time t - {shift:.3f} s - ({back:.2f} s)\n')
            for a, b in zip(ts, np.interp(ts, te, ye)):
                f.write(f'{a:.4f}\t{b:.4f}\t{np.interp(a - shift - back, t, y):.4f}\n')


def cmd_table(args):
    """The table of mean cycle maxima: xcable against the article's."""
    cases = [Case(args.work, p, r, *parse_resolution(args.resolution[-1]), args.ca, args.settle, args.assess, 'tab_')
             for p in args.periods for r in args.radii]
    run_all(cases, args.exe, args.jobs)
    rows = []
    for c in cases:
        s = summary(c)
        m = MEASURED[c.period][RADII.index(c.radius)]
        rows.append((c.period, c.radius, m, s['max'], s['max_sd'], s['max'] - m, s['cpu']))
    print('| T (s) | R (m) | measured (N) | xcable (N) | cycle sd (N) | difference (N) | CPU (s) |')
    print('|---|---|---|---|---|---|---|')
    for r in rows:
        print(f'| {r[0]:.2f} | {r[1]:.3f} | {r[2]:.1f} | {r[3]:.2f} | {r[4]:.2f} | {r[5]:+.2f} | {r[6]:.0f} |')
    d = np.array([r[5] for r in rows])
    mes = np.array([r[2] for r in rows])
    print(f'\n{len(rows)} cases: RMSE {math.sqrt(np.mean(d ** 2)):.2f} N, bias {d.mean():+.2f} N, largest '
          f'|difference| {np.abs(d).max():.2f} N, mean |difference| / measured {np.mean(np.abs(d) / mes) * 100:.1f} %, '
          f'CPU {sum(r[6] for r in rows):.0f} s')
    if args.tsv:
        os.makedirs(args.tsv, exist_ok=True)
        with open(os.path.join(args.tsv, 'bergdahl_table.tsv'), 'w') as f:
            f.write('# period_s\tradius_m\tmeasured_N\txcable_N\tcycle_sd_N\tdifference_N\tcpu_s\n')
            for r in rows:
                f.write('\t'.join(f'{v:.4g}' for v in r) + '\n')


def main():
    global KBOT, CBOT, MU, DAMPING
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('command', choices=['wave', 'table'])
    ap.add_argument('--exe', default=os.path.join(ROOT, 'bin', 'xcable'))
    ap.add_argument('--work', default=os.path.join(HERE, 'runs'))
    ap.add_argument('--jobs', type=int, default=2)
    ap.add_argument('--ca-volume', dest='ca', action='store_const', const=CA_VOLUME, default=CA_NOMINAL,
                    help='Ca 3.8 on the steel volume instead of on the nominal section')
    ap.add_argument('--settle', type=int, default=2, help='cycles after the start before the assessed ones')
    ap.add_argument('--assess', type=int, default=5, help='assessed cycles')
    ap.add_argument('--resolution', nargs='+', default=RESOLUTIONS,
                    help='nodes:dt pairs (wave: each; table: the last)')
    ap.add_argument('--period', nargs='+', type=float, default=[1.25, 3.5], help='wave: periods')
    ap.add_argument('--periods', nargs='+', type=float, default=list(PERIODS), help='table: periods')
    ap.add_argument('--radii', nargs='+', type=float, default=list(RADII), help='table: radii')
    ap.add_argument('--tsv', default=None, help='directory for the figure data')
    ap.add_argument('--seabed-stiffness', type=float, default=KBOT,
                    help='sensitivity: seabed stiffness (Pa), its damping kept at the critical ratio')
    ap.add_argument('--friction', type=float, default=MU, help='sensitivity: seabed friction coefficient')
    ap.add_argument('--damping', type=float, default=DAMPING,
                    help="sensitivity: material damping (N s), Moody's input has xi = 2")
    args = ap.parse_args()
    KBOT, MU, DAMPING = args.seabed_stiffness, args.friction, args.damping
    CBOT = 2.0 * math.sqrt(KBOT * DIAM * MASS) / DIAM
    os.makedirs(args.work, exist_ok=True)
    {'wave': cmd_wave, 'table': cmd_table}[args.command](args)


if __name__ == '__main__':
    main()
