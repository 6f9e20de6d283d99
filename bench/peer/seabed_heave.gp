# Fairlead tension of the seabed heave (seabed_heave.py), last two periods, 320 segments.
# Run from bench/peer (writes seabed_heave.png here).
# Usage: python3 seabed_heave.py --tsv /tmp/seabed_heave; gnuplot -e "dir='/tmp/seabed_heave'" seabed_heave.gp
if (!exists("dir")) dir = '/tmp/seabed_heave'
set terminal pngcairo size 900,420 font ',10'
set output 'seabed_heave.png'
set xlabel 't (s)'
set ylabel 'fairlead tension (kN)'
set xrange [24:48]
set key top left
set grid
plot dir.'/moordyn_80.tsv' every ::1 using 1:($2/1e3) with lines lw 1 lc rgb '#b0b0b0' title 'MoorDyn 2.7.2, 80 segments', \
     dir.'/moordyn_320.tsv' every ::1 using 1:($2/1e3) with lines lw 1 lc rgb '#e07020' title 'MoorDyn, 320 segments', \
     dir.'/xcable_320.tsv' every ::1 using 1:($2/1e3) with lines lw 2 lc rgb '#2050c0' title 'xcable, 320 segments'
