# SPDX-License-Identifier: LGPL-2.1-or-later
"""The paper's figures of the laboratory wedges (Pipping, Kornhuber,
Rosenau and Oncken, GJI 2016; doc/model.md §5, §6), from run folders.

2D wedge (wedge_2d):
  fig3  vertical surface displacement at the observation points minus its
        time average [µm]: (a) the whole run, (b) the last N events in the
        frame of the rigid base, (c) the same in the backstop's (the
        laboratory's) frame, the backstop's vertical displacement (from
        v0, the ramp time and the dip) subtracted;
  fig4  isolines of the slip rate − v0 over (time, position along the
        base): (a) N events, (b) the last event, where base-profile.csv is
        dense; dashed: the rate-weakening patch;
  fig5  Tukey box plots of recurrence time, rupture width and slip per
        event after the transition, with the paper's statements;
  fig6  displacement (as fig3 c), step size, fixed-point iterations and
        inner (TNNMG, linear-correction) iterations per step over N events;
  fig7  (fig7, several runs) the total inner iterations against
        Solver/Fixed-point tolerance.
3D wedge (wedge_3d):
  fig9  isolines of (V − v0) / v0 on the base at 6 instants of one event;
        dashed: the trapezoidal patch;
  fig10 step size and iterations per step over the last N events.

Events come from events.csv; without it they are found from
time-series.csv and base-profile.csv (rsfcycle.events.detect) and figure 5
says so. Called by python3 -m rsfcycle.plot.
"""

import math
import os
import re
import sys

from rsfcycle import events as catalogue
from rsfcycle import run
from rsfcycle.drawing import (UM, _pyplot, event_window, number, profile,
                              savefig, series)

COLORS = ["tab:red", "tab:blue", "tab:green", "tab:purple"]
LAB_STATEMENTS = [
    "Paper: the laboratory median\nexceeds the simulation's by\n"
    "less than a factor 2; the\nsimulation lies inside the\n"
    "laboratory range.",
    "Paper: simulated events exceed\nthe laboratory median by\n"
    "less than 14 %.",
    "Paper: simulated events lie\ninside the laboratory range and\n"
    "exceed the laboratory median\nby less than a factor 2.",
]


def time_average(t, u):
    """The time average of u(t) (trapezoidal), the mean for fewer than two
    times."""
    import numpy as np
    if len(t) < 2 or t[-1] <= t[0]:
        return float(np.mean(u))
    integrate = getattr(np, "trapezoid", None) or np.trapz
    return float(integrate(u, t) / (t[-1] - t[0]))


def uplift_columns(ts):
    """The uplift columns of a time series and their labels ("15 cm from
    the trench")."""
    columns = catalogue.uplift_columns(ts)
    labels = [re.search(r"(\d+)cm", c).group(1) + " cm from the trench"
              for c in columns]
    return columns, labels


def patch_extent(parameters):
    """The rate-weakening patch's ends along the base [m] of the 2D
    wedge."""
    length = number(parameters, "Wedge/Length", 1.0)
    depth = number(parameters, "Wedge/Depth", 0.27)
    down = number(parameters, "Wedge/Patch down-dip end", 0.35)
    patch = number(parameters, "Wedge/Patch length", 0.20)
    s_down = down * math.hypot(length, depth) / length
    return s_down - patch, s_down


def patch_outline(parameters):
    """The 3D patch's trapezoid as (s, z) corners: the up-dip edge at the
    2D patch's start, the along-base lengths at z = 0 and z = Width."""
    s_up, _ = patch_extent(parameters)
    width = number(parameters, "Wedge/Width", 0.6)
    l0 = number(parameters, "Wedge/Patch length at z min", 0.15)
    l1 = number(parameters, "Wedge/Patch length at z max", 0.25)
    return [(s_up, 0), (s_up + l0, 0), (s_up + l1, width), (s_up, width),
            (s_up, 0)]


def backstop_uplift(t, parameters):
    """Vertical displacement [m] of the backstop at times t: it moves
    up-dip, parallel to the base, by the integral of v0 (1 − cos(π t/t0))/2
    up to the ramp time t0, v0 afterwards."""
    import numpy as np
    v0 = number(parameters, "Wedge/Convergence rate", 50e-6)
    t0 = number(parameters, "Wedge/Ramp time", 100.0)
    length = number(parameters, "Wedge/Length", 1.0)
    depth = number(parameters, "Wedge/Depth", 0.27)
    t = np.asarray(t, dtype=float)
    ramp = 0.5 * v0 * (t - t0 / math.pi * np.sin(math.pi * t / t0))
    after = 0.5 * v0 * t0 + v0 * (t - t0)
    return np.where(t <= t0, ramp, after) * depth / math.hypot(length, depth)


def _mark_starts(ax, found, t0, t1):
    for e in found:
        if t0 <= e.start <= t1:
            ax.axvline(e.start, color="0.6", ls=":", lw=0.8)


def fig3(ts, found, window, out, n_events, parameters):
    """The paper's figure 3 (see the module's documentation)."""
    plt = _pyplot()
    t = ts["time_s"]
    columns, labels = uplift_columns(ts)
    rows = 3 if window else 1
    fig, axes = plt.subplots(rows, 1, figsize=(9, 3.6 * rows), squeeze=False)
    ax = axes[0, 0]
    lift = backstop_uplift(t, parameters)
    for column, label, colour in zip(columns, labels, COLORS):
        u = ts[column] - lift
        ax.plot(t, (u - time_average(t, u)) * UM, color=colour, lw=1,
                label=label)
    ax.set_title("(a) Whole run, backstop's (laboratory) frame, see (c); "
                 "average over the whole run", fontsize=10)
    panels = [ax]
    if window:
        t0, t1 = window
        inside = (t >= t0) & (t <= t1)
        ax.axvspan(t0, t1, color="0.85", zorder=0)
        lift = backstop_uplift(t[inside], parameters)
        for ax, frame in ((axes[1, 0], 0.0), (axes[2, 0], 1.0)):
            for column, label, colour in zip(columns, labels, COLORS):
                u = ts[column][inside] - frame * lift
                ax.plot(t[inside], (u - time_average(t[inside], u)) * UM,
                        color=colour, lw=1.2, label=label)
            _mark_starts(ax, found, t0, t1)
            ax.set_xlim(t0, t1)
            panels.append(ax)
        axes[1, 0].set_title(f"(b) Last {n_events} events, frame of the "
                             "rigid base (average over this window; dotted:"
                             " event starts)", fontsize=10)
        axes[2, 0].set_title("(c) The same in the backstop's (laboratory) "
                             "frame: minus the backstop's vertical "
                             "displacement", fontsize=10)
    for ax in panels:
        ax.set_xlabel("time t [s]")
        ax.set_ylabel("vertical displacement\nminus time average [µm]")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
    fig.suptitle("Paper's figure 3: vertical surface displacement relative "
                 "to a time average")
    fig.tight_layout()
    return savefig(fig, os.path.join(out, "fig3-surface-displacement.png"))


def slip_rate_panel(ax, fig, rates, v0, t0, t1, patch, title, extend=True):
    """Isolines of the slip rate − v0 (four decades below the peak) over
    (time, position) in [t0, t1]; `extend` adds one profile row on either
    side so that the isolines reach the edges."""
    import numpy as np
    from matplotlib.colors import LogNorm
    pt = rates.times
    if extend:
        i0 = max(np.searchsorted(pt, t0, side="right") - 1, 0)
        i1 = min(np.searchsorted(pt, t1), len(pt) - 1)
        inside = np.zeros(len(pt), bool)
        inside[i0:i1 + 1] = True
    else:
        inside = (pt >= t0) & (pt <= t1)
    if inside.sum() < 2:
        ax.text(0.5, 0.5, "no base-profile rows in this interval",
                transform=ax.transAxes, ha="center")
        return
    tt, dv = pt[inside], rates.rates[inside] - v0
    vmax = np.nanmax(dv)
    if not vmax > 0:
        ax.text(0.5, 0.5, "slip rate nowhere above v0",
                transform=ax.transAxes, ha="center")
        return
    top = math.floor(math.log10(vmax))
    levels = 10.0 ** np.arange(top - 3, top + 1)
    floor = levels[0] * 1e-3
    shown = np.where(dv > floor, dv, floor)
    filled = ax.contourf(tt, rates.positions, shown.T,
                         levels=np.append(levels, vmax * 1.01),
                         norm=LogNorm(vmin=levels[0], vmax=levels[-1] * 10),
                         cmap="YlOrRd")
    lines = ax.contour(tt, rates.positions, shown.T, levels=levels,
                       colors="k", linewidths=0.7)
    ax.clabel(lines, fmt=lambda x: f"{x:.0e}", fontsize=7)
    bar = fig.colorbar(filled, ax=ax, pad=0.01, ticks=levels)
    bar.set_label("slip rate − v0 [m/s]")
    for k, s in enumerate(patch):
        ax.axhline(s, color="tab:blue", ls="--", lw=1.2,
                   label="rate-weakening patch" if k == 0 else None)
    ax.legend(loc="upper right", fontsize=8)
    ax.set_xlim(max(t0, tt[0]), min(t1, tt[-1]))
    ax.set_ylabel("position along the base\nfrom the trench [m]")
    ax.set_xlabel("time t [s]")
    ax.set_title(title, fontsize=10)


def fig4(rates, found, window, v0, patch, out, n_events):
    """The paper's figure 4 (see the module's documentation)."""
    plt = _pyplot()
    fig, axes = plt.subplots(2, 1, figsize=(9, 8))
    if window is None:
        window = (rates.times[0], rates.times[-1])
    slip_rate_panel(axes[0], fig, rates, v0, *window, patch,
                    f"(a) {n_events} consecutive events (isolines: decades "
                    "of slip rate − v0)")
    done = [e for e in found if math.isfinite(e.end)
            and e.end <= rates.times[-1]]
    if done:
        e = done[-1]
        # dense rows only while the slip is fast: no interpolation across
        # the sparse rows between events
        slip_rate_panel(axes[1], fig, rates, v0, e.start - 0.02,
                        e.end + 0.02, patch,
                        f"(b) zoom into the last event (start {e.start:.3f} "
                        f"s, duration above threshold {e.duration:.3f} s; "
                        "dotted: start and end)", extend=False)
        axes[1].axvline(e.start, color="0.4", ls=":", lw=0.8)
        axes[1].axvline(e.end, color="0.4", ls=":", lw=0.8)
    else:
        axes[1].text(0.5, 0.5, "no complete event yet",
                     transform=axes[1].transAxes, ha="center")
    fig.suptitle("Paper's figure 4: isolines of the basal slip rate relative "
                 f"to plate convergence (v0 = {v0 * UM:g} µm/s)")
    fig.tight_layout()
    return savefig(fig, os.path.join(out, "fig4-slip-rate.png"))


def fig5(found, rule, source, out):
    """The paper's figure 5: box plots after the transition rule (N, T)."""
    import numpy as np
    plt = _pyplot()
    kept = [e for i, e in enumerate(found)
            if not catalogue.in_transition(i, e, rule)]
    quantities = [("recurrence time [s]", [e.recurrence for e in kept]),
                  ("rupture width [cm]", [e.width * 100 for e in kept]),
                  ("peak slip [µm]", [e.slip_um for e in kept])]
    fig, axes = plt.subplots(1, 3, figsize=(11, 5.6))
    for ax, (label, values), note in zip(axes, quantities, LAB_STATEMENTS):
        values = np.array([v for v in values if np.isfinite(v)])
        if len(values):
            ax.boxplot(values, whis=1.5, widths=0.5)  # Tukey
            jitter = np.random.default_rng(0).uniform(-0.06, 0.06,
                                                      len(values))
            ax.plot(1.45 + jitter, values, ".", color="tab:blue", alpha=0.5,
                    ms=4, label="single events")
            ax.set_xlim(0.6, 1.65)
            ax.legend(fontsize=7, loc="best")
            ax.set_title(f"{label.split(' [')[0]}\nmedian "
                         f"{np.median(values):.4g}, range {values.min():.4g}"
                         f" – {values.max():.4g}\n({len(values)} events)",
                         fontsize=9)
        else:
            ax.text(0.5, 0.5, "no events", transform=ax.transAxes,
                    ha="center")
        ax.set_ylabel(label)
        ax.set_xticks([1])
        ax.set_xticklabels(["simulation"])
        ax.grid(alpha=0.3, axis="y")
        ax.text(0.5, -0.1, note, transform=ax.transAxes, ha="center",
                va="top", fontsize=8.5,
                bbox=dict(boxstyle="round", fc="lightyellow", ec="0.7"))
    fig.suptitle("Paper's figure 5: Tukey box plots of recurrence time, "
                 "rupture width and peak slip\n"
                 f"without the transition (first {rule[0]} events and "
                 f"those before t = {rule[1]:g} s)\n{source}\n"
                 "(the paper gives no laboratory numbers, only the "
                 "statements in the boxes)", fontsize=10)
    fig.tight_layout()
    fig.subplots_adjust(bottom=0.26, top=0.74)
    return savefig(fig, os.path.join(out, "fig5-event-statistics.png"))


def solver_panels(axes, t, inside, ts):
    """Step size, fixed-point iterations and inner (TNNMG,
    linear-correction) iterations per accepted step on three axes
    (figures 6 and 10)."""
    import matplotlib.ticker
    import numpy as np
    step = ts["step_size_s"][inside]
    axes[0].semilogy(t[inside], step, ".-", ms=2, lw=0.6)
    axes[0].set_ylabel("time step size [s]")
    sizes = np.unique(step)
    if 1 < len(sizes) <= 12:  # step doubling: few distinct sizes
        axes[0].set_yticks(sizes)
        axes[0].yaxis.set_major_formatter(
            matplotlib.ticker.FormatStrFormatter("%g"))
        axes[0].yaxis.set_minor_locator(matplotlib.ticker.NullLocator())
    if len(step):
        axes[0].set_title(f"step size from {step.max():.3g} s to "
                          f"{step.min():.3g} s (factor "
                          f"{step.max() / step.min():.0f})", fontsize=9)
    fp = ts["fixed_point_iterations"][inside]
    axes[1].plot(t[inside], fp, ".-", ms=2, lw=0.6)
    axes[1].set_ylabel("fixed-point\niterations")
    if len(fp):
        axes[1].set_title(f"max {fp.max():.0f}, mean {fp.mean():.2f} per "
                          "step", fontsize=9)
    linear = ts["linear_iterations"][inside]
    axes[2].plot(t[inside], linear, ".-", ms=2, lw=0.6,
                 label="linear-correction cycles (multigrid/AMG; 1 per "
                 "direct solve)")
    if "tnnmg_iterations" in ts:
        axes[2].plot(t[inside], ts["tnnmg_iterations"][inside], "x", ms=3,
                     color="tab:orange", label="TNNMG iterations")
    axes[2].set_ylabel("inner iterations\n(sum over the fixed-\npoint "
                       "iterations)")
    axes[2].legend(fontsize=7)
    if len(linear):
        axes[2].set_title(f"cycles: max {linear.max():.0f}, mean "
                          f"{linear.mean():.1f} per step", fontsize=9)


def fig6(ts, found, window, out, n_events, parameters):
    """The paper's figure 6 (see the module's documentation)."""
    plt = _pyplot()
    t = ts["time_s"]
    t0, t1 = window or (t[0], t[-1])
    inside = (t >= t0) & (t <= t1)
    fig, axes = plt.subplots(4, 1, figsize=(9, 10), sharex=True)
    columns, labels = uplift_columns(ts)
    lift = backstop_uplift(t[inside], parameters)
    for column, label, colour in zip(columns, labels, COLORS):
        u = ts[column][inside] - lift
        axes[0].plot(t[inside], (u - time_average(t[inside], u)) * UM,
                     color=colour, lw=1.2, label=label)
    axes[0].set_ylabel("vertical surface\ndisplacement minus\n"
                       "time average [µm]")
    axes[0].set_title("backstop's (laboratory) frame, as in figure 3(c)",
                      fontsize=9)
    axes[0].legend(fontsize=7)
    solver_panels(axes[1:], t, inside, ts)
    axes[3].set_xlabel("time t [s]")
    for ax in axes:
        ax.grid(alpha=0.3)
        _mark_starts(ax, found, t0, t1)
    axes[2].yaxis.get_major_locator().set_params(integer=True)
    axes[3].set_xlim(t0, t1)
    fig.suptitle("Paper's figure 6: surface displacement, step size, outer "
                 "fixed-point and inner iterations\n"
                 f"per accepted step over {n_events} events (dotted: event "
                 "starts)", fontsize=11)
    fig.tight_layout()
    return savefig(fig, os.path.join(out, "fig6-solver.png"))


def fig7(folders, out):
    """The paper's figure 7 from run folders that differ in
    Solver/Fixed-point tolerance: the inner iterations of all spatial
    problems (all_linear_iterations) against the tolerance; unfinished
    runs marked. Returns the path."""
    import numpy as np
    from matplotlib.lines import Line2D
    plt = _pyplot()
    points = []
    for folder in folders:
        parameters = run.parameters(folder)
        eps = number(parameters, "Solver/Fixed-point tolerance", math.nan)
        try:
            ts = series(folder)
        except (OSError, ValueError) as error:
            print(f"skipping {folder}: {error}", file=sys.stderr)
            continue
        end = number(parameters, "End time", math.nan)
        column = ("all_linear_iterations" if "all_linear_iterations" in ts
                  else "linear_iterations")
        total = float(np.nansum(ts[column]))
        finished = math.isfinite(end) and ts["time_s"][-1] >= end - 1e-9
        points.append((eps, total, finished, ts["time_s"][-1]))
        print(f"{folder}: tolerance {eps:g}, {total:.0f} inner iterations up "
              f"to t = {ts['time_s'][-1]:g} s"
              + ("" if finished else " (run not finished)"))
    points = sorted(p for p in points if math.isfinite(p[0]))
    if not points:
        sys.exit("fig7: no run with a readable Solver/Fixed-point tolerance")
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.semilogx([p[0] for p in points], [p[1] for p in points], "-",
                color="0.6")
    for eps, total, finished, t_end in points:
        ax.semilogx(eps, total, "o" if finished else "s",
                    color="tab:blue" if finished else "tab:red")
        if not finished:
            ax.annotate(f"unfinished (t = {t_end:.0f} s)", (eps, total),
                        fontsize=7, xytext=(4, 4),
                        textcoords="offset points")
    ax.set_xlabel("fixed-point tolerance ε (parameters.prm: Solver/"
                  "Fixed-point tolerance)")
    ax.set_ylabel("total inner iterations\n(all spatial problems)")
    ax.legend(handles=[
        Line2D([], [], marker="o", ls="", color="tab:blue",
               label="run finished (End time reached)"),
        Line2D([], [], marker="s", ls="", color="tab:red",
               label="run not finished: total so far")], fontsize=8)
    ax.grid(alpha=0.3, which="both")
    ax.set_title("Paper's figure 7: computational effort over the "
                 "fixed-point tolerance", fontsize=11)
    fig.tight_layout()
    return savefig(fig, os.path.join(out, "fig7-effort-vs-tolerance.png"))


def load(folder):
    """(time series, profile or None, events, where the events come from)
    of a wedge run folder; without events.csv the events are found from
    the time series and the profile."""
    parameters = run.parameters(folder)
    ts = series(folder)
    try:
        rates = profile(folder)
    except (OSError, ValueError) as error:
        print(f"base-profile.csv unusable ({error})", file=sys.stderr)
        rates = None
    found = catalogue.read(folder)
    if found:
        return ts, rates, found, "events from events.csv"
    v0 = number(parameters, "Wedge/Convergence rate", 50e-6)
    threshold = number(parameters, "Output/Event threshold", 10.0)
    found = catalogue.detect(ts["time_s"], ts["max_slip_rate_m_per_s"], v0,
                             threshold, rates)
    source = ("events.csv missing or empty: events found from "
              "time-series.csv and base-profile.csv")
    print(source, file=sys.stderr)
    return ts, rates, found, source


def wedge_2d(folder, out, n_events=3, transition_time=None,
             transition_events=None):
    """Figures 3 – 6 of a 2D wedge run folder into `out`; figure 5 leaves
    out the transition (rsfcycle.events.transition). Returns the paths."""
    parameters = run.parameters(folder)
    ts, rates, found, source = load(folder)
    t_last = ts["time_s"][-1]
    if rates is not None and len(rates.times):
        t_last = min(t_last, rates.times[-1])
    window, shown = event_window(found, t_last, n_events)
    rule = catalogue.transition(parameters, transition_events,
                                transition_time)
    written = [fig3(ts, found, window, out, len(shown), parameters)]
    if rates is not None and len(rates.times) >= 2:
        v0 = number(parameters, "Wedge/Convergence rate", 50e-6)
        written.append(fig4(rates, found, window, v0,
                            patch_extent(parameters), out, len(shown)))
    written.append(fig5(found, rule, source, out))
    written.append(fig6(ts, found, window, out, len(shown), parameters))
    return written


def fig9(rates, event, parameters, v0, out):
    """The paper's figure 9: (V − v0) / v0 on the base at 6 instants of
    `event` (an Event of the catalogue)."""
    import numpy as np
    plt = _pyplot()
    rows = np.where((rates.times >= event.start)
                    & (rates.times <= event.end))[0]
    if len(rows) < 6:
        raise ValueError(f"event {event.number}: only {len(rows)} profile "
                         "rows inside it (need 6)")
    picks = rows[np.linspace(0, len(rows) - 1, 6).round().astype(int)]
    levels = v0 * np.array([0, 1, 3, 10, 30, 100, 300, 1000])
    vmax = max(rates.rates[picks].max() - v0, 2 * v0)
    levels = levels[levels < vmax]
    fig, axes = plt.subplots(2, 3, figsize=(12, 6.5), sharex=True,
                             sharey=True)
    corners = np.array(patch_outline(parameters))
    s, z = rates.positions, rates.z
    for ax, i in zip(axes.flat, picks):
        dv = rates.rates[i] - v0
        filled = ax.tricontourf(
            s, z, dv / v0, levels=np.concatenate(
                ([min(dv.min() / v0, 0) - 1], levels / v0,
                 [vmax / v0 + 1])),
            cmap="magma_r")
        ax.tricontour(s, z, dv / v0, levels=levels / v0, colors="k",
                      linewidths=0.5)
        ax.plot(corners[:, 0], corners[:, 1], "c--", lw=1)
        ax.set_title(f"t = {rates.times[i]:.3f} s "
                     f"(+{rates.times[i] - event.start:.3f})", fontsize=9)
        ax.set_aspect("equal")
    for ax in axes[1]:
        ax.set_xlabel("s along the base [m]")
    for ax in axes[:, 0]:
        ax.set_ylabel("lateral coordinate z [m]")
    fig.colorbar(filled, ax=axes, label="(V - v0) / v0", shrink=0.8)
    fig.suptitle(f"Paper's figure 9: slip rate minus v0 on the base during "
                 f"event {event.number} (start {event.start:.3f} s); "
                 "isolines at 0, 1, 3, 10, ... v0; dashed: the patch",
                 fontsize=10)
    return savefig(fig, os.path.join(out, "fig9-fault-slip-rate.png"))


def fig10(ts, found, out, n_events):
    """The paper's figure 10: step size and iterations per step over the
    last n_events events."""
    plt = _pyplot()
    t = ts["time_s"]
    window, shown = event_window(found, t[-1], n_events)
    t0, t1 = window if window else (t[0], t[-1])
    inside = (t >= t0) & (t <= t1)
    fig, axes = plt.subplots(3, 1, figsize=(9, 8), sharex=True)
    solver_panels(axes, t, inside, ts)
    axes[2].set_xlabel("time t [s]")
    for ax in axes:
        ax.grid(alpha=0.3)
        for e in shown:
            ax.axvline(e.start, color="0.6", ls=":", lw=0.8)
    fig.suptitle(f"Paper's figure 10: step size and fixed-point iterations "
                 f"over the last {len(shown)} events (dotted: starts)",
                 fontsize=10)
    fig.tight_layout()
    return savefig(fig, os.path.join(out, "fig10-solver.png"))


def wedge_3d(folder, out, n_events=3, event=None):
    """Figures 9 (the last complete event, or event number `event`) and 10
    of a 3D wedge run folder into `out`. Returns the paths."""
    parameters = run.parameters(folder)
    v0 = number(parameters, "Wedge/Convergence rate", 50e-6)
    ts = series(folder)
    found = catalogue.read(folder) or []
    rates = profile(folder)
    if rates.z is None:
        raise ValueError(f"{folder}/base-profile.csv has no z_m row: not a "
                         "3D run")
    written = []
    complete = [e for e in found if math.isfinite(e.end)
                and e.end <= rates.times[-1]]
    chosen = complete[-1] if complete and event is None else next(
        (e for e in found if e.number == event), None)
    if chosen is not None:
        written.append(fig9(rates, chosen, parameters, v0, out))
    else:
        print("no complete event (or no event of that number): no figure 9",
              file=sys.stderr)
    written.append(fig10(ts, found, out, n_events))
    return written
