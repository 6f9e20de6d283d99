#!/usr/bin/env bash
# make test-batch: the sweep scripts without Slurm, in a few seconds.
#
# Checks sweep-generate (values, ranges, replacement in the base, refusals, the
# variable table against bin/xcable's own messages), sweep-local with a case
# that fails, one killed while running, one damaged and one missing, the
# collector's rows for each status, --failed-only, and the array lists that
# sweep-submit would give sbatch (--dry-run, including a sweep split by
# MaxArraySize). Runs in a temporary directory, removed unless a check fails
# or KEEP=1.
#
# Exit codes: 0 all checks passed; 1 a check failed; 2 cannot run (no bin/xcable).
set -euo pipefail
PROG=test-batch
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd -P)
repo=$(cd "$here/.." && pwd -P)
# shellcheck source-path=SCRIPTDIR source=sweep-lib.sh
. "$here/sweep-lib.sh"
t0=$(date +%s.%N)
xcable=$repo/bin/xcable
[ -x "$xcable" ] || die 2 "$xcable not built (make build)"

tmp=$(mktemp -d /tmp/xcable-batch.XXXXXX)
passes=0
failures=0
long_pid=""
finish() {
  local code=$?
  [ -z "$long_pid" ] || kill -KILL "$long_pid" 2>/dev/null || true
  if [ $code -ne 0 ] || [ $failures -ne 0 ] || [ -n "${KEEP:-}" ]; then
    echo "$PROG: kept $tmp" >&2
  else
    rm -rf "$tmp"
  fi
  exit $code
}
trap finish EXIT

check() {
  local what=$1
  shift
  if "$@"; then
    passes=$((passes + 1))
    echo "  ok   $what"
  else
    failures=$((failures + 1))
    echo "  FAIL $what"
  fi
}
# refuses MESSAGE_PART ARGS...: sweep-generate exits 2 with one line naming the problem, writing nothing.
refuses() {
  local part=$1 out code=0
  shift
  rm -rf "$tmp/refused"
  out=$("$here/sweep-generate" "$repo/input/fast_180kN.nml" "$tmp/refused" "$@" 2>&1) || code=$?
  [ $code -eq 2 ] && [ "$(printf '%s\n' "$out" | wc -l)" -eq 1 ] && [[ "$out" == *"$part"* ]] && [ ! -e "$tmp/refused" ]
}
column() {
  awk -F, -v n="$2" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == n) c = i; next } c { print $c }' "$1"
}

echo "$PROG: sweep-generate"
# The variable table (xcable --schema tsv) against what xcable's reader itself allows.
table_matches_xcable() {
  local group allowed mine
  printf '&zz_no_group /\n' >"$tmp/probe.nml"
  # (xcable names the numbered groups once: "segment_1 ... segment_8", "point_1 ... point_8",
  # "line_1 ... line_8".)
  allowed=$("$xcable" "$tmp/probe.nml" 2>&1 | sed -n 's/.*allowed: //p' | tr -d '&' |
    sed -e 's/segment_1 \.\.\. segment_8/segment_1, segment_2, segment_3, segment_4, segment_5, segment_6, segment_7, segment_8/' \
        -e 's/point_1 \.\.\. point_8/point_1, point_2, point_3, point_4, point_5, point_6, point_7, point_8/' \
        -e 's/line_1 \.\.\. line_8/line_1, line_2, line_3, line_4, line_5, line_6, line_7, line_8/')
  mine=$(sweep_variable_table "$xcable" | awk '!seen[$1]++ { printf "%s%s", sep, $1; sep = ", " }')
  [ "$allowed" = "$mine" ] || { echo "    groups: xcable '$allowed', table '$mine'"; return 1; }
  for group in $(sweep_variable_table "$xcable" | awk '!seen[$1]++ { print $1 }'); do
    printf '&%s zz_no_variable = 1 /\n' "$group" >"$tmp/probe.nml"
    allowed=$("$xcable" "$tmp/probe.nml" 2>&1 | sed -n 's/.*allowed: //p')
    mine=$(sweep_variable_table "$xcable" | awk -v g="$group" '$1 == g { printf "%s%s", sep, $2; sep = ", " }')
    [ "$allowed" = "$mine" ] || { echo "    &$group: xcable '$allowed', table '$mine'"; return 1; }
  done
}
check "the variable table (xcable --schema tsv) is what xcable's reader allows" table_matches_xcable
check "refuses an unknown group, naming the allowed ones" \
  refuses "unknown group 'statics'; allowed: cable, material" statics%tension=1
check "refuses an unknown variable, naming the allowed ones" \
  refuses "unknown variable 'tensoin' in &static; allowed: tension" static%tensoin=1
check "refuses the vector material%p without a subscript" refuses "material%p is a vector of 5" material%p=1,2
check "refuses a table (end_b%table_time)" refuses "end_b%table_time is a table of 1000 values" end_b%table_time=1,2
check "refuses an element of a table" refuses "end_a%table_x is a table of 1000 values" 'end_a%table_x(2)=1,2'
check "refuses output%file" refuses "output%file is set by sweep-generate" output%file=x.h5
check "refuses a real for an integer" refuses '"41.5" is not an integer' numerics%nodes=41.5
check "refuses a range with a zero step" refuses "the step is zero" static%tension=1e5:2e5:0
check "refuses a variable given twice" refuses "given twice" rupture%t_break=0.01 rupture%t_break=0.02
check "refuses a non-logical for a logical" refuses "is not .true. or .false." output%energy=yes

cat >"$tmp/base.nml" <<'EOF'
! a base with several assignments a line, comments, quotes and the whole vector p
&Numerics nodes = 41, t_end = 0.02,   ! a comment / with a slash
   courant = 1.0 /
&material p = 2.703e5, 10.2, -2.128, 2.627e5, 135.5 /
&output interval = 0.01, fields = 'tension u', file = 'elsewhere/x.h5' /
EOF
sweep=$tmp/s1
"$here/sweep-generate" "$tmp/base.nml" "$sweep" 'static%tension=1e5:3e5:1e5' 'material%p(2)=10,10.5' \
  numerics%max_wall_time=0,1e-6 >/dev/null
check "12 cases and a manifest with a header" \
  test "$(ls "$sweep/cases" | wc -l)" -eq 12 -a "$(head -1 "$sweep/manifest.tsv")" = \
  "$(printf 'task\tstatic%%tension\tmaterial%%p(2)\tnumerics%%max_wall_time')"
check "the first variable varies slowest, ranges include hi" \
  test "$(sed -n 13p "$sweep/manifest.tsv")" = "$(printf '11\t300000\t10.5\t1e-6')"
case_ok() {
  local f=$sweep/cases/0007.nml
  grep -q "^   file = 'results/0007.h5'$" "$f" && grep -q '^   quiet = .true.$' "$f" &&
    grep -q '^   max_wall_time = 1e-6$' "$f" && grep -q '^   courant = 1.0$' "$f" &&
    grep -q '^&static$' "$f" && [ "$(grep -c 'file =' "$f")" -eq 1 ] &&
    [ "$(awk '/^&material/ { m = 1 } m && /p\(2\) = 10.5/ { print "ok"; exit }' "$f")" = ok ]
}
check "a case: file (relative to the sweep) and quiet set, values replaced or added, missing group added" case_ok
(cd "$sweep" && "$xcable" cases/0002.nml)
p2=$(h5dump -a namelist "$sweep/results/0002.h5" | grep -o 'p = [^,]*, [^,]*' | awk '{ print $4 + 0 }')
check "xcable runs a generated case; material%p(2) overrides the base's vector (p2 = $p2)" test "$p2" = 10.5

echo "$PROG: sweep-local and the collector"
out=$("$here/sweep-local" "$sweep" -j 2 2>&1) && code=0 || code=$?
check "sweep-local exits 1 when cases fail, naming them" test "$code" -eq 1 -a "$(grep -c 'exit 1, failed' <<<"$out")" -eq 6
check "sweep-local sums up the failed by reason, numbers as #, indices as ranges" \
  bash -c "grep -q '^  failed  *6  tasks 1,3,5,7,9,11$' <<<'$out' &&
           grep -q '^ *6  wall-clock limit of # s reached at t = # s$' <<<'$out'"
check "every task logged its attempt" test "$(grep -l 'job local_' "$sweep"/logs/0*.log | wc -l)" -eq 12
# Damage the results: one missing, one unreadable, one left 'running' by a killed run.
rm "$sweep/results/0000.h5"
head -c 4096 /dev/urandom >"$sweep/results/0002.h5"
# (t_end = 10 s on 4001 nodes: 7e5 steps, under the input limit of 1e6, so it runs until killed.)
sed -i 's/^   nodes = 41$/   nodes = 4001/; s/^   t_end = 0.02$/   t_end = 10/' "$sweep/cases/0004.nml"
(cd "$sweep" && exec "$xcable" cases/0004.nml) &
long_pid=$!
for _ in $(seq 100); do
  [ "$(result_status "$sweep/results/0004.h5")" = running ] && break
  sleep 0.1
done
"$here/sweep-collect" "$sweep" --plot >"$tmp/collect.out" 2>&1
kill -KILL "$long_pid" 2>/dev/null || true
wait "$long_pid" 2>/dev/null || true
long_pid=""
csv=$sweep/summary.csv
statuses=$(column "$csv" status | tr '\n' ' ')
check "one row per task with its status: $statuses" \
  test "$statuses" = "missing failed unreadable failed running failed complete failed complete failed complete failed "
check "a failed row keeps its reason and figures" \
  bash -c "sed -n 3p '$csv' | grep -q 'wall-clock limit' && test \"\$(sed -n 3p '$csv' | cut -d, -f9)\" != NaN"
check "a missing row has NaN figures and -1 counts" \
  bash -c "sed -n 2p '$csv' | grep -q '^0,100000,10,0,missing,NaN,.*,-1,'"
check "summary.h5 holds the statuses and the swept values as numbers" \
  bash -c "h5dump -d /status '$sweep/summary.h5' | grep -q '\"unreadable\"' &&
           h5dump -d '/swept/static%tension' '$sweep/summary.h5' | grep -q 'H5T_IEEE_F64LE'"
check "the summary figure was drawn" test -s "$sweep/sweep_summary.png"

# A run that completes with a warning (a slack release on 21 nodes buckles at the grid scale).
warned=$tmp/warned
"$here/sweep-generate" "$repo/input/fast_180kN.nml" "$warned" static%tension=5000 numerics%nodes=21 \
  numerics%t_end=1.0 output%gnuplot=.false. >/dev/null
"$here/sweep-local" "$warned" >/dev/null 2>&1 || true
"$here/sweep-collect" "$warned" >/dev/null
check "a complete run's warning reaches the summary's warnings column" \
  bash -c "test \"\$(awk -F, 'NR == 2 { print \$0 }' '$warned/summary.csv')\" != '' &&
           grep -q 'complete,.*kink at the grid scale' '$warned/summary.csv'"

echo "$PROG: --failed-only and sweep-submit's array lists"
out=$("$here/sweep-submit" "$sweep" --dry-run --failed-only --limit 3 -- --time=00:05:00)
check "sweep-submit --failed-only lists the 9 tasks that are not complete" \
  grep -q -- "--array=0-5\\\\,7\\\\,9\\\\,11%3 .*--time=00:05:00 .*sweep.sbatch" <<<"$out"
out=$(SWEEP_MAX_ARRAY_SIZE=5 "$here/sweep-submit" "$sweep" --dry-run)
check "a sweep larger than MaxArraySize is split into arrays with offsets" \
  test "$(grep -o 'array=[^ ]* --export=ALL\\,SWEEP_OFFSET=[0-9]*' <<<"$out" | tr '\n' ' ')" = \
  'array=0-4 --export=ALL\,SWEEP_OFFSET=0 array=0-4 --export=ALL\,SWEEP_OFFSET=5 array=0-1 --export=ALL\,SWEEP_OFFSET=10 '
# Make the failed cases good and rerun only what is not complete.
sed -i 's/^   max_wall_time = 1e-6$/   max_wall_time = 0/; s/^   nodes = 4001$/   nodes = 41/; s/^   t_end = 10$/   t_end = 0.02/' \
  "$sweep"/cases/*.nml
out=$("$here/sweep-local" "$sweep" --failed-only -j 2 2>&1) && code=0 || code=$?
check "sweep-local --failed-only reran exactly the 9 tasks" test "$code" -eq 0 -a "$(grep -c '^task ' <<<"$out")" -eq 9
"$here/sweep-collect" "$sweep" >/dev/null
check "then all 12 complete" test "$(column "$csv" status | grep -c '^complete$')" -eq 12
check "task 6, complete before, was not rerun" test "$(grep -c '### task 6: start' "$sweep/logs/0006.log")" -eq 1
out=$("$here/sweep-local" "$sweep" --failed-only)
check "nothing left to run" grep -q "nothing to run" <<<"$out"

echo "$PROG: a summary of many tasks that are not complete"
# 900 tasks, of which 2, 5, ..., 29 complete and the rest missing: ranges, cut after about 100 characters.
many=$tmp/many
mkdir -p "$many/results"
for ((i = 2; i < 30; i += 3)); do cp "$sweep/results/0006.h5" "$many/results/$(printf '%04d' "$i").h5"; done
out=$(SWEEP_ABS=$many SWEEP_WIDTH=4 bash -c ". '$here/sweep-lib.sh'; report_not_complete \$(seq 0 899)") && code=0 || code=$?
check "900 tasks: one line per status, indices as ranges (exit $code): $(head -c 90 <<<"$out")..." \
  test "$code" -eq 1 -a "$(wc -l <<<"$out")" -eq 1 -a \
  "$(grep -c '^  missing  *890  tasks 0-1,3-4,6-7,9-10,12-13,15-16,18-19,21-22,24-25,27-28,30-899$' <<<"$out")" -eq 1
for ((i = 30; i < 900; i += 2)); do cp "$sweep/results/0006.h5" "$many/results/$(printf '%04d' "$i").h5"; done
out=$(SWEEP_ABS=$many SWEEP_WIDTH=4 bash -c ". '$here/sweep-lib.sh'; report_not_complete \$(seq 0 899)") || true
check "a long list of ranges is cut: $(head -c 60 <<<"$out")...$(tail -c 40 <<<"$out")" \
  test "$(grep -c '^  missing  *455  tasks 0-1,3-4,.*,31,33,[0-9,]* \.\.\. and [0-9]* more ranges$' <<<"$out")" -eq 1 \
  -a "$(wc -c <<<"$out")" -lt 200

echo "$PROG: a moved sweep, interrupted and killed tasks resumed with --failed-only"
# Three copies of one case (max_wall_time may differ on --resume; it changes nothing else).
mkdir -p "$tmp/here"
"$here/sweep-generate" "$repo/input/fast_180kN.nml" "$tmp/here/ck" numerics%max_wall_time=0,1000,2000 \
  numerics%nodes=961 output%checkpoint_interval=0.2 >/dev/null
mkdir -p "$tmp/there"
mv "$tmp/here/ck" "$tmp/there/ck"
rmdir "$tmp/here"
ck=$tmp/there/ck
names_no_path() { ! cat "$ck"/cases/*.nml "$ck/sweep.env" "$ck/manifest.tsv" | grep -v '^[!#]' | grep -q -F "$tmp/here"; }
check "no case, manifest or setting names the directory the sweep was made in" names_no_path
# Task 0: SIGTERM to the task's script (as Slurm's --signal=B:TERM) once xcable runs.
SLURM_ARRAY_TASK_ID=0 bash "$here/sweep.sbatch" "$ck" >"$tmp/task0.out" 2>&1 &
long_pid=$!
for _ in $(seq 600); do [ "$(result_status "$ck/results/0000.h5")" = running ] && break; sleep 0.05; done
sleep 0.3
kill -TERM "$long_pid"
code=0
wait "$long_pid" || code=$?
long_pid=""
check "SIGTERM to the task script reaches xcable: exit $code, 'interrupted', a checkpoint" \
  test "$code" -eq 3 -a "$(result_status "$ck/results/0000.h5")" = interrupted -a -s "$ck/results/0000.h5.ckpt"
check "the task's log says it was interrupted" grep -q 'exit 3, interrupted' "$ck/logs/0000.log"
# Task 1: xcable killed (SIGKILL) after its first checkpoint: 'running', with a checkpoint.
SLURM_ARRAY_TASK_ID=1 bash "$here/sweep.sbatch" "$ck" >"$tmp/task1.out" 2>&1 &
long_pid=$!
for _ in $(seq 1200); do [ -s "$ck/results/0001.h5.ckpt" ] && break; sleep 0.05; done
xcable_pid=$(pgrep -P "$long_pid" -x xcable || true)
[ -z "$xcable_pid" ] || kill -KILL "$xcable_pid"
wait "$long_pid" || true
long_pid=""
"$here/sweep-collect" "$ck" >/dev/null
check "the collector: interrupted, running (killed), missing" \
  test "$(column "$ck/summary.csv" status | tr '\n' ' ')" = "interrupted running missing "
check "the collector counts the interrupted in summary.h5" \
  bash -c "h5dump -a interrupted '$ck/summary.h5' | grep -q '(0): 1$'"
# Moved again between submissions.
mv "$ck" "$tmp/ck2"
ck=$tmp/ck2
out=$("$here/sweep-local" "$ck" --failed-only -j 2 2>&1) && code=0 || code=$?
check "sweep-local --failed-only lists what it resumes: interrupted 0, running 1, missing 2" \
  bash -c "grep -q '^  interrupted  *1  tasks 0$' <<<'$out' && grep -q '^  running  *1  tasks 1$' <<<'$out' &&
           grep -q '^  missing  *1  tasks 2$' <<<'$out'"
check "sweep-local --failed-only completes the three (exit $code)" test "$code" -eq 0
check "tasks 0 and 1 resumed from their checkpoints, task 2 started afresh" \
  bash -c "grep -q 'resuming from results/0000.h5.ckpt' '$ck/logs/0000.log' &&
           grep -q 'resuming from results/0001.h5.ckpt' '$ck/logs/0001.log' && ! grep -q resuming '$ck/logs/0002.log'"
"$here/sweep-collect" "$ck" >/dev/null
same_figures() {
  # Every column but the task, the swept max_wall_time and the wall time: one distinct row.
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) skip[i] = ($i == "task" || $i ~ /max_wall_time/ || $i == "wall_time"); next }
           { row = ""; for (i = 1; i <= NF; i++) if (!skip[i]) row = row "," $i; rows[row] = 1 }
           END { n = 0; for (r in rows) n++; exit n != 1 }' "$ck/summary.csv"
}
all_same() { [ "$(column "$ck/summary.csv" status | grep -c '^complete$')" -eq 3 ] && same_figures; }
check "all complete, with the same figures whether resumed or not" all_same
check "no checkpoint is left" test -z "$(find "$ck" -name '*.ckpt*')"

echo "$PROG: $(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }') s"
echo "$PROG: $passes passed, $failures failed"
[ $failures -eq 0 ] || exit 1
