#!/usr/bin/env bash
# Draw all the figures of one run with gnuplot.
#   plots/draw.sh <stem> <outdir> [png|pdf]
# <stem> is the run's output without extension (results/slow_315kN for results/slow_315kN.h5);
# the run must have written gnuplot text (&output gnuplot = .true.; energy = .true. for the energy
# figure). Works for any scene (ends held, free, loaded, moved or carrying a mass; a break at an
# end or inside the cable). Writes <outdir>/{motion,tension,velocity,ends,energy,map}.<png|pdf>,
# and seabed.<png|pdf> for a run with &seabed (the line over the bottom and its touchdown points);
# the map (tension against s and t) only from 10 snapshots up (&output interval), the energy
# figure only for a run with the energy ledger; for a 3-D run also motion3d (perspective, to
# scale) and plan (seen from above). The titles and the names of the ends in the keys
# come from the namelist in <stem>.h5 when h5dump is installed.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=plots/caseinfo.sh
source "$here/caseinfo.sh"

if [ $# -lt 2 ] || [ $# -gt 3 ]; then
  echo "usage: plots/draw.sh <stem> <outdir> [png|pdf]   (e.g. plots/draw.sh results/slow_315kN results/figures/slow_315kN)" >&2
  exit 2
fi
stem=$1 outdir=$2
ext=$(format_ext "${3:-png}")
command -v gnuplot >/dev/null 2>&1 || { echo "draw.sh: gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 1; }
for f in "$stem.snapshots.dat" "$stem.history.dat"; do
  if [ ! -r "$f" ]; then
    echo "draw.sh: $f not found: run the case with &output gnuplot = .true. first" >&2
    exit 1
  fi
done
if [[ "$stem$outdir" == *"'"* ]]; then
  echo "draw.sh: paths with a single quote are not supported" >&2
  exit 2
fi
mkdir -p "$outdir"

title=$(case_title "$stem")
text=$(nml_text "$stem")
labels=""
if [ -n "$text" ]; then
  labels="label_a='$(end_label "$text" a)'; label_b='$(end_label "$text" b)'; "
fi
nsnap=$(grep -c '^# t = ' "$stem.snapshots.dat" || true)
kinds="motion tension velocity ends energy map"
# A run on a seabed (&seabed depth > 0): the line over the bottom, with its touchdown points.
seabed_vars=""
if [ -n "$text" ]; then
  depth=$(nml_get "$text" seabed depth)
  if [ -n "$depth" ] && awk -v d="${depth//[dD]/E}" 'BEGIN { exit !(d > 0) }'; then
    slope=$(nml_get "$text" seabed slope_x)
    diam=$(nml_get "$text" cable diameter)
    slope=${slope:-0}; diam=${diam:-0}
    seabed_vars="depth=${depth//[dD]/E}; slope_x=${slope//[dD]/E}; diameter=${diam//[dD]/E}; "
    kinds="$kinds seabed"
  fi
fi
# A 3-D run (its snapshot text has y in column 10): a view in perspective and a plan view too.
if sed -n '2p' "$stem.snapshots.dat" | grep -q ' y\[m\]'; then
  kinds="$kinds motion3d plan"
fi
failed=()
for kind in $kinds; do
  out="$outdir/$kind.$ext"
  rm -f "$out"
  if [ "$kind" = map ] && [ "$nsnap" -lt 10 ]; then
    echo "draw.sh: $stem.snapshots.dat holds $nsnap snapshots (fewer than 10): map not drawn (a smaller &output interval gives it)"
    continue
  fi
  extra=""
  [ "$kind" = seabed ] && extra=$seabed_vars
  if gnuplot -e "stem='$stem'; out='$out'; title='$title'; $labels$extra" "$here/$kind.gp"; then
    [ -s "$out" ] && echo "draw.sh: wrote $out"
  else
    failed+=("$kind")
  fi
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "draw.sh: gnuplot failed for: ${failed[*]}" >&2
  exit 1
fi
