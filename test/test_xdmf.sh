#!/usr/bin/env bash
# Test of the XDMF sidecar (&output xdmf = .true.): short runs with it, each sidecar checked
# against its HDF5 file by tools/check_xdmf.py (the XML read item by item, every hyperslab
# resolved with h5py: one grid per snapshot at its time, points = row i of x, y (zeros when
# planar), z, every other snapshot field a node attribute, segments within each piece).
#   test/test_xdmf.sh [bin/xcable]
# Cases (in build/test-xdmf/): a break inside an inclined line (two pieces: no segment
# across the cut), the 3-D model (y and its fields), a run with xdmf off over a stale
# sidecar (removed), a run that fails in its dynamics (no sidecar written).
# With PyPI vtk installed it also reads each pair through VTK's XDMF reader, the one ParaView
# opens .xmf files with (make check-xdmf installs it and runs only that).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
xcable=${1:-$root/bin/xcable}
[ -x "$xcable" ] || { echo "test_xdmf: $xcable not found: run make build first" >&2; exit 1; }
tmp=$root/build/test-xdmf
rm -rf "$tmp"
mkdir -p "$tmp"
failures=0
fail() { echo "test_xdmf: FAIL: $*" >&2; failures=$((failures + 1)); }
pass() { echo "test_xdmf: ok: $*"; }
vtk=()
if python3 -c 'import vtkmodules.vtkIOXdmf2' >/dev/null 2>&1; then vtk=(--vtk); fi

# run <name> <namelist body> <output options>: xcable's exit code.
run() {
  printf '%s\n' "$2" > "$tmp/$1.nml"
  printf "&output file = '%s', quiet = .true., %s /\n" "$tmp/$1.h5" "$3" >> "$tmp/$1.nml"
  local rc=0
  "$xcable" "$tmp/$1.nml" > "$tmp/$1.log" 2>&1 || rc=$?
  return $rc
}

check() {
  if python3 "$root/tools/check_xdmf.py" "$tmp/$1.xmf" "${vtk[@]}" > "$tmp/$1.check" 2>&1; then
    pass "$(cat "$tmp/$1.check")"
  else
    fail "$1: $(cat "$tmp/$1.check")"
  fi
}

if run break_middle "&end_b    x = 60.0, z = 20.0 /
&rupture  s_break = 30.0, t_break = 0.005 /
&numerics nodes = 41, courant = 1.0, t_end = 0.03 /" "interval = 0.005, xdmf = .true."; then
  check break_middle
else
  fail "break_middle did not run: $(tail -1 "$tmp/break_middle.log")"
fi

if run sway3d "&cable    length = 60.0 /
&end_a    x = 0.0, y = 0.0, z = 0.0 /
&end_b    x = 40.0, y = 20.0, z = -10.0 /
&rupture  s_break = 60.0, t_break = 0.0 /
&numerics nodes = 21, courant = 1.0, t_end = 0.2, model = '3d' /" "interval = 0.05, xdmf = .true."; then
  check sway3d
else
  fail "sway3d did not run: $(tail -1 "$tmp/sway3d.log")"
fi

# xdmf off: the sidecar of the earlier run of that file no longer describes it.
cp "$tmp/break_middle.xmf" "$tmp/stale.xmf"
if run stale "&numerics nodes = 21, t_end = 0.01 /" "interval = 0.005"; then
  if [ -e "$tmp/stale.xmf" ]; then fail "a run without xdmf left the stale sidecar of an earlier run"; \
  else pass "a new run removes the sidecar of the file it replaces"; fi
else
  fail "stale did not run: $(tail -1 "$tmp/stale.log")"
fi

# A run that fails in its dynamics (a wall-clock limit of 1 us) keeps its result file, marked
# failed, and writes no sidecar.
rc=0
run failed "&rupture  t_break = 0.005 /
&numerics nodes = 41, t_end = 0.03, max_wall_time = 1e-6 /" "interval = 0.005, xdmf = .true." || rc=$?
if [ "$rc" -eq 0 ] || [ ! -e "$tmp/failed.h5" ]; then
  fail "the failing case completed or left no result file (exit $rc): the test needs a run that fails in its dynamics"
elif [ -e "$tmp/failed.xmf" ]; then
  fail "a failed run (exit $rc) left a sidecar"
else
  pass "a failed run (exit $rc) writes no sidecar"
fi

if [ ${#vtk[@]} -eq 0 ]; then
  echo "test_xdmf: note: PyPI vtk is not installed: the sidecars were checked as XML only (make check-xdmf reads them with VTK)"
fi
if [ "$failures" -gt 0 ]; then echo "test_xdmf: $failures failed" >&2; exit 1; fi
echo "test_xdmf: all passed"
