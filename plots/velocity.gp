# Tangential velocity along the cable, one line per snapshot (the paper's figures 4 and 7).
#   gnuplot -e "stem='results/slow_315kN'; out='velocity.png'" plots/velocity.gp
# Optional: title='...' (the case, for the title). Variables: see plots/common.gp.
# u is positive towards the breaking end, so the recoil is negative.
_lastslash(p, i) = i < 1 ? 0 : (p[i:i] eq "/" ? i : _lastslash(p, i - 1))
if (!exists("plotdir")) { plotdir = _lastslash(ARG0, strlen(ARG0)) ? ARG0[1:_lastslash(ARG0, strlen(ARG0)) - 1] : "." }
load plotdir."/common.gp"
load plotdir."/snapshots.gp"

if (exists("panel")) {
    set title title
} else {
    fig_w = 1100; fig_h = 650
    load plotdir."/terminal.gp"
    set title sprintf("Tangential velocity along the cable\n%s", title)
}
set xlabel "s, unstretched arc length from the fixed end [m]"
set ylabel "tangential velocity u [m/s]  (negative: towards the fixed end)"
set xzeroaxis lt -1 lw 0.5
plot for [i = 0:nsnap - 1] snap index i using 1:6:(t_ms(i)) with lines lw 1.5 lc palette notitle
if (!exists("panel")) { unset output }
