# Work-precision figure of the xcable benchmark: error against CPU time
# (user + system of the whole process, one thread) for the box scheme and the rod (averaged and
# lumped mass), from docs/measurements/data/benchmark.dat (written by `make bench`).
#   gnuplot bench/benchmark.gp   ->  docs/measurements/benchmark.png
# Data blocks (gnuplot index): case base (fast_180kN 0, slow_315kN 15) + variant
# (box 0, rod averaged 5, rod lumped 10) + series (0, 1, 2: grids at Courant
# 0.5, 1, 2; 3: grids between at Courant 1; 4: the target configuration);
# 30, 31: the box time steps at 241 nodes; 32-35: the rod's theta rows.
# Columns: 1 nodes, 2 courant, 3 wall, 4 cpu, 5 |peak speed error|, 6 |plateau
# speed error|, 7 |1% drop error| (ms), 8 mean|dT|/Ts, 9 max|dT|/Ts,
# 10 reached t_end (1/0), 11 instructions, 12 theta.
set terminal pngcairo size 1500,1650 font ',11'
set output 'docs/measurements/benchmark.png'
array colour[3] = ['#1f4e9c', '#c0282d', '#2a9a3a']
array variant[3] = ['box', 'rod, averaged mass', 'rod, lumped mass']
array courant_pt[3] = [8, 7, 4]
array courant_dt[3] = [3, 1, 2]
array courant_name[3] = ['Courant 0.5', 'Courant 1', 'Courant 2']
block(c, v, k) = 15*c + 5*v + k
failed(y) = (column(10) == 0 ? y : NaN)

set multiplot layout 3,2 title "xcable work-precision benchmark: error against CPU time (user + system, whole process, one thread; a shared, loaded machine)\nlines: grids 31 (box) or 61 (rod) to 961 nodes at fixed Courant numbers; small dots: 91..361 nodes at Courant 1; large crosses: the target configurations; black squares: stopped before t_{end}"
set logscale xy
set grid
set xlabel 'CPU time of the whole process (s)'
set format y '10^{%T}'

# plot_panel(c, column): every variant's ladders, grids between, target, failures
plot_cmd = "plot for [v=0:2] for [k=0:2] 'docs/measurements/data/benchmark.dat' index block(C, v, k) using 4:COL with linespoints lw 1.5 pt courant_pt[k+1] dt courant_dt[k+1] lc rgb colour[v+1] notitle, \
   for [v=0:2] '' index block(C, v, 3) using 4:COL with points pt 7 ps 0.6 lc rgb colour[v+1] notitle, \
   for [v=0:2] '' index block(C, v, 4) using 4:COL with points pt 2 ps 3.5 lw 2.5 lc rgb colour[v+1] notitle, \
   for [v=0:2] for [k=0:3] '' index block(C, v, k) using 4:(failed(column(COL))) with points pt 4 ps 2 lc rgb 'black' notitle, \
   for [v=1:3] NaN with lines lw 3 lc rgb colour[v] title variant[v], \
   for [k=1:3] NaN with linespoints pt courant_pt[k] dt courant_dt[k] lc rgb 'gray40' title courant_name[k]"

unset key
C = 0; COL = 5
set title 'fast\_180kN: peak breaking-end speed (while the fixed end is in tension)'
set ylabel '|v_{peak} - v_{theory}| / v_{theory}'
set arrow 1 from graph 0, first 1e-3 to graph 1, first 1e-3 nohead dt 2 lw 2 lc rgb 'dark-green'
@plot_cmd
unset arrow

C = 0; COL = 6
set title 'fast\_180kN: plateau speed (mean after the ramp, fixed end in tension)'
set ylabel '|v_{mean} - v_{theory}| / v_{theory}'
set arrow 1 from graph 0, first 1e-3 to graph 1, first 1e-3 nohead dt 2 lw 2 lc rgb 'dark-green'
@plot_cmd
unset arrow

C = 0; COL = 7
set title 'fast\_180kN: time of the 1 % drop of the fixed-end tension'
set ylabel '|t_{1%} - t_{theory}| (ms)'
set arrow 1 from graph 0, first 0.05 to graph 1, first 0.05 nohead dt 2 lw 2 lc rgb 'dark-green'
@plot_cmd
unset arrow

C = 0; COL = 8
set key bottom left box opaque font ',10' spacing 1.1
set title 'fast\_180kN: tension field (10 ms snapshots, fixed end in tension)'
set ylabel 'mean |T - T_{ref}| / T_s'
set arrow 1 from graph 0, first 5e-3 to graph 1, first 5e-3 nohead dt 2 lw 2 lc rgb 'dark-green'
@plot_cmd
unset arrow

unset key
C = 1; COL = 8
set title 'slow\_315kN: tension field (10 ms snapshots, fixed end in tension)'
set ylabel 'mean |T - T_{ref}| / T_s'
set arrow 1 from graph 0, first 5e-3 to graph 1, first 5e-3 nohead dt 2 lw 2 lc rgb 'dark-green'
@plot_cmd
unset arrow

C = 1; COL = 7
set title 'slow\_315kN: time of the 1 % drop of the fixed-end tension'
set ylabel '|t_{1%} - t_{theory}| (ms)'
set arrow 1 from graph 0, first 0.05 to graph 1, first 0.05 nohead dt 2 lw 2 lc rgb 'dark-green'
@plot_cmd
unset arrow
unset multiplot
