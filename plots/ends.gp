# Speed and tension of every end against time (beyond the paper), two panels.
#   gnuplot -e "stem='results/slow_315kN'; out='ends.png'" plots/ends.gp
# Optional: title='...' (the case, for the title), label_a, label_b. Variables: see plots/common.gp.
# The ends are those the history header names (end_a, end_b, and for a break inside the cable
# break_a, break_b), each with its speed, the tension of the end and the magnitude of the external
# force on it (the support's reaction for a held end, the applied force for a loaded one).
# Top: the speed of every end that moves (ends whose speed stays zero are left out), with the
# largest. Bottom: the tension of every end (solid), and the external force (dashed) where it
# differs from the tension by more than 2 % of the largest tension, with the lowest tension and,
# when a load exceeds the initial one, the highest.
_lastslash(p, i) = i < 1 ? 0 : (p[i:i] eq "/" ? i : _lastslash(p, i - 1))
if (!exists("plotdir")) { plotdir = _lastslash(ARG0, strlen(ARG0)) ? ARG0[1:_lastslash(ARG0, strlen(ARG0)) - 1] : "." }
load plotdir."/common.gp"
load plotdir."/history.gp"
if (nends == 0) {
    exit error sprintf("%s: the header names no end columns ('<end>:speed'): not an xcable history of this version", hist)
}

# Largest speed, lowest and highest tension, and their ends and times.
vmax = 0; vend = ""; vt = 0
tmin = 1e300; tminend = ""; tmint = 0
tmax = -1e300; tmaxend = ""; tmaxt = 0
tmax0 = -1e300; fmax = 0
array vpeak[nends]; array fdiff[nends]; array fpeak[nends]
do for [j = 1:nends] {
    c = speed_col(j)
    stats [*:*][*:*] hist using 1:c nooutput
    vpeak[j] = STATS_max_y
    if (STATS_max_y > vmax) { vmax = STATS_max_y; vend = end_label(j); vt = STATS_pos_max_y }
    stats [*:*][*:*] hist using 1:c + 1 nooutput
    if (STATS_min_y < tmin) { tmin = STATS_min_y; tminend = end_label(j); tmint = STATS_pos_min_y }
    if (STATS_max_y > tmax) { tmax = STATS_max_y; tmaxend = end_label(j); tmaxt = STATS_pos_max_y }
    fmax = amax(fmax, amax(STATS_min_y, STATS_max_y))
    stats [*:*][*:*] hist every ::0::0 using c + 1 nooutput
    tmax0 = STATS_max > tmax0 ? STATS_max : tmax0
    stats [*:*][*:*] hist using (column(c + 2) - abs(column(c + 1))) nooutput
    fdiff[j] = amax(STATS_min, STATS_max)
    stats [*:*][*:*] hist using c + 2 nooutput
    fpeak[j] = STATS_max
}
moving(j) = vpeak[j] > 1e-6 * vmax && vpeak[j] > 1e-9
showforce(j) = fpeak[j] > 0 && fdiff[j] > 0.02 * fmax
anyforce = 0
do for [j = 1:nends] { if (showforce(j)) { anyforce = 1 } }
ffac = ffac_for(fmax)
funit = funit_for(fmax)

fig_w = 1150; fig_h = 800
load plotdir."/terminal.gp"
set multiplot layout 2, 1 title sprintf("Speed and tension of the ends\n%s", title)
set lmargin 12
set rmargin at screen 0.72
set key at screen 0.735, graph 1 left top Left reverse box opaque samplen 2 spacing 1.1 width 1
# Both quantities start from or fall to zero: the zero line (a plotted 0) keeps zero in view, and
# keeps a short run, whose held ends have not felt the release yet, from giving an empty range.

set label 1 (vmax > 0 ? sprintf("largest speed %.4g m/s (%s, t = %s)", vmax, end_name(vend), tfmt(vt, tunit)) \
                      : "no end moves") at graph 0.02, graph 0.92 left front
set ylabel "speed of the end [m/s]"
# Head room above the curves for the label.
set yrange [0 : (vmax > 0 ? 1.3 * vmax : 1)]
plot for [j = 1:nends] hist using (tfac * $1):(moving(j) ? column(speed_col(j)) : NaN) \
         with lines lw 2 lc rgb end_colour(end_label(j)) title (moving(j) ? end_name(end_label(j)) : ""), \
     0 with lines lt -1 lw 0.5 notitle
unset label 1
set autoscale y

set label 1 sprintf("lowest %.4g %s (%s, t = %s)", ffac * tmin, funit, end_name(tminend), tfmt(tmint, tunit)) \
    at graph 0.02, graph 0.92 left front
if (tmax > 1.05 * tmax0) {
    set label 2 sprintf("highest %.4g %s (%s, t = %s)", ffac * tmax, funit, end_name(tmaxend), tfmt(tmaxt, tunit)) \
        at graph 0.02, graph 0.82 left front
}
set ylabel sprintf("tension of the end [%s]", funit)
# Zero in view, and head room above the curves for the labels.
_ylo = ffac * (tmin < 0 ? tmin : 0)
_yhi = ffac * (fmax > 0 ? fmax : 1)
set yrange [_ylo - 0.05 * (_yhi - _ylo) : _yhi + (tmax > 1.05 * tmax0 ? 0.4 : 0.3) * (_yhi - _ylo)]
plot for [j = 1:nends] hist using (tfac * $1):(ffac * column(speed_col(j) + 1)) \
         with lines lw 2 lc rgb end_colour(end_label(j)) title end_name(end_label(j)), \
     for [j = 1:nends] hist using (tfac * $1):(showforce(j) ? ffac * column(speed_col(j) + 2) : NaN) \
         with lines lw 1.5 dt 2 lc rgb end_colour(end_label(j)) notitle, \
     NaN with lines lw 1.5 dt 2 lc rgb '#404040' title (anyforce ? "external force (magnitude)" : ""), \
     0 with lines lt -1 lw 0.5 notitle
unset multiplot
unset output
