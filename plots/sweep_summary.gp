# Summary figure of a sweep, from OUTDIR/summary.csv (batch/sweep-collect).
#
#   gnuplot -e "sweep='OUTDIR'" plots/sweep_summary.gp
#   gnuplot -e "sweep='OUTDIR'; x='material%p(2)'; y='front_arrival_time'; series='static%tension'" plots/sweep_summary.gp
#
# Draws column y against column x, one line per value of column series (none
# if the sweep lacks that column), from the complete cases only; the title
# counts the cases left out. Writes OUTDIR/sweep_summary.png (or out='file.png').
# Defaults: x = 'static%tension', y = 'peak_end_speed', series = 'rupture%t_break'.
# Several complete cases at the same x and series value (a third swept
# variable) are averaged: give that variable as series, or sweep it separately.

if (!exists("sweep")) {
    print "sweep_summary.gp: give the sweep directory: gnuplot -e \"sweep='OUTDIR'\" plots/sweep_summary.gp"
    exit status 2
}
if (!exists("x")) x = 'static%tension'
if (!exists("y")) y = 'peak_end_speed'
if (!exists("series")) series = 'rupture%t_break'
if (!exists("out")) out = sweep.'/sweep_summary.png'
csv = sweep.'/summary.csv'

# Column numbers from the header line (0 when absent).
column_of(name) = int(system(sprintf("awk -F, -v n='%s' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == n) { print i; exit } \
                                       print 0; exit }' '%s'", name, csv)))
xc = column_of(x)
yc = column_of(y)
sc = column_of(series)
stc = column_of('status')
if (stc == 0) { print sprintf("sweep_summary.gp: %s: no status column (not written by batch/sweep-collect?)", csv); exit status 2 }
if (xc == 0) { print sprintf("sweep_summary.gp: %s: no column '%s'", csv, x); exit status 2 }
if (yc == 0) { print sprintf("sweep_summary.gp: %s: no column '%s'", csv, y); exit status 2 }

# Distinct values of the series column, in order of appearance; counts of cases.
series_values = (sc > 0) ? system(sprintf("awk -F, -v c=%d 'NR > 1 && !seen[$c]++ { printf \"%%s \", $c }' '%s'", sc, csv)) : "all"
cases = int(system(sprintf("awk 'END { print NR - 1 }' '%s'", csv)))
left_out = int(system(sprintf("awk -F, -v c=%d 'NR > 1 && $c != \"complete\" { n++ } END { print n + 0 }' '%s'", stc, csv)))

units(name) = (name eq 'static%tension') ? ' (N)' : (name eq 'rupture%t_break') ? ' (s)' : \
              (name eq 'peak_end_speed') ? ' (m/s)' : (name eq 'min_fixed_end_tension') ? ' (N)' : \
              (name eq 'front_arrival_time' || name eq 'wall_time' || name eq 'time_reached') ? ' (s)' : ''
label(name) = name.units(name)

set terminal pngcairo size 900,600 enhanced font ",11"
set output out
set datafile separator ","
set grid
set rmargin 6
set key top left box opaque
set xlabel label(x) noenhanced
set ylabel label(y) noenhanced
set title sprintf("%s: %d cases%s", system(sprintf("basename '%s'", sweep)), cases, \
                  (left_out > 0) ? sprintf(", %d not complete and left out", left_out) : "") noenhanced
# The complete cases of one series value, as "x,y" lines (awk keeps NaN out of the lines).
cases_of(v) = sprintf("< awk -F, -v s=%d -v c=%d -v x=%d -v y=%d -v v='%s' \
                       'NR > 1 && $s == \"complete\" && (c == 0 || $c == v) { print $x \",\" $y }' '%s'", \
                      stc, sc, xc, yc, v, csv)
plot for [i = 1:words(series_values)] cases_of(word(series_values, i)) using 1:2 \
     smooth unique with linespoints lw 2 pt 7 \
     title (sc > 0 ? sprintf("%s = %s", series, word(series_values, i)) : y) noenhanced
print sprintf("sweep_summary.gp: wrote %s", out)
