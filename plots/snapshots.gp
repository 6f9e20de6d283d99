# Read the snapshot file of the run 'stem' and set the colour scale keyed to the snapshot time.
# Defines: snap (file name), nsnap (number of snapshots), t_ms(i) (time of snapshot i = 0 .. nsnap-1
# in ms), nnode (nodes per snapshot), Ts (static end tension, N).
snap = stem.".snapshots.dat"
if (!readable(snap)) {
    exit error sprintf("%s not found: run the case with &output gnuplot = .true. (stem='%s')", snap, stem)
}
# The time of each block is only in its comment line '# t = <time>'.
snaptimes = system(sprintf("sed -n 's/^# t = *//p' '%s'", snap))
nsnap = words(snaptimes)
if (nsnap == 0) {
    exit error sprintf("%s holds no snapshot (no '# t = ' block): the run wrote no snapshot text", snap)
}
t_ms(i) = 1000.0 * word(snaptimes, i + 1)
stats [*:*][*:*] snap index 0 using 4 nooutput
nnode = STATS_records
Ts = STATS_max
if (!exists("title")) { title = sprintf("%s, static tension %.0f kN", casename, Ts / 1000) }

# Colour scale: one band per snapshot when they are evenly spaced, a continuous scale otherwise.
dt_snap = nsnap > 1 ? (t_ms(nsnap - 1) - t_ms(0)) / (nsnap - 1) : 10.0
_even = 1
if (nsnap > 2) {
    do for [i = 1:nsnap - 1] {
        if (abs(t_ms(i) - t_ms(i - 1) - dt_snap) > 1e-3 * dt_snap) { _even = 0 }
    }
}
if (_even) {
    set palette maxcolors nsnap
    set cbrange [t_ms(0) - dt_snap / 2 : t_ms(nsnap - 1) + dt_snap / 2]
    set cbtics t_ms(0), (nsnap > 9 ? 2 : 1) * dt_snap out nomirror
    set mcbtics (nsnap > 9 ? 2 : 1)
} else {
    set palette maxcolors 0
    set cbrange [t_ms(0) : t_ms(nsnap - 1)]
    set cbtics auto out nomirror
}
set cblabel (_even && nsnap > 1 ? sprintf("time of the snapshot [ms] (every %.0f ms)", dt_snap) : "time of the snapshot [ms]")
set colorbox vertical default
