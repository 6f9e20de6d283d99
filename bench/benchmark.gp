# Work-precision figure of the xcable benchmark: error against wall time
# (whole process, one thread), from docs/benchmark.dat (written by `make bench`).
#   gnuplot bench/benchmark.gp   ->  docs/benchmark.png
# Data blocks (gnuplot index): 0-2 fast_180kN grids 31..961 at Courant 0.5, 1, 2;
# 3 its time steps at 241 nodes; 4 its target configuration; 5 its grids between
# at Courant 1; 6-11 the same for slow_315kN.
# Columns: nodes courant wall |speed error| |drop error| (ms) mean|dT|/Ts max|dT|/Ts reached_t_end
set terminal pngcairo size 1400,1050 font ',11'
set output 'docs/benchmark.png'
set multiplot layout 2,2 title "xcable work-precision benchmark: error against wall time (whole process, one thread)\nopen black squares: run stopped before t_{end} (buckling at the fixed end after the window measured)"
set logscale xy
set grid
set key bottom left box opaque font ',10'
set xlabel 'wall time (s)'
set xrange [0.005:20]
failed(y) = (column(8) == 0 ? y : NaN)

set title 'fast\_180kN: peak breaking-end speed (while the fixed end is in tension)'
set ylabel '|v_{peak} - v_{theory}| / v_{theory}'
set yrange [1e-7:0.1]
set arrow 1 from 0.005,1e-3 to 0.1,1e-3 nohead dt 2 lw 2 lc rgb 'dark-green'
set arrow 2 from 0.1,1e-7 to 0.1,1e-3 nohead dt 2 lw 2 lc rgb 'dark-green'
set label 1 'target' at 0.006,1.5e-3 tc rgb 'dark-green'
set label 2 'MoorDyn-like, 400 segments' at 0.42,0.032 left
plot 'docs/benchmark.dat' index 0 using 3:4 with linespoints pt 6 title 'Courant 0.5, 31..961 nodes', \
     '' index 1 using 3:4 with linespoints pt 7 title 'Courant 1, 31..961 nodes', \
     '' index 1 using 3:4:(sprintf('%d', $1)) with labels offset char 0,0.9 font ',9' notitle, \
     '' index 2 using 3:4 with linespoints pt 4 title 'Courant 2, 31..961 nodes', \
     '' index 5 using 3:4 with points pt 9 ps 1.2 title 'Courant 1, 91..361 nodes', \
     '' index 3 using 3:4 with points pt 2 ps 1.3 title '241 nodes, Courant 0.25..4', \
     '' index 0:2 using 3:(failed($4)) with points pt 4 ps 2 lc rgb 'black' notitle, \
     '' index 4 using 3:4 with points pt 3 ps 3 lw 2 lc rgb 'red' title 'target configuration', \
     '-' using 1:2 with points pt 5 ps 2 lc rgb 'black' title 'MoorDyn-like'
0.5 0.02
e
unset arrow; unset label

set title 'fast\_180kN: time of the 1 % drop of the fixed-end tension'
set ylabel '|t_{1%} - t_{theory}| (ms)'
set yrange [1e-4:100]
set arrow 1 from 0.005,0.05 to 0.1,0.05 nohead dt 2 lw 2 lc rgb 'dark-green'
set arrow 2 from 0.1,1e-4 to 0.1,0.05 nohead dt 2 lw 2 lc rgb 'dark-green'
set label 1 'target' at 0.006,0.075 tc rgb 'dark-green'
set label 2 'MoorDyn-like' at 0.55,0.35 left
plot 'docs/benchmark.dat' index 0 using 3:5 with linespoints pt 6 title 'Courant 0.5', \
     '' index 1 using 3:5 with linespoints pt 7 title 'Courant 1', \
     '' index 1 using 3:5:(sprintf('%d', $1)) with labels offset char 0,0.9 font ',9' notitle, \
     '' index 2 using 3:5 with linespoints pt 4 title 'Courant 2', \
     '' index 5 using 3:5 with points pt 9 ps 1.2 title 'Courant 1, 91..361 nodes', \
     '' index 3 using 3:5 with points pt 2 ps 1.3 title '241 nodes, Courant 0.25..4', \
     '' index 0:2 using 3:(failed($5)) with points pt 4 ps 2 lc rgb 'black' notitle, \
     '' index 4 using 3:5 with points pt 3 ps 3 lw 2 lc rgb 'red' title 'target configuration', \
     '-' using 1:2 with points pt 5 ps 2 lc rgb 'black' title 'MoorDyn-like'
0.5 0.35
e
unset arrow; unset label

set title 'slow\_315kN: tension field (10 ms snapshots while the fixed end is in tension)'
set ylabel 'mean |T - T_{ref}| / T_s'
set yrange [1e-7:0.1]
set arrow 1 from 0.005,5e-3 to 0.1,5e-3 nohead dt 2 lw 2 lc rgb 'dark-green'
set arrow 2 from 0.1,1e-7 to 0.1,5e-3 nohead dt 2 lw 2 lc rgb 'dark-green'
set label 1 'target' at 0.006,7.5e-3 tc rgb 'dark-green'
plot 'docs/benchmark.dat' index 6 using 3:6 with linespoints pt 6 title 'Courant 0.5', \
     '' index 7 using 3:6 with linespoints pt 7 title 'Courant 1', \
     '' index 7 using 3:6:(sprintf('%d', $1)) with labels offset char 0,0.9 font ',9' notitle, \
     '' index 8 using 3:6 with linespoints pt 4 title 'Courant 2', \
     '' index 11 using 3:6 with points pt 9 ps 1.2 title 'Courant 1, 91..361 nodes', \
     '' index 9 using 3:6 with points pt 2 ps 1.3 title '241 nodes, Courant 0.25..4', \
     '' index 6:8 using 3:(failed($6)) with points pt 4 ps 2 lc rgb 'black' notitle, \
     '' index 11 using 3:(failed($6)) with points pt 4 ps 2 lc rgb 'black' notitle, \
     '' index 10 using 3:6 with points pt 3 ps 3 lw 2 lc rgb 'red' title 'target configuration'
unset arrow; unset label

set title 'fast\_180kN: tension field (10 ms snapshots while the fixed end is in tension)'
set ylabel 'mean |T - T_{ref}| / T_s'
set yrange [1e-6:0.1]
plot 'docs/benchmark.dat' index 0 using 3:6 with linespoints pt 6 title 'Courant 0.5', \
     '' index 1 using 3:6 with linespoints pt 7 title 'Courant 1', \
     '' index 1 using 3:6:(sprintf('%d', $1)) with labels offset char 0,0.9 font ',9' notitle, \
     '' index 2 using 3:6 with linespoints pt 4 title 'Courant 2', \
     '' index 5 using 3:6 with points pt 9 ps 1.2 title 'Courant 1, 91..361 nodes', \
     '' index 3 using 3:6 with points pt 2 ps 1.3 title '241 nodes, Courant 0.25..4', \
     '' index 0:2 using 3:(failed($6)) with points pt 4 ps 2 lc rgb 'black' notitle, \
     '' index 4 using 3:6 with points pt 3 ps 3 lw 2 lc rgb 'red' title 'target configuration'
unset multiplot
