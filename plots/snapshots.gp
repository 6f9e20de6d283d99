# Read the snapshot file of the run 'stem' and set the colour scale keyed to the snapshot time.
# Defines: snap (file name), nsnap (number of snapshots), tval(i) (time of snapshot i = 0 .. nsnap-1
# in the figure's unit tunit: ms up to 1 s, s beyond), t_ms(i) (the same in ms), stride (every
# stride-th snapshot is drawn: at most maxlines lines), nnode (output points per snapshot, the
# break node counted twice), Ts (largest tension at t = 0, N), Lcab (unstretched length, m),
# npieces (1, or 2 for a cable broken inside), ends (a data source of the end points of every
# piece, see below), and the default title.
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
t_s(i) = real(word(snaptimes, int(i) + 1))
t_ms(i) = 1000.0 * t_s(i)
tfac = tfac_for(t_s(nsnap - 1))
tunit = tunit_for(t_s(nsnap - 1))
tval(i) = tfac * t_s(i)
stats [*:*][*:*] snap index 0 using 1:4 nooutput
nnode = STATS_records
Ts = STATS_max_y
Lcab = STATS_max_x
# Pieces: blank lines followed by data inside the first block, plus one.
npieces = 1 + int(system(sprintf("awk '/^# t = / { n++; next } n > 1 { exit } n == 1 { if (NF == 0) gap = 1; else if (gap) { b++; gap = 0 } } END { print b + 0 }' '%s'", snap)))
if (!exists("title")) { title = sprintf("%s: largest tension at t = 0 %.3g kN", casename, Ts / 1000) }

# Draw every stride-th snapshot, at most maxlines of them (all of the paper's 10 ms snapshots),
# preferring a stride whose time step is a round number (1, 2, 2.5 or 5 times a power of ten)
# and a whole number of snapshot intervals.
_dt = nsnap > 1 ? (t_s(nsnap - 1) - t_s(0)) / (nsnap - 1) : 1.0
_target = nsnap > 1 ? (t_s(nsnap - 1) - t_s(0)) / (maxlines - 1) : 1.0
_p10 = _target > 0 ? 10.0**floor(log10(_target)) : 1.0
stride = nsnap <= maxlines ? 1 : int(ceil((nsnap - 1.0) / (maxlines - 1)))
_found = nsnap <= maxlines || _dt <= 0
_round = "1 2 2.5 5 10 20 25 50 100"
do for [_k = 1:words(_round)] {
    _nice = real(word(_round, _k)) * _p10
    _m = _nice / _dt
    if (!_found && _nice >= _target * (1 - 1e-9) && abs(_m - floor(_m + 0.5)) < 1e-6 * _m) {
        stride = int(floor(_m + 0.5)); _found = 1
    }
}
ndrawn = int((nsnap - 1) / stride) + 1
drawn(i) = int(i) % stride == 0

# End points of every piece of every snapshot, one line each:
#   snapshot-index  kind  s x z tension strain u v shear curvature
# kind 0: end a (s = 0), 1: end b (s = L), 2: a new end at a break inside the cable.
ends = sprintf("< awk -v L=%.10g 'function flush() { if (n) { print k, code(fs), first; print k, code(ls), last }; n = 0 } \
  function code(s) { return s < 1e-9 * L ? 0 : (s > L * (1 - 1e-9) ? 1 : 2) } \
  /^# t = / { flush(); k++; next } /^#/ { next } NF == 0 { flush(); next } \
  { if (!n) { first = $0; fs = $1 } last = $0; ls = $1; n++ } END { flush() }' k=-1 '%s'", Lcab, snap)

# Colour scale: one band per drawn snapshot when they are evenly spaced, a continuous scale otherwise.
dt_snap = nsnap > 1 ? (tval(nsnap - 1) - tval(0)) / (nsnap - 1) : 10.0
_even = 1
if (nsnap > 2) {
    do for [i = 1:nsnap - 1] {
        if (abs(tval(i) - tval(i - 1) - dt_snap) > 1e-3 * dt_snap) { _even = 0 }
    }
}
dt_drawn = stride * dt_snap
tlast_drawn = tval((ndrawn - 1) * stride)
if (_even && ndrawn > 1) {
    set palette maxcolors ndrawn
    set cbrange [tval(0) - dt_drawn / 2 : tlast_drawn + dt_drawn / 2]
    set cbtics tval(0), (ndrawn > 9 ? 2 : 1) * dt_drawn out nomirror
    set mcbtics (ndrawn > 9 ? 2 : 1)
    set cblabel sprintf("time of the snapshot [%s] (every %g %s)", tunit, dt_drawn, tunit)
} else {
    set palette maxcolors 0
    set cbrange [tval(0) : tval(nsnap - 1) > tval(0) ? tval(nsnap - 1) : tval(0) + 1]
    set cbtics auto out nomirror
    set cblabel sprintf("time of the snapshot [%s]", tunit)
}
set colorbox vertical default
