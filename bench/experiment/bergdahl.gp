# Bergdahl et al. (2016): xcable against the measured top tension.
# Data: bergdahl.py wave --tsv data and bergdahl.py table --tsv data (run from bench/experiment):
#   gnuplot bergdahl.gp   ->  bergdahl_wave.png, bergdahl_table.png
set terminal pngcairo size 1100,760 font ',11'
set datafile separator '\t'
set output 'bergdahl_wave.png'
set multiplot layout 2,1 title "Lindahl's chain (Bergdahl et al. 2016), R = 0.2 m: top tension, the last three measured cycles"
set xlabel 'time on the measured record (s)'
set ylabel 'tension (N)'
set key top left Left reverse
set grid
set title 'T = 1.25 s'
plot 'data/bergdahl_wave_T1p25.tsv' using 1:2 with lines lw 1.5 lc rgb '#c0392b' title 'measured', \
     '' using 1:3 with lines lw 1.5 lc rgb 'black' title 'xcable'
set title 'T = 3.5 s'
plot 'data/bergdahl_wave_T3p50.tsv' using 1:2 with lines lw 1.5 lc rgb '#c0392b' title 'measured', \
     '' using 1:3 with lines lw 1.5 lc rgb 'black' title 'xcable'
unset multiplot

set output 'bergdahl_table.png'
set terminal pngcairo size 700,640 font ',11'
set title 'Mean cycle maximum of the top tension: xcable against the article'
set xlabel 'measured (N)'
set ylabel 'xcable (N)'
set key top left Left reverse
set size square
set xrange [20:85]
set yrange [20:85]
plot x with lines dt 2 lc rgb 'gray' title 'equal', \
     'data/bergdahl_table.tsv' using 3:4 with points pt 7 ps 1.2 lc rgb 'black' title 'xcable, one period and radius'
