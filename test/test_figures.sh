#!/usr/bin/env bash
# Test of the figure scripts (plots/): runs a short case, then every script, and fails unless
# each one writes a non-empty PNG (or PDF) and gnuplot prints no warning.
#   test/test_figures.sh            (needs bin/xcable: make build; XCABLE=<path> to use another)
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
xcable=${XCABLE:-$root/bin/xcable}
plots=$root/plots
failures=0
fail() { echo "test_figures: FAIL: $*" >&2; failures=$((failures + 1)); }
pass() { echo "test_figures: ok: $*"; }

command -v gnuplot >/dev/null 2>&1 || { echo "test_figures: gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 1; }
[ -x "$xcable" ] || { echo "test_figures: $xcable not found: run make build first" >&2; exit 1; }

tmp=$(mktemp -d "${TMPDIR:-/tmp}/xcable-figures.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

# Two short cases (180 and 315 kN, fast rupture): 41 nodes, 30 ms, snapshots every 10 ms, with
# the energy ledger. In 30 ms the front has not reached the fixed end: flat fixed-end tension.
for kN in 180 315; do
  cat > "$tmp/short_$kN.nml" <<NML
&static   tension = ${kN}000 /
&rupture  t_break = 0.005 /
&numerics nodes = 41, courant = 1.0, t_end = 0.03 /
&output   file = '$tmp/short_$kN.h5', interval = 0.01, energy = .true., gnuplot = .true., quiet = .true. /
NML
  if ! "$xcable" "$tmp/short_$kN.nml" > "$tmp/xcable.log" 2>&1; then
    cat "$tmp/xcable.log" >&2
    echo "test_figures: FAIL: xcable could not run the short case $tmp/short_$kN.nml" >&2
    exit 1
  fi
  blocks=$(grep -c '^# t = ' "$tmp/short_$kN.snapshots.dat" || true)
  if [ "$blocks" -ne 4 ]; then
    echo "test_figures: FAIL: xcable wrote $blocks snapshot blocks to $tmp/short_$kN.snapshots.dat," \
         "expected 4 (t = 0, 10, 20, 30 ms): the gnuplot text output of the program is broken" >&2
    exit 1
  fi
done
stem_a=$tmp/short_180 stem_b=$tmp/short_315

# check <name> <file> <stderr file> <exit status>: the figure exists, is non-empty, has the right
# signature, and gnuplot's messages hold no warning.
check() {
  local name=$1 file=$2 err=$3 rc=$4 magic
  if [ "$rc" -ne 0 ]; then fail "$name: exit status $rc: $(head -c 600 "$err")"; return; fi
  if [ ! -s "$file" ]; then fail "$name: $file missing or empty"; return; fi
  case "$file" in
    *.png) magic=$(head -c 4 "$file" | tail -c 3); [ "$magic" = PNG ] || { fail "$name: $file is not a PNG"; return; } ;;
    *.pdf) magic=$(head -c 4 "$file"); [ "$magic" = "%PDF" ] || { fail "$name: $file is not a PDF"; return; } ;;
  esac
  if grep -qi warning "$err"; then fail "$name: gnuplot warned: $(grep -i warning "$err" | head -n 3)"; return; fi
  pass "$name"
}

# Each single-run script, on both runs.
for stem in "$stem_a" "$stem_b"; do
  for kind in motion tension velocity ends energy; do
    out=$stem.$kind.png rc=0
    gnuplot -e "stem='$stem'; out='$out'" "$plots/$kind.gp" 2> "$stem.$kind.err" || rc=$?
    check "$kind.gp ($(basename "$stem"))" "$out" "$stem.$kind.err" "$rc"
  done
done
stem=$stem_b

# The paired panels: (a) 180 kN beside (b) 315 kN.
for kind in motion tension velocity; do
  out=$tmp/pair_$kind.png rc=0
  gnuplot -e "kind='$kind'; stem_a='$stem_a'; stem_b='$stem_b'; out='$out'" "$plots/pair.gp" 2> "$tmp/pair_$kind.err" || rc=$?
  check "pair.gp kind=$kind" "$out" "$tmp/pair_$kind.err" "$rc"
done

# The drivers: draw.sh on the run, in PNG and in PDF.
rc=0
"$plots/draw.sh" "$stem" "$tmp/case" > /dev/null 2> "$tmp/draw.err" || rc=$?
for kind in motion tension velocity ends energy; do check "draw.sh $kind.png" "$tmp/case/$kind.png" "$tmp/draw.err" "$rc"; done
rc=0
"$plots/draw.sh" "$stem" "$tmp/casepdf" pdf > /dev/null 2> "$tmp/drawpdf.err" || rc=$?
check "draw.sh tension.pdf" "$tmp/casepdf/tension.pdf" "$tmp/drawpdf.err" "$rc"

# draw-paper.sh reads the four paper cases by name: give it the short runs under those names.
mkdir -p "$tmp/results"
for c in fast_180kN fast_315kN slow_180kN slow_315kN; do
  src=$stem_a; [[ $c == *315kN ]] && src=$stem_b
  for ext in snapshots.dat history.dat h5; do cp "$src.$ext" "$tmp/results/$c.$ext"; done
done
rc=0
"$plots/draw-paper.sh" png "$tmp/results" "$tmp/paper" > /dev/null 2> "$tmp/paper.err" || rc=$?
for f in fig2_motion_fast fig3_tension_fast fig4_velocity_fast fig5_motion_slow fig6_tension_slow fig7_velocity_slow; do
  check "draw-paper.sh $f.png" "$tmp/paper/$f.png" "$tmp/paper.err" "$rc"
done

# Without energy columns the energy figure is skipped with a message, not an error.
mkdir -p "$tmp/noenergy"
cp "$stem.snapshots.dat" "$tmp/noenergy/run.snapshots.dat"
awk 'NR == 1 { print "# columns: t[s] end_velocity[m/s] fixed_end_tension[N] newton_iterations"; next }
     { print $1, $2, $3, $4 }' "$stem.history.dat" > "$tmp/noenergy/run.history.dat"
rc=0
gnuplot -e "stem='$tmp/noenergy/run'; out='$tmp/noenergy/energy.png'" "$plots/energy.gp" 2> "$tmp/noenergy.err" || rc=$?
if [ "$rc" -eq 0 ] && [ ! -e "$tmp/noenergy/energy.png" ] && grep -q "no energy columns" "$tmp/noenergy.err"; then
  pass "energy.gp skips a run without energy columns"
else
  fail "energy.gp without energy columns: exit $rc, output $(ls "$tmp/noenergy"), messages: $(cat "$tmp/noenergy.err")"
fi

# A missing run is a clear error.
rc=0
gnuplot -e "stem='$tmp/none'; out='$tmp/none.png'" "$plots/tension.gp" 2> "$tmp/none.err" || rc=$?
if [ "$rc" -ne 0 ] && grep -q "not found" "$tmp/none.err"; then
  pass "a missing run is reported"
else
  fail "tension.gp on a missing run: exit $rc, messages: $(cat "$tmp/none.err")"
fi

if [ "$failures" -gt 0 ]; then
  echo "test_figures: $failures check(s) failed" >&2
  exit 1
fi
echo "test_figures: all checks passed"
