#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""PNG versions of the paper's figures 9 and 10 (the 3D wedge, section 4) from
an rsfcycle run folder of a 3D wedge (prm/wedge-3d.prm).

Usage:
  /usr/bin/python3 scripts/plot_wedge_3d.py RUNDIR [--out DIR] [--event K]
                                            [--events N]

fig9-fault-slip-rate.png: isolines of the slip rate minus v0 on the base
  (along-base coordinate s against the lateral coordinate z) at 6
  consecutive instants of one event (default: the last complete one; --event
  K picks the K-th of events.csv), from base-profile.csv, whose rows are
  written every `Event profile interval` (5 ms) during events. The dashed
  outline is the trapezoidal rate-weakening patch.
fig10-solver.png: step size and fixed-point iterations (and the inner
  TNNMG/multigrid counts) per accepted step over the last N events
  (default 3), from time-series.csv.

The same data are in fault/fault-NNNNN.vtu (fault.pvd) for ParaView: the
contact faces with slip_rate_minus_v0, log10_slip_rate_over_v0, state,
slip_um, shear_traction, friction_coefficient.
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_wedge as pw  # noqa: E402  (shared readers and helpers)

plt = pw.plt
UM = 1e6


def read_profile_3d(rundir):
    """(s [m], z [m], times [s], rates [m/s], n_times x n_nodes)."""
    path = os.path.join(rundir, "base-profile.csv")
    s = z = None
    rows = []
    for line in pw.complete_lines(path):
        if not line.strip() or line.startswith("#"):
            continue
        fields = line.split(",")
        if fields[0] == "time_s":
            s = np.array([float(x) for x in fields[1:]])
        elif fields[0] == "z_m":
            z = np.array([float(x) for x in fields[1:]])
        elif s is not None and len(fields) == len(s) + 1:
            rows.append([float(x) for x in fields])
    if s is None or z is None:
        raise RuntimeError(f"{path}: no 3D position rows (time_s, z_m)")
    data = np.array(rows)
    keep = np.concatenate(([True], np.diff(data[:, 0]) > 0))
    return s, z, data[keep, 0], data[keep, 1:]


def patch_outline(prm):
    """The trapezoid (s, z) corners: up-dip edge at the 2D patch start, the
    along-base lengths at z = 0 and z = Width."""
    s_up, _ = pw.patch_extent(prm)
    width = pw.prm_float(prm, "Wedge/Width", 0.6)
    l0 = pw.prm_float(prm, "Wedge/Patch length at z min", 0.15)
    l1 = pw.prm_float(prm, "Wedge/Patch length at z max", 0.25)
    return [(s_up, 0), (s_up + l0, 0), (s_up + l1, width), (s_up, width),
            (s_up, 0)]


def fig9(profile, event, prm, v0, out):
    s, z, times, rates = profile
    sel = np.where((times >= event.start) & (times <= event.end))[0]
    if len(sel) < 6:
        raise RuntimeError(f"event {event.number}: only {len(sel)} profile "
                           "rows inside it (need 6)")
    picks = sel[np.linspace(0, len(sel) - 1, 6).round().astype(int)]
    levels = v0 * np.array([0, 1, 3, 10, 30, 100, 300, 1000])
    vmax = max(rates[picks].max() - v0, 2 * v0)
    levels = levels[levels < vmax]
    fig, axes = plt.subplots(2, 3, figsize=(12, 6.5), sharex=True,
                             sharey=True)
    corners = np.array(patch_outline(prm))
    for ax, i in zip(axes.flat, picks):
        dv = rates[i] - v0
        cs = ax.tricontourf(s, z, dv / v0,
                            levels=np.concatenate(([dv.min() / v0 - 1],
                                                   levels / v0,
                                                   [vmax / v0 + 1])),
                            cmap="magma_r")
        ax.tricontour(s, z, dv / v0, levels=levels / v0, colors="k",
                      linewidths=0.5)
        ax.plot(corners[:, 0], corners[:, 1], "c--", lw=1)
        ax.set_title(f"t = {times[i]:.3f} s (+{times[i] - event.start:.3f})",
                     fontsize=9)
        ax.set_aspect("equal")
    for ax in axes[1]:
        ax.set_xlabel("s along the base [m]")
    for ax in axes[:, 0]:
        ax.set_ylabel("lateral coordinate z [m]")
    fig.colorbar(cs, ax=axes, label="(V - v0) / v0", shrink=0.8)
    fig.suptitle(f"Paper's figure 9: slip rate minus v0 on the base during "
                 f"event {event.number} (start {event.start:.3f} s); "
                 "isolines at 0, 1, 3, 10, ... v0; dashed: the patch",
                 fontsize=10)
    pw.savefig(fig, os.path.join(out, "fig9-fault-slip-rate.png"))


def fig10(ts, events, out, n_events):
    t = ts["time_s"]
    window, shown = pw.event_window(events, t[-1], n_events)
    t0, t1 = window if window else (t[0], t[-1])
    sel = (t >= t0) & (t <= t1)
    fig, axes = plt.subplots(3, 1, figsize=(9, 8), sharex=True)
    pw.solver_panels(axes, t, sel, ts)
    axes[2].set_xlabel("time t [s]")
    for ax in axes:
        ax.grid(alpha=0.3)
        for e in shown:
            ax.axvline(e.start, color="0.6", ls=":", lw=0.8)
    fig.suptitle(f"Paper's figure 10: step size and fixed-point iterations "
                 f"over the last {len(shown)} events (dotted: starts)",
                 fontsize=10)
    fig.tight_layout()
    pw.savefig(fig, os.path.join(out, "fig10-solver.png"))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("rundir")
    ap.add_argument("--out")
    ap.add_argument("--event", type=int, default=None)
    ap.add_argument("--events", type=int, default=3)
    args = ap.parse_args()
    out = args.out or os.path.join(args.rundir, "figures")
    os.makedirs(out, exist_ok=True)
    prm = pw.read_prm(os.path.join(args.rundir, "parameters.prm"))
    v0 = pw.prm_float(prm, "Wedge/Convergence rate", 50e-6)
    ts = pw.read_time_series(args.rundir)
    events = pw.read_events_csv(args.rundir) or []
    profile = read_profile_3d(args.rundir)
    complete = [e for e in events if math.isfinite(e.end) and
                e.end <= profile[2][-1]]
    print(f"{len(events)} events")
    if complete:
        event = complete[-1] if args.event is None else \
            next(e for e in events if e.number == args.event)
        fig9(profile, event, prm, v0, out)
    else:
        print("no complete event: no figure 9", file=sys.stderr)
    fig10(ts, events, out, args.events)


if __name__ == "__main__":
    main()
