#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Seismic-cycle figures of any rsfcycle run folder (built for long runs of
Scene = mesh-file, e.g. prm/subduction-2d.prm; doc/subduction-2d.md).

Usage:
  /usr/bin/python3 scripts/plot_cycles.py RUNDIR [--out DIR] [--dip DEG]
        [--unit s|yr] [--length-unit m|km]

Writes into RUNDIR/figures/ (or DIR):
  cycles-slip-rate.png  log10(V / v0) along the contact over time: (a)
                        against time, (b) against the profile index (every
                        row of base-profile.csv: the rows are Profile
                        interval apart between events and Event profile
                        interval apart during them, so that the events,
                        seconds long, get as much room as the decades
                        between them); dashed: the rate-weakening part when
                        --dip gives the depth axis.
  cycles-uplift.png     displacement along 'up' at the observation points
                        since the start (after the gravity equilibrium),
                        and the event times.
and prints the event catalogue (events.csv) in the chosen units.
"""
import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

YEAR = 365.25 * 86400


def read_profiles(path):
    with open(path) as f:
        rows = [line for line in f if not line.startswith("#")]
    reader = csv.reader(rows)
    header = next(reader)
    positions = np.array([float(x) for x in header[1:]])
    times, rates = [], []
    for row in reader:
        if len(row) != len(header):
            continue
        times.append(float(row[0]))
        rates.append([float(x) for x in row[1:]])
    return positions, np.array(times), np.array(rates)


def read_csv(path):
    with open(path) as f:
        rows = [line for line in f if not line.startswith("#")]
    return list(csv.DictReader(rows))


def plate_rate(path):
    """v0: |Load velocity| (mesh-file) or Convergence rate (wedge)."""
    with open(path) as f:
        for line in f:
            line = line.split("#")[0].strip()
            if line.startswith("set Load velocity"):
                return math.hypot(*[float(x) for x in
                                    line.split("=")[1].split(",")])
    with open(path) as f:
        for line in f:
            line = line.split("#")[0].strip()
            if line.startswith("set Convergence rate"):
                return float(line.split("=")[1])
    raise SystemExit(path + ": no Load velocity or Convergence rate")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("rundir")
    parser.add_argument("--out")
    parser.add_argument("--dip", type=float,
                        help="dip of the contact [deg]: plot depth instead of "
                             "the distance along it")
    parser.add_argument("--unit", choices=["s", "yr"], default="s")
    parser.add_argument("--length-unit", choices=["m", "km"], default="m")
    args = parser.parse_args()
    out = args.out or os.path.join(args.rundir, "figures")
    os.makedirs(out, exist_ok=True)
    t_scale = YEAR if args.unit == "yr" else 1.0
    x_scale = 1e3 if args.length_unit == "km" else 1.0

    v0 = plate_rate(os.path.join(args.rundir, "parameters.prm"))
    series = read_csv(os.path.join(args.rundir, "time-series.csv"))
    positions, times, rates = read_profiles(
        os.path.join(args.rundir, "base-profile.csv"))
    coordinate = positions / x_scale
    label = "distance along the contact [%s]" % args.length_unit
    if args.dip is not None:
        coordinate = positions * math.sin(math.radians(args.dip)) / x_scale
        label = "depth [%s]" % args.length_unit
    log_rate = np.log10(np.maximum(rates, 1e-30) / v0)

    fig, axes = plt.subplots(1, 2, figsize=(12, 5), sharey=True)
    levels = np.linspace(-4, max(4, math.ceil(log_rate.max())), 33)
    for ax, x, xlabel in (
            (axes[0], times / t_scale, "time [%s]" % args.unit),
            (axes[1], np.arange(len(times)), "profile index")):
        cs = ax.contourf(x, coordinate, np.clip(log_rate.T, levels[0],
                                                levels[-1]),
                         levels=levels, cmap="magma")
        ax.set_xlabel(xlabel)
        if args.dip is not None:
            ax.invert_yaxis() if ax is axes[0] else None
    axes[0].set_ylabel(label)
    fig.colorbar(cs, ax=axes, label="log10(V / v0)")
    axes[0].set_title("(a) slip rate over time")
    axes[1].set_title("(b) over the profile rows (events resolved)")
    fig.savefig(os.path.join(out, "cycles-slip-rate.png"), dpi=120)
    plt.close(fig)

    events = []
    path = os.path.join(args.rundir, "events.csv")
    if os.path.exists(path):
        events = read_csv(path)
    names = [k for k in series[0].keys() if k.startswith("uplift")
             or k.endswith("_m") and k not in ("time_s",)]
    names = [k for k in names if k not in ("max_slip_rate_m_per_s",)]
    fig, ax = plt.subplots(figsize=(10, 4.5))
    t = np.array([float(r["time_s"]) for r in series]) / t_scale
    for name in names:
        u = np.array([float(r[name]) for r in series])
        ax.plot(t, u - u[0], label=name)
    for e in events:
        ax.axvline(float(e["start_s"]) / t_scale, color="0.8", lw=0.6,
                   zorder=0)
    ax.set_xlabel("time [%s]" % args.unit)
    ax.set_ylabel("displacement along up since t = 0 [m]")
    ax.legend()
    ax.set_title("surface displacement at the observation points "
                 "(grey: event starts)")
    fig.savefig(os.path.join(out, "cycles-uplift.png"), dpi=120)
    plt.close(fig)

    along = math.sin(math.radians(args.dip)) if args.dip is not None else 1
    print("event  start [%s]  duration [s]  nucleation %s [%s]  peak V [m/s]  "
          "width [%s]  slip [m]  recurrence [%s]"
          % (args.unit, "depth" if args.dip is not None else "position",
             args.length_unit, args.length_unit, args.unit))
    for e in events:
        rec = e.get("recurrence_s", "")
        rec = "%.4g" % (float(rec) / t_scale) if rec not in ("", "nan") \
            else "-"
        print("%5s  %10.5g  %12.4g  %15.4g  %12.4g  %10.4g  %8.4g  %s" % (
            e["event"], float(e["start_s"]) / t_scale,
            float(e["duration_s"]),
            float(e["nucleation_position_m"]) * along / x_scale,
            float(e["peak_slip_rate_m_per_s"]),
            float(e["rupture_width_m"]) / x_scale,
            float(e["slip_um"]) * 1e-6, rec))
    print("figures in", out)


if __name__ == "__main__":
    sys.exit(main())
