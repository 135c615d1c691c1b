# SPDX-License-Identifier: LGPL-2.1-or-later
"""The figures of a run folder, chosen from its parameters.prm.

    python3 -m rsfcycle.plot RUN [--out DIR] [--events N] ...
    python3 -m rsfcycle.plot --fig7 RUN1 RUN2 ... [--out DIR]

writes PNG files into RUN/figures/ (or DIR):

- the 2D wedge (Scene = wedge, Dimension = 2): the paper's figures 3 – 6
  (rsfcycle.wedge_plots): fig3-surface-displacement.png,
  fig4-slip-rate.png, fig5-event-statistics.png, fig6-solver.png;
- the 3D wedge (Scene = wedge, Dimension = 3): figures 9 and 10,
  fig9-fault-slip-rate.png and fig10-solver.png;
- every other scene (mesh-file, spring-slider): cycles-slip-rate.png (the
  slip rate along the contact over time, or of the one node of the
  spring-slider) and cycles-observations.png (the observation columns of
  time-series.csv, displacements since the start, event starts marked).

With --fig7 it draws the paper's figure 7, fig7-effort-vs-tolerance.png,
from runs that differ in the fixed-point tolerance (DIR: default the
current folder). Files still being written are read up to their last
complete row. Matplotlib runs with the Agg backend (no display).
"""

import argparse
import math
import os
import sys

from rsfcycle import catalog, run

from rsfcycle.drawing import (_pyplot, kind, plate_rate, profile, savefig,
                              series)


def cycles_figures(folder, out, dip=None, time_unit="s", length_unit="m"):
    """The figures of any run folder (built for long runs of mesh-file
    scenes and the spring-slider): cycles-slip-rate.png, log10(V / v0)
    along the contact against time and against the profile row (the rows
    are dense during events, so that events get room), or for one node
    (the spring-slider) its slip rate against time; and
    cycles-observations.png, the observation columns of time-series.csv
    (displacements, columns ending in _m, since the start) with the event
    starts. `dip` [deg] plots depth instead
    of the distance along the contact. Returns the paths."""
    import numpy as np
    from rsfcycle import events as catalogue
    plt = _pyplot()
    parameters = run.parameters(folder)
    v0 = plate_rate(parameters)
    t_scale = catalog.YEAR if time_unit == "yr" else 1.0
    x_scale = 1e3 if length_unit == "km" else 1.0
    found = catalogue.read(folder) or []
    written = []
    slip_rates = profile(folder)
    log_rate = np.log10(np.maximum(slip_rates.rates, 1e-30) / v0)
    if len(slip_rates.positions) >= 2 and len(slip_rates.times) >= 2:
        coordinate = slip_rates.positions / x_scale
        label = f"distance along the contact [{length_unit}]"
        if dip is not None:
            coordinate = coordinate * math.sin(math.radians(dip))
            label = f"depth [{length_unit}]"
        fig, axes = plt.subplots(1, 2, figsize=(12, 5), sharey=True)
        levels = np.linspace(-4, max(4, math.ceil(log_rate.max())), 33)
        for ax, x, xlabel in (
                (axes[0], slip_rates.times / t_scale, f"time [{time_unit}]"),
                (axes[1], np.arange(len(slip_rates.times)), "profile row")):
            filled = ax.contourf(x, coordinate,
                                 np.clip(log_rate.T, levels[0], levels[-1]),
                                 levels=levels, cmap="magma")
            ax.set_xlabel(xlabel)
        if dip is not None:
            axes[0].invert_yaxis()
        axes[0].set_ylabel(label)
        fig.colorbar(filled, ax=axes, label="log10(V / v0)")
        axes[0].set_title("(a) slip rate over time")
        axes[1].set_title("(b) over the profile rows (events resolved)")
    else:
        fig, ax = plt.subplots(figsize=(10, 4.5))
        ax.plot(slip_rates.times / t_scale, log_rate[:, 0], lw=0.8)
        ax.set_xlabel(f"time [{time_unit}]")
        ax.set_ylabel("log10(V / v0)")
        ax.set_title("slip rate of the contact node")
        ax.grid(alpha=0.3)
    written.append(savefig(fig, os.path.join(out, "cycles-slip-rate.png"),
                           dpi=120))

    ts = series(folder)
    skip = {"time_s", "step_size_s", "max_slip_rate_m_per_s",
            "slip_rate_m_per_s"}
    names = [c for c in ts if c not in skip and not c.endswith("iterations")
             and c != "spatial_problems"]
    fig, axes = plt.subplots(max(len(names), 1), 1, sharex=True,
                             figsize=(10, 2.2 * max(len(names), 1) + 1),
                             squeeze=False)
    t = ts["time_s"] / t_scale
    for ax, name in zip(axes[:, 0], names):
        if name.endswith("_m"):  # a displacement: since the start
            ax.plot(t, ts[name] - ts[name][0], lw=0.8)
            ax.set_ylabel(f"{name}\nsince t = 0", fontsize=8)
        else:
            ax.plot(t, ts[name], lw=0.8)
            ax.set_ylabel(name, fontsize=8)
        for e in found:
            ax.axvline(e.start / t_scale, color="0.8", lw=0.6, zorder=0)
        ax.grid(alpha=0.3)
    axes[-1, 0].set_xlabel(f"time [{time_unit}]")
    fig.suptitle("observation columns of time-series.csv (grey: event "
                 "starts)", fontsize=10)
    fig.tight_layout()
    written.append(savefig(fig, os.path.join(out, "cycles-observations.png"),
                           dpi=120))
    return written


def figures(folder, out=None, n_events=3, transition_time=None,
            transition_events=None, event=None, dip=None, time_unit="s",
            length_unit="m"):
    """Draw the figures of a run folder into `out` (default
    folder/figures), chosen by kind(); returns the paths written."""
    from rsfcycle import wedge_plots
    out = out or os.path.join(folder, "figures")
    os.makedirs(out, exist_ok=True)
    which = kind(run.parameters(folder))
    if which == "wedge-2d":
        return wedge_plots.wedge_2d(folder, out, n_events, transition_time,
                                    transition_events)
    if which == "wedge-3d":
        return wedge_plots.wedge_3d(folder, out, n_events, event)
    return cycles_figures(folder, out, dip, time_unit, length_unit)


def main(argv=None):
    """python3 -m rsfcycle.plot RUN [options] | --fig7 RUN ... [--out DIR]"""
    parser = argparse.ArgumentParser(
        prog="python3 -m rsfcycle.plot",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description=__doc__.split("\n\n", 1)[1].split("With --fig7")[0],
        epilog="Examples:\n  python3 -m rsfcycle.plot output-wedge-2d\n"
        "  python3 -m rsfcycle.plot output-subduction-2d --dip 15 --unit yr "
        "--length-unit km\n  python3 -m rsfcycle.plot --fig7 RUN1 RUN2 RUN3 "
        "--out figures")
    parser.add_argument("runs", nargs="+", metavar="RUN",
                        help="the run folder (several with --fig7)")
    parser.add_argument("--out", metavar="DIR",
                        help="output folder (default RUN/figures; with "
                        "--fig7 the current folder)")
    parser.add_argument("--events", type=int, default=3, metavar="N",
                        help="wedge: consecutive events shown in figures 3, "
                        "4a, 6 and 10 (default 3)")
    parser.add_argument("--transition", type=float, metavar="T",
                        help="2D wedge: figure 5 leaves out the events "
                        "starting before T [s] (default: Output/Transition "
                        "time, else 0)")
    parser.add_argument("--transition-events", type=int, metavar="N",
                        help="2D wedge: figure 5 also leaves out the first "
                        "N events (default: Output/Transition events, else "
                        "2; 0 if only --transition is given)")
    parser.add_argument("--event", type=int, metavar="K",
                        help="3D wedge: figure 9 shows event K of "
                        "events.csv (default: the last complete one)")
    parser.add_argument("--dip", type=float, metavar="DEG",
                        help="other scenes: dip of the contact, to plot "
                        "depth instead of the distance along it")
    parser.add_argument("--unit", choices=["s", "yr"], default="s",
                        help="other scenes: time unit (default s)")
    parser.add_argument("--length-unit", choices=["m", "km"], default="m",
                        help="other scenes: length unit (default m)")
    parser.add_argument("--fig7", action="store_true",
                        help="the paper's figure 7 from runs that differ in "
                        "Solver/Fixed-point tolerance")
    args = parser.parse_args(argv)
    if args.fig7:
        from rsfcycle import wedge_plots
        out = args.out or "."
        os.makedirs(out, exist_ok=True)
        wedge_plots.fig7(args.runs, out)
        return 0
    if len(args.runs) != 1:
        parser.error("one RUN expected (several only with --fig7)")
    figures(args.runs[0], args.out, args.events, args.transition,
            args.transition_events, args.event, args.dip, args.unit,
            args.length_unit)
    return 0


if __name__ == "__main__":
    sys.exit(main())
