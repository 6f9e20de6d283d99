# Loaded after a figure script by test/test_figures.sh: warns when the data of the last plot drawn
# fill less than two thirds of an axis (an empty third of the plot). A constant (a zero line, the
# ledger's drift of an exact run) has nothing to fill and is passed.
_fill(d0, d1, a0, a1) = (a1 - a0) > 0 && (d1 - d0) > 0 ? (d1 - d0) / (a1 - a0) : 1.0
if (exists("GPVAL_DATA_Y_MIN") && exists("GPVAL_Y_MIN")) {
    _fy = _fill(GPVAL_DATA_Y_MIN, GPVAL_DATA_Y_MAX, GPVAL_Y_MIN, GPVAL_Y_MAX)
    _fx = _fill(GPVAL_DATA_X_MIN, GPVAL_DATA_X_MAX, GPVAL_X_MIN, GPVAL_X_MAX)
    if (_fy < 2.0/3) { print sprintf("warning: the data fill %.0f %% of the y axis (an empty third)", 100 * _fy) }
    if (_fx < 2.0/3) { print sprintf("warning: the data fill %.0f %% of the x axis (an empty third)", 100 * _fx) }
}
