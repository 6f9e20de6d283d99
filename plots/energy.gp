# Energy ledger against time (beyond the paper): the energies, and the drift of the ledger
#   ledger = E_strain + E_kinetic + E_bending + E_gravity - W_end + dissipation,
# which stays constant up to the discretisation error (W_end: the work done on the cable by its
# ends and loads; dissipation: the energy the time weight theta > 0.5 takes out, drawn only when
# it is not zero).
#   gnuplot -e "stem='results/slow_315kN'; out='energy.png'" plots/energy.gp
# History columns 5-11: E_strain E_kinetic E_bending E_gravity W_end ledger dissipation.
# The drift is given in % of the largest E_strain + E_kinetic + E_bending of the run (the energy
# that moves; the ledger itself may be near zero or negative, gravity being measured from end a).
# Gravity and the ledger are drawn from their values at t = 0 (see below).
# Needs a run with &output energy = .true.; without it, says so and draws nothing (exit 0).
_lastslash(p, i) = i < 1 ? 0 : (p[i:i] eq "/" ? i : _lastslash(p, i - 1))
if (!exists("plotdir")) { plotdir = _lastslash(ARG0, strlen(ARG0)) ? ARG0[1:_lastslash(ARG0, strlen(ARG0)) - 1] : "." }
load plotdir."/common.gp"
load plotdir."/history.gp"

_header = system(sprintf("sed -n '1{/^#/p}' '%s'", hist))
if (strstrt(_header, "ledger") == 0 || strstrt(_header, "no energy ledger") > 0) {
    print sprintf("energy.gp: %s has no energy columns (the run had no &output energy = .true.); energy figure not drawn", hist)
    exit status 0
}
stats [*:*][*:*] hist every ::0::0 using 10 nooutput
ledger0 = STATS_max
stats [*:*][*:*] hist every ::0::0 using 8 nooutput
grav0 = STATS_max
stats [*:*][*:*] hist using ($5 + $6 + $7) nooutput
escale = STATS_max > 0 ? STATS_max : (abs(ledger0) > 0 ? abs(ledger0) : 1.0)
stats [*:*][*:*] hist using 11 nooutput
has_diss = amax(STATS_min, STATS_max) > 0
# Gravity is measured from the height of end a, so its value (and the ledger's) depends on where
# the scene lies: both are drawn as changes from t = 0 plus the energy that moves at t = 0
# (strain + kinetic + bending), so the ledger is a flat line at the top when it is conserved.
e0shift = ledger0 - grav0
stats [*:*][*:*] hist every ::0::0 using ($5 + $6 + $7) nooutput
emove0 = STATS_max
_emax = 0
do for [c = 5:11] {
    stats [*:*][*:*] hist using (c == 8 ? column(8) - grav0 : (c == 10 ? column(10) - ledger0 + emove0 : column(c))) nooutput
    _emax = amax(_emax, amax(STATS_min, STATS_max))
}
efac = efac_for(_emax)
eunit = eunit_for(_emax)

fig_w = 1150; fig_h = 800
load plotdir."/terminal.gp"
set multiplot title sprintf("Energy ledger = strain + kinetic + bending + gravity − W_end%s: it should stay constant\n%s", \
    has_diss ? " + dissipated" : "", title)
set lmargin 12

set size 1, 0.58
set origin 0, 0.37
set ylabel sprintf("energy [%s]", eunit)
set rmargin at screen 0.71
set key at screen 0.725, graph 0.5 left center Left reverse box opaque samplen 2 spacing 1.1 width 1
set xzeroaxis lt -1 lw 0.5
unset xlabel
set format x ""
plot hist using (tfac * $1):(efac * $5) with lines lw 2 lc rgb '#1f78b4' title "strain", \
     ''   using (tfac * $1):(efac * $6) with lines lw 2 lc rgb '#d7301f' title "kinetic", \
     ''   using (tfac * $1):(efac * $7) with lines lw 2 lc rgb '#6a9a00' title "bending", \
     ''   using (tfac * $1):(efac * ($8 - grav0)) with lines lw 2 lc rgb '#8c564b' title "gravity (change from t = 0)", \
     ''   using (tfac * $1):(efac * $9) with lines lw 2 lc rgb '#e08a00' title "W_end (work of ends, loads)", \
     ''   using (tfac * $1):(has_diss ? efac * $11 : NaN) with lines lw 2 lc rgb '#7b3294' \
          title (has_diss ? "dissipated" : ""), \
     ''   using (tfac * $1):(efac * ($10 - ledger0 + emove0)) with lines lw 3 lc rgb 'black' \
          title "ledger (gravity from t = 0)"

set size 1, 0.37
set origin 0, 0
set format x "% h"
set xlabel sprintf("time, t [%s]", tunit)
set ylabel "ledger drift [%]"
set key off
stats [*:*][*:*] hist using (100 * ($10 - ledger0) / escale) nooutput
_drift = abs(STATS_min) > abs(STATS_max) ? STATS_min : STATS_max
_head = sprintf("ledger(0) = %.4g %s; drift in %% of %.4g %s, the largest strain + kinetic + bending energy", \
    efac * ledger0, eunit, efac * escale, eunit)
if (STATS_max - STATS_min < 1e-12) {
    # The history holds 10 significant digits: a ledger that does not change in them.
    set title sprintf("%s\nno change in the 10 digits of the history file (drift below %.1g %%)", _head, \
        100 * 1e-9 * (abs(ledger0) > escale ? abs(ledger0) : escale) / escale) offset 0, -0.5
    set yrange [-1e-3 : 1e-3]
} else {
    set title sprintf("%s\nlargest drift %.3g %%", _head, _drift) offset 0, -0.5
}
plot hist using (tfac * $1):(100 * ($10 - ledger0) / escale) with lines lw 2 lc rgb 'black'
unset multiplot
unset output
