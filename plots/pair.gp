# Two runs side by side, as in the paper's figures 2-7: panel (a) beside panel (b), same scales.
#   gnuplot -e "kind='tension'; stem_a='results/fast_180kN'; stem_b='results/fast_315kN'; \
#               out='fig3_tension_fast.png'" plots/pair.gp
# kind: motion, tension or velocity (the panel script plots/<kind>.gp draws each panel).
# Optional: title_a, title_b (panel titles; default: the case names), figtitle (title of the figure),
#           scale_stems (space-separated stems whose data set the common axis ranges; default:
#           stem_a and stem_b; give all four cases to draw fast and slow figures at one scale).
_lastslash(p, i) = i < 1 ? 0 : (p[i:i] eq "/" ? i : _lastslash(p, i - 1))
if (!exists("plotdir")) { plotdir = _lastslash(ARG0, strlen(ARG0)) ? ARG0[1:_lastslash(ARG0, strlen(ARG0)) - 1] : "." }
if (!exists("kind") || !exists("stem_a") || !exists("stem_b")) {
    exit error "pair.gp needs kind='motion|tension|velocity', stem_a='...', stem_b='...' and out='....png'"
}
if (kind ne "motion" && kind ne "tension" && kind ne "velocity") {
    exit error sprintf("pair.gp: kind='%s': must be motion, tension or velocity", kind)
}
stem = stem_a
load plotdir."/common.gp"
if (!exists("scale_stems")) { scale_stems = stem_a." ".stem_b }
if (!exists("figtitle")) { figtitle = sprintf("%s: (a) %s, (b) %s", kind, basename(stem_a), basename(stem_b)) }

# Common ranges over scale_stems, rounded outwards to a round step. Motion panels share one
# vertical exaggeration (plots/common.gp, vexag_for: 100 for the paper's cases), unless vexag is given.
xcol(x) = kind eq "motion" ? column(2) : column(1)
ycol(x) = kind eq "motion" ? column(3) : (kind eq "tension" ? column(4) : column(6))
xmin = 1e30; xmax = -1e30; ymin = 1e30; ymax = -1e30
do for [k = 1:words(scale_stems)] {
    _f = word(scale_stems, k).".snapshots.dat"
    if (!readable(_f)) { exit error sprintf("pair.gp: %s not found (scale_stems)", _f) }
    stats [*:*][*:*] _f using (xcol(0)):(ycol(0)) nooutput
    xmin = STATS_min_x < xmin ? STATS_min_x : xmin
    xmax = STATS_max_x > xmax ? STATS_max_x : xmax
    ymin = STATS_min_y < ymin ? STATS_min_y : ymin
    ymax = STATS_max_y > ymax ? STATS_max_y : ymax
}
# Scale of the y axis: z in cm at 100x exaggeration, in m otherwise; tension in kN from 2 kN up.
if (kind eq "motion") {
    if (!exists("vexag")) { vexag = vexag_for(xmax - xmin, ymax - ymin) }
    _yf = vexag == 100 ? 100.0 : 1.0
} else {
    _yf = kind eq "tension" ? ffac_for(amax(ymin, ymax)) : 1.0
    if (kind eq "tension") { tension_fac = _yf }
}
ymin = _yf * ymin; ymax = _yf * ymax
set xrange [_lo(xmin, xmax) : _hi(xmin, xmax)]
set yrange [_lo(ymin, ymax) : _hi(ymin, ymax)]

fig_w = 1800; fig_h = (kind eq "motion" ? 560 : 650)
load plotdir."/terminal.gp"
panel = 1
set multiplot layout 1, 2 title figtitle
stem = stem_a
title = exists("title_a") ? title_a : "(a) ".basename(stem_a)
load plotdir."/".kind.".gp"
stem = stem_b
title = exists("title_b") ? title_b : "(b) ".basename(stem_b)
load plotdir."/".kind.".gp"
unset multiplot
unset output
