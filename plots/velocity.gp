# Tangential velocity along the cable, one line per snapshot (the paper's figures 4 and 7).
#   gnuplot -e "stem='results/slow_315kN'; out='velocity.png'" plots/velocity.gp
# Optional: title='...' (the case, for the title), label_a, label_b. Variables: see plots/common.gp.
# u is positive towards end b (s increasing), so the recoil of a released end b is negative, and
# that of the piece on the side of end b after a break inside is positive. When the cable also
# moves sideways (a swing: the normal velocity v reaches a fifth of the largest |u|), a second
# panel gives v (positive to the left of the direction of increasing s). In a panel of
# plots/pair.gp only u is drawn. Symbols mark the ends of every piece, as in plots/motion.gp.
_lastslash(p, i) = i < 1 ? 0 : (p[i:i] eq "/" ? i : _lastslash(p, i - 1))
if (!exists("plotdir")) { plotdir = _lastslash(ARG0, strlen(ARG0)) ? ARG0[1:_lastslash(ARG0, strlen(ARG0)) - 1] : "." }
load plotdir."/common.gp"
load plotdir."/snapshots.gp"

stats [*:*][*:*] snap using 6:7 nooutput
_umax = amax(STATS_min_x, STATS_max_x)
_vmax = amax(STATS_min_y, STATS_max_y)
_two = !exists("panel") && _vmax > 0.2 * _umax

if (exists("panel")) {
    set title title
} else {
    fig_w = 1100; fig_h = _two ? 1000 : 650
    load plotdir."/terminal.gp"
    if (_two) {
        set multiplot layout 2, 1 title sprintf("Tangential and normal velocity along the cable\n%s", title)
        set lmargin 12
        set rmargin 16
    } else {
        set title sprintf("Tangential velocity along the cable\n%s", title)
    }
}
set xlabel "s, unstretched arc length from end a [m]"
if (!exists("panel")) { set xrange [0 : Lcab] }
set ylabel "tangential velocity u [m/s]  (positive: towards end b)"
set xzeroaxis lt -1 lw 0.5
if (exists("panel")) { set key top left box opaque samplen 1 spacing 1.1 } else { @bottom_key }
plot for [i = 0:nsnap - 1:stride] snap index i using 1:6:(tval(i)) with lines lw 1.5 lc palette notitle, \
     ends using 3:(drawn($1) && $2 == 0 ? $8 : NaN):(tval($1)) with points pt 5 ps 0.8 lc palette notitle, \
     ends using 3:(drawn($1) && $2 == 1 ? $8 : NaN):(tval($1)) with points pt 7 ps 0.9 lc palette notitle, \
     ends using 3:(drawn($1) && $2 == 2 ? $8 : NaN):(tval($1)) with points pt 9 ps 1.0 lc palette notitle, \
     NaN with points pt 5 ps 0.8 lc rgb '#404040' title label_a, \
     NaN with points pt 7 ps 0.9 lc rgb '#404040' title label_b, \
     NaN with points pt 9 ps 1.0 lc rgb '#404040' title (npieces > 1 ? "ends at the break" : "")
if (_two) {
    set ylabel "normal velocity v [m/s]"
    set key off
    plot for [i = 0:nsnap - 1:stride] snap index i using 1:7:(tval(i)) with lines lw 1.5 lc palette notitle, \
         ends using 3:(drawn($1) && $2 == 0 ? $9 : NaN):(tval($1)) with points pt 5 ps 0.8 lc palette notitle, \
         ends using 3:(drawn($1) && $2 == 1 ? $9 : NaN):(tval($1)) with points pt 7 ps 0.9 lc palette notitle, \
         ends using 3:(drawn($1) && $2 == 2 ? $9 : NaN):(tval($1)) with points pt 9 ps 1.0 lc palette notitle
    unset multiplot
}
if (!exists("panel")) { unset output }
