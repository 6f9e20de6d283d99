#!/usr/bin/env bash
# make test-slurm: the sweep scripts against a real Slurm on this machine.
#
# Installs Debian's slurm-wlm and munge if they are missing (as root), starts a
# private munged, slurmctld and slurmd (-N localhost) as background processes
# with their configuration, sockets, state and logs under a temporary directory
# (no systemd, nothing under /etc touched, ports 6817/6818 or the next free
# pair), submits an 8-case sweep (2 breaking times x 4 tensions from
# input/fast_180kN.nml on 41 nodes to t = 0.07 s) as a job array, waits,
# collects and checks the summary; then removes one result, resubmits with
# --failed-only and checks that exactly that task ran again. Then a long task
# (a heaving mass on a cable, its t_end set so that it runs about 90 s
# on this machine) is submitted with --time=1 --signal=B:TERM@50: Slurm's
# signal (or its time limit) interrupts it, the collector shows it
# 'interrupted', sweep-submit --failed-only resumes it from its checkpoint,
# and its figures equal those of a copy of the sweep run uninterrupted with
# sweep-local meanwhile (about three minutes more). The daemons it
# started are stopped by their PIDs on every exit. Set KEEP=1 to keep the
# temporary directory (it is kept anyway when a check fails).
#
# Exit codes: 0 all checks passed; 1 a check failed; 2 cannot set up Slurm.
set -euo pipefail
PROG=test-slurm
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd -P)
repo=$(cd "$here/.." && pwd -P)
# shellcheck source-path=SCRIPTDIR source=sweep-lib.sh
. "$here/sweep-lib.sh"
t0=$(date +%s.%N)
elapsed() { awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }'; }
say() { echo "$PROG: [$(elapsed) s] $*"; }

[ -x "$repo/bin/xcable" ] || die 2 "$repo/bin/xcable not built (make build)"

# --- 1. Slurm and munge ---------------------------------------------------------
have_pkg() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; }
missing=()
for pkg in slurm-wlm munge; do have_pkg "$pkg" || missing+=("$pkg"); done
if [ ${#missing[@]} -gt 0 ]; then
  [ "$(id -u)" -eq 0 ] || die 2 "missing Debian packages ${missing[*]}; run as root to install them"
  say "installing from apt: ${missing[*]}"
  # Keep the packages' init scripts from starting system daemons: this test
  # starts its own. Only a policy file that this script made is removed.
  made_policy=""
  if [ ! -e /usr/sbin/policy-rc.d ]; then
    printf '#!/bin/sh\nexit 101\n' >/usr/sbin/policy-rc.d
    chmod 755 /usr/sbin/policy-rc.d
    made_policy=1
  fi
  rc=0
  { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"; } \
    >/tmp/xcable-test-slurm-apt.log 2>&1 || rc=$?
  [ -z "$made_policy" ] || rm -f /usr/sbin/policy-rc.d
  [ $rc -eq 0 ] || die 2 "apt-get install ${missing[*]} failed (log: /tmp/xcable-test-slurm-apt.log)"
  say "installed $(dpkg-query -W -f='${Package} ${Version}\n' "${missing[@]}" | paste -sd, - | sed 's/,/, /g')"
fi
for cmd in munged munge slurmctld slurmd sbatch squeue sinfo scontrol h5dump; do
  command -v "$cmd" >/dev/null 2>&1 || die 2 "$cmd not found after installing slurm-wlm, munge and hdf5-tools"
done
[ "$(id -u)" -eq 0 ] || die 2 "slurmd must run as root here (this test runs its own single-node cluster)"

# --- 2. a private single-node cluster -------------------------------------------
tmp=$(mktemp -d /tmp/xcable-slurm.XXXXXX)
chmod 755 "$tmp"
pids=()
jobs_submitted=()
failures=0
passes=0

cleanup() {
  local code=$? pid i
  set +e
  if [ ${#jobs_submitted[@]} -gt 0 ] && [ -n "${SLURM_CONF:-}" ]; then
    timeout 10 scancel "${jobs_submitted[@]}" >/dev/null 2>&1
  fi
  # Stop in reverse order of start: slurmd, slurmctld, munged.
  for ((i = ${#pids[@]} - 1; i >= 0; i--)); do
    pid=${pids[i]}
    kill -TERM "$pid" 2>/dev/null || continue
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -0 "$pid" 2>/dev/null && kill -KILL "$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
  done
  [ ${#pids[@]} -eq 0 ] || say "stopped the daemons it started (pids ${pids[*]})"
  if [ $code -ne 0 ] || [ $failures -ne 0 ] || [ -n "${KEEP:-}" ]; then
    echo "$PROG: kept $tmp (daemon logs in $tmp/log, the sweep in $tmp/sweep)" >&2
  else
    rm -rf "$tmp"
  fi
  exit $code
}
trap cleanup EXIT
trap 'exit 130' INT TERM

port_free() { ! (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; }
port=6817
while ! port_free "$port" || ! port_free $((port + 1)); do
  port=$((port + 2))
  [ $port -lt 6900 ] || die 2 "no free pair of ports from 6817 to 6900"
done

mkdir -p "$tmp"/{etc,munge,state,spool,log,run}
chmod 700 "$tmp/munge"
dd if=/dev/urandom of="$tmp/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$tmp/munge/munge.key"
socket=$tmp/munge/munge.socket
munged --foreground --force --socket="$socket" --key-file="$tmp/munge/munge.key" \
  --pid-file="$tmp/run/munged.pid" --log-file="$tmp/log/munged.log" --seed-file="$tmp/munge/munge.seed" \
  >"$tmp/log/munged.out" 2>&1 &
pids+=($!)
for _ in $(seq 50); do [ -S "$socket" ] && break; sleep 0.1; done
munge --socket="$socket" -n </dev/null | unmunge --socket="$socket" >/dev/null 2>&1 ||
  die 2 "munged did not start (log: $tmp/log/munged.log, $tmp/log/munged.out)"

cpus=2
cat >"$tmp/etc/slurm.conf" <<EOF
# Single-node test cluster of xcable's batch/test-slurm.sh
ClusterName=xcabletest
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/run/slurmctld.pid
SlurmdPidFile=$tmp/run/slurmd.pid
SlurmctldLogFile=$tmp/log/slurmctld.log
SlurmdLogFile=$tmp/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SwitchType=switch/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SlurmdParameters=config_overrides
ReturnToService=2
MailProg=/bin/true
MaxArraySize=1001
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$tmp/etc/slurm.conf

slurmctld -D -i -f "$SLURM_CONF" >"$tmp/log/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -N localhost -f "$SLURM_CONF" >"$tmp/log/slurmd.out" 2>&1 &
pids+=($!)
state=""
for _ in $(seq 300); do
  state=$(sinfo -h -n localhost -o '%T' 2>/dev/null || true)
  [ "$state" = idle ] && break
  for pid in "${pids[@]}"; do
    kill -0 "$pid" 2>/dev/null || die 2 "a daemon stopped (logs: $tmp/log/slurmctld.log, $tmp/log/slurmd.log, *.out)"
  done
  sleep 0.1
done
[ "$state" = idle ] || die 2 "node localhost is '${state:-unknown}', not idle, after 30 s (logs in $tmp/log)"
say "slurm $(sinfo -V | awk '{ print $2 }'): munged, slurmctld, slurmd running (pids ${pids[*]})," \
    "node localhost idle, ports $port-$((port + 1))"

# --- 3. the sweep ----------------------------------------------------------------
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

# wait_jobs ID...: until none of the jobs is in the queue (at most WAIT_LIMIT s, 180 by default).
wait_jobs() {
  local ids
  ids=$(IFS=,; echo "$*")
  for _ in $(seq $((${WAIT_LIMIT:-180} * 10))); do
    [ -z "$(squeue -h -j "$ids" -o '%i' 2>/dev/null)" ] && return 0
    sleep 0.1
  done
  echo "$PROG: jobs $ids still queued after ${WAIT_LIMIT:-180} s:" >&2
  squeue -j "$ids" >&2 || true
  return 1
}

# column CSV NAME: the values of a named column of summary.csv, one a line.
column() {
  awk -F, -v n="$2" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == n) c = i; next } c { print $c }' "$1"
}

sweep=$tmp/sweep
"$here/sweep-generate" "$repo/input/fast_180kN.nml" "$sweep" 'rupture%t_break=0.005,0.02' \
  'static%tension=100e3:400e3:100e3' numerics%nodes=41 numerics%t_end=0.07 output%gnuplot=.false. >/dev/null
check "sweep-generate wrote 8 cases and an 8-row manifest" \
  test "$(ls "$sweep/cases" | wc -l)" -eq 8 -a "$(($(wc -l <"$sweep/manifest.tsv") - 1))" -eq 8

out=$("$here/sweep-submit" "$sweep" --limit 2)
echo "  $out" | head -1
job=$(awk 'NR > 1 && !/^#/ { id = $1 } END { print id }' "$sweep/jobs.txt")
jobs_submitted+=("$job")
check "sweep-submit submitted array job $job as --array=0-7%2" grep -q "	0-7%2$" "$sweep/jobs.txt"
t_submit=$(elapsed)
wait_jobs "$job"
say "array job $job finished ($(awk -v a="$t_submit" -v b="$(elapsed)" 'BEGIN { printf "%.1f", b - a }') s after submission)"

check "each task has its Slurm output logs/slurm-${job}_N.out" test "$(find "$sweep/logs" -name "slurm-${job}_*.out" | wc -l)" -eq 8
check "each task logged its run in logs/NNNN.log under job $job" \
  test "$(grep -l "job ${job}_" "$sweep"/logs/0*.log 2>/dev/null | wc -l)" -eq 8

"$here/sweep-collect" "$sweep" --plot >"$tmp/collect.out"
csv=$sweep/summary.csv
check "summary.csv has 8 rows" test "$(($(wc -l <"$csv") - 1))" -eq 8
check "all 8 cases complete" test "$(column "$csv" status | grep -c '^complete$')" -eq 8
check "summary.h5 has 8 rows per column" \
  bash -c "h5dump -H -d /peak_end_speed '$sweep/summary.h5' | grep -q 'SIMPLE { ( 8 )'"
check "the summary figure was drawn" test -s "$sweep/sweep_summary.png"
increasing() {
  paste -d, <(column "$csv" rupture%t_break) <(column "$csv" static%tension) <(column "$csv" peak_end_speed) |
    awk -F, '{ if (($1 in last) && !($3 > last[$1] && $2 > tension[$1])) bad = 1; last[$1] = $3; tension[$1] = $2 }
             END { exit bad }'
}
check "peak end speed increases with tension for each breaking time" increasing
plausible() {
  paste -d, <(column "$csv" peak_end_speed) <(column "$csv" front_arrival_time) <(column "$csv" newton_iterations) \
            <(column "$csv" energy_drift) <(column "$csv" time_reached) |
    awk -F, '{ if (!($1 > 50 && $1 < 300 && $2 > 0.02 && $2 < 0.07 && $3 > 0 && $4 >= 0 && $4 < 0.05 \
                     && $5 > 0.0699)) bad = 1 } END { exit bad }'
}
check "speeds 50-300 m/s, front arrival 20-70 ms, Newton iterations > 0, drift < 5 %, t_end reached" plausible
echo "  peak end speed (m/s) by task: $(column "$csv" peak_end_speed | awk '{ printf "%.1f ", $1 }')"

# --- 4. resubmission of the missing and failed ------------------------------------
rm "$sweep/results/0002.h5"
"$here/sweep-collect" "$sweep" >/dev/null
check "a removed result is a 'missing' row" test "$(column "$csv" status | sed -n 3p)" = missing
# Submitted held, so that the guard against a second resubmission can be seen.
"$here/sweep-submit" "$sweep" --failed-only -- --hold >/dev/null
job2=$(awk 'NR > 1 && !/^#/ { id = $1 } END { print id }' "$sweep/jobs.txt")
jobs_submitted+=("$job2")
check "sweep-submit --failed-only submitted only task 2 (job $job2)" \
  bash -c "awk -F'\t' -v j='$job2' '\$1 == j && \$4 == \"2\" { f = 1 } END { exit !f }' '$sweep/jobs.txt'"
code=0
out=$("$here/sweep-submit" "$sweep" --failed-only 2>&1) || code=$?
check "sweep-submit --failed-only refuses while job $job2 of the sweep is queued" \
  test "$code" -eq 2 -a "$(grep -c "still queued or running ($job2)" <<<"$out")" -eq 1
scontrol release "$job2"
wait_jobs "$job2"
"$here/sweep-collect" "$sweep" >/dev/null
check "after resubmission all 8 cases complete" test "$(column "$csv" status | grep -c '^complete$')" -eq 8
check "task 2 ran again under job $job2" grep -q "job ${job2}_2," "$sweep/logs/0002.log"
out=$("$here/sweep-submit" "$sweep" --failed-only)
check "sweep-submit --failed-only with nothing left submits nothing" grep -q "nothing to submit" <<<"$out"

# --- 5. a task interrupted by Slurm, resumed with --failed-only --------------------
# Its length: about 90 s on this machine now, from a 2 s (simulated) trial (Slurm signals it
# 10-40 s after its start: its periodic checks are 30 s apart).
cal=$tmp/calibrate.nml
sed "s|'results/hanging_mass_heave.h5'|'$tmp/calibrate.h5'|; s|t_end = 20.0|t_end = 2.0|; s|nodes = 121|nodes = 241|" \
  "$repo/input/hanging_mass_heave.nml" >"$cal"
c0=$(date +%s.%N)
"$repo/bin/xcable" "$cal" 2>/dev/null || die 1 "the trial run of input/hanging_mass_heave.nml failed"
t_long=$(awk -v a="$c0" -v b="$(date +%s.%N)" 'BEGIN { t = int(2 * 90 / (b - a)); if (t < 30) t = 30; if (t > 300) t = 300; print t }')
long=$tmp/long
"$here/sweep-generate" "$repo/input/hanging_mass_heave.nml" "$long" numerics%nodes=241 numerics%t_end="$t_long" \
  output%interval=1 output%gnuplot=.false. >/dev/null
cp -r "$long" "$tmp/long_ref"
say "a task of t_end = $t_long s (about 90 s), submitted with --time=1 --signal=B:TERM@50;" \
    "a copy of its sweep runs uninterrupted beside it (sweep-local)"
"$here/sweep-local" "$tmp/long_ref" -j 1 >"$tmp/long_ref.out" 2>&1 &
ref_pid=$!
"$here/sweep-submit" "$long" -- --time=1 --signal=B:TERM@50 >/dev/null
job3=$(awk 'NR > 1 && !/^#/ { id = $1 } END { print id }' "$long/jobs.txt")
jobs_submitted+=("$job3")
t_submit=$(elapsed)
WAIT_LIMIT=300 wait_jobs "$job3"
say "job $job3 ended $(awk -v a="$t_submit" -v b="$(elapsed)" 'BEGIN { printf "%.1f", b - a }') s after submission:" \
    "$(grep -o 'exit [0-9]*, [a-z]*' "$long/logs/0000.log" | tail -1)"
"$here/sweep-collect" "$long" >/dev/null
check "Slurm interrupted the task (job $job3): the collector says 'interrupted'" \
  test "$(column "$long/summary.csv" status)" = interrupted
check "the task wrote a checkpoint and logged exit 3" \
  bash -c "test -s '$long/results/0000.h5.ckpt' && grep -q 'exit 3, interrupted' '$long/logs/0000.log'"
out=$("$here/sweep-submit" "$long" --failed-only)
job4=$(awk 'NR > 1 && !/^#/ { id = $1 } END { print id }' "$long/jobs.txt")
jobs_submitted+=("$job4")
check "sweep-submit --failed-only lists it as interrupted and submits it (job $job4)" \
  bash -c "grep -q '^  interrupted  *1  tasks 0$' <<<'$out' && test '$job4' != '$job3'"
WAIT_LIMIT=300 wait_jobs "$job4"
"$here/sweep-collect" "$long" >/dev/null
check "resumed from its checkpoint under job $job4, now complete" \
  bash -c "grep -q 'resuming from results/0000.h5.ckpt' '$long/logs/0000.log' &&
           test \"\$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if (\$i == \"status\") c = i; next } { print \$c }' '$long/summary.csv')\" = complete"
wait "$ref_pid" || true
"$here/sweep-collect" "$tmp/long_ref" >/dev/null
# figures CSV: the row of summary.csv without the wall time.
figures() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) skip[i] = ($i == "wall_time"); next }
           { row = ""; for (i = 1; i <= NF; i++) if (!skip[i]) row = row "," $i; print row }' "$1"
}
check "the same figures as the uninterrupted copy (every column of summary.csv but wall_time)" \
  test "$(figures "$long/summary.csv")" = "$(figures "$tmp/long_ref/summary.csv")" -a \
  "$(column "$tmp/long_ref/summary.csv" status)" = complete
echo "  interrupted and resumed: $(figures "$long/summary.csv" | cut -c 1-150)..."

say "done"
echo "$PROG: $passes passed, $failures failed"
[ $failures -eq 0 ] || exit 1
