# Read the time history of the run 'stem'. Defines: hist (file name), Ts (tension at end a at
# t = 0, N), t_end_s (last time, s), tfac and tunit (the time unit of the figure: ms up to 1 s,
# s beyond), the time axis, and the default title.
hist = stem.".history.dat"
if (!readable(hist)) {
    exit error sprintf("%s not found: run the case with &output gnuplot = .true. (stem='%s')", hist, stem)
}
stats [*:*][*:*] hist using 1:3 nooutput
if (STATS_records < 2) {
    exit error sprintf("%s holds fewer than two time steps", hist)
}
t_end_s = STATS_max_x
tfac = tfac_for(t_end_s)
tunit = tunit_for(t_end_s)
t_end_ms = 1000 * t_end_s
stats [*:*][*:*] hist every ::0::0 using 3 nooutput
Ts = STATS_max
if (!exists("title")) { title = sprintf("%s: tension at end a at t = 0 %.3g kN", casename, Ts / 1000) }
set xrange [0:tfac * t_end_s]
set xlabel sprintf("time, t [%s]", tunit)
# A tic every 10 ms (the snapshot interval of the paper's cases) when that gives at most 20 tics.
if (tunit eq "ms" && t_end_ms <= 200) { set xtics 10 out; set mxtics 2 } else { set xtics auto out; set mxtics default }

# Columns of the ends, from the header: '<end>:speed[m/s] <end>:tension[N] <end>:force[N]' for
# each end. endcols = "end_a 12 end_b 15 ..." (name, column of its speed); nends of them.
endcols = system(sprintf("sed -n '1s/^# columns: *//p' '%s' | tr ' ' '\\n' | awk '/:speed/ { n = $0; sub(/:speed.*/, \"\", n); printf \"%%s %%d \", n, NR }'", hist))
nends = words(endcols) / 2
end_label(j) = word(endcols, 2 * j - 1)
speed_col(j) = int(word(endcols, 2 * j))
