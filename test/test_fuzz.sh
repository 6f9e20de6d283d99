#!/usr/bin/env bash
# Bad-input fuzzing of xcable (issue 6, item 5).
#
#   test/test_fuzz.sh [path/to/xcable]        (default bin/xcable)
#
# Makes malformed namelists by corrupting the valid input/*.nml files
# (truncation, wrong types, NaN and Inf, huge and tiny values, unknown groups
# and variables, duplicated groups, bad syntax, binary junk, output paths that
# cannot be created) and runs xcable on each in a scratch directory of its own
# that has an empty results/ (so a case that slipped through would write its
# result file there). Every case must end with
#   - exit code 2 (no signal, no timeout),
#   - exactly one line on stderr, 'xcable: error: ...', containing every
#     word the case expects: the variable (or group) at fault with its value
#     where it has one, and the specific reason (not merely the file name),
#   - no 'Backtrace', 'Fortran runtime error' or 'Segmentation' anywhere,
#   - no file created or changed (the scratch directory and any absolute
#     output path are checked).
# The --resume cases start from a result file and checkpoint of a run
# stopped by SIGTERM (made once, in the setup) and offer it damaged, from
# another case, from another version (its version attribute rewritten and
# its header checksum recomputed, by python3), without its result file, etc.
# Controls first: the unchanged inputs pass `--check` and one short real run
# does write its result file (so the 'no file' check can see one).
# Exit code: 0 if every case passed, 1 otherwise (each failure is listed).
set -u

exe=${1:-bin/xcable}
[[ -x $exe ]] || { echo "test_fuzz: no executable $exe (make build first)" >&2; exit 1; }
exe=$(cd "$(dirname "$exe")" && pwd)/$(basename "$exe")
root=$(cd "$(dirname "$0")/.." && pwd)
inputs=("$root"/input/*.nml)
work=$(mktemp -d "${TMPDIR:-/tmp}/xcable_fuzz.XXXXXX")
trap 'rm -rf "$work"' EXIT
limit=30          # seconds per case: a validation takes milliseconds
n=0
failed=0
failures=()

# --- case construction ------------------------------------------------------
# begin NAME EXPECT...: a new scratch directory; the case file is $f. The
# message must contain every EXPECT (case-insensitive).
begin() {
   n=$((n + 1))
   name=$1
   shift
   expect=("$@")
   dir=$work/$(printf 'case%03d' "$n")
   mkdir -p "$dir/results"
   f=$dir/case.nml
   extra_paths=()
}
# from BASE: start from input/BASE.nml.
# from CASE: start from input/CASE.nml; the paper's cases state &material compression = 'law',
# which is dropped so that a case can add its own &material group (a group may be given once).
from() { cp "$root/input/$1.nml" "$f"; sed -i -e "/^&material compression = 'law' \/\$/d" "$f"; }
# edit SED-EXPRESSION: change the case file.
edit() { sed -i -e "$1" "$f"; }
# add TEXT: append a line.
add() { printf '%s\n' "$1" >>"$f"; }
# set_in GROUP TEXT: put 'TEXT' right after '&GROUP' (the group must be present).
set_in() { sed -i -e "s|^&$1 |\&$1 $2, |" "$f"; }
# cut_after PATTERN OFFSET: keep the file up to OFFSET bytes after the first PATTERN.
cut_after() {
   local at
   at=$(grep -b -o -m1 -F -- "$1" "$f" | head -1 | cut -d: -f1)
   head -c $((at + $2)) "$f" >"$f.tmp" && mv "$f.tmp" "$f"
}

# --- running and checking ---------------------------------------------------
# check: run xcable on the case and assert the rules above.
check() {
   local out=$dir.stdout err=$dir.stderr rc lines problem='' before after p
   before=$(cd "$dir" && { find . -mindepth 1; find . -type f -exec md5sum {} +; } | sort)
   (cd "$dir" && timeout "$limit" "$exe" "${args[@]:-case.nml}" >"$out" 2>"$err")
   rc=$?
   after=$(cd "$dir" && { find . -mindepth 1; find . -type f -exec md5sum {} +; } | sort)
   lines=$(awk 'END { print NR }' "$err")
   if ((rc == 124)); then
      problem="timed out after $limit s (hang)"
   elif ((rc > 128)); then
      problem="killed by signal $((rc - 128))"
   elif ((rc != 2)); then
      problem="exit code $rc, expected 2"
   fi
   if grep -q -i -E 'backtrace|fortran runtime error|segmentation|error termination' "$out" "$err"; then
      problem="${problem:+$problem; }crash output"
   fi
   if [[ $lines != 1 ]]; then
      problem="${problem:+$problem; }$lines lines on stderr, expected 1"
   elif ! grep -q '^xcable: error: ' "$err"; then
      problem="${problem:+$problem; }stderr does not start with 'xcable: error: '"
   else
      for p in "${expect[@]}"; do
         grep -q -i -F -- "$p" "$err" || problem="${problem:+$problem; }message does not name '$p'"
      done
   fi
   if [[ $before != "$after" ]]; then
      problem="${problem:+$problem; }created or changed: $(comm -13 <(echo "$before") <(echo "$after") | tr '\n' ' ')"
   fi
   for p in "${extra_paths[@]}"; do
      [[ -e $p ]] && problem="${problem:+$problem; }created $p"
   done
   if [[ -n $problem ]]; then
      failed=$((failed + 1))
      failures+=("$(printf 'case%03d %s: %s | %s' "$n" "$name" "$problem" "$(head -c 300 "$err" | head -3 | tr '\n' ' ')")")
      printf '  FAIL %03d %-44s %s\n' "$n" "$name" "$problem"
   else
      printf '  ok   %03d %-44s %s\n' "$n" "$name" "$(head -c 110 "$err" | head -1)"
   fi
   args=()
}
args=()

# --- controls ---------------------------------------------------------------
echo "controls: the valid inputs"
for input in "${inputs[@]}"; do
   if ! (cd "$root" && "$exe" --check "$input" >/dev/null 2>&1); then
      echo "  FAIL control: $input is refused by --check"
      failed=$((failed + 1))
      failures+=("control $input refused")
   fi
done
# Valid variants the stricter scan must still accept.
control_ok() {
   local what=$1 text=$2 c=$work/control.nml
   printf '%b' "$text" >"$c"
   if ! "$exe" --check "$c" >/dev/null 2>"$c.err"; then
      echo "  FAIL control: refused $what: $(head -1 "$c.err")"
      failed=$((failed + 1))
      failures+=("control refused: $what")
   else
      echo "  ok   accepted: $what"
   fi
}
control_ok 'CR LF line ends' "! DOS text\r\n&static tension = 180000 /\r\n&numerics nodes = 41 /\r\n"
control_ok 'an element and a range of p' "&material p(2) = 10.2, p(3:4) = -2.128, 2.627e5 /\n"
control_ok 'p filled from element 4' "&material p(4) = 2.627e5, 135.5 /\n"
control_ok 'repeat counts' "&material p = 2.703e5, 10.2, -2.128, 2*2.627e5 /\n"
control_ok 'tabs and trailing blanks' "&static\ttension = 180000   /  \n"
control_ok 'internal damping' "&material damping = 250 /\n"
control_ok 'a fluid with a current' "&fluid density = 1025, cd_normal = 1.2, cd_tangential = 0.008, ca_normal = 1, current_x = 0.5 /\n"
begin control_run ''
from fast_180kN
edit 's/nodes = [0-9]*/nodes = 21/; s/t_end = [0-9.]*/t_end = 0.002/; s/interval = [0-9.]*/interval = 0.001/'
(cd "$dir" && timeout "$limit" "$exe" case.nml >/dev/null 2>&1)
if [[ $? != 0 || ! -s $dir/results/fast_180kN.h5 ]]; then
   echo "  FAIL control: a short valid run did not write results/fast_180kN.h5"
   failed=$((failed + 1))
   failures+=("control run wrote no result file")
else
   echo "  ok   a short valid run writes its result file"
fi

echo "malformed namelists"
# --- truncation ---------------------------------------------------------------
for base in fast_180kN fast_315kN slow_180kN slow_315kN; do
   begin "truncated $base inside &numerics" '&numerics'
   from $base; cut_after '&numerics' 20; check
done
begin 'truncated inside a quoted file name' '&output'
from slow_315kN; cut_after "file = '" 5; check
begin 'truncated to the comment header' 'no namelist group'
from fast_180kN; cut_after '&static' 0; check
begin 'truncated to zero bytes' 'case.nml' 'no namelist group found'
from fast_180kN; : >"$f"; check
begin 'truncated inside a value (no /)' '&static'
from slow_180kN; cut_after '&static' 22; check

# --- wrong types --------------------------------------------------------------
begin 'real given as a word' 'tension'
from fast_315kN; edit 's/tension = 315000/tension = abc/'; check
begin 'real given as a string' 'tension'
from fast_315kN; edit "s/tension = 315000/tension = '315000'/"; check
begin 'integer given as a real' 'nodes'
from fast_315kN; edit 's/nodes = 241/nodes = 24.1/'; check
begin 'integer given as a logical' 'nodes'
from fast_315kN; edit 's/nodes = 241/nodes = .true./'; check
begin 'real with a unit' 't_break'
from fast_180kN; edit 's/t_break = 0.005/t_break = 5 ms/'; check
begin 'logical given as an integer' 'gnuplot'
from fast_180kN; edit 's/gnuplot = .true./gnuplot = 1/'; check
begin 'logical given as a string' 'energy'
from fast_180kN; edit "s/energy = .true./energy = 'yes'/"; check
begin 'logical given as a word' 'skip_quiescent'
from fast_180kN; set_in numerics 'skip_quiescent = maybe'; check
begin 'string without quotes' 'file'
from slow_180kN; edit "s|file = 'results/slow_180kN.h5'|file = results/slow_180kN.h5|"; check
begin 'law given as a number' 'law'
from slow_180kN; add '&material law = 5 /'; check
begin 'array with a word' 'p = 2.703e5, ten' '"ten" is not a finite real number'
from slow_180kN; add '&material p = 2.703e5, ten, -2.128, 2.627e5, 135.5 /'; check
begin 'fields given as a number' 'fields'
from slow_180kN; set_in output 'fields = 3'; check

# --- NaN and Inf ----------------------------------------------------------------
begin 'tension = NaN' 'tension'
from fast_315kN; edit 's/tension = 315000/tension = NaN/'; check
begin 't_break = Inf' 't_break'
from fast_315kN; edit 's/t_break = 0.005/t_break = Inf/'; check
begin 'courant = -Infinity' 'courant'
from fast_315kN; edit 's/courant = 1.0/courant = -Infinity/'; check
begin 't_end = +inf' 't_end'
from slow_315kN; edit 's/t_end = [0-9.]*/t_end = +inf/'; check
begin 'interval = nan' 'interval'
from slow_315kN; edit 's/interval = 0.01/interval = nan/'; check
begin 'p(2) = NaN' 'p(2) = NaN' 'not a finite real number'
from slow_315kN; add '&material p(2) = NaN /'; check
begin 'theta = NaN' 'theta'
from slow_315kN; set_in numerics 'theta = NaN'; check
begin 'length = Infinity' 'length'
from slow_315kN; add '&cable length = Infinity /'; check
begin 'NaN behind a repeat count' 'tension'
from fast_315kN; edit 's/tension = 315000/tension = 1*NaN/'; check
begin 'max_wall_time = Inf' 'max_wall_time'
from fast_180kN; set_in numerics 'max_wall_time = Inf'; check
begin 'checkpoint_interval = NaN' 'checkpoint_interval'
from fast_180kN; edit 's/^&output   /\&output   checkpoint_interval = NaN, /'; check

# --- huge and tiny values ---------------------------------------------------------
begin 'tension = 1e300' 'tension'
from fast_315kN; edit 's/tension = 315000/tension = 1e300/'; check
begin 'tension = 1e-300 (cannot hold the weight)' 'tension'
from fast_315kN; edit 's/tension = 315000/tension = 1e-300/'; check
begin 'tension beyond the law (strain_max)' 'tension'
from fast_315kN; edit 's/tension = 315000/tension = 9e5/'; check
begin 'nodes overflowing an integer' 'nodes'
from fast_315kN; edit 's/nodes = 241/nodes = 99999999999/'; check
begin 'nodes = 2147483647' 'nodes'
from fast_315kN; edit 's/nodes = 241/nodes = 2147483647/'; check
begin 'nodes = -5' 'nodes'
from fast_315kN; edit 's/nodes = 241/nodes = -5/'; check
begin 'nodes = 2' 'nodes'
from fast_315kN; edit 's/nodes = 241/nodes = 2/'; check
begin 'dt = 1e-300' 'dt'
from fast_315kN; set_in numerics 'dt = 1e-300'; check
begin 'courant = 1e-300' 'courant'
from fast_315kN; edit 's/courant = 1.0/courant = 1e-300/'; check
begin 'courant = 1e300' 'courant'
from fast_315kN; edit 's/courant = 1.0/courant = 1e300/'; check
begin 't_end = 1e300' 't_end'
from slow_315kN; edit 's/t_end = [0-9.]*/t_end = 1e300/'; check
begin 'length = 1e-300' 'length'
from slow_315kN; add '&cable length = 1e-300 /'; check
begin 'density = 1e-320 (denormal)' 'density'
from slow_315kN; add '&cable density = 1e-320 /'; check
begin 'diameter = 1e300' 'diameter'
from slow_315kN; add '&cable diameter = 1e300 /'; check
begin 'young = 1e-300' 'young'
from slow_315kN; add '&cable young = 1e-300 /'; check
begin 'checkpoint_interval = -1' 'checkpoint_interval = -1' 'must be 0 (none) or > 0'
from fast_180kN; edit 's/^&output   /\&output   checkpoint_interval = -1, /'; check
begin 'checkpoint_interval = 1e300' 'checkpoint_interval' '1e7'
from fast_180kN; edit 's/^&output   /\&output   checkpoint_interval = 1e300, /'; check
begin 'gravity = 0, the box scheme (static direction undetermined)' 'gravity' 'box'
from slow_315kN; add '&cable gravity = 0 /'; set_in numerics "scheme = 'box'"; check
begin 'gravity = 0, a cable held at one end only (no static shape)' 'gravity = 0' 'held at one end'
from slow_315kN; add '&cable gravity = 0 /'; add "&end_b kind = 'free' /"; set_in rupture 'enabled = .false.'; check
begin 'gravity = 1e300' 'gravity'
from slow_315kN; add '&cable gravity = 1e300 /'; check
begin 'bending_stiffness = 1e-300' 'bending_stiffness'
from slow_315kN; add '&cable bending_stiffness = 1e-300 /'; check
begin 'area = -1' 'area'
from slow_315kN; add '&cable area = -1 /'; check
begin 't_break = -0.005' 't_break'
from fast_315kN; edit 's/t_break = 0.005/t_break = -0.005/'; check
begin 'theta = 0.4' 'theta'
from slow_315kN; set_in numerics 'theta = 0.4'; check
begin 'newton_tol = 1e-300' 'newton_tol'
from slow_315kN; set_in numerics 'newton_tol = 1e-300'; check
begin 'newton_max_iter = 0' 'newton_max_iter'
from slow_315kN; set_in numerics 'newton_max_iter = 0'; check
begin 'min_step_fraction = 0' 'min_step_fraction'
from slow_315kN; set_in numerics 'min_step_fraction = 0'; check
begin 'interval = 1e-300' 'interval'
from slow_315kN; edit 's/interval = 0.01/interval = 1e-300/'; check
begin 'p(1) = 1e300' 'p(1) = 1e300' 'in [-1e12, 1e12]'
from slow_315kN; add '&material p(1) = 1e300 /'; check
begin 'p(5) = -135.5 (f decreasing)' 'p(5) = -135.5' '> 0' 'tanh law'
from slow_315kN; add '&material p(5) = -135.5 /'; check
begin 'strain_max = 1e-300' 'tension'
from slow_315kN; add '&material strain_max = 1e-300 /'; check
begin 'linear law with ea = 1e-300' 'ea'
from slow_315kN; add "&material law = 'linear', ea = 1e-300 /"; check
begin 'dt larger than t_end' 'dt'
from slow_315kN; set_in numerics 'dt = 1.0'; check

# --- unknown groups and variables, duplicates, subscripts --------------------------
begin 'unknown group &foo' '&foo'
from fast_180kN; add '&foo bar = 1 /'; check
begin 'misspelled group &statics' '&statics'
from fast_180kN; edit 's/&static /\&statics /'; check
begin 'misspelled variable tensionn' 'tensionn'
from fast_180kN; edit 's/tension = /tensionn = /'; check
begin 'variable of another group' 't_break'
from fast_180kN; edit 's/tension = 180000/tension = 180000, t_break = 0.1/'; check
begin 'misspelled variable in &cable' 'lenght'
from fast_180kN; add '&cable lenght = 60 /'; check
begin 'duplicated group &static' '&static'
from fast_180kN; add '&static tension = 100000 /'; check
begin 'duplicated group &numerics' '&numerics'
from slow_315kN; add '&numerics nodes = 121 /'; check
begin 'subscript out of range p(7)' 'p(7)' 'index from 1 to 5'
from slow_315kN; add '&material p(7) = 1 /'; check
begin 'subscript zero p(0)' 'p(0)' 'index from 1 to 5'
from slow_315kN; add '&material p(0) = 1 /'; check
begin 'too many values for p' 'p = 1, 2, 3, 4, 5, 6' 'p takes at most 5'
from slow_315kN; add '&material p = 1, 2, 3, 4, 5, 6 /'; check
begin 'subscript on a scalar' 'tension'
from slow_315kN; edit 's/tension = 315000/tension(2) = 315000/'; check
begin 'repeat count on a scalar' 'nodes'
from slow_315kN; edit 's/nodes = 241/nodes = 2*241/'; check
begin 'unknown law name' 'law'
from slow_315kN; add "&material law = 'rubber' /"; check
begin 'unknown snapshot field' 'fields'
from slow_315kN; set_in output "fields = 'tension torque'"; check

# --- scenes: ends, tables, the rupture position ----------------------------------
begin 'unknown end kind' "kind = 'pinned'" "'fixed', 'free', 'force', 'motion', 'mass'"
from slow_315kN; add "&end_a kind = 'pinned' /"; check
begin 'unknown end kind lists the spring' "kind = 'pinned'" "'mass', 'spring'"
from slow_315kN; add "&end_b kind = 'pinned' /"; check
begin 'spring with a negative stiffness' '&end_b' 'stiffness = -5' '[0, 1e12]'
from slow_315kN; add "&end_b kind = 'spring', x = 70, stiffness = -5 /"; set_in rupture 's_break = 30'; check
begin 'spring with a negative damping' '&end_b' 'damping = -1' '[0, 1e12]'
from slow_315kN; add "&end_b kind = 'spring', x = 70, stiffness = 1e4, damping = -1 /"; set_in rupture 's_break = 30'; check
begin 'spring with no stiffness' '&end_b' 'stiffness = 0' "must be > 0 for kind = 'spring'"
from slow_315kN; add "&end_b kind = 'spring', x = 70 /"; set_in rupture 's_break = 30'; check
begin 'spring values given to a force end' '&end_b' 'stiffness = 1000' "kind = 'force'" "kind 'spring'"
from slow_315kN; add "&end_b kind = 'force', force_x = 1e4, stiffness = 1000 /"; set_in rupture 's_break = 30'; check
begin 'rest_length given to a fixed end' '&end_b' 'rest_length = 2' "kind = 'fixed'" "kind 'spring'"
from slow_315kN; add "&end_b kind = 'fixed', x = 50, rest_length = 2 /"; check
begin 'amplitude and period on a fixed end (issue 29)' '&end_b' 'amplitude = 0.5' "kind = 'fixed'" "kind 'motion'"
from slow_315kN; add "&end_b kind = 'fixed', x = 50, amplitude = 0.5, period = 2 /"; check
begin "spring anchored at the other end's point with a rest length" '&end_b' 'rest_length = 2' "the other end's point"
from slow_315kN; add "&end_b kind = 'spring', x = 0, z = 0, stiffness = 1e4, rest_length = 2 /"; set_in rupture 's_break = 30'; check
begin 'end kind given as a number' 'kind = 1' 'must be a quoted string'
from slow_315kN; add '&end_b kind = 1 /'; check
begin 'unknown force history' "history = 'sudden'" "'constant', 'ramp', 'table'"
from slow_315kN; add "&end_b kind = 'force', history = 'sudden' /"; check
begin 'unknown motion' "motion = 'circle'" "'harmonic', 'table'"
from slow_315kN; add "&end_a kind = 'motion', motion = 'circle' /"; check
begin 'unknown scheme' "scheme = 'fem'" "'rod', 'box'"
from slow_315kN; set_in numerics "scheme = 'fem'"; check
begin 'unknown mass_matrix' "mass_matrix = 'full'" "'averaged', 'lumped'"
from slow_315kN; set_in numerics "mass_matrix = 'full'"; check
begin 'unknown compression' "compression = 'slack'" "'law', 'none'"
from slow_315kN; add "&material compression = 'slack' /"; check
begin 'mass end with mass = 0' '&end_b' 'mass = 0' "must be > 0 for kind = 'mass'"
from slow_315kN; add "&end_b kind = 'mass' /"; set_in rupture 's_break = 30'; check
begin 'mass end with mass = -5' '&end_b' 'mass = -5' 'in [0, 1e9]'
from slow_315kN; add "&end_b kind = 'mass', mass = -5 /"; set_in rupture 's_break = 30'; check
begin 'break beyond the length' 's_break = 70' 'in [0, 60 (&cable length)]'
from slow_315kN; set_in rupture 's_break = 70'; check
begin 'break at a negative position' 's_break = -5' 'in [0, 60'
from slow_315kN; set_in rupture 's_break = -5'; check
begin 'break beyond a shorter cable' 's_break = 50' 'in [0, 40 (&cable length)]'
from slow_315kN; set_in rupture 's_break = 50'; add '&cable length = 40 /'; check
# the break at the breaking load (&rupture criterion = 'tension', mbl)
begin 'rupture criterion not a word' '&rupture' "criterion = 'force'" "'time', 'tension'"
from slow_315kN; set_in rupture "criterion = 'force'"; check
begin 'tension break without mbl' '&rupture' 'mbl = not given' "criterion = 'tension'" 'above 0 N'
from slow_315kN; set_in rupture "criterion = 'tension'"; check
begin 'tension break with mbl = 0' '&rupture' 'mbl = 0' 'above 0 N'
from slow_315kN; set_in rupture "criterion = 'tension', mbl = 0"; check
begin 'tension break with mbl = -5' '&rupture' 'mbl = -5' '> 0'
from slow_315kN; set_in rupture "criterion = 'tension', mbl = -5"; check
begin 'tension break with s_break' '&rupture' "criterion = 'tension'" 's_break = 30' 'not used'
from slow_315kN; set_in rupture "criterion = 'tension', mbl = 1e6, s_break = 30"; check
begin 'tension break with time' '&rupture' "criterion = 'tension'" 'time = 0.1' 'not used'
from slow_315kN; set_in rupture "criterion = 'tension', mbl = 1e6, time = 0.1"; check
begin 'tension break with s_break and time' '&rupture' 's_break = 30 and time = 0.1' 'not used'
from slow_315kN; set_in rupture "criterion = 'tension', mbl = 1e6, time = 0.1, s_break = 30"; check
begin 'MBL below the static tension' '&rupture' 'mbl = 300000' 'would part in statics' '315 kN'
from slow_315kN; set_in rupture "criterion = 'tension', mbl = 3e5"; check
begin 'MBL at the static tension' '&rupture' 'mbl = 315000' 'would part in statics'
from slow_315kN; set_in rupture "criterion = 'tension', mbl = 315000"; check
begin 'tension break with the box scheme' '&rupture' "criterion = 'tension'" 'box scheme'
from slow_315kN; set_in rupture "criterion = 'tension', mbl = 1e6"; set_in numerics "scheme = 'box'"; check
begin 'two free ends' "kind = 'free'" 'no support' 'no static state'
from slow_315kN; add "&end_a kind = 'free' /"; add "&end_b kind = 'free' /"; check
begin 'a free end and a force end' "&end_b: kind = 'force'" 'nothing holds the cable'
from slow_315kN; add "&end_a kind = 'free' /"; add "&end_b kind = 'force' /"; check
begin 'tension and end position both given' 'tension = 315000' '&end_b x = 50' 'both given'
from slow_315kN; add '&end_b x = 50 /'; check
begin 'position of a force end' '&end_b' 'z = 1' "kind = 'force'" 'follows from the statics'
from slow_315kN; add "&end_b kind = 'force', z = 1 /"; set_in rupture 's_break = 30'; check
begin 'force ramp without ramp_time' 'ramp_time = 0' "history = 'ramp'"
from slow_315kN; add "&end_b kind = 'force', history = 'ramp' /"; set_in rupture 's_break = 30'; check
begin 'harmonic motion with period = 0' 'period = 0' "motion = 'harmonic'"
from slow_315kN; add "&end_a kind = 'motion', period = 0 /"; check
begin 'harmonic motion without direction' 'direction_x = 0, direction_y = 0, direction_z = 0' 'must not be zero'
from slow_315kN; add "&end_a kind = 'motion', direction_z = 0 /"; check
begin 'harmonic motion direction of zero length (3 components)' 'direction_x = 0, direction_y = 0, direction_z = 0' \
   'must not be zero'
from slack_swing; edit "s|^&end_b .*|\&end_b kind = 'motion', x = 50, direction_x = 0, direction_y = 0, direction_z = 0 /|"
check
# The 3-D model (issue 15): 3-D data under model = '2d', GIp <= 0, and what the 3-D model does not do.
begin "3-D data with model = '2d'" "model = '2d'" '&end_b y = 5' "allowed: model = '3d' or 'auto'"
from slack_swing; edit "s|x = 50.0, z = 0.0|x = 50.0, y = 5.0, z = 0.0|"; set_in numerics "model = '2d'"; check
begin "a torque with model = '2d'" "model = '2d'" '&end_b torque = 10' 'x-z plane'
from slack_swing; edit "s|^&end_b .*|\&end_b kind = 'force', force_x = 100, torque = 10 /|"
set_in rupture 'enabled = .false.'; set_in numerics "model = '2d'"; check
begin "a cross current with model = '2d'" "model = '2d'" 'current_y = 0.5'
from slack_swing; add '&fluid density = 1025, current_y = 0.5 /'; set_in numerics "model = '2d'"; check
begin 'gip = -1' 'gip = -1' '1e-6'
from slack_swing; add '&cable gip = -1 /'; check
begin 'gip = 1e-300' 'gip' '1e-6'
from slack_swing; add '&cable gip = 1e-300 /'; check
begin 'model given as a word not allowed' "model = 'xyz'" "'auto'"
from slack_swing; set_in numerics "model = 'xyz'"; check
begin "model = '3d' with the box scheme" "scheme = 'box'" "model = '3d'" "scheme = 'rod'"
from slow_315kN; set_in numerics "scheme = 'box', model = '3d'"; check
begin "a 3-D scene with the box scheme (model 'auto')" "scheme = 'box'" '&end_a y = 1' 'planar'
from slow_315kN; add "&end_a y = 1 /"; set_in numerics "scheme = 'box'"; check
# A break inside the cable runs in 3-D too (two 3-D pieces); what it refuses is what the planar run refuses.
begin "model = '3d', a break inside the cable on 4 nodes" 'nodes = 4' 'break inside the cable' 'at least 5 nodes'
from inclined_break_middle; edit 's/nodes = 481/nodes = 4/'; set_in numerics "model = '3d'"; check
begin 'current_y without a fluid' 'current_y = 0.5' 'needs a fluid'
from slack_swing; add '&fluid current_y = 0.5 /'; check
begin 'y of a free end' '&end_b' 'y = 2' "kind = 'free'" 'leave y out'
from slack_swing; edit "s|^&end_b .*|\&end_b kind = 'free', y = 2 /|"; set_in rupture 'enabled = .false.'; check
begin 'tension and end b y both given' 'tension = 315000' 'y = 3' 'both given'
from slow_315kN; add '&end_b y = 3 /'; check
begin 'break at a free end (the default s_break)' 's_break = 60 (the default, L)' "kind = 'free'" 'nothing to break'
from slow_315kN; add "&end_b kind = 'free' /"; check
begin 'table motion without a table' "motion = 'table' without a table"
from slow_315kN; add "&end_a kind = 'motion', motion = 'table' /"; check
begin 'table of one row' 'table_time = 0' '1 row' 'at least 2'
from slow_315kN; add "&end_a kind = 'motion', motion = 'table', table_time = 0, table_x = 0, table_z = 0 /"; check
begin 'table times not increasing' 'table_time(3) = 0.5' 'increase strictly'
from slow_315kN
add "&end_a kind = 'motion', motion = 'table', table_time = 0, 1, 0.5, table_x = 3*0, table_z = 3*0 /"; check
begin 'table columns of unequal counts' 'table_time has 3 values' 'table_x 2' 'equal counts'
from slow_315kN
add "&end_a kind = 'motion', motion = 'table', table_time = 0, 1, 2, table_x = 0, 0, table_z = 3*0 /"; check
begin 'table longer than 1000 rows' 'table_time = 1001*0' 'takes at most 1000'
from slow_315kN; add "&end_a table_time = 1001*0 /"; check
begin 'table_y of other count' 'table_y has 3 values' 'table_time 2' 'one value a row'
from slow_315kN
add "&end_a kind = 'motion', motion = 'table', table_time = 0, 1, table_x = 2*0, table_y = 3*0, table_z = 2*0 /"; check
begin 'table_y without a table' 'table_y has 2 values' 'table_time 0'
from slow_315kN; add "&end_a kind = 'motion', motion = 'table', table_y = 0, 1 /"; check
begin 'table_y NaN' 'table_y = 0, NaN' '"NaN" is not a finite real number'
from slow_315kN; add "&end_a table_time = 0, 1, table_x = 0, 0, table_y = 0, NaN, table_z = 0, 0 /"; check
begin 'table_y infinite' 'table_y' 'Inf'
from slow_315kN; add "&end_a table_time = 0, 1, table_x = 0, 0, table_y = Inf, 0, table_z = 0, 0 /"; check
begin 'table_y too large' 'table_y(2) = 2e9' '[-1e9, 1e9]'
from slow_315kN; add "&end_a table_time = 0, 1, table_x = 0, 0, table_y = 0, 2e9, table_z = 0, 0 /"; check
begin "table_y with model = '2d'" "model = '2d'" '&end_b table_y(2) = 0.5' "allowed: model = '3d' or 'auto'"
from slack_swing; edit "s|^&end_b .*|\&end_b kind = 'motion', motion = 'table', x = 50.0, z = 0.0, table_time = 0, 1, table_x = 0, 0, table_y = 0, 0.5, table_z = 0, 0 /|"
set_in numerics "model = '2d'"; check
begin 'table value NaN' 'table_x = 0, NaN' '"NaN" is not a finite real number'
from slow_315kN; add "&end_a table_time = 0, 1, table_x = 0, NaN, table_z = 0, 0 /"; check
begin 'table both inline and in a file' "table_file = 't.dat'" 'inline table' 'give one'
from slow_315kN; printf '0 0\n1 1\n' >"$dir/t.dat"
add "&end_a kind = 'motion', motion = 'table', table_time = 0, 1, table_x = 0, 1, table_z = 0, 0, table_file = 't.dat' /"
check
begin 'missing table file' "table_file = 'no_such.dat'" 'no such file'
from slow_315kN; add "&end_a kind = 'motion', motion = 'table', table_file = 'no_such.dat' /"; check
begin 'table file with a word' "table_file = 't.dat'" 'line 3' '"x" is not a finite real number'
from slow_315kN; printf '# t x z\n0 0 0\n1 x 0\n' >"$dir/t.dat"
add "&end_a kind = 'motion', motion = 'table', table_file = 't.dat' /"; check
begin 'table file with five columns' "table_file = 't.dat'" 'line 1' 'expected 2, 3 or 4 numbers' 't, x, y, z'
from slow_315kN; printf '0 0 0 0 0\n1 1 1 1 1\n' >"$dir/t.dat"
add "&end_a kind = 'motion', motion = 'table', table_file = 't.dat' /"; check
begin 'table file of four columns then three' "table_file = 't.dat'" 'line 2' '3 numbers' 'before have 4'
from slow_315kN; printf '0 0 0 0\n1 1 1\n' >"$dir/t.dat"
add "&end_a kind = 'motion', motion = 'table', table_file = 't.dat' /"; check
begin 'table file y column with model 2d' "model = '2d'" "table_y(2) = 1" 'x-z plane'
from slow_315kN; printf '0 0 0 0\n1 0 1 0\n' >"$dir/t.dat"
add "&end_a kind = 'motion', motion = 'table', table_file = 't.dat' /"; set_in numerics "model = '2d'"; check
begin 'table file times not increasing' "table_file = 't.dat'" 'line 3' 'increase strictly'
from slow_315kN; printf '0 0\n1 1\n1 2\n' >"$dir/t.dat"
add "&end_a kind = 'motion', motion = 'table', table_file = 't.dat' /"; check
begin 'table file with a NUL byte' "table_file = 't.dat'" 'line 2, column 1' 'byte 0 is not printable'
from slow_315kN; printf '0 0\n\0001 1\n' >"$dir/t.dat"
add "&end_a kind = 'motion', motion = 'table', table_file = 't.dat' /"; check
begin 'table file is a directory' "table_file = 'tdir'" 'not a regular text file'
from slow_315kN; mkdir "$dir/tdir"
add "&end_a kind = 'motion', motion = 'table', table_file = 'tdir' /"; check
begin 'table file longer than 1000 rows' "table_file = 't.dat'" 'line 1001' 'more than 1000 rows'
from slow_315kN; seq 0 1000 | awk '{ print $1, 0 }' >"$dir/t.dat"
add "&end_a kind = 'motion', motion = 'table', table_file = 't.dat' /"; check

# --- the table law and damping (&material) ------------------------------------------
begin 'table law without a table' "law = 'table' without a table" 'table_file'
from slow_315kN; add "&material law = 'table' /"; check
begin 'table law with one row' 'table_strain = 0.1' '1 row' 'at least 2'
from slow_315kN; add "&material law = 'table', table_strain = 0.1, table_tension = 1e4 /"; check
begin 'table law strains not increasing' 'table_strain(3) = 0.1' 'not above table_strain(2) = 0.2' \
   'strains must increase strictly'
from slow_315kN; add "&material law = 'table', table_strain = 0, 0.2, 0.1, table_tension = 0, 1e4, 2e4 /"; check
begin 'table law tension decreasing' 'table_tension(3) = 10000' 'not above table_tension(2) = 20000' \
   'tensions must increase strictly' 'negative slope'
from slow_315kN; add "&material law = 'table', table_strain = 0, 0.1, 0.2, table_tension = 0, 2e4, 1e4 /"; check
begin 'table law tension flat' 'table_tension(2) = 0' 'tensions must increase strictly'
from slow_315kN; add "&material law = 'table', table_strain = 0, 0.1, table_tension = 2*0 /"; check
begin 'table law tension NaN' 'table_tension = 0, NaN' '"NaN" is not a finite real number'
from slow_315kN; add "&material law = 'table', table_strain = 0, 0.1, table_tension = 0, NaN /"; check
begin 'table law strain -Inf' 'table_strain = -Inf, 0' '"-Inf" is not a finite real number'
from slow_315kN; add "&material law = 'table', table_strain = -Inf, 0, table_tension = 0, 1e4 /"; check
begin 'table law strain at -1' 'table_strain(1) = -1' '> -1 and <= 1'
from slow_315kN; add "&material law = 'table', table_strain = -1, 0, table_tension = 0, 1e4 /"; check
begin 'table law columns of unequal counts' 'table_strain has 3 values' 'table_tension 2' 'equal counts'
from slow_315kN; add "&material law = 'table', table_strain = 0, 0.1, 0.2, table_tension = 0, 1e4 /"; check
begin 'table law longer than 1000 rows' 'table_tension = 1001*0' 'takes at most 1000'
from slow_315kN; add "&material law = 'table', table_tension = 1001*0 /"; check
begin "table rows with law = 'tanh'" 'table_strain = 0, 0.1' "law = 'tanh'" "set law = 'table'"
from slow_315kN; add '&material table_strain = 0, 0.1, table_tension = 0, 1e4 /'; check
begin "table file with law = 'linear'" "table_file = 't.dat'" "law = 'linear'" "set law = 'table'"
from slow_315kN; printf '0 0\n0.1 1e4\n' >"$dir/t.dat"; add "&material law = 'linear', table_file = 't.dat' /"; check
begin 'table law both inline and in a file' "table_file = 't.dat'" 'inline table (table_strain, 2 rows)' 'give one'
from slow_315kN; printf '0 0\n0.1 1e4\n' >"$dir/t.dat"
add "&material law = 'table', table_strain = 0, 0.1, table_tension = 0, 1e4, table_file = 't.dat' /"; check
begin 'missing table file of the law' "table_file = 'no_such.dat'" 'no such file (the path is relative'
from slow_315kN; add "&material law = 'table', table_file = 'no_such.dat' /"; check
begin 'law table file with a word' "table_file = 't.dat'" 'line 3' '"1e4x" is not a finite real number'
from slow_315kN; printf '# strain tension\n0 0\n0.1 1e4x\n' >"$dir/t.dat"
add "&material law = 'table', table_file = 't.dat' /"; check
begin 'law table file with three columns' "table_file = 't.dat'" 'line 1' 'expected 2 numbers (strain and tension)'
from slow_315kN; printf '0 0 0\n0.1 1e4 0\n' >"$dir/t.dat"
add "&material law = 'table', table_file = 't.dat' /"; check
begin 'law table file strains not increasing' "table_file = 't.dat'" 'line 4' 'strains must increase strictly'
from slow_315kN; printf '0 0\n0.2 1e4\n\n0.1 2e4\n' >"$dir/t.dat"
add "&material law = 'table', table_file = 't.dat' /"; check
begin 'law table file tension decreasing' "table_file = 't.dat'" 'line 3' 'tension 5000 is not above' \
   'tensions must increase strictly'
from slow_315kN; printf '0 0\n0.1 1e4\n0.2 5e3\n' >"$dir/t.dat"
add "&material law = 'table', table_file = 't.dat' /"; check
begin 'law table file with one row' "table_file = 't.dat'" 'has 1 row; a table must have at least 2'
from slow_315kN; printf '# only\n0.1 1e4\n' >"$dir/t.dat"
add "&material law = 'table', table_file = 't.dat' /"; check
begin 'law table file without rows' "table_file = 't.dat'" 'has 0 rows; a table must have at least 2'
from slow_315kN; printf '# strain tension\n\n' >"$dir/t.dat"
add "&material law = 'table', table_file = 't.dat' /"; check
begin 'law table file longer than 1000 rows' "table_file = 't.dat'" 'line 1001' 'more than 1000 rows'
from slow_315kN; seq 0 1000 | awk '{ print $1 / 1000, $1 * 10 }' >"$dir/t.dat"
add "&material law = 'table', table_file = 't.dat' /"; check
begin 'damping = -5' 'damping = -5' 'in [0, 1e12]'
from slow_315kN; add '&material damping = -5 /'; check
begin 'damping = NaN' 'damping = NaN' 'not a finite real number'
from slow_315kN; add '&material damping = NaN /'; check
begin 'damping = 1e300' 'damping = 1e300' 'in [0, 1e12]'
from slow_315kN; add '&material damping = 1e300 /'; check

# --- fluid loads (&fluid) --------------------------------------------------------------
begin 'fluid density = -1025' 'density = -1025' 'in [0, 100000]'
from slow_315kN; add '&fluid density = -1025 /'; check
begin 'cd_normal = NaN' 'cd_normal = NaN' 'not a finite real number'
from slow_315kN; add '&fluid density = 1025, cd_normal = NaN /'; check
begin 'cd_tangential = -0.1' 'cd_tangential = -0.1' 'in [0, 1000]'
from slow_315kN; add '&fluid density = 1025, cd_tangential = -0.1 /'; check
begin 'ca_normal = Inf' 'ca_normal = Inf' 'not a finite real number'
from slow_315kN; add '&fluid density = 1025, ca_normal = Inf /'; check
begin 'a current without a fluid' 'current_x = 0.5' 'a current needs a fluid'
from slow_315kN; add '&fluid current_x = 0.5 /'; check
begin 'drag coefficients without a fluid' '&fluid' 'without a fluid (density = 0 and air_density = 0)'
from slow_315kN; add '&fluid cd_normal = 1.2 /'; check
begin 'a negative air density' 'air_density = -1.2' 'in [0, 100]'
from slow_315kN; add '&fluid density = 1025, air_density = -1.2 /'; check
begin 'a negative surface band' 'surface_band = -0.1' 'in [0, 1000]'
from slow_315kN; add '&fluid density = 1025, surface_band = -0.1 /'; check
begin 'a surface level that is not a number' 'surface_z' 'NaN'
from slow_315kN; add '&fluid density = 1025, surface_z = NaN /'; check
begin 'a current in the air alone' 'current_x = 0.5' 'a current needs a fluid'
from slow_315kN; add '&fluid air_density = 1.2, current_x = 0.5 /'; check
begin 'fluid with the box scheme' 'box' 'no fluid loads'
from slow_315kN; add '&fluid density = 1025 /'; edit 's/^&numerics /\&numerics scheme = '"'"'box'"'"', /'; check
# --- the seabed (&seabed) -----------------------------------------------------------------
begin 'a negative seabed depth' 'depth = -40' 'in [0, 100000]'
from slow_315kN; add '&seabed depth = -40 /'; check
begin 'a seabed with no stiffness' 'stiffness = 0' 'must be > 0'
from slow_315kN; add '&seabed depth = 40, stiffness = 0 /'; check
begin 'a negative friction coefficient' 'mu_axial = -0.3' 'in [0, 100]'
from slow_315kN; add '&seabed depth = 40, mu_axial = -0.3 /'; check
begin 'a negative contact damping' 'damping = -1' 'in [0, 1e15]'
from slow_315kN; add '&seabed depth = 40, damping = -1 /'; check
begin 'static friction without a friction coefficient' "static_friction = 'end_a'" 'mu_axial > 0, now 0'
from slow_315kN; add "&seabed depth = 40, static_friction = 'end_a' /"; check
begin 'static friction towards no end' "static_friction = 'anchor'" "one of 'none', 'end_a', 'end_b'"
from slow_315kN; add "&seabed depth = 40, mu_axial = 1, static_friction = 'anchor' /"; check
begin 'a fixed end below the seabed' 'end_b: z = 0' 'below the seabed'
from slack_swing; add '&seabed depth = 1, slope_x = 0.5 /'; check
begin "a spring's anchor below the seabed" 'end_b: z = -40' 'the spring end is below the seabed'
from slack_swing; add '&fluid density = 1025 /'; add '&seabed depth = 30 /'
edit "s/^&end_b .*/\&end_b kind = 'spring', x = 50.0, z = -40.0, stiffness = 1e5 \//"; check
begin 'a moving end below the seabed' 'end_b: z = -40' 'the motion end is below the seabed'
from slack_swing; add '&fluid density = 1025 /'; add '&seabed depth = 30 /'
edit "s/^&end_b .*/\&end_b kind = 'motion', x = 50.0, z = -40.0, amplitude = 1.0, period = 5.0 \//"; check
begin 'the water surface below the seabed' 'surface_z = -50' 'below the seabed'
from slow_315kN; add '&fluid density = 1025, surface_z = -50 /'; add '&seabed depth = 40 /'; check
begin 'air with the box scheme' 'box' 'no fluid loads'
from slow_315kN; add '&fluid air_density = 1.2 /'; edit 's/^&numerics /\&numerics scheme = '"'"'box'"'"', /'; check

# --- a line of segments (&segment_1 ... &segment_8) ------------------------------------------
# chain_mooring_heave: &cable length = 250, &numerics nodes = 101, &rupture enabled = .false.
begin 'a segment numbered with a gap' '&segment_2 given without &segment_1' 'without a gap'
from chain_mooring_heave; add '&segment_2 length = 250 /'; check
begin 'a segment without its length' '&segment_2' 'length not given'
from chain_mooring_heave; add '&segment_1 length = 250 /'; add '&segment_2 diameter = 0.05 /'; check
begin 'a segment length that is not a number' '&segment_1' 'length = NaN' 'finite'
from chain_mooring_heave; add '&segment_1 length = NaN /'; check
begin 'segment lengths that are not &cable length' '&cable' 'length = 250' '100 + 100 = 200' 'must be their sum'
from chain_mooring_heave; add '&segment_1 length = 100 /'; add '&segment_2 length = 100 /'; check
begin 'nodes in one segment of two' '&segment_2' 'nodes not given' 'every segment'
from chain_mooring_heave; add '&segment_1 length = 100, nodes = 41 /'; add '&segment_2 length = 150 /'; check
begin 'segment nodes against &numerics nodes' '&numerics' 'nodes = 101' '41 + 81 - 1 joints = 121' 'give nodes = 121'
from chain_mooring_heave; add '&segment_1 length = 100, nodes = 41 /'; add '&segment_2 length = 150, nodes = 81 /'; check
begin 'too few nodes for three segments' '&numerics' 'nodes = 6' 'at least 2*3 + 1 = 7'
from chain_mooring_heave; edit 's/nodes = 101/nodes = 6/'; add '&segment_1 length = 100 /'; add '&segment_2 length = 100 /'
add '&segment_3 length = 50 /'; check
begin 'a segment diameter in millimetres' '&segment_1' 'diameter = 76' 'in metres'
from chain_mooring_heave; add '&segment_1 length = 100, diameter = 76 /'; add '&segment_2 length = 150 /'; check
begin 'an unknown law in a segment' '&segment_2' "law = 'chain'" "'tanh', 'linear', 'table'"
from chain_mooring_heave; add '&segment_1 length = 100 /'; add "&segment_2 length = 150, law = 'chain' /"; check
begin "a segment's table file missing" '&segment_2' "table_file = 'no_such_law.txt'" 'no such file'
from chain_mooring_heave; add '&segment_1 length = 100 /'
add "&segment_2 length = 150, law = 'table', table_file = 'no_such_law.txt' /"; check
begin 'segments with the box scheme' '&numerics' "scheme = 'box'" 'one uniform cable'
from chain_mooring_heave; add '&segment_1 length = 100 /'; add '&segment_2 length = 150 /'
edit 's/^&numerics /\&numerics scheme = '"'"'box'"'"', /'; check
begin "a segment's MBL on a line that does not break" '&segment_1' 'mbl = 5e6' "criterion = 'tension'"
from chain_mooring_heave; add '&segment_1 length = 100, mbl = 5e6 /'; add '&segment_2 length = 150 /'; check
begin 'a break by tension without an MBL for every segment' '&segment_2' 'mbl = 0 and &rupture mbl = not given'
from chain_mooring_heave; add '&segment_1 length = 100, mbl = 5e6 /'; add '&segment_2 length = 150 /'
edit "s/^&rupture  enabled = .false. \//\&rupture criterion = 'tension' \//"; check
begin 'a ninth segment' 'unknown group &segment_9' '&segment_1 ... &segment_8'
from chain_mooring_heave; add '&segment_9 length = 250 /'; check

# --- bodies at the joints (&point_1 ... &point_8) -----------------------------------------
begin 'a point without its joint' '&point_1' 'joint not given'
from chain_mooring_heave; add '&segment_1 length = 100 /'; add '&segment_2 length = 150 /'; add '&point_1 mass = 500 /'
check
begin 'a point on a joint the line does not have' '&point_1' 'joint = 3' 'allowed: 0 .. 2'
from chain_mooring_heave; add '&segment_1 length = 100 /'; add '&segment_2 length = 150 /'
add '&point_1 joint = 3, mass = 500 /'; check
begin 'a point on a held end' '&point_1' 'joint = 0' 'that is end a, which is held'
from chain_mooring_heave; add '&point_1 joint = 0, mass = 500 /'; check
begin 'two points on one joint' '&point_2' '&point_1 sits on it already'
from chain_mooring_heave; add '&segment_1 length = 100 /'; add '&segment_2 length = 150 /'
add '&point_1 joint = 1, mass = 500 /'; add '&point_2 joint = 1, volume = 2 /'; check
begin 'a negative clump mass' '&point_1' 'mass = -500'
from chain_mooring_heave; add '&segment_1 length = 100 /'; add '&segment_2 length = 150 /'
add '&point_1 joint = 1, mass = -500 /'; check
begin 'a drag coefficient without an area' '&point_1' 'cd = 1' 'give area > 0'
from chain_mooring_heave; add '&segment_1 length = 100 /'; add '&segment_2 length = 150 /'
add '&point_1 joint = 1, mass = 500, cd = 1.0 /'; check
begin 'a ninth point' 'unknown group &point_9' '&point_1 ... &point_8'
from chain_mooring_heave; add '&point_9 joint = 1 /'; check

# --- networks of lines (&line_1 ... &line_8 between &point_k with a kind) ---------------
# network: a three-line spread meeting at a free buoy (valid input; the run is refused).
network() {
   cat >"$f" <<'EOF'
&cable    diameter = 0.1, density = 7850 /
&fluid    density = 1025 /
&segment_1 length = 50, nodes = 11 /
&segment_2 length = 100, nodes = 21 /
&point_1  kind = 'free', z = -20, volume = 10, mass = 1000 /
&point_2  kind = 'fixed', x = 200, z = -100 /
&point_3  kind = 'fixed', x = -100, y = 173.2, z = -100 /
&point_4  kind = 'motion', x = -100, y = -173.2, z = -100, amplitude = 1, period = 10, direction_x = 1, direction_z = 0 /
&line_1   end_a = 'point_2', end_b = 'point_1', segments = 1, 2 /
&line_2   end_a = 'point_3', end_b = 'point_1', segments = 1, 2 /
&line_3   end_a = 'point_4', end_b = 'point_1', length = 160, nodes = 31 /
&numerics t_end = 1 /
EOF
}
begin 'a network whose free point is out of reach' '&line_1' '&point_1 (its end b)' 'within reach of its lines'
network; check
begin 'a network out of reach, with --check' '&line_1' '&point_1 (its end b)' 'within reach of its lines'
network; args=(--check case.nml); check
begin 'a network point that joins no line' '&point_5' "kind 'fixed' joins no line"
network; add "&point_5 kind = 'fixed', x = 1 /"; check
begin 'a line end at no such point' '&line_3' "end_a = 'point_9'" 'no such point'
network; edit "s/end_a = 'point_4'/end_a = 'point_9'/"; check
begin 'a line end at a body of the single line' '&line_3' "end_a = 'point_4'" '&point_4 has no kind'
network; edit "s/^&point_4 .*/\&point_4 joint = 1, mass = 5 \//"; check
begin 'a line closed on itself' '&line_3' "end_a = 'point_1', end_b = 'point_1'" 'both ends on one point'
network; edit "s/end_a = 'point_4'/end_a = 'point_1'/"; check
begin 'lines that float' '&line_1' 'nothing holds them' "make one of those points kind 'fixed' or 'motion'"
network; edit "s/kind = 'fixed'/kind = 'free'/g; s/kind = 'motion',/kind = 'free',/; s/, amplitude = 1, period = 10, direction_x = 1, direction_z = 0//"
check
begin 'a line segment number out of range' '&line_1' 'segments(2) = 9' 'from 1 to 8'
network; edit "0,/segments = 1, 2/s//segments = 1, 9/"; check
begin 'a line segment not given' '&line_1' 'segments(2) = 3' '&segment_3 is not given'
network; edit "0,/segments = 1, 2/s//segments = 1, 3/"; check
begin 'a segment no line uses' '&segment_3' 'used by no line'
network; add '&segment_3 length = 5 /'; check
begin 'a gap in the line numbering' '&line_3 given without &line_2'
network; edit '/^&line_2/d'; check
begin 'a line without end_b' '&line_3' 'end_b not given'
network; edit "s/, end_b = 'point_1', length = 160/, length = 160/"; check
begin 'a line length not its segments' '&line_1' 'length = 140' '50 + 100 = 150'
network; edit "0,/segments = 1, 2 \//s//segments = 1, 2, length = 140 \//"; check
begin 'a uniform line without a length' '&line_3' 'length not given'
network; edit 's/, length = 160//'; check
begin 'nodes of a line of segments' '&line_1' 'nodes = 5' 'given for a line of segments'
network; edit "0,/segments = 1, 2 \//s//segments = 1, 2, nodes = 5 \//"; check
begin 'a network with &end_a' '&end_a' "kind = 'fixed'" 'leave &end_a and &end_b out'
network; add "&end_a kind = 'fixed' /"; check
begin 'a network with &static tension' '&static' 'tension = 300000'
network; add '&static tension = 3e5 /'; check
begin 'a network with the box scheme' '&numerics' "scheme = 'box'" "scheme = 'rod' for a network"
network; edit "s/^&numerics /\&numerics scheme = 'box', /"; check
begin 'a network with the 2-D model' '&numerics' "model = '2d'" "allowed: model = '3d' or 'auto'"
network; edit "s/^&numerics /\&numerics model = '2d', /"; check
begin "a network's break without its line" '&rupture' 'line not given' 'give line = 1 .. 3'
network; add '&rupture t_break = 0.01 /'; check
begin "a network's break on no such line" '&rupture' 'line = 5' 'no such line' 'allowed: 1 .. 3'
network; add '&rupture line = 5 /'; check
begin "a network's break beyond its line" '&rupture' 's_break = 150.5' 'must be from 0 to 150' '&line_2'
network; add '&rupture line = 2, s_break = 150.5 /'; check
begin "a network's break at a free point" '&rupture' 's_break = 150' "&point_1 of kind 'free'" 'a break at a free point'
network; add '&rupture line = 2 /'; check
begin "a network's break by tension with a line" '&rupture' "criterion = 'tension', line = 2" 'not used'
network; add "&rupture criterion = 'tension', mbl = 1e6, line = 2 /"; check
begin "a network's break by tension: a uniform line without mbl" '&line_3' 'a uniform line' '&rupture mbl = not given'
network; add "&rupture criterion = 'tension' /"; check
begin "a network's break by tension: a segment without mbl" '&segment_2' 'mbl = 0 and &rupture mbl = not given'
network; edit 's/^&segment_1 length = 50, nodes = 11/\&segment_1 length = 50, nodes = 11, mbl = 1e6/'
edit 's/length = 160, nodes = 31/segments = 1, 2/'; add "&rupture criterion = 'tension' /"; check
begin '&rupture line on the single line' '&rupture' 'line = 1' 'only with &line groups'
from slow_315kN; set_in rupture 'line = 1'; check
begin "a network's statics with friction" '&seabed' "static_friction = 'end_a'" "allowed: static_friction = 'none'"
network; add "&seabed depth = 100.0, static_friction = 'end_a' /"; check
begin 'a body on a line of a network' '&point_5' 'joint = 1' 'split the line at a free point'
network; add '&point_5 joint = 1, mass = 50 /'; check
begin 'a network point without lines' '&point_1' "kind = 'fixed'" 'without any &line group'
from chain_mooring_heave; add "&point_1 kind = 'fixed', x = 3 /"; check
begin 'a network point with a joint' '&point_1' 'joint = 1' 'a network point'
network; edit "s/^&point_1  kind = 'free',/\&point_1 kind = 'free', joint = 1,/"; check
begin 'a body on a fixed point' '&point_2' 'mass = 5' 'a body there does nothing'
network; edit "s/^&point_2  kind = 'fixed',/\&point_2 kind = 'fixed', mass = 5,/"; check
begin 'a motion variable on a fixed point' '&point_2' 'period = 3' "a variable of kind 'motion'"
network; edit "s/^&point_2  kind = 'fixed',/\&point_2 kind = 'fixed', period = 3,/"; check
begin 'a network variable on a body' '&point_1' 'z = -3' 'without kind'
from chain_mooring_heave; add '&segment_1 length = 100 /'; add '&segment_2 length = 150 /'
add '&point_1 joint = 1, mass = 500, z = -3 /'; check
begin 'a motion point with period 0' '&point_4' 'period = 0' "must be > 0 for motion = 'harmonic'"
network; edit 's/period = 10/period = 0/'; check
begin 'an unknown point kind' '&point_1' "kind = 'anchor'" "'fixed', 'free', 'motion'"
network; edit "s/^&point_1  kind = 'free'/\&point_1 kind = 'anchor'/"; check
begin 'nodes in one segment of a line' '&line_1' '&segment_2 gives no nodes'
network; edit 's/^&segment_2 length = 100, nodes = 21/\&segment_2 length = 100/'; check
begin 'too few nodes shared on a line' '&numerics' 'nodes = 4' 'the 2 segments of &line_1'
network; edit 's/, nodes = 11 / /; s/, nodes = 21 / /; s/^&numerics t_end = 1/\&numerics t_end = 1, nodes = 4/'; check
begin 'a buoy point without water' '&point_1' 'volume = 10' 'buoyancy needs water'
network; edit '/^&fluid/d'; check
begin 'an anchor point below the seabed' '&point_2' 'z = -100' 'below the seabed'
network; add '&seabed depth = 90 /'; check
begin 'a ninth line' 'unknown group &line_9' '&line_1 ... &line_8'
network; add "&line_9 end_a = 'point_1' /"; check

# --- syntax -------------------------------------------------------------------------
begin 'assignment without =' '&static'
from fast_180kN; edit 's/tension = 180000/tension 180000/'; check
begin 'assignment without value' 'tension'
from fast_180kN; edit 's/tension = 180000/tension = /'; check
begin 'group without a name' 'line 19' '"&" without a group name'
from fast_180kN; add '& tension = 1 /'; check
begin 'old-style $group ... $end' '"$static tension = 1 $end"' 'outside any namelist group'
from fast_180kN; add '$static tension = 1 $end'; check
begin 'text after the closing /' 't_break = 0.005 / junk' 'outside any namelist group'
from fast_180kN; edit 's|t_break = 0.005 /|t_break = 0.005 / junk|'; check
begin 'missing closing / (next group starts)' '&rupture'
from fast_180kN; edit 's|t_break = 0.005 /|t_break = 0.005|'; check
begin 'unterminated quote' '&output'
from fast_180kN; edit "s|file = 'results/fast_180kN.h5'|file = 'results/fast_180kN.h5|"; check
begin 'line longer than 1024 characters' 'line 19 is longer than 1024 characters'
from fast_180kN; add "! $(printf 'x%.0s' {1..1500})"; check
begin 'file name longer than the variable holds' 'file'
from fast_180kN; edit "s|file = 'results/fast_180kN.h5'|file = 'results/$(printf 'd%.0s' {1..600}).h5'|"; check
begin 'CR-only line ends (old Mac text)' 'line 1, column' 'carriage return without line feed'
from fast_180kN; tr '\n' '\r' <"$f" >"$f.tmp"; mv "$f.tmp" "$f"; check

# --- binary junk ---------------------------------------------------------------------
begin 'NUL byte inside a group' 'line 19, column 18' 'byte 0 is not printable'
from fast_180kN; printf '&cable length = 6\0000 /\n' >>"$f"; check
begin 'junk bytes appended' 'line 19, column 1' 'byte 137 is not printable'
from slow_315kN; printf '\x89HDF\r\n\x1a\n\x00\x00\xff\xfe\x01' >>"$f"; check
begin 'UTF-8 in a comment' 'line 19, column 59' 'byte 195 is not printable'
from slow_315kN; add '! Zugfestigkeit in kN, Dehnung in % (Kabel aus Polyamid, Länge 60 m)'; check
begin 'the executable as input' 'line 1, column 1' 'byte 127 is not printable'
# Its first 1 MB: the statically linked program is larger than the 5 MB a namelist may have.
head -c 1048576 "$exe" >"$f"; check
begin 'an HDF5 file as input' 'line 1, column 1' 'byte 137 is not printable'
printf '\x89HDF\r\n\x1a\n' >"$f"; head -c 2000 /dev/zero >>"$f"; check
begin 'input is a directory' 'case.nml' 'not a regular text file'
rm -rf "$f"; mkdir "$f"; check
begin 'input does not exist' 'missing.nml'
args=(missing.nml); check

# --- --resume misuse ------------------------------------------------------------------
# The setup: input/fast_180kN.nml run to t_end = 10 s without its rupture, stopped
# by SIGTERM once its result file says 'running': results/fast_180kN.h5
# 'interrupted' and its checkpoint results/fast_180kN.h5.ckpt. A second such run
# gives a result file of another run (another run_id). Without the rupture the run
# lasts seconds; with it, its buckled zone collapses at t = 0.38 s, 0.4 s of CPU
# after the start, and under load SIGTERM could come after that (exit 1).
resume_base() { from fast_180kN; edit 's/t_end = 0.14/t_end = 10/'; set_in rupture 'enabled = .false.'; }
stopped_run() {
   local d=$1 p i
   mkdir -p "$d/results"
   cp "$f" "$d/case.nml"
   (cd "$d" && exec "$exe" case.nml 2>/dev/null) &
   p=$!
   for ((i = 0; i < 3000; i++)); do
      HDF5_USE_FILE_LOCKING=FALSE h5dump -a /status "$d/results/fast_180kN.h5" 2>/dev/null | grep -q '"running' && break
      sleep 0.01
   done
   kill -TERM "$p"
   wait "$p"
}
begin 'setup'
resume_base
stopped_run "$work/stopped_a"
code_a=$?
stopped_run "$work/stopped_b"
code_b=$?
n=$((n - 1))
if ((code_a != 3 || code_b != 3)) || [[ ! -s $work/stopped_a/results/fast_180kN.h5.ckpt ]]; then
   echo "  FAIL setup of the --resume cases: runs stopped by SIGTERM exited $code_a, $code_b (expected 3)"
   failed=$((failed + 1))
   failures+=("setup of the --resume cases")
fi
# stopped [a|b] [RESULT] [CHECKPOINT]: copy the result file and checkpoint of a stopped run into the case.
stopped() {
   local from=$work/stopped_${1:-a}
   [[ ${2:-yes} == no ]] || cp "$from/results/fast_180kN.h5" "$dir/results/"
   [[ ${3:-yes} == no ]] || cp "$from/results/fast_180kN.h5.ckpt" "$dir/results/"
}
# set_attrs FILE NAME=VALUE...: rewrite string attributes of an HDF5 file's root
# (python3 with h5py, as bench/ uses). For a checkpoint the header checksum is
# recomputed (FNV-1a over 64-bit words of code_version, namelist and run_id,
# system/posix.c), so that it looks written by another version.
set_attrs() {
   python3 - "$@" <<'PY' || { echo "    (set_attrs needs python3 with h5py)"; return 1; }
import sys
import h5py, numpy
def fnv(h, b):
    p, m = 0x100000001b3, (1 << 64) - 1
    for i in range(0, len(b) - len(b) % 8, 8):
        h = ((h ^ int.from_bytes(b[i:i + 8], 'little')) * p) & m
    for c in b[len(b) - len(b) % 8:]:
        h = ((h ^ c) * p) & m
    return ((h ^ len(b)) * p) & m
def text(f, name):
    v = f.attrs[name]
    return (v if isinstance(v, bytes) else v.tobytes() if hasattr(v, 'tobytes') else str(v).encode())
def header(f):
    h = 0xcbf29ce484222325
    for name in ('code_version', 'namelist', 'run_id'):
        h = fnv(h, text(f, name))
    return b'%016X' % h
with h5py.File(sys.argv[1], 'r+') as f:
    checkpoint = 'header_checksum' in f.attrs
    if checkpoint:
        assert header(f) == text(f, 'header_checksum'), 'cannot reproduce the header checksum'
    for item in sys.argv[2:]:
        name, value = item.split('=', 1)
        f.attrs.create(name, numpy.bytes_(value.encode()))
    if checkpoint:
        f.attrs.create('header_checksum', numpy.bytes_(header(f)))
PY
}
begin '--resume without a checkpoint' 'no checkpoint' 'results/fast_180kN.h5.ckpt' 'without --resume'
resume_base; stopped a yes no; args=(--resume case.nml); check
begin '--resume of a checkpoint of another case' 'written for another case' 'tension = 180000' 'tension = 170000'
resume_base; edit 's/tension = 180000/tension = 170000/'; stopped; args=(--resume case.nml); check
begin '--resume of a checkpoint with other nodes' 'written for another case' 'nodes = 241' 'nodes = 201'
resume_base; edit 's/nodes = 241/nodes = 201/'; stopped; args=(--resume case.nml); check
begin '--resume of another version'"'"'s checkpoint' 'written by xcable 0.0.9' 'only with the version that wrote it'
resume_base; stopped; set_attrs "$dir/results/fast_180kN.h5.ckpt" code_version=0.0.9; args=(--resume case.nml); check
begin '--resume of a truncated checkpoint' 'results/fast_180kN.h5.ckpt' 'cannot be read'
resume_base; stopped; head -c 5000 "$work/stopped_a/results/fast_180kN.h5.ckpt" >"$dir/results/fast_180kN.h5.ckpt"
args=(--resume case.nml); check
begin '--resume of a result file posing as a checkpoint' 'results/fast_180kN.h5.ckpt' 'not an xcable checkpoint'
resume_base; stopped a yes no; cp "$dir/results/fast_180kN.h5" "$dir/results/fast_180kN.h5.ckpt"
args=(--resume case.nml); check
begin '--resume of an empty checkpoint' 'results/fast_180kN.h5.ckpt' 'cannot be read'
resume_base; stopped a yes no; : >"$dir/results/fast_180kN.h5.ckpt"; args=(--resume case.nml); check
begin '--resume without the result file' 'results/fast_180kN.h5' 'is missing'
resume_base; stopped a no yes; args=(--resume case.nml); check
begin '--resume with the result file of another run' 'belongs to run' 'the checkpoint to run'
resume_base; stopped a no yes; cp "$work/stopped_b/results/fast_180kN.h5" "$dir/results/"
args=(--resume case.nml); check
begin '--resume of a complete run' 'already complete'
resume_base; stopped; set_attrs "$dir/results/fast_180kN.h5" status=complete; args=(--resume case.nml); check
begin '--resume with the box scheme' 'box scheme'
resume_base; set_in numerics "scheme = 'box'"; stopped; args=(--resume case.nml); check
begin "--resume of a 2-D checkpoint with model = '3d'" 'results/fast_180kN.h5.ckpt' 'written by a 2-D run' \
   'runs the 3-D model'
resume_base; set_in numerics "model = '3d'"; stopped; args=(--resume case.nml); check
begin '--resume with no case' '--resume' 'without a case file' 'usage'
args=(--resume); check
begin '--resume with two cases' 'usage'
resume_base; args=(--resume case.nml case.nml); check

# --- output paths ------------------------------------------------------------------
begin 'output in a missing directory' 'no/such/dir'
from fast_180kN; edit "s|file = 'results/fast_180kN.h5'|file = 'no/such/dir/out.h5'|"; check
begin 'output whose parent is a regular file' 'case.nml/out.h5'
from fast_180kN; edit "s|file = 'results/fast_180kN.h5'|file = 'case.nml/out.h5'|"; check
begin 'output in /proc' '/proc/'
from fast_180kN; edit "s|file = 'results/fast_180kN.h5'|file = '/proc/xcable_fuzz_$$.h5'|"
extra_paths=("/proc/xcable_fuzz_$$.h5"); check
begin 'output over a read-only /proc file' '/proc/version'
from fast_180kN; edit "s|file = 'results/fast_180kN.h5'|file = '/proc/version'|"; check
begin 'output is a directory' 'results'
from fast_180kN; edit "s|file = 'results/fast_180kN.h5'|file = 'results/'|"; check
begin 'gnuplot text cannot be created' 'snapshots.dat'
from fast_180kN; mkdir -p "$dir/results/fast_180kN.snapshots.dat"; check
begin 'XDMF sidecar cannot be created' 'xdmf'
from fast_180kN; edit "s|gnuplot = .true.|gnuplot = .true., xdmf = .true.|"; mkdir -p "$dir/results/fast_180kN.xmf.part"; check
begin 'xdmf given as a string' 'xdmf'
from fast_180kN; edit "s|gnuplot = .true.|gnuplot = .true., xdmf = 'yes'|"; check
begin 'output is the input file itself' 'input file itself'
from fast_180kN; edit "s|file = 'results/fast_180kN.h5'|file = 'case.nml'|"; check
begin 'output path is the root directory' 'file'
from fast_180kN; edit "s|file = 'results/fast_180kN.h5'|file = '/'|"; check

begin '--check: the output folder does not exist' 'file' 'no_such_folder' 'does its folder exist'
from fast_180kN; edit "s|file = 'results/fast_180kN.h5'|file = 'no_such_folder/x.h5'|"; args=(--check case.nml); check

begin 'a diameter in millimetres: a hint at the unit' 'diameter = 50' 'in metres'
from slow_315kN; add '&cable diameter = 50 /'; check

begin 'strain_max in per cent: a hint at the unit' 'strain_max = 35' 'not per cent'
from slow_315kN; add '&material strain_max = 35 /'; check

begin 'table strains in per cent: a hint at the unit' 'table_strain(3) = 5' 'not per cent'
from slow_315kN; add "&material law = 'table', table_strain = 0, 1, 5, table_tension = 0, 1e4, 6e4 /"; check

begin 'a tension in kN: a hint at the unit' 'tension = 180' 'in N'
from slow_315kN; edit "s|tension = 315000|tension = 180|"; check

begin 'more than a million steps: a hint at the step' 't_end' 'courant = ' 'any Courant number'
from slow_315kN; edit "s|t_end = 0.16|t_end = 2000|"; edit "s|interval = 0.01|interval = 1|"; check

echo "$n cases, $failed failed"
if ((failed > 0)); then
   printf '%s\n' "${failures[@]}"
   exit 1
fi
exit 0
