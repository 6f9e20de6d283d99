# Shared definitions of the xcable figure scripts; loaded by each of them, not run on its own.
#
# Variables the caller may set (gnuplot -e "..."):
#   stem   run output without extension, e.g. 'results/slow_315kN' (required)
#   out    output file; '.png' gives pngcairo, '.pdf' gives pdfcairo (required for a whole figure)
#   title  description of the case used in the title (default: the stem's basename and the static tension)
# Set by a script that draws panels into its own multiplot (plots/pair.gp), never by hand:
#   panel  when it exists, the script draws one panel only: no terminal, no output, title = 'title'

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

# One palette for the snapshot time, from dark blue (t = 0, the static state) through green and
# orange to dark red (the last snapshot); every colour dark enough to show on white.
set palette defined (0 '#1a1a80', 1 '#1f78b4', 2 '#1b9e77', 3 '#6a9a00', 4 '#e08a00', 5 '#d7301f', 6 '#7f0000')

set grid lc rgb '#d0d0d0' lw 0.5
set border lw 1
