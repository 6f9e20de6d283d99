# Motion of the cable in the vertical plane, one line per snapshot (the paper's figures 2 and 5).
#   gnuplot -e "stem='results/slow_315kN'; out='motion.png'" plots/motion.gp
# Optional: title='...' (the case, for the title), label_a, label_b, vexag. Variables: see plots/common.gp.
# x and z are drawn with equal lengths per unit, except that the vertical scale is exaggerated
# when the motion is much flatter than it is wide: 100 times, as in the paper, with z in cm
# ("1 cm drawn as 1 m"), or 10 times; a swing or a hanging line is drawn to scale. The axis label
# says which. A broken cable is drawn as its pieces; symbols mark the ends of every piece.
_lastslash(p, i) = i < 1 ? 0 : (p[i:i] eq "/" ? i : _lastslash(p, i - 1))
if (!exists("plotdir")) { plotdir = _lastslash(ARG0, strlen(ARG0)) ? ARG0[1:_lastslash(ARG0, strlen(ARG0)) - 1] : "." }
load plotdir."/common.gp"
load plotdir."/snapshots.gp"

# Extent of the motion (all snapshots), and the vertical exaggeration it calls for.
stats [*:*][*:*] snap using 2:3 nooutput
_x0 = STATS_min_x; _x1 = STATS_max_x; _z0 = STATS_min_y; _z1 = STATS_max_y
_vx = exists("vexag") ? vexag : vexag_for(_x1 - _x0, _z1 - _z0)
# z is plotted in cm at 100x (the paper's figures), in m otherwise.
zf = _vx == 100 ? 100.0 : 1.0
zunit = _vx == 100 ? "cm" : "m"

if (!exists("panel")) {
    # Ranges rounded outwards; a line much taller than wide (a hanging line) gets a box at least
    # 0.6 times as wide as it is tall, so the figure keeps a readable shape.
    _pad = 0.04 * ((_x1 - _x0) > _vx * (_z1 - _z0) ? (_x1 - _x0) : _vx * (_z1 - _z0))
    _pad = _pad > 0 ? _pad : 1.0
    _xa = _x0 - _pad; _xb = _x1 + _pad
    _za = _vx * _z0 - _pad; _zb = _vx * _z1 + _pad
    if ((_xb - _xa) < 0.6 * (_zb - _za)) {
        _xc = 0.5 * (_xa + _xb); _xa = _xc - 0.3 * (_zb - _za); _xb = _xc + 0.3 * (_zb - _za)
    }
    set xrange [_lo(_xa, _xb) : _hi(_xa, _xb)]
    set yrange [_lo(_za, _zb) * zf / _vx : _hi(_za, _zb) * zf / _vx]
    # Canvas shaped to the drawing: plot area about 760 px wide, or 700 px tall for tall scenes.
    _aspect = (_hi(_za, _zb) - _lo(_za, _zb)) / (_hi(_xa, _xb) - _lo(_xa, _xb))
    if (_aspect <= 700.0 / 760) {
        fig_w = 1100; fig_h = int(760 * _aspect) + 200
        fig_h = fig_h < 420 ? 420 : fig_h
    } else {
        fig_h = 900; fig_w = int(700 / _aspect) + 380
        fig_w = fig_w < 760 ? 760 : fig_w
    }
    load plotdir."/terminal.gp"
    set title sprintf("Motion of the cable in the vertical plane%s\n%s", \
        _vx == 1 ? " (drawn to scale)" : sprintf(" (vertical scale exaggerated %d×)", _vx), title)
} else {
    set title title
}
if (_vx == 1) {
    set size ratio -1
    set ylabel "z, height above end a [m]"
} else {
    set size ratio -(_vx / zf)
    set ylabel _vx == 100 ? "z, height above end a [cm]  (1 cm drawn as 1 m)" : \
                            "z, height above end a [m]  (vertical scale ×10)"
}
set xlabel "x, horizontal distance from end a [m]"
set key top left box opaque samplen 1 spacing 1.1
if (_vx == 1 && _z1 - _z0 > _x1 - _x0) { set key top right }
# Pieces: a single blank line inside a block ends a line in gnuplot, so a broken cable is drawn
# as two lines. End symbols: square end a, circle end b, triangles the two new ends at a break.
plot for [i = 0:nsnap - 1:stride] snap index i using 2:(zf * $3):(tval(i)) with lines lw 1.5 lc palette notitle, \
     ends using 4:(drawn($1) && $2 == 0 ? zf * $5 : NaN):(tval($1)) with points pt 5 ps 0.8 lc palette notitle, \
     ends using 4:(drawn($1) && $2 == 1 ? zf * $5 : NaN):(tval($1)) with points pt 7 ps 0.9 lc palette notitle, \
     ends using 4:(drawn($1) && $2 == 2 ? zf * $5 : NaN):(tval($1)) with points pt 9 ps 1.0 lc palette notitle, \
     NaN with points pt 5 ps 0.8 lc rgb '#404040' title label_a, \
     NaN with points pt 7 ps 0.9 lc rgb '#404040' title label_b, \
     NaN with points pt 9 ps 1.0 lc rgb '#404040' title (npieces > 1 ? "ends at the break" : "")
if (!exists("panel")) { unset output }
