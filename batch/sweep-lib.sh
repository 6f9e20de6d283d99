# shellcheck shell=bash
# Shared helpers of the batch/sweep-* scripts; sourced, not run.
#
# A sweep directory (written by batch/sweep-generate) holds
#   sweep.env       what the other scripts need: number of cases, name width, xcable path
#   manifest.tsv    task index and the swept values, one row per case
#   cases/NNNN.nml  one namelist per task (NNNN = task index, zero-padded)
#   results/NNNN.h5 the result of each task (&output file of its namelist)
#   logs/NNNN.log   what each task printed, one block per attempt
#   logs/slurm-*.out  Slurm's own output of each array task (Slurm runs only)
#   jobs.txt        the Slurm jobs submitted for this sweep
#   summary.csv, summary.h5  written by batch/sweep-collect

# sweep_variable_table XCABLE: the variables the namelist groups accept, one a
# line as "group variable type", type r real, i integer, l logical, s string,
# followed by the element count for an array (r5: the vector p; r1000: a
# table). Taken from "XCABLE --schema tsv", the schema of the executable the
# sweep runs (src/xcable/io/schema.f90), so it cannot drift from it.
sweep_variable_table() {
  local exe=$1 tsv
  tsv=$("$exe" --schema tsv) || return 1
  awk -F '\t' 'NR > 1 && NF == 4 { t = substr($3, 1, 1); if ($4 > 1) t = t $4; print $1, $2, t }' <<<"$tsv"
}

# die CODE MESSAGE: one line on stderr, prefixed with the script's name, and exit.
die() {
  local code=$1
  shift
  echo "${PROG:-sweep}: $*" >&2
  exit "$code"
}

# load_sweep DIR: check that DIR is a sweep directory and read its sweep.env;
# sets SWEEP_ABS (absolute path of DIR) and the SWEEP_* variables.
load_sweep() {
  local dir=$1
  [ -d "$dir" ] || die 2 "$dir: no such directory"
  [ -r "$dir/sweep.env" ] || die 2 "$dir: not a sweep directory (no sweep.env; make one with batch/sweep-generate)"
  SWEEP_ABS=$(cd "$dir" && pwd -P)
  # shellcheck disable=SC1091
  . "$SWEEP_ABS/sweep.env"
  [[ "${SWEEP_CASES:-}" =~ ^[0-9]+$ && "${SWEEP_WIDTH:-}" =~ ^[0-9]+$ ]] ||
    die 2 "$dir/sweep.env: SWEEP_CASES or SWEEP_WIDTH missing or not a number"
}

# case_name TASK: the zero-padded name of a task's files (0007).
case_name() {
  printf '%0*d' "$SWEEP_WIDTH" "$1"
}

# result_status FILE: complete, failed, interrupted (stopped by SIGTERM with a
# checkpoint), running (written by a run that is still going or was killed),
# missing or unreadable.
result_status() {
  local file=$1 out
  if [ ! -e "$file" ]; then
    echo missing
    return
  fi
  command -v h5dump >/dev/null 2>&1 || die 1 "h5dump not found (Debian package hdf5-tools, or the HDF5 module of the cluster)"
  if ! out=$(HDF5_USE_FILE_LOCKING=FALSE h5dump -a /status "$file" 2>/dev/null); then
    echo unreadable
    return
  fi
  out=$(printf '%s\n' "$out" | sed -n 's/^ *(0): "\([a-z]*\) *"$/\1/p')
  echo "${out:-unreadable}"
}

# result_status_reason FILE: "status<TAB>reason" of a result: the status as
# result_status, the reason a failed run gives (failure_reason), with every
# number replaced by # so that runs failing the same way share one reason.
result_status_reason() {
  local file=$1 out status reason
  status=$(result_status "$file")
  reason=""
  if [ "$status" = failed ]; then
    out=$(HDF5_USE_FILE_LOCKING=FALSE h5dump -w 0 -a /failure_reason "$file" 2>/dev/null || true)
    reason=$(printf '%s\n' "$out" | sed -n 's/^ *(0): "\(.*\)"$/\1/p' | sed 's/ *$//' |
             sed -E 's/[-+]?[0-9]+(\.[0-9]*)?([eE][-+]?[0-9]+)?/#/g' | head -c 200)
  fi
  printf '%s\t%s\n' "$status" "$reason"
}

# report_not_complete TASK...: a summary of the given tasks that are not
# complete, readable however many there are: one line per status with the
# count and the task indices as ranges (0-1,3-4,...), and under 'failed' one
# line per reason. A long index list is cut after about 100 characters
# ('... and N more ranges'). Prints nothing and returns 0 when every task is
# complete; returns 1 otherwise.
report_not_complete() {
  local task rows=""
  for task in "$@"; do
    rows+="$task	$(result_status_reason "$SWEEP_ABS/results/$(case_name "$task").h5")"$'\n'
  done
  printf '%s' "$rows" | awk -F '\t' '
    function ranges(list,    n, v, i, lo, hi, out, sep, parts, count) {
      n = split(list, v, " ")
      out = ""; sep = ""; count = 0
      for (i = 1; i <= n; i++) {
        if (i == 1) { lo = v[i]; hi = v[i]; continue }
        if (v[i] == hi + 1) { hi = v[i]; continue }
        parts[++count] = (lo == hi ? lo : lo "-" hi); lo = v[i]; hi = v[i]
      }
      if (n > 0) parts[++count] = (lo == hi ? lo : lo "-" hi)
      for (i = 1; i <= count; i++) {
        if (length(out) > 100) { return out sprintf(" ... and %d more ranges", count - i + 1) }
        out = out sep parts[i]; sep = ","
      }
      return out
    }
    $2 != "complete" {
      bad++
      if (!($2 in count)) order[++nstatus] = $2
      count[$2]++; tasks[$2] = tasks[$2] " " $1
      if ($2 == "failed") {
        if (!($3 in rcount)) rorder[++nreason] = $3
        rcount[$3]++; rtasks[$3] = rtasks[$3] " " $1
      }
    }
    END {
      if (!bad) exit 0
      for (i = 1; i <= nstatus; i++) {
        s = order[i]
        printf "  %-12s %6d  tasks %s\n", s, count[s], ranges(tasks[s])
        if (s == "failed")
          for (j = 1; j <= nreason; j++) {
            r = rorder[j]
            printf "    %6d  %s\n            tasks %s\n", rcount[r], (r == "" ? "(no reason in the file)" : r), ranges(rtasks[r])
          }
      }
      exit 1
    }'
}

# incomplete_tasks: the tasks of the loaded sweep whose result is not complete, one a line.
incomplete_tasks() {
  local task status
  for ((task = 0; task < SWEEP_CASES; task++)); do
    status=$(result_status "$SWEEP_ABS/results/$(case_name "$task").h5")
    [ "$status" = complete ] || echo "$task"
  done
}

# compress_ranges: ascending integers on stdin, one a line, as a Slurm index list ("0-3,5,7-9").
compress_ranges() {
  awk 'NF == 0 { next }
       { v = $1 + 0
         if (n == 0) { lo = v; hi = v; n = 1; next }
         if (v == hi + 1) { hi = v; next }
         out = out sep (lo == hi ? lo : lo "-" hi); sep = ","; lo = v; hi = v }
       END { if (n) out = out sep (lo == hi ? lo : lo "-" hi); print out }'
}
