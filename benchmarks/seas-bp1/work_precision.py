#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Work-precision of BP1-FD's first event: start, peak slip rate and slip
against the wall time to the event's end, one point per rsfcycle run folder.

    work_precision.py LABEL=RUN_FOLDER ... [--out DIR] [--merge S]

Each run folder's events.csv gives the first event (rows starting within
--merge seconds of the previous row's end are merged into it, for runs made
without `Output/Event merge time`); log.txt gives the wall time: that of the
first progress line after the first event ended (or the timer table's total
if the run stopped there). SCycle's 50 m first event (README.md) gives
the reference lines. Prints a Markdown table and writes
work-precision.png.
"""
import argparse
import csv
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

YEAR = 365.25 * 24 * 3600
SCYCLE = {"start": 196.304, "peak": 18.48, "slip": 4.0976}


def first_event(folder, merge):
    with open(os.path.join(folder, "events.csv")) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit(folder + ": events.csv has no event")
    e = {"start": float(rows[0]["start_s"]), "end": float(rows[0]["end_s"]),
         "peak": float(rows[0]["peak_slip_rate_m_per_s"]),
         "slip": float(rows[0]["slip_um"]) * 1e-6}
    for r in rows[1:]:
        if float(r["start_s"]) - e["end"] > merge:
            break
        e["end"] = float(r["end_s"])
        e["peak"] = max(e["peak"], float(r["peak_slip_rate_m_per_s"]))
    return e


def wall_time(folder):
    """Seconds of wall time to the end of the first event."""
    text = open(os.path.join(folder, "log.txt")).read()
    after = text.split("event 1 ended", 1)
    if len(after) == 2:
        m = re.search(r"wall (\d+)h(\d+)m(\d+)s", after[1])
        if m:
            h, mi, s = (int(x) for x in m.groups())
            return 3600 * h + 60 * mi + s
    m = re.search(r"Total wallclock time elapsed since start\s*\|\s*([\d.e+]+)s",
                  text)
    if not m:
        raise SystemExit(folder + ": no wall time in log.txt")
    return float(m.group(1))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("runs", nargs="+", help="LABEL=RUN_FOLDER")
    parser.add_argument("--merge", type=float, default=0.0,
                        help="events.csv rows starting within this many "
                        "seconds of the previous end belong to it [s]")
    parser.add_argument("--out", default=".")
    args = parser.parse_args()

    points = []
    for item in args.runs:
        label, folder = item.split("=", 1)
        e = first_event(folder, args.merge)
        points.append((label, wall_time(folder) / 60, e))

    print("| run | wall to the first event's end [min] | start [yr] | "
          "against SCycle | peak slip rate [m/s] | against SCycle | "
          "largest slip [m] | against SCycle's surface slip |")
    print("|---|---|---|---|---|---|---|---|")
    for label, wall, e in points:
        start = e["start"] / YEAR
        print("| %s | %.1f | %.3f | %+.2f %% | %.2f | %+.1f %% | %.4f | %+.2f %% |"
              % (label, wall, start, 100 * (start / SCYCLE["start"] - 1),
                 e["peak"], 100 * (e["peak"] / SCYCLE["peak"] - 1), e["slip"],
                 100 * (e["slip"] / SCYCLE["slip"] - 1)))

    fig, axes = plt.subplots(1, 3, figsize=(13, 4))
    keys = [("start", "first event [yr]", YEAR), ("peak", "peak slip rate [m/s]", 1),
            ("slip", "largest slip of the first event [m]", 1)]
    for ax, (key, name, scale) in zip(axes, keys):
        for label, wall, e in points:
            ax.plot(wall, e[key] / scale, "o")
            ax.annotate(label, (wall, e[key] / scale), fontsize=7,
                        xytext=(3, 3), textcoords="offset points")
        ax.axhline(SCYCLE[key], color="k", lw=0.8, ls="--", label="SCycle 50 m")
        ax.set_xscale("log")
        ax.set_xlabel("wall time to the event's end [min]")
        ax.set_ylabel(name)
        ax.legend(fontsize=7)
    fig.suptitle("BP1-FD at 50 m, elastic, generalized-α: work against precision")
    fig.tight_layout()
    os.makedirs(args.out, exist_ok=True)
    fig.savefig(os.path.join(args.out, "work-precision.png"), dpi=120)


if __name__ == "__main__":
    main()
