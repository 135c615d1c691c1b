#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Figures of SEAS BP1 runs from their SEAS files, as in the benchmark
paper (Erickson et al. 2020): slip contours and on-fault station series.

Usage: plot_bp1.py --run LABEL=RUNDIR [...] [--station 075] [--out DIR]

RUNDIR: an rsfcycle run folder written with Output/SEAS on
(prm/seas-bp1-qd.prm, prm/seas-bp1-fd.prm). Writes
  DIR/slip-contours-LABEL.png: slip along depth from slip.dat, blue every
    5 years between events, red every second during them;
  DIR/station-XXX.png: log10 slip rate and shear stress at the station
    fltst_dpXXX over time for every run;
  DIR/first-event-XXX.png: the same around each run's first event (time
    from the first moment the maximum slip rate exceeds 1 mm/s), which
    shows the quasi-dynamic and the fully dynamic rupture side by side.
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from seas_files import YEAR, read_seas, read_table  # noqa: E402

def slip_contours(label, rundir, out):
    rows = read_seas(os.path.join(rundir, "slip.dat"))
    depth = np.array(rows[0][2:]) / 1e3
    data = np.array(rows[1:])
    fig, ax = plt.subplots(figsize=(6, 5))
    last_t = -1e300
    for row in data:
        t = row[0]
        # rows seconds apart are the event rows (max V > 1 mm/s)
        event = row[1] > -3
        ax.plot(row[2:], depth, color="tab:red" if event else "tab:blue",
                lw=0.4)
        last_t = t
    ax.invert_yaxis()
    ax.set_xlabel("slip [m]")
    ax.set_ylabel("depth [km]")
    ax.set_title("%s: slip every 5 yr (blue) and 1 s in events (red), "
                 "to %.0f yr" % (label, last_t / YEAR), fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "slip-contours-%s.png" % label), dpi=120)
    plt.close(fig)


def two_panels(curves, xlabel, title, path):
    """log10 slip rate above, shear stress below; curves: (label, t, d)
    with d the rows of a station file."""
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    for label, t, d in curves:
        a1.plot(t, d[:, 2], lw=0.8, label=label)
        a2.plot(t, d[:, 3], lw=0.8, label=label)
    a1.set_ylabel("log10 slip rate [m/s]")
    a2.set_ylabel("shear stress [MPa]")
    a2.set_xlabel(xlabel)
    a1.set_title(title)
    a1.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def station(runs, name, out):
    curves = []
    for label, rundir in runs:
        d = read_table(os.path.join(rundir, "fltst_dp" + name))
        curves.append((label, d[:, 0] / YEAR, d))
    two_panels(curves, "time [yr]",
               "station at %.1f km depth" % (int(name) / 10),
               os.path.join(out, "station-%s.png" % name))


def first_event(runs, name, out):
    curves = []
    for label, rundir in runs:
        g = read_table(os.path.join(rundir, "global.dat"))
        start = g[np.argmax(g[:, 1] > -3), 0]
        d = read_table(os.path.join(rundir, "fltst_dp" + name))
        d = d[(d[:, 0] > start - 30) & (d[:, 0] < start + 200)]
        curves.append((label, d[:, 0] - start, d))
    two_panels(curves,
               "time from the first event's start (max V > 1 mm/s) [s]",
               "first event, station at %.1f km depth" % (int(name) / 10),
               os.path.join(out, "first-event-%s.png" % name))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--run", action="append", required=True)
    parser.add_argument("--station", default="075")
    parser.add_argument("--out", default=".")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    runs = [tuple(item.split("=", 1)) for item in args.run]
    for label, rundir in runs:
        slip_contours(label, rundir, args.out)
    station(runs, args.station, args.out)
    first_event(runs, args.station, args.out)


if __name__ == "__main__":
    main()
