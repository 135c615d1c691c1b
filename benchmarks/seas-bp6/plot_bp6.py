#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Figures of SEAS BP6 runs side by side (README.md in this folder).

Usage: plot_bp6.py OUT.png TITLE RUN [RUN ...]

Each RUN is LABEL=FOLDER with the SEAS BP6 files (compare.py reads the same).
Four panels: the slip rate at the stations x3 = 0, 1, 2.5, 5 km over time,
the slip there, the slip profiles at 30, 100, 365 and 730 days, and the
maximum slip rate on the fault (global.dat). Runs are told apart by line
style, stations and times by colour.
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from compare import DAY, read_seas  # noqa: E402

STATIONS = ["fltst_strk+00", "fltst_strk+10", "fltst_strk+25", "fltst_strk+50"]
PROFILE_DAYS = [30, 100, 365, 730]
STYLES = ["-", "--", ":", "-."]


def main():
    out, title, runs = sys.argv[1], sys.argv[2], sys.argv[3:]
    fig, axes = plt.subplots(2, 2, figsize=(11, 8))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for r, run in enumerate(runs):
        label, _, folder = run.partition("=")
        style = STYLES[r % len(STYLES)]
        for s, station in enumerate(STATIONS):
            path = os.path.join(folder, station)
            if not os.path.exists(path):
                path += ".dat"  # (the peer's names)
            if not os.path.exists(path):
                continue
            names, d = read_seas(path)
            col = {n: i for i, n in enumerate(names)}
            t = d[:, 0] / DAY
            name = "x3 = %g km" % (int(station[-3:]) / 10)
            axes[0, 0].plot(t, 10 ** d[:, col["slip_rate"]], style, color=colours[s],
                            label=name if r == 0 else None)
            axes[0, 1].plot(t, d[:, col["slip"]], style, color=colours[s])
        _, p = read_seas(os.path.join(folder, "slip.dat"))
        x, rows = p[0, 2:] / 1e3, p[1:]
        for k, day in enumerate(PROFILE_DAYS):
            profile = [np.interp(day * DAY, rows[:, 0], rows[:, 2 + j]) for j in range(len(x))]
            axes[1, 0].plot(x, profile, style, color=colours[k], label="%d days" % day if r == 0 else None)
        _, g = read_seas(os.path.join(folder, "global.dat"))
        axes[1, 1].plot(g[:, 0] / DAY, 10 ** g[:, 1], style, color="k", label=label)
    axes[0, 0].set(yscale="log", xlabel="t [days]", ylabel="slip rate [m/s]", ylim=(1e-12, None))
    axes[0, 0].legend(fontsize=8)
    axes[0, 1].set(xlabel="t [days]", ylabel="slip [m]")
    axes[1, 0].set(xlabel="x3 [km]", ylabel="slip [m]")
    axes[1, 0].legend(fontsize=8)
    axes[1, 1].set(yscale="log", xlabel="t [days]", ylabel="max slip rate [m/s]")
    axes[1, 1].legend(fontsize=8, title="line style")
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
