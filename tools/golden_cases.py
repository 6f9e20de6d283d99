#!/usr/bin/env python3
"""Golden figures of the input/ cases: every dataset of each case's result file reduced to a few
numbers (shape, sum, sum of squares, largest magnitude, first and last value), and every numeric
attribute of /static and /summary likewise, so that a restructure cannot change a shipped case
unnoticed.

    tools/golden_cases.py check [EXE]   run every input/*.nml with EXE (default bin/xcable) and
                                        compare with test/golden/input_cases.json; exit 1 on a
                                        difference (make test runs this)
    tools/golden_cases.py write [EXE]   run them and write the file anew (only for an intended
                                        change of results: say which figure moved and why)

A dataset agrees when each of its numbers is within `RELATIVE` (1e-9) of the dataset's largest
magnitude, at least FLOOR (sum and sum of squares scaled by the element count): round-off of a reordered
expression passes, a changed result does not. The run's wall time, run id, the namelist's
path and the Newton and factorisation counts (which a change of round-off may move by one) are
not compared."""
import json
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PINS = os.path.join(ROOT, 'test', 'golden', 'input_cases.json')
RELATIVE = 1e-9
# A dataset of round-off alone (a fixed end's velocity, 1e-16 m/s) is compared on this scale (SI units).
FLOOR = 1e-6
SKIP = {'wall_time', 'newton_iterations', 'factorisations', 'max_newton_iterations'}


def figures(path):
    out = {}

    def visit(name, obj):
        if isinstance(obj, h5py.Dataset) and name.split('/')[-1] not in SKIP:
            v = obj[()]
            a = np.asarray(v)
            if a.dtype.kind in 'fiu' and a.size > 0:
                a = a.astype(float).ravel()
                if np.all(np.isfinite(a)):
                    out[name] = dict(shape=list(obj.shape), sum=float(a.sum()), sumsq=float((a * a).sum()),
                                     maxabs=float(np.abs(a).max()), first=float(a[0]), last=float(a[-1]))
                else:
                    out[name] = dict(shape=list(obj.shape), nonfinite=int((~np.isfinite(a)).sum()))
    def numeric_attributes(obj, prefix):
        for k, v in obj.attrs.items():
            a = np.asarray(v)
            if k in SKIP or a.dtype.kind not in 'fiu' or a.size == 0:
                continue
            a = a.astype(float).ravel()
            if np.all(np.isfinite(a)):
                out[prefix + '@' + k] = dict(shape=list(a.shape), sum=float(a.sum()), sumsq=float((a * a).sum()),
                                             maxabs=float(np.abs(a).max()), first=float(a[0]), last=float(a[-1]))
    with h5py.File(path, 'r') as f:
        out['@status'] = f.attrs['status'].decode() if isinstance(f.attrs['status'], bytes) else str(f.attrs['status'])
        f.visititems(visit)
        for group in ('static', 'summary'):
            if group in f:
                numeric_attributes(f[group], group)
    return out


def run_all(exe):
    cases = sorted(c[:-4] for c in os.listdir(os.path.join(ROOT, 'input')) if c.endswith('.nml'))
    result = {}
    with tempfile.TemporaryDirectory() as tmp:
        os.symlink(os.path.join(ROOT, 'input'), os.path.join(tmp, 'input'))
        os.mkdir(os.path.join(tmp, 'results'))
        for c in cases:
            p = subprocess.run([exe, 'input/%s.nml' % c], cwd=tmp, capture_output=True, text=True)
            h5 = os.path.join(tmp, 'results', c + '.h5')
            if p.returncode != 0 or not os.path.exists(h5):
                result[c] = {'@exit': p.returncode, '@stderr': p.stderr.strip()[-300:]}
            else:
                result[c] = figures(h5)
    return result


def close(a, b, scale):
    return abs(a - b) <= RELATIVE * scale


def compare(pinned, now):
    bad = []
    for case in sorted(set(pinned) | set(now)):
        if case not in pinned or case not in now:
            bad.append('%s: case only in %s' % (case, 'the pins' if case in pinned else 'this run'))
            continue
        p, n = pinned[case], now[case]
        for name in sorted(set(p) | set(n)):
            if name not in p or name not in n:
                bad.append('%s: %s only in %s' % (case, name, 'the pins' if name in p else 'this run'))
                continue
            a, b = p[name], n[name]
            if not isinstance(a, dict):
                if a != b:
                    bad.append('%s: %s %r, pinned %r' % (case, name, b, a))
                continue
            if a.get('shape') != b.get('shape') or ('nonfinite' in a) != ('nonfinite' in b):
                bad.append('%s: %s shape %s, pinned %s' % (case, name, b.get('shape'), a.get('shape')))
                continue
            if 'nonfinite' in a:
                continue
            m = max(a['maxabs'], b['maxabs'], FLOOR)
            count = max(int(np.prod(a['shape'])), 1)
            for key, scale in (('maxabs', m), ('first', m), ('last', m), ('sum', m * count),
                               ('sumsq', m * m * count)):
                if not close(a[key], b[key], scale):
                    bad.append('%s: %s %s %.17g, pinned %.17g (%.2e of its scale)' %
                               (case, name, key, b[key], a[key], abs(a[key] - b[key]) / scale))
                    break
    return bad


def main():
    if len(sys.argv) < 2 or sys.argv[1] not in ('check', 'write'):
        print(__doc__)
        sys.exit(2)
    exe = os.path.abspath(sys.argv[2]) if len(sys.argv) > 2 else os.path.join(ROOT, 'bin', 'xcable')
    now = run_all(exe)
    if sys.argv[1] == 'write':
        with open(PINS, 'w') as f:
            json.dump(now, f, indent=0, sort_keys=True)
            f.write('\n')
        print('golden_cases: wrote %s (%d cases)' % (os.path.relpath(PINS, ROOT), len(now)))
        return
    with open(PINS) as f:
        pinned = json.load(f)
    bad = compare(pinned, now)
    items = sum(len(v) for v in pinned.values())
    if bad:
        print('golden_cases: %d of %d pinned items differ:' % (len(bad), items))
        for line in bad if os.environ.get('GOLDEN_ALL') else bad[:40]:
            print('  ' + line)
        print('golden_cases: if the change is intended, run tools/golden_cases.py write and say why')
        sys.exit(1)
    print('golden_cases: the %d input/ cases agree with their %d pinned items (to %.0e of each scale)' %
          (len(pinned), items, RELATIVE))


main()
