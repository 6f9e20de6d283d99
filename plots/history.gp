# Read the time history of the run 'stem'. Defines: hist (file name), Ts (static end tension, N),
# t_end_ms (last time, ms), and the default title.
hist = stem.".history.dat"
if (!readable(hist)) {
    exit error sprintf("%s not found: run the case with &output gnuplot = .true. (stem='%s')", hist, stem)
}
stats [*:*][*:*] hist using 1:3 nooutput
if (STATS_records < 2) {
    exit error sprintf("%s holds fewer than two time steps", hist)
}
t_end_ms = 1000 * STATS_max_x
stats [*:*][*:*] hist every ::0::0 using 3 nooutput
Ts = STATS_max
if (!exists("title")) { title = sprintf("%s, static tension %.0f kN", casename, Ts / 1000) }
set xrange [0:t_end_ms]
set xlabel "time after the release starts, t [ms]"
# A tic every 10 ms (the snapshot interval of the paper's cases) when that gives at most 20 tics.
if (t_end_ms <= 200) { set xtics 10 out; set mxtics 2 } else { set xtics auto out; set mxtics default }
