# SPDX-License-Identifier: LGPL-2.1-or-later
"""Reading the SEAS benchmarks' plain-text files (shared by compare.py and
plot_bp1.py)."""
import numpy as np

YEAR = 365.25 * 24 * 3600  # rsfcycle's year [s]


def read_seas(path):
    """The numeric rows of a SEAS file: `#` header lines and the line of
    column names are skipped; rows may differ in length (slip.dat's first
    row has two more entries than the station files' columns)."""
    rows = []
    with open(path) as f:
        for line in f:
            if not line.strip() or line[0] == "#" or line[0].isalpha():
                continue
            rows.append([float(x) for x in line.split()])
    return rows


def read_table(path):
    """read_seas() as an array (files with rows of one length)."""
    return np.array(read_seas(path))
