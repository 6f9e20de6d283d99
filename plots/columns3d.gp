# Helper of plots/motion3d.gp and plots/plan.gp (loaded after snapshots.gp, not run): stops with a
# message unless the snapshot text has the columns of a 3-D run (y in column 10).
_ncol = int(system(sprintf("awk '/^#/ || NF == 0 { next } { print NF; exit }' '%s'", snap)))
if (_ncol < 15) {
    exit error sprintf("%s has %d columns, no y (column 10): not a 3-D run (&numerics model = '3d')", snap, _ncol)
}
