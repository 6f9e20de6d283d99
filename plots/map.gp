# A field along the cable against time, as a colour map (beyond the paper): time across, the
# unstretched arc length s up, the value in colour. Fronts show as the edges of colour bands, and
# their slope is their speed in unstretched metres per second.
#   gnuplot -e "stem='results/slow_315kN'; out='map.png'" plots/map.gp
#   gnuplot -e "stem='...'; out='u.png'; field='u'" plots/map.gp
# field: 'tension' (default), 'strain', 'u' (tangential velocity) or 'v' (normal velocity).
# Compression (or a negative velocity) is drawn in blues, tension in reds, zero in white.
# Built from the snapshots: the time resolution is the snapshot interval (&output interval).
# Optional: title='...' (the case, for the title). Variables: see plots/common.gp.
_lastslash(p, i) = i < 1 ? 0 : (p[i:i] eq "/" ? i : _lastslash(p, i - 1))
if (!exists("plotdir")) { plotdir = _lastslash(ARG0, strlen(ARG0)) ? ARG0[1:_lastslash(ARG0, strlen(ARG0)) - 1] : "." }
if (!exists("field")) { field = "tension" }
_col = field eq "tension" ? 4 : (field eq "strain" ? 5 : (field eq "u" ? 6 : (field eq "v" ? 7 : 0)))
if (_col == 0) { exit error sprintf("map.gp: field='%s': must be tension, strain, u or v", field) }
load plotdir."/common.gp"
load plotdir."/snapshots.gp"
if (nsnap < 2) { exit error sprintf("map.gp: %s holds one snapshot only: nothing to map", snap) }

# Scans for pm3d: one per snapshot (time, s, value), separated by one blank line; the blank line
# between the pieces of a broken cable is dropped (the break node, in both, closes the gap).
grid = sprintf("< awk '/^# t = / { if (k++) print \"\"; t = $4; next } /^#/ || NF == 0 { next } { print t, $1, $%d }' '%s'", _col, snap)

stats [*:*][*:*] snap using _col nooutput
_vmin = STATS_min; _vmax = STATS_max
if (field eq "tension") {
    vfac = ffac_for(amax(_vmin, _vmax)); vname = sprintf("tension T [%s]", funit_for(amax(_vmin, _vmax)))
    fname = "Tension"
} else {
    vfac = 1.0
    vname = field eq "strain" ? "strain [-]" : (field eq "u" ? "tangential velocity u [m/s]" : "normal velocity v [m/s]")
    fname = field eq "strain" ? "Strain" : (field eq "u" ? "Tangential velocity" : "Normal velocity")
}
_lo_c = vfac * _vmin; _hi_c = vfac * _vmax
if (_hi_c <= _lo_c) { _hi_c = _lo_c + 1 }
# White at zero: blues below, reds above (only the part of the scale the data use).
if (_lo_c < 0 && _hi_c > 0) {
    set palette defined (_lo_c '#08306b', 0.5 * _lo_c '#6baed6', 0 '#ffffff', 0.25 * _hi_c '#fdbb84', \
                         0.6 * _hi_c '#e34a33', _hi_c '#7f0000')
} else {
    if (_hi_c > 0) {
        set palette defined (0 '#ffffff', 0.25 '#fdbb84', 0.6 '#e34a33', 1 '#7f0000')
    } else {
        set palette defined (0 '#08306b', 0.5 '#6baed6', 1 '#ffffff')
    }
}
set palette maxcolors 0
set cbrange [_lo_c : _hi_c]
set cbtics auto out nomirror
set mcbtics default
set cblabel vname offset 1.5, 0

fig_w = 1100; fig_h = 650
load plotdir."/terminal.gp"
set title sprintf("%s along the cable against time (from %d snapshots)\n%s", fname, nsnap, title) offset 0, 1.5
set view map
set pm3d corners2color mean interpolate 1,4
set tmargin 4
set xrange [tval(0) : tval(nsnap - 1)]
set yrange [0 : Lcab]
set xlabel sprintf("time, t [%s]", tunit)
set ylabel "s, unstretched arc length from end a [m]"
set xtics out nomirror
set ytics out nomirror
set grid front lc rgb '#a0a0a0' lw 0.5
set key off
splot grid using (tfac * $1):2:(vfac * $3) with pm3d notitle
unset output
