# Breaking-end velocity and fixed-end tension against time (beyond the paper), two panels.
#   gnuplot -e "stem='results/slow_315kN'; out='ends.png'" plots/ends.gp
# Optional: title='...' (the case, for the title). Variables: see plots/common.gp.
_lastslash(p, i) = i < 1 ? 0 : (p[i:i] eq "/" ? i : _lastslash(p, i - 1))
if (!exists("plotdir")) { plotdir = _lastslash(ARG0, strlen(ARG0)) ? ARG0[1:_lastslash(ARG0, strlen(ARG0)) - 1] : "." }
load plotdir."/common.gp"
load plotdir."/history.gp"

fig_w = 1000; fig_h = 750
load plotdir."/terminal.gp"
set multiplot layout 2, 1 title sprintf("Breaking-end velocity and fixed-end tension\n%s", title)
set key off
# Both quantities start from or fall to zero: the zero line (a plotted 0) keeps zero in view, and
# keeps a short run, whose fixed end has not felt the rupture yet, from giving an empty range.

stats [*:*][*:*] hist using 2 nooutput
set label 1 sprintf("largest speed %.1f m/s", abs(STATS_min) > abs(STATS_max) ? abs(STATS_min) : abs(STATS_max)) \
    at graph 0.98, graph 0.9 right front
set ylabel "breaking-end velocity u(L) [m/s]"
plot hist using (1000 * $1):2 with lines lw 2 lc rgb '#1f78b4', 0 with lines lt -1 lw 0.5

stats [*:*][*:*] hist using (1000 * $1):3 nooutput
set label 1 sprintf("lowest %.1f kN at t = %.0f ms", STATS_min_y / 1000, STATS_pos_min_y) at graph 0.98, graph 0.9 right front
set ylabel "fixed-end tension T(0) [kN]"
plot hist using (1000 * $1):($3 / 1000) with lines lw 2 lc rgb '#d7301f', 0 with lines lt -1 lw 0.5
unset multiplot
unset output
