# Motion of the cable in the vertical plane, one line per snapshot (the paper's figures 2 and 5).
#   gnuplot -e "stem='results/slow_315kN'; out='motion.png'" plots/motion.gp
# Optional: title='...' (the case, for the title). Variables: see plots/common.gp.
# z is drawn in cm against x in m with equal lengths per unit (size ratio -1): the vertical
# scale is exaggerated exactly 100 times, as in the paper.
_lastslash(p, i) = i < 1 ? 0 : (p[i:i] eq "/" ? i : _lastslash(p, i - 1))
if (!exists("plotdir")) { plotdir = _lastslash(ARG0, strlen(ARG0)) ? ARG0[1:_lastslash(ARG0, strlen(ARG0)) - 1] : "." }
load plotdir."/common.gp"
load plotdir."/snapshots.gp"

if (exists("panel")) {
    set title title
} else {
    fig_w = 1100; fig_h = 650
    load plotdir."/terminal.gp"
    set title sprintf("Motion of the cable in the vertical plane (vertical scale exaggerated 100×)\n%s", title)
}
set xlabel "x, horizontal distance from the fixed end [m]"
set ylabel "z, height above the fixed end [cm]  (1 cm drawn as 1 m)"
set size ratio -1
set key top left box opaque samplen 1
plot for [i = 0:nsnap - 1] snap index i using 2:(100 * $3):(t_ms(i)) with lines lw 1.5 lc palette notitle, \
     for [i = 0:nsnap - 1] snap index i every ::(nnode - 1)::(nnode - 1) using 2:(100 * $3):(t_ms(i)) \
         with points pt 7 ps 0.8 lc palette notitle, \
     NaN with points pt 7 ps 0.8 lc rgb '#404040' title "breaking end"
if (!exists("panel")) { unset output }
