# Helper of plots/motion.gp (loaded, not run): draws one view of the motion. _view 0: x and z;
# 1: distance along the chord a-b and deflection normal to it (px, pz of plots/motion.gp).
# _ex: exaggeration of the vertical (1, 10, or 100 with the vertical in cm).
_zf = _ex == 100 ? 100.0 : 1.0
set size ratio -(_ex / _zf)
_scale = _ex == 1 ? "" : (_ex == 100 ? "  (1 cm drawn as 1 m)" : "  (vertical scale ×10)")
if (_view == 0) {
    set xlabel "x, horizontal distance from end a [m]"
    set ylabel sprintf("z, height above end a [%s]%s", _ex == 100 ? "cm" : "m", _scale)
} else {
    set xlabel "distance along the chord from end a towards end b [m]"
    set ylabel sprintf("deflection from the chord [%s]%s", _ex == 100 ? "cm" : "m", _ex == 100 ? _scale : "  (×10)")
}
# The key in the first view only (the second view shares it).
if (exists("panel")) {
    set key top left box opaque samplen 1 spacing 1.1
    if (_view == 0 && _ex == 1 && v0_z1 - v0_z0 > v0_x1 - v0_x0) { set key top right }
    if (_view == 0 && c_sin > 0.05 && _ex == 1) { set key bottom right }
} else {
    # Below the last view (the key is drawn with the first; the second view keeps the margin).
    @bottom_key
    if (two_views && _view == 0) { set bmargin 3 }
}
if (_view == 1) { set key off }
# Pieces: a single blank line inside a block ends a line in gnuplot, so a broken cable is drawn
# as two lines. End symbols: square end a, circle end b, triangles the two new ends at a break.
plot for [i = 0:nsnap - 1:stride] snap index i using (px($2, $3)):(_zf * pz($2, $3)):(tval(i)) \
         with lines lw 1.5 lc palette notitle, \
     ends using (px($4, $5)):(drawn($1) && $2 == 0 ? _zf * pz($4, $5) : NaN):(tval($1)) with points pt 5 ps 0.8 lc palette notitle, \
     ends using (px($4, $5)):(drawn($1) && $2 == 1 ? _zf * pz($4, $5) : NaN):(tval($1)) with points pt 7 ps 0.9 lc palette notitle, \
     ends using (px($4, $5)):(drawn($1) && $2 == 2 ? _zf * pz($4, $5) : NaN):(tval($1)) with points pt 9 ps 1.0 lc palette notitle, \
     NaN with points pt 5 ps 0.8 lc rgb '#404040' title label_a, \
     NaN with points pt 7 ps 0.9 lc rgb '#404040' title label_b, \
     NaN with points pt 9 ps 1.0 lc rgb '#404040' title (npieces > 1 ? "ends at the break" : "")
