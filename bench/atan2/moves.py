#!/usr/bin/env python3
"""How far results move: one program against another on every case of input/,
and the first program against itself with one input changed by a unit in the
last place (docs/measurements/data/speed_rounds.md, "An own atan2").

    python3 bench/atan2/moves.py BASE_BIN NEW_BIN [case ...]

For each case: runs BASE on the case, NEW on the case, BASE on the case with one
number changed by one unit in the last place (PERTURB below), each in its own
directory under $MOVES_DIR (default /tmp/h43_moves); then, per HDF5 dataset, the largest difference relative to
the dataset's largest value (datasets whose values are all below 1e-9 left out),
the worst dataset of each comparison, and the energy ledger's drift (/summary
attribute energy_drift) of the three runs.
"""
import os
import shutil
import subprocess
import sys

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# case: (text in the namelist, its replacement one unit in the last place away)
PERTURB = {
    'fast_180kN': ('tension = 180000 ', 'tension = 180000.00000000003 '),
    'fast_315kN': ('tension = 315000 ', 'tension = 315000.00000000006 '),
    'slow_180kN': ('tension = 180000 ', 'tension = 180000.00000000003 '),
    'slow_315kN': ('tension = 315000 ', 'tension = 315000.00000000006 '),
    'polyester_break': ('tension = 308000 ', 'tension = 308000.00000000006 '),
    'hanging_mass_heave': ('amplitude = 1.0,', 'amplitude = 1.0000000000000002,'),
    'inclined_break_middle': ('x = 60.0,', 'x = 60.00000000000001,'),
    'koh_swinging_cable': ('x = 1.805,', 'x = 1.8050000000000002,'),
    'slack_swing': ('x = 50.0,', 'x = 50.00000000000001,'),
    'sway3d': ('x = 40.0,', 'x = 40.00000000000001,'),
}


def run(binary, case, tag, perturb=False, extra=None):
    work = os.path.join(os.environ.get('MOVES_DIR', '/tmp/h43_moves'), tag, case)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work + '/results')
    shutil.copytree(os.path.join(ROOT, 'input'), work + '/input')
    nml = f'{work}/input/{case}.nml'
    text = open(nml).read()
    if perturb:
        old, new = PERTURB[case]
        assert text.count(old) == 1, (case, old)
        text = text.replace(old, new)
    if extra:
        for old, new in extra:
            text = text.replace(old, new)
    open(nml, 'w').write(text)
    subprocess.run([binary, f'input/{case}.nml'], cwd=work, check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    out = [l for l in text.splitlines() if l.startswith('&output')][0]
    name = out.split("file = '")[1].split("'")[0]
    return os.path.join(work, name)


def datasets(path):
    found = {}

    def visit(name, obj):
        if isinstance(obj, h5py.Dataset) and obj.dtype.kind == 'f':
            found[name] = np.asarray(obj[()], dtype=float)
    with h5py.File(path, 'r') as f:
        f.visititems(visit)
        drift = f['summary'].attrs.get('energy_drift', np.nan) if 'summary' in f else np.nan
    return found, float(np.asarray(drift).ravel()[0])


def worst(a, b):
    best = (0.0, '-')
    for name, x in a.items():
        y = b.get(name)
        if y is None or y.shape != x.shape:
            return (np.inf, name + ' (shape)')
        scale = np.nanmax(np.abs(x)) if x.size else 0
        if not scale > 1e-9:
            continue
        d = np.nanmax(np.abs(x - y)) / scale
        if d > best[0]:
            best = (d, name)
    return best


def main():
    base, new = sys.argv[1], sys.argv[2]
    cases = sys.argv[3:] or sorted(PERTURB)
    print('| case | new: worst dataset | input changed: worst dataset | new / input changed '
          '| energy_drift: base / new / input changed |')
    print('|---|---|---|---:|---|')
    for case in cases:
        a, da = datasets(run(base, case, 'base'))
        b, db = datasets(run(new, case, 'new'))
        c, dc = datasets(run(base, case, 'perturbed', perturb=True))
        wb, wc = worst(a, b), worst(a, c)
        ratio = wb[0] / wc[0] if wc[0] > 0 else np.inf
        print(f'| {case} | {wb[0]:.1e} ({wb[1]}) | {wc[0]:.1e} ({wc[1]}) | {ratio:.2f} '
              f'| {da:.3g} / {db:.3g} / {dc:.3g} |', flush=True)


if __name__ == '__main__':
    main()
