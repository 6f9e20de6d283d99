# Shared definitions of the xcable figure scripts; loaded by each of them, not run on its own.
#
# Variables the caller may set (gnuplot -e "..."):
#   stem     run output without extension, e.g. 'results/slow_315kN' (required)
#   out      output file; '.png' gives pngcairo, '.pdf' gives pdfcairo (required for a whole figure)
#   title    description of the case used in the title (default: the stem's basename and the
#            tension at end a at t = 0)
#   label_a, label_b   names of the two ends in the keys (default 'end a (s = 0)', 'end b (s = L)';
#            plots/draw.sh gives the kind of each end, e.g. 'end a (fixed)', 'end b (200 kg mass)')
#   maxlines most snapshot lines drawn in one panel (default 20; beyond it every n-th snapshot)
# Set by a script that draws panels into its own multiplot (plots/pair.gp), never by hand:
#   panel  when it exists, the script draws one panel only: no terminal, no output, title = 'title'
#   vexag  vertical exaggeration of the motion panels (1, 10 or 100; default: chosen from the data)

set encoding utf8

# Last component of a path (no external command).
_lastslash(p, i) = i < 1 ? 0 : (p[i:i] eq "/" ? i : _lastslash(p, i - 1))
basename(p) = p[_lastslash(p, strlen(p)) + 1:]
# True when the file exists and can be read.
readable(f) = system(sprintf("test -r '%s' && echo yes || echo no", f)) eq "yes"

if (!exists("stem")) {
    exit error "no run given: call with gnuplot -e \"stem='results/slow_315kN'; out='motion.png'\" ".ARG0
}
casename = basename(stem)
if (!exists("label_a")) { label_a = "end a (s = 0)" }
if (!exists("label_b")) { label_b = "end b (s = L)" }
if (!exists("maxlines")) { maxlines = 20 }

# Units that suit the run: time in ms for runs up to 1 s, in s beyond; forces in kN from 2 kN up,
# in N below; energies in kJ from 2 kJ up, in J below. Each gives (factor, unit name).
tfac_for(tmax) = tmax <= 1.0 ? 1000.0 : 1.0
tunit_for(tmax) = tmax <= 1.0 ? "ms" : "s"
ffac_for(fmax) = fmax >= 2000.0 ? 1e-3 : 1.0
funit_for(fmax) = fmax >= 2000.0 ? "kN" : "N"
efac_for(emax) = emax >= 2000.0 ? 1e-3 : 1.0
eunit_for(emax) = emax >= 2000.0 ? "kJ" : "J"
amax(a, b) = abs(a) > abs(b) ? abs(a) : abs(b)
# A time in the unit of the figure, with as many decimals as the unit needs.
tfmt(t, unit) = unit eq "ms" ? sprintf("%.0f ms", 1000.0 * t) : sprintf("%.3g s", t)

# Vertical exaggeration of a motion figure with horizontal extent xext and vertical extent zext
# (m): the paper's 100 (z in cm, "1 cm drawn as 1 m") when the exaggerated height stays within
# 3/4 of the width, else 10, else none (a swing, a hanging line: true shape).
vexag_for(xext, zext) = 100 * zext <= 0.75 * xext ? 100 : (10 * zext <= 0.75 * xext ? 10 : 1)

# Axis range [_lo, _hi] around [a, b], rounded outwards to a round step.
_unit(r) = 10.0**floor(log10(r))
_step(r) = r / _unit(r) < 2.5 ? _unit(r) / 4 : (r / _unit(r) < 5 ? _unit(r) / 2 : _unit(r))
_lo(a, b) = floor(a / _step(b - a)) * _step(b - a)
_hi(a, b) = ceil(b / _step(b - a)) * _step(b - a)

# Names of the ends in the history header (end_a, end_b, break_a, break_b), colours and symbols.
end_name(n) = n eq "end_a" ? label_a : (n eq "end_b" ? label_b : \
              (n eq "break_a" ? "break, side of end a" : (n eq "break_b" ? "break, side of end b" : n)))
# A network's ends line_k_a and line_k_b: a colour per line (ColorBrewer's Paired, dark for
# end a, light for end b; lines 7 and 8 grey and black).
_line_dark(k) = k == 1 ? 0x1f78b4 : k == 2 ? 0xe31a1c : k == 3 ? 0x33a02c : k == 4 ? 0xff7f00 : \
                k == 5 ? 0x6a3d9a : k == 6 ? 0xb15928 : k == 7 ? 0x505050 : 0x000000
_line_light(k) = k == 1 ? 0x7fb2d9 : k == 2 ? 0xf08a8b : k == 3 ? 0x8acd72 : k == 4 ? 0xfdb462 : \
                 k == 5 ? 0xb39bd0 : k == 6 ? 0xd9a066 : k == 7 ? 0xa0a0a0 : 0x808080
_is_line_end(n) = strlen(n) == 8 && n[1:5] eq "line_"
end_colour(n) = n eq "end_a" ? 0x1f78b4 : (n eq "end_b" ? 0xd7301f : (n eq "break_a" ? 0x33a02c : \
                (_is_line_end(n) ? (n[8:8] eq "a" ? _line_dark(int(n[6:6])) : _line_light(int(n[6:6]))) : 0xe08a00)))

# One palette for the snapshot time, from dark blue (t = 0, the static state) through green and
# orange to dark red (the last snapshot); every colour dark enough to show on white.
set palette defined (0 '#1a1a80', 1 '#1f78b4', 2 '#1b9e77', 3 '#6a9a00', 4 '#e08a00', 5 '#d7301f', 6 '#7f0000')

set grid lc rgb '#d0d0d0' lw 0.5
set border lw 1

# The key of a figure, in one row in the bottom margin below the x label: clear of the data and of
# the title whatever the scene (test/test_figures.sh draws every figure with and without its key
# and fails when the key covers anything).
bottom_key = "set key at screen 0.5, screen 0.01 center bottom horizontal maxrows 1 box opaque samplen 1 spacing 1.1 width 1; set bmargin 5.5"
# In the top left corner of the figure, for a 3-D view (its margins are not the plot's to set).
corner_key = "set key at screen 0.01, screen 0.99 left top Left reverse box opaque samplen 1 spacing 1.1 width 1"
