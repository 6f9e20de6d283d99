#!/usr/bin/env python3
"""test/test_outputs.py [EXE]: the result files explain themselves (make test runs this).

Runs a planar case (input/slow_180kN), a 3-D one (input/sway3d) and a cable broken inside
(input/inclined_break_middle, two pieces), a network of lines (input/buoy_spread) and one whose
hawser parts (input/buoy_spread_break, /summary@break_line) with EXE (default bin/xcable) and reads each file
with h5py:
  - every dataset has a `units` and a one-line `description` attribute, both str (UTF-8
    text), the units one of the SI words of the output registry;
  - every group has a `description`;
  - every [time, node] dataset has /time attached to its dimension 0 (label 'time') and /s
    to its dimension 1 (label 'node'); every static field /static/s (label 'node'); every
    history dataset /history/time (label 'time');
  - every text attribute reads as str, not bytes (but the CLASS and NAME HDF5 gives a
    dimension scale);
  - every dataset path is listed by `EXE --outputs tsv` (the registry);
  - /w and /history/step (renamed /vy, /history/dt) are gone.
Prints what is wrong; exit 1 if anything is."""
import os
import re
import subprocess
import sys
import tempfile

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CASES = ['slow_180kN', 'sway3d', 'inclined_break_middle', 'buoy_spread', 'buoy_spread_break']
UNITS = {'N', 'm', 'm/s', '1/m', 's', 'J', 'rad', '-', '1'}
SCALE_ATTRS = {'CLASS', 'NAME', 'REFERENCE_LIST', 'DIMENSION_LIST'}


def registry(exe):
    """The registry's path patterns, as regular expressions."""
    text = subprocess.run([exe, '--outputs', 'tsv'], capture_output=True, text=True, check=True).stdout
    patterns = []
    for line in text.splitlines()[1:]:
        path = line.split('\t')[0]
        patterns.append(re.compile('^' + re.escape(path).replace(re.escape('<end>'), '(end_a|end_b|break_a|break_b|line_[1-8]_[ab])') + '$'))
    return patterns


def scales(ds):
    return [(d.label, [d[i].name for i in range(len(d))]) for d in ds.dims]


def check_file(path, patterns):
    bad = []
    with h5py.File(path, 'r') as f:
        if f.attrs.get('status') != 'complete':
            bad.append('status %r, not the str complete' % f.attrs.get('status'))
        for name in ('w', 'static/w', 'history/step'):
            if name in f:
                bad.append('/%s is still written' % name)

        def visit(name, obj):
            where = '/' + name
            for k, v in obj.attrs.items():
                # CLASS and NAME of a dimension scale are the HDF5 specification's ASCII strings.
                if isinstance(v, (bytes, np.bytes_)) and k not in SCALE_ATTRS:
                    bad.append('%s@%s reads as bytes' % (where, k))
            if isinstance(obj, h5py.Group):
                if not isinstance(obj.attrs.get('description'), str) or not obj.attrs['description']:
                    bad.append('%s: group without a description' % where)
                return
            if not any(p.match(where) for p in patterns):
                bad.append('%s: not in the registry (xcable --outputs tsv)' % where)
            units, text = obj.attrs.get('units'), obj.attrs.get('description')
            if not isinstance(units, str) or units not in UNITS:
                bad.append('%s: units %r' % (where, units))
            if not isinstance(text, str) or not text or '\n' in text:
                bad.append('%s: description %r' % (where, text))
            parent = where.rsplit('/', 1)[0] or '/'
            if obj.ndim == 2:
                want = [('time', ['/time']), ('node', ['/s'])]
            elif parent == '/static' and name != 'static/s':
                want = [('node', ['/static/s'])]
            elif parent.startswith('/history') and name != 'history/time':
                want = [('time', ['/history/time'])]
            else:
                want = None
            if want is not None and scales(obj) != want:
                bad.append('%s: dimension scales %s, expected %s' % (where, scales(obj), want))
        for k, v in f.attrs.items():
            if isinstance(v, (bytes, np.bytes_)):
                bad.append('/@%s reads as bytes' % k)
        if not isinstance(f.attrs.get('description'), str):
            bad.append('/: no description')
        f.visititems(visit)
        fields = [k for k in f if isinstance(f[k], h5py.Dataset) and f[k].ndim == 2]
        if not fields:
            bad.append('no [time, node] dataset')
        if 'summary' not in f or 'history' not in f:
            bad.append('no /summary or /history')
    return bad


def main():
    exe = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, 'bin', 'xcable'))
    patterns = registry(exe)
    failed = 0
    with tempfile.TemporaryDirectory() as tmp:
        os.symlink(os.path.join(ROOT, 'input'), os.path.join(tmp, 'input'))
        os.mkdir(os.path.join(tmp, 'results'))
        for case in CASES:
            p = subprocess.run([exe, 'input/%s.nml' % case], cwd=tmp, capture_output=True, text=True)
            path = os.path.join(tmp, 'results', case + '.h5')
            if p.returncode != 0 or not os.path.exists(path):
                print('test_outputs: %s: exit %d: %s' % (case, p.returncode, p.stderr.strip()[-300:]))
                failed += 1
                continue
            bad = check_file(path, patterns)
            if case == 'inclined_break_middle':
                with h5py.File(path, 'r') as f:
                    if 'break_a' not in f['history']:
                        bad.append('no break inside the cable (no /history/break_a)')
            if case == 'buoy_spread':
                with h5py.File(path, 'r') as f:
                    ends = sorted(k for k in f['history'] if k.startswith('line_'))
                    want = ['line_%d_%s' % (l, s) for l in (1, 2, 3) for s in 'ab']
                    if ends != want:
                        bad.append('the network\'s history has the ends %s, not %s' % (ends, want))
                    if 'span' in f['static'].attrs or 'tension_a' in f['static'].attrs:
                        bad.append('/static has the figures of one line (span, tension_a) for a network')
            if case == 'buoy_spread_break':
                with h5py.File(path, 'r') as f:
                    if f['summary'].attrs.get('break_line') != 3:
                        bad.append('the network\'s /summary@break_line is %s, not 3' % f['summary'].attrs.get('break_line'))
            for line in bad[:20]:
                print('test_outputs: %s: %s' % (case, line))
            failed += bool(bad)
            if not bad:
                print('test_outputs: %s: every dataset has units, a description and its dimension scales' % case)
    sys.exit(1 if failed else 0)


if __name__ == '__main__':
    main()
