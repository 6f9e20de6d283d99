# The line over the seabed (a run with &seabed): the bottom, the line at t = 0 (the static state,
# black) and at the snapshots (thin, coloured by time), and the touchdown points, where the line
# leaves the bottom (red: at every snapshot; a circle and its arc length: at t = 0).
#   gnuplot -e "stem='results/chain_mooring_heave'; out='seabed.png'; depth=60; slope_x=0.02; diameter=0.1368" plots/seabed.gp
# depth, slope_x: the bottom z = -depth + slope_x x (&seabed; slope_y is not drawn: a 3-D run is
# drawn projected on x-z); diameter (&cable) sets the contact tolerance: a node is on the bottom
# when it is less than a tenth of the diameter (1 mm at least) above it. The tensions at the
# fairlead and the anchor against time are in ends.png. Optional: title, label_a, label_b,
# maxlines (see plots/common.gp).
_lastslash(p, i) = i < 1 ? 0 : (p[i:i] eq "/" ? i : _lastslash(p, i - 1))
if (!exists("plotdir")) { plotdir = _lastslash(ARG0, strlen(ARG0)) ? ARG0[1:_lastslash(ARG0, strlen(ARG0)) - 1] : "." }
load plotdir."/common.gp"
load plotdir."/snapshots.gp"
if (!exists("depth") || !exists("slope_x")) {
    exit error "seabed.gp: give depth and slope_x (the &seabed of the run), e.g. depth=60; slope_x=0"
}
if (!exists("diameter")) { diameter = 0.0 }
tol = 0.1 * diameter > 1e-3 ? 0.1 * diameter : 1e-3
zb(x) = -depth + slope_x * x

# The touchdown points of every snapshot: a node on the bottom whose next node is not (or the
# other way round: a node that lands after a stretch in the water), from the snapshot text.
_touchcmd(sel) = sprintf("awk -v D=%.17g -v S=%.17g -v tol=%.17g -v sel=%d '" . \
    "/^# t = / { b++; p = 0; next } /^#/ { next } NF == 0 { p = 0; next } " . \
    "{ on = ($3 <= -D + S * $2 + tol); if (p && on != pon && (sel < 0 || b == sel + 1)) " . \
    "{ if (on) print $1, $2, $3, b - 1; else print ps, px, pz, b - 1 } p = 1; pon = on; ps = $1; px = $2; pz = $3 }' '%s'", \
    depth, slope_x, tol, sel, snap)
_touch(sel) = "< " . _touchcmd(sel)
_first = system(_touchcmd(0) . " | head -1")
s_td = words(_first) >= 1 ? real(word(_first, 1)) : -1
# The snapshots with a touchdown point (report=1 prints it with the number of snapshots).
ntouch = int(system(_touchcmd(-1) . " | awk '{ b[$4] = 1 } END { print length(b) }'"))
if (exists("report")) { print sprintf("seabed.gp: %d of %d snapshots have a touchdown point", ntouch, nsnap) }

stats [*:*][*:*] snap using 2:3 nooutput
x0 = STATS_min_x; x1 = STATS_max_x
zlo = STATS_min_y < zb(x0) ? STATS_min_y : zb(x0)
zlo = zlo < zb(x1) ? zlo : zb(x1)
zhi = STATS_max_y
pad = 0.05 * (x1 - x0)

fig_w = 1150; fig_h = 560
load plotdir."/terminal.gp"
set title sprintf("The line over the seabed\n%s", title)
set xlabel "x [m]"
set ylabel "z [m]"
set size ratio -1
set xrange [x0 - pad:x1 + pad]
set yrange [zlo - 0.1 * (zhi - zlo):zhi + 0.1 * (zhi - zlo)]
set key at graph 0.03, graph 0.96 left top box opaque
unset grid
if (s_td >= 0) {
    set label 1 sprintf("touchdown at t = 0: s = %.4g m", s_td) at word(_first, 2) - 0.01 * (x1 - x0), word(_first, 3) + 0.08 * (zhi - zlo) \
        right front textcolor rgb "#b2182b"
}
plot [x0 - pad:x1 + pad] zb(x) with filledcurves y1 = zlo - 0.1 * (zhi - zlo) fillcolor rgb "#d8c3a5" \
         notitle, \
     zb(x) with lines linecolor rgb "#8c6d46" linewidth 2 title sprintf("seabed, z = -%g + %g x", depth, slope_x), \
     for [i = 1:nsnap - 1:stride] snap index i using 2:3 with lines linewidth 0.8 \
         linecolor palette cb tval(i) notitle, \
     snap index 0 using 2:3 with lines linecolor rgb "black" linewidth 2 title "t = 0 (static state)", \
     _touch(-1) using 2:3 with points pointtype 7 pointsize 0.5 linecolor rgb "#e31a1c" \
         title sprintf("touchdown, the %d snapshots", nsnap), \
     _touch(0) using 2:3 with points pointtype 6 pointsize 2 linewidth 2 linecolor rgb "#b2182b" notitle
