# Helper of plots/motion.gp (loaded, not run): the motion of a line that stays on one vertical
# (a hanging line moved up and down at its top), as the heights of its two ends against time,
# from the position at rest, and the stretch of the line (the change of the distance between them;
# below the dotted line the ends are closer than the unstretched length: the line is slack).
# Uses the snapshots: the time resolution is the snapshot interval.
_heights = sprintf("< awk '/^# t = / { if (n) print t, za, zb; t = $4; n = 0; next } /^#/ || NF == 0 { next } { if (!n++) za = $3; zb = $3 } END { if (n) print t, za, zb }' '%s'", snap)
stats [*:*][*:*] _heights every ::0::0 using 2 nooutput
_za0 = STATS_min
stats [*:*][*:*] _heights every ::0::0 using 3 nooutput
_zb0 = STATS_min
fig_w = 1100; fig_h = 650
load plotdir."/terminal.gp"
set title sprintf("Motion of the cable: it stays on the vertical through end a; heights of its ends from their positions at rest\n%s", title)
set xlabel sprintf("time, t [%s]", tunit)
set ylabel "vertical displacement from rest [m]  (up: positive)"
set xrange [tval(0) : tval(nsnap - 1)]
set xzeroaxis lt -1 lw 0.5
set bmargin 7
set key at screen 0.5, screen 0.015 center bottom maxrows 2 box samplen 2 spacing 1.1 width 2
unset colorbox
plot _heights using (tfac * $1):($2 - _za0) with lines lw 2 lc rgb end_colour("end_a") title label_a, \
     ''       using (tfac * $1):($3 - _zb0) with lines lw 2 lc rgb end_colour("end_b") title label_b, \
     ''       using (tfac * $1):(($2 - $3) - (_za0 - _zb0)) with lines lw 1.5 dt 2 lc rgb '#404040' \
              title "stretch of the line (distance a–b minus that at rest)", \
     (Lcab - (_za0 - _zb0)) with lines lw 1.5 dt 3 lc rgb '#7b3294' \
              title "distance a–b = unstretched length: slack below"
unset output
