#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""SEAS BP6 results of several runs side by side (README.md in this folder).

Usage: compare.py [--front SLIP] RUN [RUN ...]

Each RUN is a folder with the SEAS BP6 files (fltst_strk*, global.dat,
slip.dat as rsfcycle writes them: a first row of positions after two
zeros, then rows t max_slip_rate slip...), optionally as LABEL=FOLDER.
Prints, per station, the slip at 30 days, 100 days, 1 year and 2 years
[mm], the peak slip rate [m/s] and its time [days]; the maximum of
global.dat's max slip rate and its time; and the slip front (the largest
|x3| where the slip reaches SLIP, default 1 mm, linear between profile
positions and between profile rows) at 10, 30, 100, 365 and 730 days [km].
The last columns give each run's relative difference from the first.
"""
import argparse
import glob
import os

import numpy as np

DAY = 86400.0
YEAR = 365.25 * DAY
SLIP_TIMES = [30 * DAY, 100 * DAY, YEAR, 2 * YEAR]
FRONT_TIMES = [10 * DAY, 30 * DAY, 100 * DAY, 365 * DAY, 730 * DAY]


def read_seas(path):
    """Numeric rows and field names of a SEAS file."""
    names, rows = None, []
    with open(path) as f:
        for line in f:
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            if line[0].isalpha():
                names = line.split()
                continue
            rows.append([float(v) for v in line.split()])
    return names, np.array(rows)


def at(t, series_t, values):
    """values at time t, linear in time (the last value after the end)."""
    return float(np.interp(t, series_t, values))


def front(x, slip, threshold):
    """The largest |x| where slip >= threshold (linear between points)."""
    best = 0.0
    for i in range(len(x) - 1):
        for a, b in ((i, i + 1), (i + 1, i)):
            if slip[a] >= threshold > slip[b]:
                xa = x[a] + (threshold - slip[a]) / (slip[b] - slip[a]) * (x[b] - x[a])
                best = max(best, abs(xa))
    if slip[0] >= threshold:
        best = max(best, abs(x[0]))
    if slip[-1] >= threshold:
        best = max(best, abs(x[-1]))
    return best


def summarise(folder, threshold):
    result = {"stations": {}}
    for path in sorted(glob.glob(os.path.join(folder, "fltst_strk*"))):
        names, d = read_seas(path)
        t = d[:, 0]
        col = {n: i for i, n in enumerate(names)}
        slip = d[:, col["slip"]]
        log_v = d[:, col["slip_rate"]]
        peak = int(np.argmax(log_v))
        result["stations"][os.path.basename(path).replace(".dat", "")] = {
            "slip": [at(s, t, slip) * 1e3 for s in SLIP_TIMES],
            "peak": (10 ** log_v[peak], t[peak] / DAY),
        }
    _, g = read_seas(os.path.join(folder, "global.dat"))
    peak = int(np.argmax(g[:, 1]))
    result["global"] = (10 ** g[peak, 1], g[peak, 0] / DAY)
    _, p = read_seas(os.path.join(folder, "slip.dat"))
    x, rows = p[0, 2:], p[1:]
    fronts = []
    for s in FRONT_TIMES:
        profile = np.array([np.interp(s, rows[:, 0], rows[:, 2 + j]) for j in range(len(x))])
        fronts.append(front(x, profile, threshold) / 1e3)
    result["front"] = fronts
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--front", type=float, default=1e-3, help="slip front threshold [m]")
    parser.add_argument("runs", nargs="+")
    args = parser.parse_args()
    labels, results = [], []
    for run in args.runs:
        label, _, folder = run.rpartition("=")
        labels.append(label or os.path.basename(os.path.normpath(folder)))
        results.append(summarise(folder, args.front))

    def rel(values):
        ref = values[0]
        return " ".join("%+.2f%%" % (100 * (v - ref) / ref) if ref else "-" for v in values[1:])

    print("runs: " + ", ".join(labels))
    print("\nslip [mm] at 30 d, 100 d, 1 yr, 2 yr; peak slip rate [m/s] and its day")
    for station in results[0]["stations"]:
        for label, r in zip(labels, results):
            s = r["stations"].get(station)
            if s is None:
                continue
            print("%-14s %-12s %9.3f %9.3f %9.3f %9.3f   %.4e  %7.2f" % (station, label, *s["slip"], *s["peak"]))
        finals = [r["stations"][station]["slip"][3] for r in results if station in r["stations"]]
        peaks = [r["stations"][station]["peak"][0] for r in results if station in r["stations"]]
        if len(finals) > 1:
            print("%-14s %-12s 2-yr slip %s, peak rate %s" % ("", "vs first", rel(finals), rel(peaks)))
    print("\nmax slip rate [m/s] and its day")
    for label, r in zip(labels, results):
        print("%-12s %.4e %7.2f" % (label, *r["global"]))
    print("\nslip front (slip >= %g m) [km] at %s days" % (args.front, ", ".join("%g" % (t / DAY) for t in FRONT_TIMES)))
    for label, r in zip(labels, results):
        print("%-12s " % label + " ".join("%7.3f" % f for f in r["front"]))
    if len(results) > 1:
        for label, r in zip(labels[1:], results[1:]):
            print("%-12s " % ("vs " + labels[0]) + " ".join(
                "%+6.2f%%" % (100 * (f - f0) / f0) if f0 else "      -" for f, f0 in zip(r["front"], results[0]["front"])) + "  (" + label + ")")

if __name__ == "__main__":
    main()
