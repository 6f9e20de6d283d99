#!/usr/bin/env bash
# The cost of checkpoints (docs/measurements/benchmark.md, "Cost of checkpoints").
#
#   bench/checkpoint_cost.sh [REPS] [CASE]   (default 7 and input/fast_180kN.nml;
#                                             about a minute, plus three callgrind runs of ~30 s)
#
# docs/measurements/benchmark.md has its tables for input/fast_180kN.nml (REPS 7) and
# input/hanging_mass_heave.nml (REPS 3, about 5 minutes).
#
# On the case (fast_180kN: 241 nodes, 592 steps, the energy ledger on), with
# example/checkpoint_cost.f90: median wall and CPU times of the dynamics
# without checkpoints, with checkpoints enabled but no interval (what xcable
# does by default: it checks for SIGTERM before each step), and with a
# checkpoint every 200, 50 and 10 steps; the cost of one checkpoint with the
# history of t = 0 and of t_end. Then the instructions of the whole process
# (valgrind --tool=callgrind, if installed): without checkpoints (plain),
# the same after making the namelist fingerprint (text), and with checkpoints
# enabled but off (off): text - plain is the fingerprint, off - text the
# checks before every step. Not a test: it prints tables.
set -euo pipefail
cd "$(dirname "$0")/.."
reps=${1:-7}
base=${2:-input/fast_180kN.nml}
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
mkdir -p build
case_file=build/checkpoint_cost.nml
sed "s|^\(&output .*file = \)'[^']*'|\1'build/checkpoint_cost.h5'|" "$base" >"$case_file"
grep -q "file = 'build/checkpoint_cost.h5'" "$case_file" || { echo "checkpoint_cost.sh: $base has no &output file" >&2; exit 2; }
exe=$(fpm run --example checkpoint_cost --profile release --runner echo 2>/dev/null | tail -n 1)
[ -x "$exe" ] || { echo "checkpoint_cost.sh: cannot build example/checkpoint_cost.f90" >&2; exit 1; }
echo "$base: xcable $(git describe --always --dirty 2>/dev/null || echo unknown), $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores," \
     "load $(cut -d' ' -f1 /proc/loadavg)"
echo
"$exe" "$case_file" "$reps"
if command -v valgrind >/dev/null 2>&1; then
  echo
  echo "| run (one, under callgrind) | instructions, whole process |"
  echo "|---|---|"
  for mode in plain text off; do
    out=build/checkpoint_cost.callgrind.$mode
    valgrind --tool=callgrind --callgrind-out-file="$out" "$exe" "$case_file" 1 "$mode" 2>"$out.log" >/dev/null
    count=$(sed -n 's/^summary: *//p' "$out" | head -1)
    echo "| $mode | $count |"
    rm -f "$out"
  done
fi
