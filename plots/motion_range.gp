# Helper of plots/motion.gp (loaded, not run): axis ranges of one view of the motion from the
# STATS_* of its coordinates and its exaggeration _ex. Sets _xa, _xb (horizontal, m) and _za, _zb
# (vertical, in metres times _ex), padded by 4 % of their own extent and rounded outwards; a view much taller than
# wide (a hanging line) gets a box at least 0.6 times as wide as it is tall.
_x0 = STATS_min_x; _x1 = STATS_max_x; _z0 = _ex * STATS_min_y; _z1 = _ex * STATS_max_y
# Each axis padded by 4 % of its own extent, so that the drawing fills its box (a pad of the
# larger extent left empty thirds in the exaggerated views: test/test_figures.sh checks the fill).
_pad = 0.04 * ((_x1 - _x0) > (_z1 - _z0) ? (_x1 - _x0) : (_z1 - _z0))
_pad = _pad > 0 ? _pad : 1.0
_padx = (_x1 - _x0) > 0 ? 0.04 * (_x1 - _x0) : _pad
_padz = (_z1 - _z0) > 0 ? 0.04 * (_z1 - _z0) : _pad
_xa = _x0 - _padx; _xb = _x1 + _padx
_za = _z0 - _padz; _zb = _z1 + _padz
if ((_xb - _xa) < 0.6 * (_zb - _za)) {
    _xc = 0.5 * (_xa + _xb); _xa = _xc - 0.3 * (_zb - _za); _xb = _xc + 0.3 * (_zb - _za)
}
_t1 = _lo(_xa, _xb); _t2 = _hi(_xa, _xb); _xa = _t1; _xb = _t2
_t1 = _lo(_za, _zb); _t2 = _hi(_za, _zb); _za = _t1; _zb = _t2
