# Bash helpers shared by plots/draw.sh and plots/draw-paper.sh (sourced, not run).
# What they say about a run comes from the namelist stored in <stem>.h5 (read with h5dump, from
# hdf5-tools) and from <stem>.history.dat; without h5dump or the .h5 file they say less, never fail.

# Tension at end a at t = 0 in kN (column 3 of <stem>.history.dat), rounded.
static_kN() {
  awk '!/^#/ && NF >= 3 { printf "%.0f", $3 / 1000; exit }' "$1.history.dat"
}

# The resolved namelist of a run on one line (empty without <stem>.h5 or h5dump).
nml_text() {
  local stem=$1
  [ -r "$stem.h5" ] && command -v h5dump >/dev/null 2>&1 || return 0
  h5dump -a /namelist "$stem.h5" 2>/dev/null | sed -n '/(0): "/,/^ *"$/p' | tr '\n' ' ' | sed 's/  */ /g'
  return 0
}

# nml_get <namelist text> <group> <variable>: the value as written (quotes removed), or nothing.
nml_get() {
  printf '%s\n' "$1" | awk -v g="$2" -v v="$3" '{
    n = split($0, part, "&")
    for (i = 1; i <= n; i++) {
      if (index(part[i], g " ") != 1 && index(part[i], g "/") != 1) continue
      if (match(part[i], "[ ,]" v " *= *[^,/]*")) {
        s = substr(part[i], RSTART, RLENGTH); sub(/^[ ,]*[a-z_0-9]+ *= */, "", s)
        gsub(/'"'"'/, "", s); gsub(/^ +| +$/, "", s); print s
      }
      exit
    } }'
}

# Breaking time of a run in ms (nothing when it cannot be found).
t_break_ms() {
  local t
  t=$(nml_get "$(nml_text "$1")" rupture t_break)
  [ -n "$t" ] && awk -v t="${t//[dD]/E}" 'BEGIN { printf "%g", 1000 * t }'
  return 0
}

# A number in plain words: 0.005 -> 5 ms, 2.7 -> 2.7 s (for times), as given otherwise.
_time_words() {
  awk -v t="${1//[dD]/E}" 'BEGIN { if (t == 0) print "at once"; else if (t < 1) printf "in %g ms", 1000 * t; else printf "in %g s", t }'
}

# Description of end a or end b of a run for the keys of the figures, e.g. 'end a (fixed)',
# 'end b (released)', 'end a (moved ±1 m, 2.7 s)' (amplitude, period), 'end b (200 kg mass)'.
# end_label <namelist text> a|b
end_label() {
  local text=$1 e=$2 kind desc enabled sb L
  kind=$(nml_get "$text" "end_$e" kind)
  case "$kind" in
    fixed) desc=fixed ;;
    free) desc=free ;;
    force) desc="applied force" ;;
    mass) desc="$(nml_get "$text" "end_$e" mass) kg mass" ;;
    motion)
      if [ "$(nml_get "$text" "end_$e" motion)" = harmonic ]; then
        desc="moved ±$(nml_get "$text" "end_$e" amplitude) m, $(nml_get "$text" "end_$e" period) s"
      else
        desc="moved (table)"
      fi ;;
    *) desc="" ;;
  esac
  enabled=$(nml_get "$text" rupture enabled)
  sb=$(nml_get "$text" rupture s_break)
  L=$(nml_get "$text" cable length)
  if [ "$enabled" = ".true." ] && [ -n "$sb" ] && [ -n "$L" ]; then
    if awk -v s="$sb" -v L="$L" -v e="$e" 'BEGIN { exit !((e == "b" && (s < 0 || s >= L)) || (e == "a" && s == 0)) }'; then
      desc="released"
    fi
  fi
  printf 'end %s%s' "$e" "${desc:+ ($desc)}"
}

# The same in words for a title: 'end a fixed', 'end b released at once', 'end b carrying a
# 200 kg mass', 'end a moved ±1 m (period 2.7 s)'. title_end <namelist text> a|b
title_end() {
  local text=$1 e=$2 label dir
  label=$(end_label "$text" "$e")
  case "$label" in
    *"(released)") printf 'end %s released %s' "$e" "$(_time_words "$(nml_get "$text" rupture t_break)")" ;;
    *"kg mass)") printf 'end %s carrying a %s kg mass' "$e" "$(nml_get "$text" "end_$e" mass)" ;;
    *"(moved ±"*)
      dir=$(awk -v x="$(nml_get "$text" "end_$e" direction_x)" -v z="$(nml_get "$text" "end_$e" direction_z)" \
            'BEGIN { print (x == 0 ? "vertically " : (z == 0 ? "horizontally " : "")) }')
      printf 'end %s moved %s±%s m (period %s s)' "$e" "$dir" "$(nml_get "$text" "end_$e" amplitude)" \
             "$(nml_get "$text" "end_$e" period)" ;;
    *"(applied force)") printf 'end %s under an applied force' "$e" ;;
    *) printf '%s' "$label" | sed 's/ (\(.*\))$/ \1/' ;;
  esac
}

# One-line description of a run for the figure titles. The paper's cases (ends held, the static
# tension given): "<case>: static tension N kN, breaking time M ms". Other scenes, e.g.
# "<case>: end a fixed, end b fixed; break at s = 30 m of 60 m in 5 ms".
case_title() {
  local stem=$1 text tb ts enabled sb L where
  text=$(nml_text "$stem")
  tb=$(t_break_ms "$stem")
  ts=$(nml_get "$text" static tension)
  if [ -z "$text" ] || { [ -n "$ts" ] && [ "$(nml_get "$text" end_a kind)" = fixed ] && \
                         [ "$(nml_get "$text" end_b kind)" = fixed ] && [ -z "$(nml_get "$text" end_b x)" ]; }; then
    printf '%s: static tension %s kN%s' "$(basename "$stem")" "$(static_kN "$stem")" "${tb:+, breaking time $tb ms}"
    return 0
  fi
  enabled=$(nml_get "$text" rupture enabled)
  sb=$(nml_get "$text" rupture s_break)
  L=$(nml_get "$text" cable length)
  where=""
  if [ "$enabled" != ".true." ]; then
    where="; no break"
  elif awk -v s="$sb" -v L="$L" 'BEGIN { exit !(s > 0 && s < L) }'; then
    where="; break at s = $sb m of $L m $(_time_words "$(nml_get "$text" rupture t_break)")"
  fi
  printf '%s: %s, %s%s' "$(basename "$stem")" "$(title_end "$text" a)" "$(title_end "$text" b)" "$where"
}

# File extension for a format argument (png or pdf); fails on anything else.
format_ext() {
  case "${1:-png}" in
    png) echo png ;;
    pdf) echo pdf ;;
    *) echo "format '$1' unknown: use png (pngcairo) or pdf (pdfcairo)" >&2; return 2 ;;
  esac
}
