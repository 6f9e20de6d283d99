# Motion of a 3-D run (&numerics model = '3d'), one line per snapshot in perspective, x, y and z
# drawn to the same scale (z up), with the shadow of every line on the floor of the box.
#   gnuplot -e "stem='results/sway3d'; out='motion3d.png'" plots/motion3d.gp
# Optional: title='...', label_a, label_b, view_rot_x, view_rot_z (the view angles in degrees,
# default 62 and 32). Variables: see plots/common.gp. The snapshot text of a 3-D run has y in
# column 10 (docs/user/results.md, Figures); a planar run's text has no y and is refused with a message.
_lastslash(p, i) = i < 1 ? 0 : (p[i:i] eq "/" ? i : _lastslash(p, i - 1))
if (!exists("plotdir")) { plotdir = _lastslash(ARG0, strlen(ARG0)) ? ARG0[1:_lastslash(ARG0, strlen(ARG0)) - 1] : "." }
load plotdir."/common.gp"
load plotdir."/snapshots.gp"
load plotdir."/columns3d.gp"
if (!exists("view_rot_x")) { view_rot_x = 62 }
if (!exists("view_rot_z")) { view_rot_z = 32 }

stats [*:*][*:*] snap using 2:10 nooutput
_x0 = STATS_min_x; _x1 = STATS_max_x; _y0 = STATS_min_y; _y1 = STATS_max_y
stats [*:*] snap using 3 nooutput
_z0 = STATS_min; _z1 = STATS_max
# A cube around the motion (equal scales): each axis spans the largest extent, centred.
_ext = _x1 - _x0
_ext = _y1 - _y0 > _ext ? _y1 - _y0 : _ext
_ext = _z1 - _z0 > _ext ? _z1 - _z0 : _ext
_ext = _ext > 0 ? 1.08 * _ext : 1.0
set xrange [0.5 * (_x0 + _x1) - 0.5 * _ext : 0.5 * (_x0 + _x1) + 0.5 * _ext]
set yrange [0.5 * (_y0 + _y1) - 0.5 * _ext : 0.5 * (_y0 + _y1) + 0.5 * _ext]
zfloor = 0.5 * (_z0 + _z1) - 0.5 * _ext
set zrange [zfloor : 0.5 * (_z0 + _z1) + 0.5 * _ext]

fig_w = 1000; fig_h = 860
load plotdir."/terminal.gp"
set title sprintf("Motion of the cable in 3-D (drawn to scale, z up; grey: shadows on the floor)\n%s", title)
set xlabel "x [m]"
set ylabel "y [m]"
set zlabel "z [m]" rotate parallel
set view view_rot_x, view_rot_z
set view equal xyz
set xyplane at zfloor
set grid xtics ytics ztics lc rgb '#d0d0d0' lw 0.5
@corner_key
splot for [i = 0:nsnap - 1:stride] snap index i using 2:10:(zfloor) with lines lw 2 lc rgb '#9a9a9a' notitle, \
      for [i = 0:nsnap - 1:stride] snap index i using 2:10:3:(tval(i)) with lines lw 1.5 lc palette notitle, \
      ends using 4:12:(drawn($1) && $2 == 0 ? $5 : NaN):(tval($1)) with points pt 5 ps 0.8 lc palette notitle, \
      ends using 4:12:(drawn($1) && $2 == 1 ? $5 : NaN):(tval($1)) with points pt 7 ps 0.9 lc palette notitle, \
      keyentry with points pt 5 ps 0.8 lc rgb '#404040' title label_a, \
      keyentry with points pt 7 ps 0.9 lc rgb '#404040' title label_b
unset output
