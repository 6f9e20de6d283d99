# Bash helpers shared by plots/draw.sh and plots/draw-paper.sh (sourced, not run).

# Static end tension of a run in kN (the fixed-end tension at t = 0 in <stem>.history.dat).
static_kN() {
  awk '!/^#/ && NF >= 3 { printf "%.0f", $3 / 1000; exit }' "$1.history.dat"
}

# Breaking time of a run in ms, from the namelist stored in <stem>.h5 (needs h5dump, from
# hdf5-tools); prints nothing when it cannot be found.
t_break_ms() {
  local stem=$1 t
  [ -r "$stem.h5" ] && command -v h5dump >/dev/null 2>&1 || return 0
  t=$(h5dump -a /namelist "$stem.h5" 2>/dev/null | sed -n 's/.*t_break *= *\([-+0-9.EeDd]*\).*/\1/p' | head -n 1)
  [ -n "$t" ] && awk -v t="${t//[dD]/E}" 'BEGIN { printf "%g", 1000 * t }'
  return 0
}

# One-line description of a run for the figure titles: "<case>: static tension N kN, breaking time M ms".
case_title() {
  local stem=$1 tb
  tb=$(t_break_ms "$stem")
  printf '%s: static tension %s kN%s' "$(basename "$stem")" "$(static_kN "$stem")" "${tb:+, breaking time $tb ms}"
}

# File extension for a format argument (png or pdf); fails on anything else.
format_ext() {
  case "${1:-png}" in
    png) echo png ;;
    pdf) echo pdf ;;
    *) echo "format '$1' unknown: use png (pngcairo) or pdf (pdfcairo)" >&2; return 2 ;;
  esac
}
