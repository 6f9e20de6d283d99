# Plan view of a 3-D run (&numerics model = '3d'): the cable seen from above (x, y), one line per
# snapshot, as plots/motion.gp draws the vertical plane.
#   gnuplot -e "stem='results/sway3d'; out='plan.png'" plots/plan.gp
# Optional: title='...', label_a, label_b. Variables: see plots/common.gp. x and y are drawn
# with equal lengths per unit, except that y is exaggerated when the motion is much narrower
# across than along x: 100 times with y in cm ("1 cm drawn as 1 m"), or 10 times (vexag_for of
# plots/common.gp); the axis label says which. A planar run's text has no y and is refused.
_lastslash(p, i) = i < 1 ? 0 : (p[i:i] eq "/" ? i : _lastslash(p, i - 1))
if (!exists("plotdir")) { plotdir = _lastslash(ARG0, strlen(ARG0)) ? ARG0[1:_lastslash(ARG0, strlen(ARG0)) - 1] : "." }
load plotdir."/common.gp"
load plotdir."/snapshots.gp"
load plotdir."/columns3d.gp"

stats [*:*][*:*] snap using 2:10 nooutput
_ex = vexag_for(STATS_max_x - STATS_min_x, STATS_max_y - STATS_min_y)
load plotdir."/motion_range.gp"
_yf = _ex == 100 ? 100.0 : 1.0
_aspect = (_zb - _za) / (_xb - _xa)
if (_aspect <= 700.0 / 760) {
    fig_w = 1100; fig_h = int(760 * _aspect) + 200
    fig_h = fig_h < 420 ? 420 : fig_h
} else {
    fig_h = 900; fig_w = int(700 / _aspect) + 380
    fig_w = fig_w < 760 ? 760 : fig_w
}
load plotdir."/terminal.gp"
_what = _ex == 1 ? " (drawn to scale)" : sprintf(" (y exaggerated %d×)", _ex)
set title sprintf("Plan view of the cable, seen from above%s\n%s", _what, title)
set xrange [_xa : _xb]
set yrange [_za * (_ex == 100 ? 1 : 1.0 / _ex) : _zb * (_ex == 100 ? 1 : 1.0 / _ex)]
set size ratio -(_ex / _yf)
set xlabel "x, horizontal distance from end a [m]"
_scale = _ex == 1 ? "" : (_ex == 100 ? "  (1 cm drawn as 1 m)" : "  (×10)")
set ylabel sprintf("y, across the x-z plane [%s]%s", _ex == 100 ? "cm" : "m", _scale)
@bottom_key
plot for [i = 0:nsnap - 1:stride] snap index i using 2:(_yf * $10):(tval(i)) with lines lw 1.5 lc palette notitle, \
     ends using 4:(drawn($1) && $2 == 0 ? _yf * $12 : NaN):(tval($1)) with points pt 5 ps 0.8 lc palette notitle, \
     ends using 4:(drawn($1) && $2 == 1 ? _yf * $12 : NaN):(tval($1)) with points pt 7 ps 0.9 lc palette notitle, \
     keyentry with points pt 5 ps 0.8 lc rgb '#404040' title label_a, \
     keyentry with points pt 7 ps 0.9 lc rgb '#404040' title label_b
unset output
