#!/usr/bin/env bash
# tools/same_results.sh OLD_EXE NEW_EXE [CASE...]: run the input/ cases (default: all) with two
# builds of xcable and compare every HDF5 dataset and attribute (h5diff) and every text file (cmp).
# Default: bit for bit. With RELATIVE=1e-12 in the environment: to that fraction of each
# dataset's largest magnitude.
# A restructure that must change no number runs this before it lands; the wall time, the run id
# and the file's creation attributes are skipped (tools/same_h5.py).
set -uo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
old=$(realpath "$1"); new=$(realpath "$2"); shift 2
cases=("$@")
[[ ${#cases[@]} -eq 0 ]] && cases=($(cd "$here/input" && ls *.nml | sed 's/\.nml$//'))
work=$(mktemp -d /tmp/same_results.XXXXXX)
bad=0
for c in "${cases[@]}"; do
   for side in old new; do
      mkdir -p "$work/$side/results"
      ln -sfn "$here/input" "$work/$side/input"
      exe=$old; [[ $side == new ]] && exe=$new
      (cd "$work/$side" && "$exe" "input/$c.nml" >"results/$c.out" 2>"results/$c.err")
      echo $? >"$work/$side/results/$c.code"
   done
   cmp -s "$work/old/results/$c.code" "$work/new/results/$c.code" || { echo "$c: exit codes differ"; bad=1; }
   opt=()
   [[ -n ${RELATIVE:-} ]] && opt=(--relative "$RELATIVE")
   if [[ -f $work/old/results/$c.h5 ]]; then
      if ! out=$(python3 "$here/tools/same_h5.py" "$work/old/results/$c.h5" "$work/new/results/$c.h5" "${opt[@]}"); then
         echo "$c: the result files differ:"; echo "$out" | head -20; bad=1
      fi
   fi
   for f in "$work/old/results/$c".*.dat; do
      [[ -e $f ]] || continue
      cmp -s "$f" "$work/new/results/$(basename "$f")" || { echo "$c: $(basename "$f") differs"; bad=1; }
   done
   echo "$c: compared"
done
[[ $bad -eq 0 ]] && echo "same_results: all ${#cases[@]} cases the same" && rm -rf "$work"
[[ $bad -ne 0 ]] && echo "same_results: differences (runs kept in $work)"
exit $bad
