"""Pieces shared by the study scripts of bench/studies/."""
import os
import numpy as np


def crossing(t, y, level):
    """First time y falls to level (linear interpolation), NaN if never."""
    below = np.nonzero(y <= level)[0]
    if below.size == 0 or below[0] == 0:
        return float("nan")
    i = below[0]
    return float(t[i - 1] + (t[i] - t[i - 1]) * (level - y[i - 1]) / (y[i] - y[i - 1]))


def text_attr(value):
    """An HDF5 string attribute as str."""
    return value.decode() if isinstance(value, bytes) else value


def write_tables(path, tables):
    """Write the generated tables to path, keeping the hand-written text of an
    existing page above its marker line ('<!-- generated table(s) below ...')."""
    marker = "<!-- generated table"
    text = tables
    if os.path.exists(path):
        old = open(path).read()
        if marker in old:
            at = old.index(marker)
            text = old[:at] + old[at:].split("\n", 1)[0] + "\n\n" + tables
    with open(path, "w") as f:
        f.write(text)
