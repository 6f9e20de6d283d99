#!/usr/bin/env bash
# Test of the figure scripts (plots/): runs short cases, then every script on each, and fails
# unless each one writes a non-empty PNG (or PDF) and gnuplot prints no warning.
#   test/test_figures.sh            (needs bin/xcable: make build; XCABLE=<path> to use another)
# The runs and figures go to build/test-figures/ (kept for a look; cleared at the start):
#   short_180, short_315   the paper's layout: end b released, 41 nodes, 30 ms
#   break_middle           an inclined line (end b 60 m across, 20 m up) parting at s = 30 m:
#                          two pieces in the snapshots, four ends in the history; 41 nodes, 30 ms
#   heave                  a hanging 200 kg mass, the top moved up and down (a line that stays
#                          on one vertical; a moving end and a mass end); 21 nodes, 1.5 s
#   sway3d                 the 3-D model: a slack line, end b 20 m off the x-z plane, let go;
#                          21 nodes, 0.5 s: y columns in the text, 3-D and plan views
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
xcable=${XCABLE:-$root/bin/xcable}
plots=$root/plots
failures=0
fail() { echo "test_figures: FAIL: $*" >&2; failures=$((failures + 1)); }
pass() { echo "test_figures: ok: $*"; }

command -v gnuplot >/dev/null 2>&1 || { echo "test_figures: gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 1; }
[ -x "$xcable" ] || { echo "test_figures: $xcable not found: run make build first" >&2; exit 1; }

tmp=$root/build/test-figures
rm -rf "$tmp"
mkdir -p "$tmp"

# run <name> <namelist body>: runs xcable on the namelist (output to $tmp/<name>.h5), or stops.
run() {
  local name=$1 body=$2
  printf '%s\n' "$body" > "$tmp/$name.nml"
  printf "&output file = '%s', energy = .true., gnuplot = .true., quiet = .true., %s /\n" \
    "$tmp/$name.h5" "${3:-interval = 0.01}" >> "$tmp/$name.nml"
  if ! "$xcable" "$tmp/$name.nml" > "$tmp/$name.log" 2>&1; then
    cat "$tmp/$name.log" >&2
    echo "test_figures: FAIL: xcable could not run $tmp/$name.nml" >&2
    exit 1
  fi
}

# The paper's layout: two short cases (180 and 315 kN, fast rupture), snapshots every 10 ms. In
# 30 ms the front has not reached the fixed end: flat fixed-end tension.
for kN in 180 315; do
  run "short_$kN" "&static   tension = ${kN}000 /
&rupture  t_break = 0.005 /
&numerics nodes = 41, courant = 1.0, t_end = 0.03 /"
  blocks=$(grep -c '^# t = ' "$tmp/short_$kN.snapshots.dat" || true)
  if [ "$blocks" -ne 4 ]; then
    echo "test_figures: FAIL: xcable wrote $blocks snapshot blocks to $tmp/short_$kN.snapshots.dat," \
         "expected 4 (t = 0, 10, 20, 30 ms): the gnuplot text output of the program is broken" >&2
    exit 1
  fi
done
stem_a=$tmp/short_180 stem_b=$tmp/short_315

# A break in the middle of an inclined line, snapshots every 1 ms (31: enough for the map).
run break_middle "&end_b    x = 60.0, z = 20.0 /
&rupture  s_break = 30.0, t_break = 0.005 /
&numerics nodes = 41, courant = 1.0, t_end = 0.03 /" "interval = 0.001"
# A heaved hanging mass, snapshots every 50 ms.
run heave "&end_a    kind = 'motion', amplitude = 0.5, period = 1.0, ramp_time = 0.5 /
&end_b    kind = 'mass', mass = 200.0 /
&rupture  enabled = .false. /
&numerics nodes = 21, courant = 1.0, t_end = 1.5 /" "interval = 0.05"
stem_m=$tmp/break_middle stem_h=$tmp/heave
# The 3-D model: end b off the x-z plane, released at once; snapshots every 50 ms.
run sway3d "&end_b    kind = 'fixed', x = 40.0, y = 20.0, z = 0.0 /
&rupture  s_break = 60.0, t_break = 0.0 /
&numerics model = '3d', nodes = 21, courant = 2.0, t_end = 0.5 /" "interval = 0.05"
stem_3=$tmp/sway3d
# A chain on a sloping seabed, its fairlead heaved: the line over the bottom (seabed.gp).
run seabed "&cable    length = 100.0, diameter = 0.1, density = 7850.0, area = 0.0075, bending_stiffness = 1.0 /
&material law = 'linear', ea = 1.0e8, compression = 'none' /
&fluid    density = 1025.0 /
&seabed   depth = 30.0, slope_x = 0.02 /
&end_a    kind = 'fixed', x = 0.0, z = -30.0 /
&end_b    kind = 'motion', x = 80.0, z = -5.0, motion = 'harmonic', amplitude = 1.0, period = 5.0,
          direction_x = 0.0, direction_z = 1.0, ramp_time = 2.0 /
&rupture  enabled = .false. /
&numerics nodes = 41, courant = 4.0, t_end = 6.0 /" "interval = 0.2"
stem_s=$tmp/seabed

# The 3-D run's text: the snapshot header names the 3-D columns 10-15 and every data line has
# 15 columns, y (column 10) reaching end b's 20 m; the history names each end's y, vy, force_y.
want3="y[m] vy[m/s] curvature_z[1/m] twist[1/m] binormal_shear[N] curvature_n[1/m]"
if sed -n 2p "$stem_3.snapshots.dat" | grep -qF "curvature[1/m] $want3"; then
  pass "sway3d: the snapshot header names the 3-D columns"
else
  fail "sway3d: snapshot header '$(sed -n 2p "$stem_3.snapshots.dat")' lacks '$want3'"
fi
cols=$(awk '/^#/ || NF == 0 { next } { print NF }' "$stem_3.snapshots.dat" | sort -u | tr '\n' ' ')
ymax=$(awk '/^#/ || NF == 0 { next } { if ($10 > m) m = $10 } END { print m + 0 }' "$stem_3.snapshots.dat")
if [ "$cols" = "15 " ] && awk -v y="$ymax" 'BEGIN { exit !(y > 19.9 && y < 20.1) }'; then
  pass "sway3d: 15 columns in every snapshot line, largest y $ymax m"
else
  fail "sway3d: snapshot lines have '$cols' columns, largest y '$ymax' (expected 15 columns, y up to 20 m)"
fi
if head -n 1 "$stem_3.history.dat" | grep -qF "end_b:y[m] end_b:vy[m/s] end_b:force_y[N]"; then
  pass "sway3d: the history names the ends' y columns"
else
  fail "sway3d: history header lacks end_b:y[m] end_b:vy[m/s] end_b:force_y[N]: $(head -n 1 "$stem_3.history.dat")"
fi
if command -v h5ls >/dev/null 2>&1; then
  missing=""
  listing=$(h5ls -r "$stem_3.h5")
  for d in /binormal_shear /curvature_n /static/binormal_shear /static/y /history/end_a/force_y /history/end_b/y \
           /history/end_b/vy; do
    printf '%s\n' "$listing" | grep -q "^$d " || missing="$missing $d"
  done
  if [ -z "$missing" ]; then pass "sway3d: the HDF5 file has the 3-D fields, static fields and end history"
  else fail "sway3d: the HDF5 file lacks$missing"; fi
  if h5ls -r "$stem_b.h5" | grep -q "binormal_shear\|/y "; then
    fail "short_315 (a planar run) has 3-D datasets: $(h5ls -r "$stem_b.h5" | grep "binormal_shear\|/y ")"
  else
    pass "short_315: a planar run has no 3-D datasets"
  fi
fi

# What the scripts read from the files: the pieces of the snapshots and the ends of the history.
# probe <stem>: prints "npieces nsnap nends Lcab" as the plot scripts see them.
probe() {
  gnuplot -e "stem='$1'" -e "plotdir='$plots'; load '$plots/common.gp'; load '$plots/snapshots.gp'; \
    load '$plots/history.gp'; print sprintf('%d %d %d %g', npieces, nsnap, nends, Lcab)" 2>&1
}
expect_probe() {
  local stem=$1 want=$2 got
  got=$(probe "$stem")
  if [ "$got" = "$want" ]; then pass "$(basename "$stem"): pieces, snapshots, ends, length = $want"
  else fail "$(basename "$stem"): the scripts read '$got' (pieces snapshots ends length), expected '$want'"; fi
}
expect_probe "$stem_b" "1 4 2 60"
expect_probe "$stem_m" "2 31 4 60"
expect_probe "$stem_h" "1 31 2 60"
if grep -q 'break_a:speed' "$stem_m.history.dat" && grep -q 'break_b:force' "$stem_m.history.dat"; then
  pass "break_middle: the history header names the ends at the break"
else
  fail "break_middle: the history header lacks break_a/break_b: $(head -n 1 "$stem_m.history.dat")"
fi

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
  if [ -s "$err" ]; then fail "$name: gnuplot said: $(head -c 600 "$err")"; return; fi
  pass "$name"
}

# Each single-run script on each run (the paper's layout, the break in the middle, the heave, 3-D).
for stem in "$stem_a" "$stem_b" "$stem_m" "$stem_h" "$stem_3"; do
  for kind in motion tension velocity ends energy map; do
    out=$stem.$kind.png rc=0
    # check_fill.gp warns (and so fails the check) when the data leave a third of an axis empty.
    gnuplot -e "stem='$stem'; out='$out'" "$plots/$kind.gp" -e "load '$plots/check_fill.gp'" 2> "$stem.$kind.err" || rc=$?
    check "$kind.gp ($(basename "$stem"))" "$out" "$stem.$kind.err" "$rc"
  done
done
# The line over the seabed: drawn without warnings, its touchdown points found in every
# snapshot (the label names the arc length of the one at t = 0), and a clear refusal without
# the bottom's depth.
out=$stem_s.seabed.png rc=0
gnuplot -e "stem='$stem_s'; out='$out'; depth=30; slope_x=0.02; diameter=0.1" "$plots/seabed.gp" \
  -e "load '$plots/check_fill.gp'" 2> "$stem_s.seabed.err" || rc=$?
check "seabed.gp (seabed)" "$out" "$stem_s.seabed.err" "$rc"
touch=$(gnuplot -e "stem='$stem_s'; out='$tmp/seabed_report.png'; depth=30; slope_x=0.02; diameter=0.1; report=1" \
  "$plots/seabed.gp" 2>&1 | sed -n 's/^seabed.gp: //p')
if [ "$(echo "$touch" | awk '{ print ($1 == $3 && $3 > 20) ? "yes" : "no" }')" = yes ]; then
  pass "seabed: $touch"
else
  fail "seabed: expected a touchdown point in each of more than 20 snapshots, got '$touch'"
fi
rc=0
gnuplot -e "stem='$stem_s'; out='$tmp/seabed_nodepth.png'" "$plots/seabed.gp" 2> "$tmp/seabed_nodepth.err" || rc=$?
if [ "$rc" -ne 0 ] && [ ! -s "$tmp/seabed_nodepth.png" ] && grep -q "give depth and slope_x" "$tmp/seabed_nodepth.err"; then
  pass "seabed.gp refuses a call without the bottom"
else
  fail "seabed.gp without depth: exit $rc, messages: $(cat "$tmp/seabed_nodepth.err")"
fi
# The 3-D views of the 3-D run, and a clear refusal of a planar run.
for kind in motion3d plan; do
  out=$stem_3.$kind.png rc=0
  gnuplot -e "stem='$stem_3'; out='$out'" "$plots/$kind.gp" 2> "$stem_3.$kind.err" || rc=$?
  check "$kind.gp (sway3d)" "$out" "$stem_3.$kind.err" "$rc"
  rc=0
  gnuplot -e "stem='$stem_b'; out='$tmp/planar_$kind.png'" "$plots/$kind.gp" 2> "$tmp/planar_$kind.err" || rc=$?
  if [ "$rc" -ne 0 ] && [ ! -e "$tmp/planar_$kind.png" ] && grep -q "not a 3-D run" "$tmp/planar_$kind.err"; then
    pass "$kind.gp refuses a planar run"
  else
    fail "$kind.gp on a planar run: exit $rc, messages: $(cat "$tmp/planar_$kind.err")"
  fi
done
# The other fields of the map.
for field in strain u v; do
  out=$stem_m.map_$field.png rc=0
  gnuplot -e "stem='$stem_m'; out='$out'; field='$field'" "$plots/map.gp" 2> "$stem_m.map_$field.err" || rc=$?
  check "map.gp field=$field (break_middle)" "$out" "$stem_m.map_$field.err" "$rc"
done

# Keys that cover nothing: each figure is drawn again from a copy of the scripts with every key
# off (and the margins they keep), and the pixels where the two drawings differ, the key's, must
# be blank in the drawing without it (tools/check_figure_keys.py): a key over data, a grid line, a
# label or the title fails.
keyless=$tmp/keyless
rm -rf "$keyless"; cp -r "$plots" "$keyless"
sed -i -E -e 's/set key (top|bottom|at|left|right|outside|below|inside)[^};]*/set key off /' "$keyless"/*.gp
# A 3-D view lays itself out anew without a key: its key is drawn in white instead (same layout).
sed -i -E -e 's/^bottom_key = .*/bottom_key = "set key off; set bmargin 5.5"/' \
   -e "s/^corner_key = .*/corner_key = \"set key at screen 0.01, screen 0.99 left top Left reverse box lc rgb 'white' opaque textcolor rgb 'white' samplen 1 spacing 1.1 width 1\"/" \
   "$keyless/common.gp"
sed -i -e "s/lc rgb '#404040' title label_/lc rgb '#ffffff' title label_/" "$keyless/motion3d.gp"
for stem in "$stem_a" "$stem_m" "$stem_h" "$stem_3" "$stem_s"; do
  kinds="motion tension velocity ends energy"
  [ "$stem" = "$stem_3" ] && kinds="$kinds motion3d plan"
  [ "$stem" = "$stem_s" ] && kinds="seabed"
  for kind in $kinds; do
    name="$kind.gp ($(basename "$stem"))" rc=0 extra=""
    [ "$kind" = seabed ] && extra="depth=30; slope_x=0.02; diameter=0.1; "
    gnuplot -e "stem='$stem'; out='$stem.$kind.keyless.png'; $extra" "$keyless/$kind.gp" 2> "$stem.$kind.keyless.err" || rc=$?
    if [ "$rc" -ne 0 ] || [ ! -s "$stem.$kind.keyless.png" ]; then fail "$name without its key: $(head -c 300 "$stem.$kind.keyless.err")"; continue; fi
    if msg=$(python3 "$root/tools/check_figure_keys.py" "$stem.$kind.png" "$stem.$kind.keyless.png" "$name"); then
      pass "$msg"
    else
      fail "$msg"
    fi
  done
done

# The paired panels: (a) 180 kN beside (b) 315 kN, and two scenes side by side.
for kind in motion tension velocity; do
  out=$tmp/pair_$kind.png rc=0
  gnuplot -e "kind='$kind'; stem_a='$stem_a'; stem_b='$stem_b'; out='$out'" "$plots/pair.gp" 2> "$tmp/pair_$kind.err" || rc=$?
  check "pair.gp kind=$kind" "$out" "$tmp/pair_$kind.err" "$rc"
  out=$tmp/pair_scenes_$kind.png rc=0
  gnuplot -e "kind='$kind'; stem_a='$stem_m'; stem_b='$stem_b'; out='$out'" "$plots/pair.gp" 2> "$tmp/pair_scenes_$kind.err" || rc=$?
  check "pair.gp kind=$kind (break_middle beside short_315)" "$out" "$tmp/pair_scenes_$kind.err" "$rc"
done

# The drivers: draw.sh on each kind of run, in PNG, and in PDF; draw.sh's messages are not
# warnings (it says which figures it skips and why).
for stem in "$stem_b" "$stem_m" "$stem_h" "$stem_3" "$stem_s"; do
  name=$(basename "$stem") rc=0
  "$plots/draw.sh" "$stem" "$tmp/draw_$name" > "$tmp/draw_$name.log" 2> "$tmp/draw_$name.err" || rc=$?
  for kind in motion tension velocity ends energy; do
    check "draw.sh $kind.png ($name)" "$tmp/draw_$name/$kind.png" "$tmp/draw_$name.err" "$rc"
  done
done
for kind in motion3d plan; do
  check "draw.sh $kind.png (sway3d)" "$tmp/draw_sway3d/$kind.png" "$tmp/draw_sway3d.err" 0
  if [ -e "$tmp/draw_short_315/$kind.png" ]; then fail "draw.sh drew $kind.png for a planar run (short_315)"; fi
done
check "draw.sh seabed.png (seabed)" "$tmp/draw_seabed/seabed.png" "$tmp/draw_seabed.err" 0
if [ -e "$tmp/draw_short_315/seabed.png" ]; then fail "draw.sh drew seabed.png for a run without a seabed (short_315)"; fi
check "draw.sh map.png (break_middle)" "$tmp/draw_break_middle/map.png" "$tmp/draw_break_middle.err" 0
if [ ! -e "$tmp/draw_short_315/map.png" ] && grep -q "map not drawn" "$tmp/draw_short_315.log"; then
  pass "draw.sh skips the map of a run with few snapshots, and says so"
else
  fail "draw.sh on short_315 (4 snapshots): expected no map and a message; got $(ls "$tmp/draw_short_315")"
fi
rc=0
"$plots/draw.sh" "$stem_m" "$tmp/draw_pdf" pdf > /dev/null 2> "$tmp/draw_pdf.err" || rc=$?
for kind in motion tension velocity ends energy map; do check "draw.sh $kind.pdf (break_middle)" "$tmp/draw_pdf/$kind.pdf" "$tmp/draw_pdf.err" "$rc"; done

# Titles and key labels from the stored namelist (needs h5dump).
if command -v h5dump >/dev/null 2>&1; then
  # shellcheck source=plots/caseinfo.sh
  source "$plots/caseinfo.sh"
  want="break_middle: end a fixed, end b fixed; break at s = 30 m of 60 m in 5 ms"
  got=$(case_title "$stem_m")
  [ "$got" = "$want" ] && pass "case_title: $got" || fail "case_title of break_middle: '$got', expected '$want'"
  want="short_315: static tension 315 kN, breaking time 5 ms"
  got=$(case_title "$stem_b")
  [ "$got" = "$want" ] && pass "case_title: $got" || fail "case_title of short_315: '$got', expected '$want'"
  got="$(end_label "$(nml_text "$stem_h")" a) / $(end_label "$(nml_text "$stem_h")" b)"
  want="end a (moved ±0.5 m, 1 s) / end b (200 kg mass)"
  [ "$got" = "$want" ] && pass "end_label: $got" || fail "end_label of heave: '$got', expected '$want'"
fi

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

# Without the energy ledger the energy figure is skipped with a message, not an error: a run
# without &output energy (the header ends '(no energy ledger)'), and the old 4-column layout.
mkdir -p "$tmp/noenergy"
sed "s/energy = .true./energy = .false./; s|$tmp/short_180.h5|$tmp/noenergy/run.h5|" "$tmp/short_180.nml" > "$tmp/noenergy/run.nml"
"$xcable" "$tmp/noenergy/run.nml" > /dev/null 2>&1 || fail "xcable could not run $tmp/noenergy/run.nml"
awk 'NR == 1 { print "# columns: t[s] end_velocity[m/s] fixed_end_tension[N] newton_iterations"; next }
     { print $1, $2, $3, $4 }' "$stem_a.history.dat" > "$tmp/noenergy/old.history.dat"
cp "$stem_a.snapshots.dat" "$tmp/noenergy/old.snapshots.dat"
for run in run old; do
  rc=0
  gnuplot -e "stem='$tmp/noenergy/$run'; out='$tmp/noenergy/$run.energy.png'" "$plots/energy.gp" 2> "$tmp/noenergy/$run.err" || rc=$?
  if [ "$rc" -eq 0 ] && [ ! -e "$tmp/noenergy/$run.energy.png" ] && grep -q "no energy columns" "$tmp/noenergy/$run.err"; then
    pass "energy.gp skips a run without energy columns ($run)"
  else
    fail "energy.gp without energy columns ($run): exit $rc, output $(ls "$tmp/noenergy"), messages: $(cat "$tmp/noenergy/$run.err")"
  fi
done

# A missing run is a clear error.
rc=0
gnuplot -e "stem='$tmp/none'; out='$tmp/none.png'" "$plots/tension.gp" 2> "$tmp/none.err" || rc=$?
if [ "$rc" -ne 0 ] && grep -q "not found" "$tmp/none.err"; then
  pass "a missing run is reported"
else
  fail "tension.gp on a missing run: exit $rc, messages: $(cat "$tmp/none.err")"
fi

if [ "$failures" -gt 0 ]; then
  echo "test_figures: $failures check(s) failed (runs and figures in $tmp)" >&2
  exit 1
fi
echo "test_figures: all checks passed (runs and figures in $tmp)"
