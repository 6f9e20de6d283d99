#!/usr/bin/env bash
# Draw the paper's figures 2-7 from the four paper cases: panel (a) 180 kN beside panel (b) 315 kN,
# for the fast (t_br = 5 ms) and the slow (t_br = 50 ms) rupture, all at one scale per quantity.
#   plots/draw-paper.sh [png|pdf] [results-dir] [outdir]
# Reads <results-dir>/{fast,slow}_{180,315}kN.{snapshots,history}.dat (default results/) and writes
#   <outdir>/fig2_motion_fast  fig3_tension_fast  fig4_velocity_fast
#            fig5_motion_slow  fig6_tension_slow  fig7_velocity_slow   (.png or .pdf)
# (default outdir: results/figures).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=plots/caseinfo.sh
source "$here/caseinfo.sh"

if [ $# -gt 3 ]; then
  echo "usage: plots/draw-paper.sh [png|pdf] [results-dir] [outdir]" >&2
  exit 2
fi
ext=$(format_ext "${1:-png}")
results=${2:-results}
outdir=${3:-results/figures}
command -v gnuplot >/dev/null 2>&1 || { echo "draw-paper.sh: gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 1; }
if [[ "$results$outdir" == *"'"* ]]; then
  echo "draw-paper.sh: paths with a single quote are not supported" >&2
  exit 2
fi

all_stems=""
for c in fast_180kN fast_315kN slow_180kN slow_315kN; do
  for f in "$results/$c.snapshots.dat" "$results/$c.history.dat"; do
    if [ ! -r "$f" ]; then
      echo "draw-paper.sh: $f not found: run input/$c.nml first (make figures does it)" >&2
      exit 1
    fi
  done
  all_stems+="$results/$c "
done
mkdir -p "$outdir"

declare -A caption=(
  [motion]="Motion of a breaking cable (vertical scale exaggerated 100×)"
  [tension]="Variation of the tension of a breaking cable"
  [velocity]="Variation of the velocity of a breaking cable"
)
fig=2
failed=()
for speed in fast slow; do
  a=$results/${speed}_180kN b=$results/${speed}_315kN
  tb=$(t_break_ms "$a")
  for kind in motion tension velocity; do
    out="$outdir/fig${fig}_${kind}_${speed}.$ext"
    figtitle="Fig. $fig: ${caption[$kind]}, $speed rupture${tb:+ (t_br = $tb ms)}"
    title_a="(a) $(basename "$a"): static tension $(static_kN "$a") kN"
    title_b="(b) $(basename "$b"): static tension $(static_kN "$b") kN"
    rm -f "$out"
    if gnuplot -e "kind='$kind'; stem_a='$a'; stem_b='$b'; title_a='$title_a'; title_b='$title_b'; \
                   figtitle='$figtitle'; scale_stems='${all_stems% }'; out='$out'; \
                   label_a='fixed end'; label_b='breaking end'; vexag=100" "$here/pair.gp"; then
      echo "draw-paper.sh: wrote $out"
    else
      failed+=("$(basename "$out")")
    fi
    fig=$((fig + 1))
  done
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "draw-paper.sh: gnuplot failed for: ${failed[*]}" >&2
  exit 1
fi
