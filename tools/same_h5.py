#!/usr/bin/env python3
"""tools/same_h5.py A.h5 B.h5 [--relative R]: compare every dataset and attribute of two xcable
result files, bit for bit (default) or to R relative to each dataset's largest magnitude. The
attributes that differ between two runs of the same case (run_id, wall_time, the namelist path)
are skipped; dimension scales are compared by name. Prints what differs; exit 1 if anything does."""
import sys
import h5py
import numpy as np

SKIP = {'run_id', 'wall_time', 'namelist_file', 'created'}
# The dimension scales' bookkeeping: DIMENSION_LIST is compared by the names of the scales it
# attaches, REFERENCE_LIST (its mirror on the scale) not at all.
SCALES = {'DIMENSION_LIST', 'REFERENCE_LIST'}


def items(f):
    out = {}
    def visit(name, obj):
        if isinstance(obj, h5py.Dataset):
            out['D ' + name] = obj[()]
        for k, v in obj.attrs.items():
            if k in SCALES:
                # Object references (addresses in the file): compared as the scales' names.
                if k == 'DIMENSION_LIST':
                    out['A ' + name + '@' + k] = np.array(
                        [[d.label] + [d[i].name for i in range(len(d))] for d in obj.dims], dtype=object)
            elif k not in SKIP:
                out['A ' + name + '@' + k] = v
    for k, v in f.attrs.items():
        if k not in SKIP:
            out['A /@' + k] = v
    f.visititems(visit)
    return out


def same(a, b, rel):
    a = np.asarray(a)
    b = np.asarray(b)
    if a.shape != b.shape or a.dtype.kind != b.dtype.kind:
        return False, 'shape or type'
    if a.dtype.kind in 'fc':
        if rel is None:
            ok = a.tobytes() == b.tobytes()
            return ok, '' if ok else 'max diff %.3e' % np.nanmax(np.abs(a - b))
        scale = max(np.nanmax(np.abs(a)) if a.size else 0, 1e-300)
        d = np.nanmax(np.abs(a - b)) / scale if a.size else 0
        nan_ok = np.array_equal(np.isnan(a), np.isnan(b))
        return (d <= rel and nan_ok), 'relative %.3e' % d
    return np.array_equal(a, b), ''


def main():
    args = sys.argv[1:]
    rel = None
    if '--relative' in args:
        i = args.index('--relative')
        rel = float(args[i + 1])
        del args[i:i + 2]
    with h5py.File(args[0], 'r') as fa, h5py.File(args[1], 'r') as fb:
        a, b = items(fa), items(fb)
    bad = 0
    for k in sorted(set(a) | set(b)):
        if k not in a or k not in b:
            print('only in one file:', k)
            bad += 1
            continue
        ok, why = same(a[k], b[k], rel)
        if not ok:
            print('differs:', k, why)
            bad += 1
    print('%d items compared, %d differ' % (len(set(a) | set(b)), bad))
    sys.exit(1 if bad else 0)


main()
