# Energy ledger against time (beyond the paper): the energies, and the drift of the ledger
#   ledger = E_strain + E_kinetic + E_bending + E_gravity - W_end,
# which the model conserves (no dissipation) up to the discretisation error.
#   gnuplot -e "stem='results/slow_315kN'; out='energy.png'" plots/energy.gp
# Needs a run with &output energy = .true.; without it, says so and draws nothing (exit 0).
_lastslash(p, i) = i < 1 ? 0 : (p[i:i] eq "/" ? i : _lastslash(p, i - 1))
if (!exists("plotdir")) { plotdir = _lastslash(ARG0, strlen(ARG0)) ? ARG0[1:_lastslash(ARG0, strlen(ARG0)) - 1] : "." }
load plotdir."/common.gp"
load plotdir."/history.gp"

_header = system(sprintf("sed -n '1{/^#/p}' '%s'", hist))
if (strstrt(_header, "ledger") == 0) {
    print sprintf("energy.gp: %s has no energy columns (the run had no &output energy = .true.); energy figure not drawn", hist)
    exit status 0
}
stats [*:*][*:*] hist every ::0::0 using 10 nooutput
ledger0 = STATS_max

fig_w = 1000; fig_h = 800
load plotdir."/terminal.gp"
set multiplot title sprintf("Energy ledger (no dissipation in the model: the ledger should stay constant)\n%s", title)
set lmargin 12
set rmargin 4

set size 1, 0.58
set origin 0, 0.37
set ylabel "energy [kJ]"
set key right center box opaque samplen 2 spacing 1.1
set xzeroaxis lt -1 lw 0.5
unset xlabel
set format x ""
plot hist using (1000 * $1):($5 / 1000) with lines lw 2 lc rgb '#1f78b4' title "strain", \
     ''   using (1000 * $1):($6 / 1000) with lines lw 2 lc rgb '#d7301f' title "kinetic", \
     ''   using (1000 * $1):($7 / 1000) with lines lw 2 lc rgb '#6a9a00' title "bending", \
     ''   using (1000 * $1):($8 / 1000) with lines lw 2 lc rgb '#8c564b' title "gravity", \
     ''   using (1000 * $1):($9 / 1000) with lines lw 2 lc rgb '#e08a00' title "W_end (work of end force)", \
     ''   using (1000 * $1):($10 / 1000) with lines lw 3 lc rgb 'black' title "ledger"

set size 1, 0.37
set origin 0, 0
set format x "% h"
set xlabel "time after the release starts, t [ms]"
set ylabel "ledger drift [% of ledger(0)]"
set key off
stats [*:*][*:*] hist using (100 * ($10 - ledger0) / ledger0) nooutput
set title sprintf("ledger(0) = %.1f kJ; largest drift %.3g %%", ledger0 / 1000, \
    abs(STATS_min) > abs(STATS_max) ? STATS_min : STATS_max) offset 0, -0.5
if (STATS_max - STATS_min < 1e-12) { set yrange [-1e-3 : 1e-3] }
plot hist using (1000 * $1):(100 * ($10 - ledger0) / ledger0) with lines lw 2 lc rgb 'black'
unset multiplot
unset output
