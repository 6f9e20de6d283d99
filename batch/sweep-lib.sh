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

# result_status FILE: complete, failed, running (written by a run that is still
# going or was killed), missing or unreadable.
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
