# Motion of the cable in the vertical plane, one line per snapshot (the paper's figures 2 and 5);
# for a 3-D run its projection on the x-z plane (plots/motion3d.gp and plots/plan.gp show the rest).
#   gnuplot -e "stem='results/slow_315kN'; out='motion.png'" plots/motion.gp
# Optional: title='...' (the case, for the title), label_a, label_b, vexag. Variables: see plots/common.gp.
# x and z are drawn with equal lengths per unit, except that the vertical scale is exaggerated
# when the motion is much flatter than it is wide: 100 times, as in the paper, with z in cm
# ("1 cm drawn as 1 m"), or 10 times; a swing or a hanging line is drawn to scale. The axis label
# says which. A broken cable is drawn as its pieces; symbols mark the ends of every piece.
# An inclined line (its chord from end a to end b at t = 0 at more than 3 degrees) whose motion
# is flat along that chord gets a second panel: the deflection from the chord, normal to it,
# exaggerated in the same way, against the distance along the chord. A line that stays on a
# vertical (a hanging line heaved at its top) is drawn as the heights of its ends against time.
_lastslash(p, i) = i < 1 ? 0 : (p[i:i] eq "/" ? i : _lastslash(p, i - 1))
if (!exists("plotdir")) { plotdir = _lastslash(ARG0, strlen(ARG0)) ? ARG0[1:_lastslash(ARG0, strlen(ARG0)) - 1] : "." }
load plotdir."/common.gp"
load plotdir."/snapshots.gp"

# A 3-D run (y in column 10 of its snapshot text): this figure is its projection on the x-z plane.
_plane = int(system(sprintf("awk '/^#/ || NF == 0 { next } { print NF; exit }' '%s'", snap))) >= 15 ? \
         "projected on the vertical x-z plane" : "in the vertical plane"
# The chord at t = 0: from the first point of the first snapshot (end a) to its last (end b).
_chord = system(sprintf("awk '/^# t = / { if (n++) exit; next } /^#/ || NF == 0 { next } { if (!k++) { print $2, $3 } x = $2; z = $3 } END { print x, z }' '%s'", snap))
ca_x = real(word(_chord, 1)); ca_z = real(word(_chord, 2))
_dx = real(word(_chord, 3)) - ca_x; _dz = real(word(_chord, 4)) - ca_z
_len = sqrt(_dx**2 + _dz**2)
c_cos = _len > 0 ? _dx / _len : 1.0
c_sin = _len > 0 ? _dz / _len : 0.0
# View 0: x, z. View 1: along the chord, and normal to it (positive on the upper side).
px(x, z) = _view == 0 ? x : (x - ca_x) * c_cos + (z - ca_z) * c_sin
pz(x, z) = _view == 0 ? z : -(x - ca_x) * c_sin + (z - ca_z) * c_cos

# Extents in a view, its exaggeration (vexag_for: 100 with z in cm, 10, or 1) and rounded ranges
# (in metres drawn): sets v<k>_x0, v<k>_x1 (x range), v<k>_z0, v<k>_z1 (z range, in metres times
# the exaggeration) and v<k>_ex.
_view = 0
stats [*:*][*:*] snap using (px($2, $3)):(pz($2, $3)) nooutput
v0_ex = exists("vexag") ? vexag : vexag_for(STATS_max_x - STATS_min_x, STATS_max_y - STATS_min_y)
_ex = v0_ex
load plotdir."/motion_range.gp"
v0_x0 = _xa; v0_x1 = _xb; v0_z0 = _za; v0_z1 = _zb

# A line that stays on one vertical (a hanging line heaved at its top) has no shape to draw:
# its motion is drawn as the heights of its ends against time instead.
if (!exists("panel") && STATS_max_x - STATS_min_x <= 1e-6 * (STATS_max_y - STATS_min_y)) {
    load plotdir."/motion_vertical.gp"
    exit
}

two_views = 0
if (!exists("panel") && v0_ex == 1 && abs(c_sin) > 0.05 && _len > 0) {
    _view = 1
    stats [*:*][*:*] snap using (px($2, $3)):(pz($2, $3)) nooutput
    if (STATS_max_y - STATS_min_y > 1e-6 * _len) {
        v1_ex = vexag_for(STATS_max_x - STATS_min_x, STATS_max_y - STATS_min_y)
        if (v1_ex > 1) {
            two_views = 1
            _ex = v1_ex
            load plotdir."/motion_range.gp"
            v1_x0 = _xa; v1_x1 = _xb; v1_z0 = _za; v1_z1 = _zb
        }
    }
}

if (!exists("panel")) {
    # Canvas shaped to the drawing: plot areas about 760 px wide, or 700 px tall for tall scenes.
    _aspect0 = (v0_z1 - v0_z0) / (v0_x1 - v0_x0)
    if (two_views) {
        _aspect1 = (v1_z1 - v1_z0) / (v1_x1 - v1_x0)
        _h0 = int(760 * _aspect0) + 110; _h0 = _h0 < 300 ? 300 : _h0
        _h1 = int(760 * _aspect1) + 110; _h1 = _h1 < 300 ? 300 : _h1
        fig_w = 1100; fig_h = _h0 + _h1 + 70
    } else {
        if (_aspect0 <= 700.0 / 760) {
            fig_w = 1100; fig_h = int(760 * _aspect0) + 200
            fig_h = fig_h < 420 ? 420 : fig_h
        } else {
            fig_h = 900; fig_w = int(700 / _aspect0) + 380
            fig_w = fig_w < 760 ? 760 : fig_w
        }
    }
    load plotdir."/terminal.gp"
    _what = v0_ex == 1 ? " (drawn to scale)" : sprintf(" (vertical scale exaggerated %d×)", v0_ex)
    if (two_views) {
        set multiplot title sprintf("Motion of the cable %s%s, and its deflection from the chord a–b (exaggerated %d×)\n%s", \
            _plane, _what, v1_ex, title)
        set lmargin 12
        set rmargin 18
        set size 1, (_h0 + 0.0) / fig_h
        set origin 0, (_h1 + 0.0) / fig_h
    } else {
        set title sprintf("Motion of the cable %s%s\n%s", _plane, _what, title)
    }
} else {
    set title title
}
_view = 0
_ex = v0_ex
if (!exists("panel")) {
    set xrange [v0_x0 : v0_x1]
    set yrange [v0_z0 * (_ex == 100 ? 1 : 1.0 / _ex) : v0_z1 * (_ex == 100 ? 1 : 1.0 / _ex)]
}
load plotdir."/motion_view.gp"
if (two_views) {
    _view = 1
    _ex = v1_ex
    set size 1, (_h1 + 0.0) / fig_h
    set origin 0, 0
    unset title
    set xrange [v1_x0 : v1_x1]
    set yrange [v1_z0 * (_ex == 100 ? 1 : 1.0 / _ex) : v1_z1 * (_ex == 100 ? 1 : 1.0 / _ex)]
    # The deflection view is short: half as many tics as gnuplot would put there.
    set ytics 2 * _step((v1_z1 - v1_z0) * (_ex == 100 ? 1 : 1.0 / _ex))
    load plotdir."/motion_view.gp"
    unset multiplot
}
if (!exists("panel")) { unset output }
