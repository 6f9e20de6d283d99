#!/usr/bin/env bash
# make test: checkpoints and --resume through the program, as a cluster uses them.
#
#   test/test_checkpoint.sh [path/to/xcable]        (default bin/xcable)
#
# One case (the paper's rupture at 180 kN in water with a current and
# Kelvin-Voigt damping, 481 nodes, 2114 steps, about 1.8 s on an idle core of
# the development machine) is run three ways:
#   reference  uninterrupted, without checkpoints;
#   killed     checkpoint_interval = 0.2 s, SIGKILL once its first checkpoint
#              is there and a snapshot has been written after it (the file
#              stays 'running'; the resume cuts that snapshot), then --resume;
#   stopped    no checkpoint interval, SIGTERM 0.3 s after the result file
#              says 'running' (the handler is in place before): exit 3,
#              'interrupted', a checkpoint; before resuming it, damaged copies
#              of that checkpoint (truncated, one data byte flipped, one header
#              byte flipped) are offered to --resume and must be refused: exit
#              2, one line on stderr naming the checkpoint, and neither the
#              result file nor the checkpoint changed; then the intact one is
#              resumed.
# Both resumed runs must end 'complete', without a checkpoint, and equal the
# reference bit for bit: every snapshot dataset, the history, the static state,
# every summary figure but the wall time (h5diff without tolerance), and the
# gnuplot text files byte for byte.
#
# The 3-D model the same two ways (a fairlead moving 1 m across the plane in
# water with a current across it, its end let go at 1.5 s, 121 nodes, 500
# steps, about 1.3 s): killed after its first checkpoint and resumed (the
# snapshots of the 3-D fields written after the checkpoint are cut too), and
# stopped by SIGTERM and resumed; both equal their reference bit for bit, the
# 3-D fields (/y, /vy, ...) and the history's y components included. The same
# line parted inside (s = 20 m, at 0.1 s: two 3-D pieces, 122 output nodes)
# killed after its first checkpoint (after the break) and resumed. The 2-D
# checkpoint offered to the 3-D case is refused (exit 2, naming both models).
# The box scheme the same two ways (the paper's rupture at 180 kN, 961 nodes, 2366 steps, about
# 1 s): killed after its first checkpoint and resumed, and stopped by SIGTERM and resumed; both
# equal their reference bit for bit.
# A network of lines (input/buoy_spread.nml, 20 s) stopped by SIGTERM and resumed equals its
# reference bit for bit. The network of input/buoy_spread_break.nml parted inside its hawser
# (line 3, s = 55 m, at 0.5 s: a fourth line, the break's ends in the history) killed after its
# first checkpoint (after the break) and resumed equals its reference bit for bit.
# Then 24 SIGKILLs placed inside the 3-D run's file writes (a preloaded
# library counts write calls; needs a C compiler): each resume equals the
# reference or is refused with exit 2; none completes with other numbers.
#
# The kill and the SIGTERM wait for events (a file, a status), not for a
# fixed time after the start, so a loaded machine slows the test but does
# not change what it checks. Exit code: 0 all checks passed, 1 otherwise.
set -u
exe=${1:-bin/xcable}
[[ -x $exe ]] || { echo "test_checkpoint: no executable $exe (make build first)" >&2; exit 1; }
exe=$(cd "$(dirname "$exe")" && pwd)/$(basename "$exe")
root=$(cd "$(dirname "$0")/.." && pwd)
for tool in h5diff h5dump md5sum; do
   command -v "$tool" >/dev/null || { echo "test_checkpoint: $tool not found (hdf5-tools, coreutils)" >&2; exit 1; }
done
work=$(mktemp -d "${TMPDIR:-/tmp}/xcable_checkpoint.XXXXXX")
pid=""
passes=0
failures=0
finish() {
   [[ -z $pid ]] || kill -KILL "$pid" 2>/dev/null
   if ((failures > 0)) || [[ -n ${KEEP:-} ]]; then echo "test_checkpoint: kept $work" >&2; else rm -rf "$work"; fi
}
trap finish EXIT
cd "$work" || exit 1
t0=$(date +%s.%N)

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
status_of() { HDF5_USE_FILE_LOCKING=FALSE h5dump -a /status "$1" 2>/dev/null | sed -n 's/^ *(0): "\([a-z]*\) *"$/\1/p'; }
int_attr() { h5dump -a "$2" "$1" 2>/dev/null | sed -n 's/^ *(0): \([0-9-]*\)$/\1/p'; }
# wait_for SECONDS COMMAND...: until the command succeeds (0) or the time is up (1).
wait_for() {
   local limit=$1 i
   shift
   for ((i = 0; i < limit * 100; i++)); do
      "$@" && return 0
      kill -0 "$pid" 2>/dev/null || { "$@"; return; }
      sleep 0.01
   done
   return 1
}

# write_case NAME [OUTPUT EXTRA]: the namelist NAME.nml writing NAME.h5.
write_case() {
   cat >"$1.nml" <<EOF
! test/test_checkpoint.sh: the paper's rupture at 180 kN in water, damped
&static   tension = 180000 /
&rupture  t_break = 0.005 /
&material damping = 2000, compression = 'law' /
&fluid    density = 1025, cd_normal = 1.2, cd_tangential = 0.01, ca_normal = 1, current_x = 0.5 /
&numerics nodes = 481, courant = 1.0, t_end = 0.25 /
&output   file = '$1.h5', interval = 0.01, gnuplot = .true., energy = .true.$2 /
EOF
}

# write_case3 NAME [OUTPUT EXTRA]: the 3-D namelist NAME.nml writing NAME.h5.
write_case3() {
   cat >"$1.nml" <<EOF
! test/test_checkpoint.sh: a fairlead moving across the plane in water (3-D), its end let go
&material compression = 'law' /
&end_a    kind = 'fixed', x = 0, z = 0 /
&end_b    kind = 'motion', x = 50, z = 0, amplitude = 1, period = 2, direction_x = 0, direction_y = 1,
          direction_z = 0, ramp_time = 0.5 /
&fluid    density = 1025, cd_normal = 1.2, cd_tangential = 0.01, ca_normal = 1, current_y = 0.3 /
&rupture  s_break = 60, t_break = 0.5, time = 1.5 /
&numerics model = '3d', nodes = 121, dt = 0.005, t_end = 2.5 /
&output   file = '$1.h5', interval = 0.02, gnuplot = .true., energy = .true.$2 /
EOF
}

# write_caseb NAME [OUTPUT EXTRA]: the box-scheme namelist NAME.nml writing NAME.h5.
write_caseb() {
   cat >"$1.nml" <<EOF
! test/test_checkpoint.sh: the paper's rupture at 180 kN with the box scheme
&material compression = 'law' /
&static   tension = 180000 /
&rupture  t_break = 0.005 /
&numerics scheme = 'box', nodes = 961, courant = 1.0, t_end = 0.14 /
&output   file = '$1.h5', interval = 0.01, gnuplot = .true., energy = .true.$2 /
EOF
}

# shape FILE DATASET: the dataspace line of a dataset (h5diff passes datasets of other shapes
# as "not comparable" with exit code 0, so the shapes are compared first).
shape() { h5dump -H -d "$2" "$1" 2>/dev/null | grep -m1 DATASPACE; }
# same_as_reference NAME [REF]: bitwise equal to REF.h5 (default ref) but for the wall time (h5diff, cmp);
# the 3-D fields are compared when REF.h5 has them, and must be absent from NAME.h5 otherwise.
same_as_reference() {
   local name=$1 ref=${2:-ref} d attr bad=0
   for d in /time /s /tension /shear /strain /u /v /x /z /curvature /static /history; do
      h5diff -q "$ref.h5" "$name.h5" "$d" "$d" >/dev/null 2>&1 || { echo "    $d differs"; bad=1; }
   done
   for d in /time /tension /shear /strain /u /v /x /z /curvature /history/time; do
      [[ "$(shape "$ref.h5" "$d")" == "$(shape "$name.h5" "$d")" ]] || { echo "    $d has another shape"; bad=1; }
   done
   for d in /y /vy /curvature_z /twist /binormal_shear /curvature_n; do
      if h5dump -H -d "$d" "$ref.h5" >/dev/null 2>&1; then
         h5diff -q "$ref.h5" "$name.h5" "$d" "$d" >/dev/null 2>&1 || { echo "    $d differs"; bad=1; }
         [[ "$(shape "$ref.h5" "$d")" == "$(shape "$name.h5" "$d")" ]] || { echo "    $d has another shape"; bad=1; }
      else
         ! h5dump -H -d "$d" "$name.h5" >/dev/null 2>&1 || { echo "    $d only in $name.h5"; bad=1; }
      fi
   done
   for attr in $(h5dump -A -g /summary "$ref.h5" | sed -n 's/^ *ATTRIBUTE "\([a-z0-9_]*\)".*/\1/p'); do
      # (units and description: of the datasets inside /summary, which h5dump -A lists too)
      [[ $attr == wall_time || $attr == units || $attr == description ]] && continue
      [[ "$(h5dump -a "/summary/$attr" "$ref.h5" | tail -n +2)" == "$(h5dump -a "/summary/$attr" "$name.h5" | tail -n +2)" ]] ||
         { echo "    /summary $attr differs"; bad=1; }
   done
   cmp -s "$ref.snapshots.dat" "$name.snapshots.dat" || { echo "    $name.snapshots.dat differs"; bad=1; }
   cmp -s "$ref.history.dat" "$name.history.dat" || { echo "    $name.history.dat differs"; bad=1; }
   return $bad
}

echo "test_checkpoint: reference run"
write_case ref ''
"$exe" ref.nml 2>ref.err
check "the reference run completes, without a checkpoint" test "$(status_of ref.h5)" = complete -a ! -e ref.h5.ckpt
steps=$(int_attr ref.h5 /summary/steps)
# differs NAME: the comparison sees a difference (its control).
differs() { ! same_as_reference "$1" >/dev/null; }

# snapshots FILE: snapshots in a result file; counted CHECKPOINT: those its checkpoint counts.
snapshots() { HDF5_USE_FILE_LOCKING=FALSE h5dump -H -d /time "$1" 2>/dev/null | sed -n 's/.*SIMPLE { ( \([0-9]*\) ).*/\1/p' | head -n 1; }
counted() { h5dump -d /progress/snapshot_index "$1" 2>/dev/null | sed -n 's/^ *(0): \([0-9]*\)$/\1/p'; }
beyond_checkpoint() {
   local n c
   n=$(snapshots "$1.h5")
   c=$(counted "$1.h5.ckpt")
   [[ -n $n && -n $c ]] && ((n > c))
}
# killed_and_resumed NAME REF STEPS: NAME.nml (checkpoint_interval = 0.2) killed by SIGKILL
# after its first checkpoint, then --resume; it must equal REF.h5 (STEPS steps).
# The first checkpoint (after 0.2 s of dynamics), then a snapshot written after it (before the
# next, 0.2 s later; a snapshot comes every 0.07 s of wall time in 2-D, 0.05 s in 3-D). A new
# checkpoint between that look and the kill would leave nothing to cut: then again (at most
# three times).
killed_and_resumed() {
   local name=$1 ref=$2 steps=$3 attempt kept cut_at
   for attempt in 1 2 3; do
      rm -f "$name.h5" "$name.h5.ckpt" "$name.h5.ckpt.tmp" "$name.snapshots.dat" "$name.history.dat"
      "$exe" "$name.nml" 2>"$name.err" &
      pid=$!
      wait_for 120 test -s "$name.h5.ckpt"
      wait_for 120 beyond_checkpoint "$name"
      kill -KILL "$pid" 2>/dev/null
      wait "$pid" 2>/dev/null
      code=$?
      pid=""
      beyond_checkpoint "$name" && break
      echo "    attempt $attempt: a checkpoint came just before the kill; again"
   done
   check "killed by SIGKILL (exit $code) after its first checkpoint, the file left 'running'" \
      test "$code" -eq 137 -a -s "$name.h5.ckpt" -a "$(status_of "$name.h5")" = running
   kept=$(snapshots "$name.h5")
   cut_at=$(counted "$name.h5.ckpt")
   check "killed with $kept snapshots written, $cut_at of them before the checkpoint (the rest is cut on resume)" \
      test "${kept:-0}" -gt "${cut_at:-0}"
   "$exe" --resume "$name.nml" 2>"$name.resume.err"
   code=$?
   check "--resume completes it (exit $code): 'complete', resumes = 1, no checkpoint left" \
      test "$code" -eq 0 -a "$(status_of "$name.h5")" = complete -a "$(int_attr "$name.h5" /resumes)" = 1 \
      -a ! -e "$name.h5.ckpt"
   check "the resumed run equals the uninterrupted one bit for bit ($steps steps, snapshots, history, summary, text)" \
      same_as_reference "$name" "$ref"
}

echo "test_checkpoint: SIGKILL after the first checkpoint, then --resume"
write_case killed ', checkpoint_interval = 0.2'
killed_and_resumed killed ref "$steps"

echo "test_checkpoint: SIGTERM, damaged checkpoints refused, then --resume"
write_case stopped ''
"$exe" stopped.nml 2>stopped.err &
pid=$!
# The handler is installed before the result file is made: SIGTERM once it says 'running'.
running() { [[ "$(status_of "$1")" == running ]]; }
wait_for 120 running stopped.h5
sleep 0.3
kill -TERM "$pid" 2>/dev/null
wait "$pid"
code=$?
pid=""
check "SIGTERM: exit 3, 'interrupted', a checkpoint (no checkpoint_interval)" \
   test "$code" -eq 3 -a "$(status_of stopped.h5)" = interrupted -a -s stopped.h5.ckpt
check "SIGTERM: one line on stderr says how to continue" grep -q "interrupted (SIGTERM) at t = .*xcable --resume stopped.nml" stopped.err
cp stopped.h5.ckpt good.ckpt
check "control: the comparison tells the interrupted file from the reference" differs stopped
# refused WHAT EXPECT: --resume of the damaged stopped.h5.ckpt fails with exit 2 and one line naming it and EXPECT; nothing changes.
refused() {
   local what=$1 expect=$2 before after code lines
   before=$(md5sum stopped.h5 stopped.h5.ckpt stopped.snapshots.dat; ls | grep -v "^refused\.")
   "$exe" --resume stopped.nml >refused.out 2>refused.err
   code=$?
   after=$(md5sum stopped.h5 stopped.h5.ckpt stopped.snapshots.dat; ls | grep -v "^refused\.")
   lines=$(wc -l <refused.err)
   check "$what: exit $code, $lines line: $(head -c 150 refused.err)" \
      test "$code" -eq 2 -a "$lines" -eq 1 -a "$before" = "$after" -a "$(status_of stopped.h5)" = interrupted
   grep -q -F "'stopped.h5.ckpt'" refused.err && grep -q -F "$expect" refused.err ||
      { failures=$((failures + 1)); echo "  FAIL $what: the message lacks the file name or '$expect'"; }
}
head -c $(($(stat -c %s good.ckpt) / 2)) good.ckpt >stopped.h5.ckpt
refused "a truncated checkpoint is refused" "cannot be read"
cp good.ckpt stopped.h5.ckpt
offset=$(h5dump -p -H -d /pieces/1/r good.ckpt | sed -n 's/^ *OFFSET \([0-9]*\)$/\1/p')
printf '\x5a' | dd of=stopped.h5.ckpt bs=1 seek=$((offset + 100)) conv=notrunc status=none
refused "a checkpoint with one data byte changed is refused" "does not match its checksum"
cp good.ckpt stopped.h5.ckpt
offset=$(grep -b -o -a -m1 'tension = 180000' good.ckpt | head -1 | cut -d: -f1)
printf '7' | dd of=stopped.h5.ckpt bs=1 seek=$((offset + 10)) conv=notrunc status=none
refused "a checkpoint with one header byte changed is refused" "header does not match its checksum"
cp good.ckpt stopped.h5.ckpt
"$exe" --resume stopped.nml 2>stopped.resume.err
code=$?
check "--resume of the intact checkpoint completes it (exit $code), no checkpoint left" \
   test "$code" -eq 0 -a "$(status_of stopped.h5)" = complete -a ! -e stopped.h5.ckpt
check "the resumed run equals the uninterrupted one bit for bit" same_as_reference stopped

echo "test_checkpoint: box scheme reference run"
write_caseb refb ''
"$exe" refb.nml 2>refb.err
check "the box-scheme reference run completes, without a checkpoint" \
   test "$(status_of refb.h5)" = complete -a ! -e refb.h5.ckpt
stepsb=$(int_attr refb.h5 /summary/steps)

echo "test_checkpoint: box scheme, SIGKILL after the first checkpoint, then --resume"
write_caseb killedb ', checkpoint_interval = 0.2'
killed_and_resumed killedb refb "$stepsb"

echo "test_checkpoint: box scheme, SIGTERM, then --resume"
write_caseb stoppedb ''
"$exe" stoppedb.nml 2>stoppedb.err &
pid=$!
wait_for 120 running stoppedb.h5
sleep 0.1
kill -TERM "$pid" 2>/dev/null
wait "$pid"
code=$?
pid=""
check "SIGTERM: exit 3, 'interrupted', a checkpoint" \
   test "$code" -eq 3 -a "$(status_of stoppedb.h5)" = interrupted -a -s stoppedb.h5.ckpt
not_sameb() { ! same_as_reference stoppedb refb >/dev/null; }
check "control: the comparison tells the interrupted file from the reference" not_sameb
"$exe" --resume stoppedb.nml 2>stoppedb.resume.err
code=$?
check "--resume completes it (exit $code), no checkpoint left" \
   test "$code" -eq 0 -a "$(status_of stoppedb.h5)" = complete -a ! -e stoppedb.h5.ckpt
check "the resumed box-scheme run equals the uninterrupted one bit for bit ($stepsb steps)" \
   same_as_reference stoppedb refb

echo "test_checkpoint: 3-D reference run"
write_case3 ref3 ''
"$exe" ref3.nml 2>ref3.err
check "the 3-D reference run completes, with the 3-D fields and the ends' y history" \
   test "$(status_of ref3.h5)" = complete -a ! -e ref3.h5.ckpt
h5dump -H -d /y ref3.h5 >/dev/null 2>&1 && h5dump -H -d /history/end_b/y ref3.h5 >/dev/null 2>&1 ||
   { failures=$((failures + 1)); echo "  FAIL the 3-D reference has no /y or /history/end_b/y"; }
steps3=$(int_attr ref3.h5 /summary/steps)

echo "test_checkpoint: 3-D, SIGKILL after the first checkpoint, then --resume"
write_case3 killed3 ', checkpoint_interval = 0.2'
killed_and_resumed killed3 ref3 "$steps3"

echo "test_checkpoint: 3-D break inside the cable, SIGKILL after the first checkpoint, then --resume"
# inside NAME: the 3-D case parted at s = 20 m at 0.1 s (ramp 0.2 s) instead of letting go of end b.
inside() { sed -i 's/s_break = 60, t_break = 0.5, time = 1.5/s_break = 20, t_break = 0.2, time = 0.1/' "$1.nml"; }
write_case3 refin ''
inside refin
"$exe" refin.nml 2>refin.err
check "the reference run parted inside completes, with the break's ends in the history and 122 output nodes" \
   test "$(status_of refin.h5)" = complete -a "$(h5dump -H -d /s refin.h5 | grep -c '( 122 )')" = 1
h5dump -H -d /history/break_b/y refin.h5 >/dev/null 2>&1 ||
   { failures=$((failures + 1)); echo "  FAIL the 3-D break inside has no /history/break_b/y"; }
write_case3 killedin ', checkpoint_interval = 0.2'
inside killedin
killed_and_resumed killedin refin "$(int_attr refin.h5 /summary/steps)"

echo "test_checkpoint: 3-D, SIGTERM, the 2-D checkpoint refused, then --resume"
write_case3 stopped3 ''
"$exe" stopped3.nml 2>stopped3.err &
pid=$!
wait_for 120 running stopped3.h5
# The whole 3-D run takes about 0.25 s on a quiet machine after the statics: the signal must
# land well inside it (0.3 s let it finish first, and the test fail, on a fast machine).
sleep 0.05
kill -TERM "$pid" 2>/dev/null
wait "$pid"
code=$?
pid=""
check "SIGTERM: exit 3, 'interrupted', a checkpoint" \
   test "$code" -eq 3 -a "$(status_of stopped3.h5)" = interrupted -a -s stopped3.h5.ckpt
not_same3() { ! same_as_reference stopped3 ref3 >/dev/null; }
check "control: the comparison tells the interrupted file from the reference" not_same3
cp stopped3.h5.ckpt good3.ckpt
cp good.ckpt stopped3.h5.ckpt
before=$(md5sum stopped3.h5 stopped3.snapshots.dat)
"$exe" --resume stopped3.nml >refused.out 2>refused.err
code=$?
check "the 2-D checkpoint offered to the 3-D case: exit $code, $(head -c 150 refused.err)" \
   test "$code" -eq 2 -a "$(wc -l <refused.err)" -eq 1 -a "$before" = "$(md5sum stopped3.h5 stopped3.snapshots.dat)"
grep -q -F "was written by a 2-D run, this case runs the 3-D model" refused.err ||
   { failures=$((failures + 1)); echo "  FAIL the refusal does not name the two models"; }
cp good3.ckpt stopped3.h5.ckpt
"$exe" --resume stopped3.nml 2>stopped3.resume.err
code=$?
check "--resume completes it (exit $code), no checkpoint left" \
   test "$code" -eq 0 -a "$(status_of stopped3.h5)" = complete -a ! -e stopped3.h5.ckpt
check "the resumed 3-D run equals the uninterrupted one bit for bit ($steps3 steps)" same_as_reference stopped3 ref3

# Kills inside a file write. A SIGKILL that lands while HDF5 writes its metadata (the flush
# after each snapshot) can leave the file's chunk index pointing past the end of allocated
# space that its header records; before the reopen extended that end, a resume reused the
# space and a row written after the checkpoint read back as zeros ('complete' but wrong, at a
# quarter of the kill points). A preloaded library counts the program's write calls and sends
# SIGKILL at the N-th; N is swept over the run after its first checkpoints. Every resume must
# either equal the reference bit for bit or be refused with one line and exit 2 (a file too
# damaged to continue); never complete with other numbers.
echo "test_checkpoint: 3-D, SIGKILL inside the N-th file write, then --resume"
cc_tool=$(command -v cc || command -v gcc || true)
if [[ -z $cc_tool ]]; then
   echo "  skip: no C compiler for the write-counting library"
else
   cat >killwrite.c <<'EOF'
#define _GNU_SOURCE
#include <dlfcn.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>
/* Counts write and pwrite calls on files (fd > 2); SIGKILL at call number KILL_AT_WRITE;
   the count goes to COUNT_WRITES_TO at exit. */
static long calls = 0, kill_at = -2;
static void count_call(void) {
   if (kill_at == -2) { const char *v = getenv("KILL_AT_WRITE"); kill_at = v ? atol(v) : -1; }
   if (kill_at >= 0 && calls == kill_at) raise(SIGKILL);
   calls++;
}
__attribute__((destructor)) static void report(void) {
   const char *path = getenv("COUNT_WRITES_TO");
   FILE *f = path ? fopen(path, "w") : NULL;
   if (f) { fprintf(f, "%ld\n", calls); fclose(f); }
}
ssize_t write(int fd, const void *buf, size_t n) {
   static ssize_t (*next)(int, const void *, size_t);
   if (!next) next = (ssize_t (*)(int, const void *, size_t))dlsym(RTLD_NEXT, "write");
   if (fd > 2) count_call();
   return next(fd, buf, n);
}
ssize_t pwrite(int fd, const void *buf, size_t n, off_t off) {
   static ssize_t (*next)(int, const void *, size_t, off_t);
   if (!next) next = (ssize_t (*)(int, const void *, size_t, off_t))dlsym(RTLD_NEXT, "pwrite");
   count_call();
   return next(fd, buf, n, off);
}
ssize_t pwrite64(int fd, const void *buf, size_t n, off_t off) {
   static ssize_t (*next)(int, const void *, size_t, off_t);
   if (!next) next = (ssize_t (*)(int, const void *, size_t, off_t))dlsym(RTLD_NEXT, "pwrite64");
   count_call();
   return next(fd, buf, n, off);
}
EOF
   "$cc_tool" -shared -fPIC -O1 -o killwrite.so killwrite.c -ldl
   write_case3 kw ', checkpoint_interval = 0.05'
   rm -f kw.h5 kw.h5.ckpt
   COUNT_WRITES_TO=writes.txt LD_PRELOAD=$PWD/killwrite.so "$exe" kw.nml 2>kw.err
   total=$(cat writes.txt 2>/dev/null || echo 0)
   equal=0 refused=0 early=0 wrong=0
   for ((k = 8; k < 32; k++)); do
      n=$((total * k / 32))
      rm -f kw.h5 kw.h5.ckpt kw.h5.ckpt.tmp kw.snapshots.dat kw.history.dat
      # (a subshell, so that bash's "Killed" notice goes to /dev/null)
      (KILL_AT_WRITE=$n LD_PRELOAD=$PWD/killwrite.so "$exe" kw.nml 2>kw.err; true) 2>/dev/null
      if [[ ! -s kw.h5.ckpt ]]; then early=$((early + 1)); continue; fi
      "$exe" --resume kw.nml >kw.out 2>kw.rerr
      code=$?
      if ((code == 0)) && same_as_reference kw ref3 >kw.diff; then
         equal=$((equal + 1))
      elif ((code == 2)) && (($(wc -l <kw.rerr) == 1)); then
         refused=$((refused + 1))
      else
         wrong=$((wrong + 1))
         echo "    write $n of $total: resume exit $code, $(tr '\n' ' ' <kw.diff | head -c 200)"
      fi
   done
   check "24 kills inside file writes ($total writes in the run): $equal resumed bit for bit, $refused refused, $early before a checkpoint, $wrong wrong" \
      test "$wrong" -eq 0 -a "$equal" -ge 12
fi

echo "test_checkpoint: a network of lines, SIGTERM, then --resume"
# input/buoy_spread.nml shortened: three lines at a free buoy, 4912 steps.
sed -e "s#results/buoy_spread.h5#refnet.h5#" -e "s/t_end = 40.0/t_end = 20.0/" -e "s/energy = .true. \//energy = .true., gnuplot = .true. \//" "$root/input/buoy_spread.nml" >refnet.nml
sed -e "s#refnet.h5#stopnet.h5#" refnet.nml >stopnet.nml
"$exe" refnet.nml 2>refnet.err
check "the network's reference run completes" test "$(status_of refnet.h5)" = complete
"$exe" stopnet.nml 2>stopnet.err &
pid=$!
wait_for 120 running stopnet.h5
sleep 0.3
kill -TERM "$pid" 2>/dev/null
wait "$pid"
code=$?
pid=""
check "network, SIGTERM: exit 3, 'interrupted', a checkpoint" \
   test "$code" -eq 3 -a "$(status_of stopnet.h5)" = interrupted -a -s stopnet.h5.ckpt
not_same_net() { ! same_as_reference stopnet refnet >/dev/null; }
check "control: the comparison tells the interrupted network from its reference" not_same_net
"$exe" --resume stopnet.nml >stopnet.out 2>stopnet.rerr
code=$?
check "network, --resume: exit $code, 'complete', no checkpoint left" \
   test "$code" -eq 0 -a "$(status_of stopnet.h5)" = complete -a ! -e stopnet.h5.ckpt
check "network: the resumed run equals its reference bit for bit" same_as_reference stopnet refnet

echo "test_checkpoint: a network parted inside a line, SIGKILL after the first checkpoint, then --resume"
# input/buoy_spread_break.nml with a break by time in the hawser, 10 s.
netbreak() {
   sed -e "s#results/buoy_spread_break.h5#$1.h5#" -e "s/t_end = 40.0/t_end = 10.0/" \
      -e "s/&rupture   criterion = 'tension', t_break = 0.01 \//\&rupture line = 3, s_break = 55.0, time = 0.5, t_break = 0.05 \//" \
      -e "s/energy = .true. \//energy = .true.$2 \//" -e "s#input/buoy_spread_drift.dat#$root/input/buoy_spread_drift.dat#" \
      -e "s/mbl = [0-9.e]*/mbl = 0.0/" "$root/input/buoy_spread_break.nml" >"$1.nml"
}
netbreak refnb ''
"$exe" refnb.nml 2>refnb.err
check "the network's reference run parted inside completes, with four lines' ends and the break's in the history" \
   test "$(status_of refnb.h5)" = complete -a "$(int_attr refnb.h5 /summary/break_line)" = 3
h5dump -H -d /history/break_b/y refnb.h5 >/dev/null 2>&1 ||
   { failures=$((failures + 1)); echo "  FAIL the network's break inside has no /history/break_b/y"; }
netbreak killednb ', checkpoint_interval = 0.2'
killed_and_resumed killednb refnb "$(int_attr refnb.h5 /summary/steps)"

echo "test_checkpoint: $(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }') s, $passes passed, $failures failed"
((failures == 0))
