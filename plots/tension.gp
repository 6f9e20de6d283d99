# Tension along the cable, one line per snapshot (the paper's figures 3 and 6).
#   gnuplot -e "stem='results/slow_315kN'; out='tension.png'" plots/tension.gp
# Optional: title='...' (the case, for the title), label_a, label_b. Variables: see plots/common.gp.
# A cable broken inside is drawn as its two pieces (the break node is in both); symbols mark the
# ends of every piece, as in plots/motion.gp. kN from 2 kN up, N below.
_lastslash(p, i) = i < 1 ? 0 : (p[i:i] eq "/" ? i : _lastslash(p, i - 1))
if (!exists("plotdir")) { plotdir = _lastslash(ARG0, strlen(ARG0)) ? ARG0[1:_lastslash(ARG0, strlen(ARG0)) - 1] : "." }
load plotdir."/common.gp"
load plotdir."/snapshots.gp"

# Unit from this run, or the one plots/pair.gp chose for both panels (tension_fac).
stats [*:*][*:*] snap using 4 nooutput
ffac = exists("tension_fac") ? tension_fac : ffac_for(amax(STATS_min, STATS_max))
funit = ffac == 1.0 ? "N" : "kN"
if (exists("panel")) {
    set title title
} else {
    fig_w = 1100; fig_h = 650
    load plotdir."/terminal.gp"
    set title sprintf("Tension along the cable\n%s", title)
}
set xlabel "s, unstretched arc length from end a [m]"
if (!exists("panel")) { set xrange [0 : Lcab] }
set ylabel sprintf("tension T [%s]  (negative: compression)", funit)
set xzeroaxis lt -1 lw 0.5
if (exists("panel")) { set key top right box opaque samplen 1 spacing 1.1 } else { @bottom_key }
plot for [i = 0:nsnap - 1:stride] snap index i using 1:(ffac * $4):(tval(i)) with lines lw 1.5 lc palette notitle, \
     ends using 3:(drawn($1) && $2 == 0 ? ffac * $6 : NaN):(tval($1)) with points pt 5 ps 0.8 lc palette notitle, \
     ends using 3:(drawn($1) && $2 == 1 ? ffac * $6 : NaN):(tval($1)) with points pt 7 ps 0.9 lc palette notitle, \
     ends using 3:(drawn($1) && $2 == 2 ? ffac * $6 : NaN):(tval($1)) with points pt 9 ps 1.0 lc palette notitle, \
     NaN with points pt 5 ps 0.8 lc rgb '#404040' title label_a, \
     NaN with points pt 7 ps 0.9 lc rgb '#404040' title label_b, \
     NaN with points pt 9 ps 1.0 lc rgb '#404040' title (npieces > 1 ? "ends at the break" : "")
if (!exists("panel")) { unset output }
