#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""PNG versions of the paper's figures 3-7 from rsfcycle run folders.

Pipping, Kornhuber, Rosenau and Oncken, "On the efficient and reliable
numerical solution of rate-and-state friction problems", GJI 2016, section 3
(the 2D laboratory wedge).

Usage:
  /usr/bin/python3 scripts/plot_wedge.py RUNDIR [--out DIR] [--events N]
                                         [--transition T]
  /usr/bin/python3 scripts/plot_wedge.py --fig7 RUNDIR1 RUNDIR2 ... [--out DIR]

The first form writes fig3-surface-displacement.png, fig4-slip-rate.png,
fig5-event-statistics.png and fig6-solver.png into RUNDIR/figures/ (or DIR).
The second writes fig7-effort-vs-tolerance.png into DIR (default: the current
directory) from a set of runs that differ in the fixed-point tolerance.

Inputs (all in the run folder): time-series.csv, base-profile.csv,
parameters.prm and, if present, events.csv (the event catalogue written by
rsfcycle; see doc/events.md). Without events.csv, the events are detected
here from time-series.csv with the same threshold (parameters.prm, Output,
"Event threshold" times v0); rupture width and slip are then estimated from
base-profile.csv (5 ms sampling during events) and the figures say so.

Figures:
  fig3: vertical surface displacement at the observation points minus its
        time average [µm]: (a) whole run, (b) the last N events as computed
        (frame of the rigid base, where the wedge slides up-dip and so rises
        by v0 sin(dip) per second), (c) the same in the backstop's, i.e. the
        laboratory's, frame (the backstop's vertical displacement, computed
        from v0, the ramp time and the dip, subtracted).
  fig4: isolines of slip rate - v0 over (time, position along the base):
        (a) N events, (b) the last event where base-profile.csv is dense;
        dashed lines: the rate-weakening patch.
  fig5: Tukey box plots of recurrence time, rupture width and slip per event
        after the transition, with the paper's statements about the lab.
  fig6: displacement (as fig3 c), step size, fixed-point iterations, and
        TNNMG / linear-correction iterations per accepted step over N events.
  fig7: sum of linear_iterations against Solver/Fixed-point tolerance.

Files that are still being written are read up to their last complete line.
--events N: number of consecutive events in figures 3, 4a and 6 (default 3).
Figure 5 leaves out the transition as rsfcycle's summary does: the first
N events and those starting before T seconds, with N and T from
parameters.prm (Output: "Transition events", "Transition time"; 2 and 0 if
absent). --transition T sets T (and N = 0 unless --transition-events N is
given too).
"""

import argparse
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import LogNorm  # noqa: E402

UM = 1e6  # m -> micrometres


# --------------------------------------------------------------------------
# Reading
# --------------------------------------------------------------------------
def complete_lines(path):
    """The lines of a text file up to its last newline (a file that is being
    written may end in a partial line)."""
    with open(path, "r", errors="replace") as f:
        text = f.read()
    if not text.endswith("\n"):
        text = text[: text.rfind("\n") + 1]
    return text.splitlines()


def to_float(s):
    s = s.strip()
    if s == "" or s.lower() in ("nan", "-nan", "none", "na"):
        return math.nan
    return float(s)


def read_table(path, comment="#"):
    """CSV with one header line: (list of column names, 2D float array).
    Rows of the wrong length or that do not parse are skipped."""
    header, rows = None, []
    for line in complete_lines(path):
        if not line.strip() or line.lstrip().startswith(comment):
            continue
        fields = line.split(",")
        if header is None:
            header = [h.strip() for h in fields]
            continue
        if len(fields) != len(header):
            continue
        try:
            rows.append([to_float(x) for x in fields])
        except ValueError:
            continue
    if header is None:
        raise RuntimeError(f"{path}: no header line")
    data = np.array(rows, dtype=float).reshape(-1, len(header))
    return header, data


def read_time_series(rundir):
    header, data = read_table(os.path.join(rundir, "time-series.csv"))
    ts = {name: data[:, i] for i, name in enumerate(header)}
    if len(data) == 0:
        raise RuntimeError("time-series.csv has no complete data row")
    return ts


def read_base_profile(rundir):
    """(positions along the base [m], times [s], slip rates [m/s], shape
    n_times x n_nodes)."""
    path = os.path.join(rundir, "base-profile.csv")
    header, data = read_table(path)
    positions = np.array([float(x) for x in header[1:]])
    times, rates = data[:, 0], data[:, 1:]
    # Keep times strictly increasing (contour needs a monotone grid).
    keep = np.concatenate(([True], np.diff(times) > 0))
    return positions, times[keep], rates[keep]


def read_prm(path):
    """deal.II parameter file -> {"Subsection/.../Name": "value"}."""
    values, stack = {}, []
    if not os.path.exists(path):
        return values
    for line in complete_lines(path):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        m = re.match(r"subsection\s+(.*)$", line)
        if m:
            stack.append(m.group(1).strip())
        elif line == "end":
            if stack:
                stack.pop()
        else:
            m = re.match(r"set\s+(.*?)\s*=\s*(.*)$", line)
            if m:
                values["/".join(stack + [m.group(1)])] = m.group(2).strip()
    return values


def prm_float(prm, key, default):
    try:
        return float(prm[key])
    except (KeyError, ValueError):
        return default


class Event:
    def __init__(self, **kw):
        self.number = kw.get("number", 0)
        self.start = kw.get("start", math.nan)
        self.end = kw.get("end", math.nan)
        self.duration = kw.get("duration", self.end - self.start)
        self.nucleation = kw.get("nucleation", math.nan)
        self.peak_rate = kw.get("peak_rate", math.nan)
        self.width = kw.get("width", math.nan)
        self.slip_um = kw.get("slip_um", math.nan)
        self.recurrence = kw.get("recurrence", math.nan)


def read_events_csv(rundir):
    path = os.path.join(rundir, "events.csv")
    if not os.path.exists(path):
        return None
    try:
        header, data = read_table(path)
    except (RuntimeError, OSError):
        return None
    col = {name: i for i, name in enumerate(header)}

    def get(row, name):
        return row[col[name]] if name in col else math.nan

    events = []
    for row in data:
        events.append(Event(
            number=int(get(row, "event")) if np.isfinite(get(row, "event"))
            else len(events) + 1,
            start=get(row, "start_s"), end=get(row, "end_s"),
            duration=get(row, "duration_s"),
            nucleation=get(row, "nucleation_position_m"),
            peak_rate=get(row, "peak_slip_rate_m_per_s"),
            width=get(row, "rupture_width_m"), slip_um=get(row, "slip_um"),
            recurrence=get(row, "recurrence_s")))
    return events


def detect_events(ts, profile, v0, threshold):
    """Fallback when events.csv is missing: the definitions of doc/events.md
    applied to time-series.csv (start, end, peak rate) and base-profile.csv
    (nucleation, width, slip; only as fine as its sampling)."""
    t, vmax = ts["time_s"], ts["max_slip_rate_m_per_s"]
    above = vmax > threshold * v0
    events = []
    i, n = 0, len(t)
    while i < n:
        if not above[i]:
            i += 1
            continue
        j = i
        while j + 1 < n and above[j + 1]:
            j += 1
        if j == n - 1:  # still running at the end of the file: incomplete
            break
        ev = Event(number=len(events) + 1, start=t[i], end=t[j + 1],
                   peak_rate=float(vmax[i:j + 1].max()))
        ev.duration = ev.end - ev.start
        if profile is not None:
            pos, pt, rates = profile
            sel = (pt >= ev.start) & (pt <= ev.end)
            if sel.any():
                r = rates[sel]
                ev.nucleation = pos[np.argmax(r[0])]
                hit = (r > threshold * v0).any(axis=0)
                if hit.any():
                    ev.width = pos[hit].max() - pos[hit].min()
            # slip accumulated during the event: trapezoid over the profile
            # samples in [start, end] (every "Event profile interval")
            idx = np.flatnonzero(sel)
            if len(idx) > 1:
                k0, k1 = idx[0], idx[-1]
                slip = np.trapz(rates[k0:k1 + 1], pt[k0:k1 + 1], axis=0)
                dur = pt[k1] - pt[k0]
                ev.slip_um = (slip.max() - v0 * dur) * UM
        if events:
            ev.recurrence = ev.start - events[-1].start
        events.append(ev)
        i = j + 1
    return events


def in_transition(index, event, transition):
    """The rule of rsfcycle's summary: the first `Transition events` events
    and those starting before `Transition time` belong to the transition."""
    n, t = transition
    return index < n or event.start < t


# --------------------------------------------------------------------------
# Helpers
# --------------------------------------------------------------------------
def time_average(t, u):
    if len(t) < 2 or t[-1] <= t[0]:
        return float(np.mean(u))
    return float(np.trapz(u, t) / (t[-1] - t[0]))


def uplift_columns(ts):
    cols = [c for c in ts if c.startswith("uplift_")]
    labels = []
    for c in cols:
        m = re.match(r"uplift_(\d+)cm_m", c)
        labels.append(f"{m.group(1)} cm from the trench" if m else c)
    return cols, labels


def event_window(events, t_last, n, pad=None):
    """Time interval around the last n complete events."""
    done = [e for e in events if np.isfinite(e.end) and e.end <= t_last]
    if not done:
        return None, []
    sel = done[-n:]
    rec = [e.recurrence for e in sel if np.isfinite(e.recurrence)]
    if pad is None:
        pad = 0.5 * (np.median(rec) if rec else 1.0)
    t0 = sel[0].start - pad
    t1 = min(sel[-1].end + pad, t_last)
    return (t0, t1), sel


def patch_extent(prm):
    length = prm_float(prm, "Wedge/Length", 1.0)
    depth = prm_float(prm, "Wedge/Depth", 0.27)
    x_down = prm_float(prm, "Wedge/Patch down-dip end", 0.35)
    patch = prm_float(prm, "Wedge/Patch length", 0.20)
    s_down = x_down * math.hypot(length, depth) / length
    return s_down - patch, s_down


def backstop_uplift(t, prm):
    """Vertical displacement [m] of the backstop at times t: it moves up-dip,
    parallel to the base, by the integral of |v(t)| = v0 (1 - cos(pi t/t0))/2
    (t <= t0), v0 afterwards."""
    v0 = prm_float(prm, "Wedge/Convergence rate", 50e-6)
    t0 = prm_float(prm, "Wedge/Ramp time", 100.0)
    length = prm_float(prm, "Wedge/Length", 1.0)
    depth = prm_float(prm, "Wedge/Depth", 0.27)
    t = np.asarray(t, dtype=float)
    ramp = 0.5 * v0 * (t - t0 / math.pi * np.sin(math.pi * t / t0))
    after = 0.5 * v0 * t0 + v0 * (t - t0)
    along = np.where(t <= t0, ramp, after)
    return along * depth / math.hypot(length, depth)


def savefig(fig, path):
    fig.savefig(path, dpi=130)
    plt.close(fig)
    print("wrote", path)


COLORS = ["tab:red", "tab:blue", "tab:green", "tab:purple"]


# --------------------------------------------------------------------------
# Figures
# --------------------------------------------------------------------------
def fig3(ts, events, window, out, n_events, prm):
    t = ts["time_s"]
    cols, labels = uplift_columns(ts)
    nrow = 3 if window else 1
    fig, axes = plt.subplots(nrow, 1, figsize=(9, 3.6 * nrow), squeeze=False)
    ax = axes[0, 0]
    lift_all = backstop_uplift(t, prm)
    for c, lab, col in zip(cols, labels, COLORS):
        u = ts[c] - lift_all
        ax.plot(t, (u - time_average(t, u)) * UM, color=col, lw=1, label=lab)
    ax.set_xlabel("time t [s]")
    ax.set_ylabel("vertical displacement\nminus time average [µm]")
    ax.set_title("(a) Whole run, backstop's (laboratory) frame, see (c); "
                 "average over the whole run", fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    if window:
        t0, t1 = window
        sel = (t >= t0) & (t <= t1)
        ax.axvspan(t0, t1, color="0.85", zorder=0)
        ax = axes[1, 0]
        for c, lab, col in zip(cols, labels, COLORS):
            u = ts[c][sel]
            ax.plot(t[sel], (u - time_average(t[sel], u)) * UM, color=col,
                    lw=1.2, label=lab)
        for e in events:
            if t0 <= e.start <= t1:
                ax.axvline(e.start, color="0.6", ls=":", lw=0.8)
        ax.set_xlim(t0, t1)
        ax.set_xlabel("time t [s]")
        ax.set_ylabel("vertical displacement\nminus time average [µm]")
        ax.set_title(f"(b) Last {n_events} events, frame of the rigid base "
                     "(average over this window; dotted: event starts)",
                     fontsize=10)
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
        # The laboratory's frame: the backstop is at rest and the belt moves.
        # There the secular uplift v0 sin(dip) t of the wedge sliding up-dip
        # is absent.
        ax = axes[2, 0]
        lift = backstop_uplift(t[sel], prm)
        for c, lab, col in zip(cols, labels, COLORS):
            u = ts[c][sel] - lift
            ax.plot(t[sel], (u - time_average(t[sel], u)) * UM, color=col,
                    lw=1.2, label=lab)
        for e in events:
            if t0 <= e.start <= t1:
                ax.axvline(e.start, color="0.6", ls=":", lw=0.8)
        ax.set_xlim(t0, t1)
        ax.set_xlabel("time t [s]")
        ax.set_ylabel("vertical displacement\nminus time average [µm]")
        ax.set_title("(c) The same in the backstop's (laboratory) frame: "
                     "minus the backstop's vertical displacement",
                     fontsize=10)
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
    fig.suptitle("Paper's figure 3: vertical surface displacement relative to "
                 "a time average")
    fig.tight_layout()
    savefig(fig, os.path.join(out, "fig3-surface-displacement.png"))


def slip_rate_panel(ax, fig, pos, pt, rates, v0, t0, t1, patch, title,
                    extend=True):
    if extend:
        # one sample on either side, so that the isolines reach the edges
        i0 = max(np.searchsorted(pt, t0, side="right") - 1, 0)
        i1 = min(np.searchsorted(pt, t1), len(pt) - 1)
        sel = np.zeros(len(pt), bool)
        sel[i0:i1 + 1] = True
    else:
        sel = (pt >= t0) & (pt <= t1)
    if sel.sum() < 2:
        ax.text(0.5, 0.5, "no base-profile rows in this interval",
                transform=ax.transAxes, ha="center")
        return
    tt, dv = pt[sel], rates[sel] - v0
    vmax = np.nanmax(dv)
    if not vmax > 0:
        ax.text(0.5, 0.5, "slip rate nowhere above v0",
                transform=ax.transAxes, ha="center")
        return
    # Four isolines as in the paper: the four decades of V - v0 below the
    # peak (e.g. 1e-6 ... 1e-3 m/s for a peak of 1.1e-3 m/s).
    top = math.floor(math.log10(vmax))
    levels = 10.0 ** np.arange(top - 3, top + 1)
    floor = levels[0] * 1e-3
    pos_dv = np.where(dv > floor, dv, floor)
    cf = ax.contourf(tt, pos, pos_dv.T, levels=np.append(levels, vmax * 1.01),
                     norm=LogNorm(vmin=levels[0], vmax=levels[-1] * 10),
                     cmap="YlOrRd")
    cs = ax.contour(tt, pos, pos_dv.T, levels=levels, colors="k",
                    linewidths=0.7)
    ax.clabel(cs, fmt=lambda x: f"{x:.0e}", fontsize=7)
    cb = fig.colorbar(cf, ax=ax, pad=0.01, ticks=levels)
    cb.set_label("slip rate − v0 [m/s]")
    for k, s in enumerate(patch):
        ax.axhline(s, color="tab:blue", ls="--", lw=1.2,
                   label="rate-weakening patch" if k == 0 else None)
    ax.legend(loc="upper right", fontsize=8)
    ax.set_xlim(max(t0, tt[0]), min(t1, tt[-1]))
    ax.set_ylabel("position along the base\nfrom the trench [m]")
    ax.set_xlabel("time t [s]")
    ax.set_title(title, fontsize=10)


def fig4(profile, events, window, v0, patch, out, n_events):
    pos, pt, rates = profile
    fig, axes = plt.subplots(2, 1, figsize=(9, 8))
    if window is None:
        window = (pt[0], pt[-1])
    slip_rate_panel(axes[0], fig, pos, pt, rates, v0, *window, patch,
                    f"(a) {n_events} consecutive events (isolines: decades "
                    "of slip rate − v0)")
    done = [e for e in events if np.isfinite(e.end) and e.end <= pt[-1]]
    if done:
        e = done[-1]
        # base-profile.csv is dense ("Event profile interval") only while
        # the threshold is exceeded; outside that, rows are ~1 s apart and
        # interpolating across them would be misleading.
        z0, z1 = e.start - 0.02, e.end + 0.02
        slip_rate_panel(axes[1], fig, pos, pt, rates, v0, z0, z1, patch,
                        f"(b) zoom into the last event (start "
                        f"{e.start:.3f} s, duration above threshold "
                        f"{e.duration:.3f} s; dotted: start and end)",
                        extend=False)
        axes[1].axvline(e.start, color="0.4", ls=":", lw=0.8)
        axes[1].axvline(e.end, color="0.4", ls=":", lw=0.8)
    else:
        axes[1].text(0.5, 0.5, "no complete event yet",
                     transform=axes[1].transAxes, ha="center")
    fig.suptitle("Paper's figure 4: isolines of the basal slip rate relative "
                 f"to plate convergence (v0 = {v0 * UM:g} µm/s)")
    fig.tight_layout()
    savefig(fig, os.path.join(out, "fig4-slip-rate.png"))


LAB_STATEMENTS = [
    "Paper: the laboratory median\nexceeds the simulation's by\n"
    "less than a factor 2; the\nsimulation lies inside the\n"
    "laboratory range.",
    "Paper: simulated events exceed\nthe laboratory median by\n"
    "less than 14 %.",
    "Paper: simulated events lie\ninside the laboratory range and\n"
    "exceed the laboratory median\nby less than a factor 2.",
]


def fig5(events, transition, source, out):
    kept = [e for i, e in enumerate(events)
            if not in_transition(i, e, transition)]
    quantities = [
        ("recurrence time [s]", [e.recurrence for e in kept]),
        ("rupture width [cm]", [e.width * 100 for e in kept]),
        ("peak slip [µm]", [e.slip_um for e in kept]),
    ]
    fig, axes = plt.subplots(1, 3, figsize=(11, 5.6))
    for ax, (label, vals), note in zip(axes, quantities, LAB_STATEMENTS):
        vals = np.array([v for v in vals if np.isfinite(v)])
        if len(vals):
            ax.boxplot(vals, whis=1.5, widths=0.5)  # Tukey
            jitter = np.random.default_rng(0).uniform(-0.06, 0.06, len(vals))
            ax.plot(1.45 + jitter, vals, ".", color="tab:blue", alpha=0.5,
                    ms=4, label="single events")
            ax.set_xlim(0.6, 1.65)
            ax.legend(fontsize=7, loc="best")
            med = np.median(vals)
            ax.set_title(f"{label.split(' [')[0]}\nmedian {med:.4g}, range "
                         f"{vals.min():.4g} – {vals.max():.4g}\n"
                         f"({len(vals)} events)", fontsize=9)
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
                 f"without the transition (first {transition[0]} events and "
                 f"those before t = {transition[1]:g} s)\n{source}\n"
                 "(the paper gives no laboratory numbers, only the "
                 "statements in the boxes)", fontsize=10)
    fig.tight_layout()
    fig.subplots_adjust(bottom=0.26, top=0.74)
    savefig(fig, os.path.join(out, "fig5-event-statistics.png"))


def solver_panels(axes, t, sel, ts):
    """Step size, fixed-point iterations and inner (TNNMG, linear-correction)
    iterations per accepted step on three axes (figures 6 and 10)."""
    axes[0].semilogy(t[sel], ts["step_size_s"][sel], ".-", ms=2, lw=0.6)
    axes[0].set_ylabel("time step size [s]")
    sizes = np.unique(ts["step_size_s"][sel])
    if 1 < len(sizes) <= 12:  # step doubling: few distinct sizes, label all
        axes[0].set_yticks(sizes)
        axes[0].yaxis.set_major_formatter(
            matplotlib.ticker.FormatStrFormatter("%g"))
        axes[0].yaxis.set_minor_locator(matplotlib.ticker.NullLocator())
    dt = ts["step_size_s"][sel]
    if len(dt):
        axes[0].set_title(f"step size from {dt.max():.3g} s to {dt.min():.3g}"
                          f" s (factor {dt.max() / dt.min():.0f})",
                          fontsize=9)
    fp = ts["fixed_point_iterations"][sel]
    axes[1].plot(t[sel], fp, ".-", ms=2, lw=0.6)
    axes[1].set_ylabel("fixed-point\niterations")
    if len(fp):
        axes[1].set_title(f"max {fp.max():.0f}, mean {fp.mean():.2f} per "
                          "step", fontsize=9)
    lin = ts["linear_iterations"][sel]
    axes[2].plot(t[sel], lin, ".-", ms=2, lw=0.6,
                 label="linear-correction cycles (multigrid/AMG; 1 per "
                 "direct solve)")
    if "tnnmg_iterations" in ts:
        axes[2].plot(t[sel], ts["tnnmg_iterations"][sel], "x", ms=3,
                     color="tab:orange", label="TNNMG iterations")
    axes[2].set_ylabel("inner iterations\n(sum over the fixed-\npoint "
                       "iterations)")
    axes[2].legend(fontsize=7)
    if len(lin):
        axes[2].set_title(f"cycles: max {lin.max():.0f}, mean "
                          f"{lin.mean():.1f} per step", fontsize=9)


def fig6(ts, events, window, out, n_events, prm):
    t = ts["time_s"]
    if window is None:
        window = (t[0], t[-1])
    t0, t1 = window
    sel = (t >= t0) & (t <= t1)
    fig, axes = plt.subplots(4, 1, figsize=(9, 10), sharex=True)
    cols, labels = uplift_columns(ts)
    lift = backstop_uplift(t[sel], prm)
    for c, lab, col in zip(cols, labels, COLORS):
        u = ts[c][sel] - lift
        axes[0].plot(t[sel], (u - time_average(t[sel], u)) * UM, color=col,
                     lw=1.2, label=lab)
    axes[0].set_ylabel("vertical surface\ndisplacement minus\n"
                       "time average [µm]")
    axes[0].set_title("backstop's (laboratory) frame, as in figure 3(c)",
                      fontsize=9)
    axes[0].legend(fontsize=7)
    solver_panels(axes[1:], t, sel, ts)
    axes[3].set_xlabel("time t [s]")
    for ax in axes:
        ax.grid(alpha=0.3)
        for e in events:
            if t0 <= e.start <= t1:
                ax.axvline(e.start, color="0.6", ls=":", lw=0.8)
    axes[2].yaxis.get_major_locator().set_params(integer=True)
    axes[3].set_xlim(t0, t1)
    fig.suptitle("Paper's figure 6: surface displacement, step size, outer "
                 "fixed-point and inner iterations\n"
                 f"per accepted step over {n_events} events (dotted: event "
                 "starts)", fontsize=11)
    fig.tight_layout()
    savefig(fig, os.path.join(out, "fig6-solver.png"))


def fig7(rundirs, out):
    points = []
    for d in rundirs:
        prm = read_prm(os.path.join(d, "parameters.prm"))
        eps = prm_float(prm, "Solver/Fixed-point tolerance", math.nan)
        try:
            ts = read_time_series(d)
        except (RuntimeError, OSError) as err:
            print(f"skipping {d}: {err}", file=sys.stderr)
            continue
        end = prm_float(prm, "End time", math.nan)
        # all spatial problems (step-doubling comparisons and rejected
        # attempts included) where the run recorded them
        column = ("all_linear_iterations" if "all_linear_iterations" in ts
                  else "linear_iterations")
        total = float(np.nansum(ts[column]))
        finished = np.isfinite(end) and ts["time_s"][-1] >= end - 1e-9
        points.append((eps, total, finished, d, ts["time_s"][-1]))
        print(f"{d}: tolerance {eps:g}, {total:.0f} linear iterations up to "
              f"t = {ts['time_s'][-1]:g} s" + ("" if finished else
                                               " (run not finished)"))
    points = [p for p in points if np.isfinite(p[0])]
    if not points:
        raise SystemExit("fig7: no run with a readable tolerance")
    points.sort()
    fig, ax = plt.subplots(figsize=(7, 4.5))
    x = [p[0] for p in points]
    y = [p[1] for p in points]
    ax.semilogx(x, y, "-", color="0.6")
    for eps, total, finished, d, tend in points:
        ax.semilogx(eps, total, "o" if finished else "s",
                    color="tab:blue" if finished else "tab:red")
        if not finished:
            ax.annotate(f"unfinished (t = {tend:.0f} s)", (eps, total),
                        fontsize=7, xytext=(4, 4),
                        textcoords="offset points")
    ax.set_xlabel("fixed-point tolerance ε (parameters.prm: Solver/"
                  "Fixed-point tolerance)")
    ax.set_ylabel("total inner iterations\n(all spatial problems)")
    from matplotlib.lines import Line2D
    ax.legend(handles=[
        Line2D([], [], marker="o", ls="", color="tab:blue",
               label="run finished (End time reached)"),
        Line2D([], [], marker="s", ls="", color="tab:red",
               label="run not finished: total so far")], fontsize=8)
    ax.grid(alpha=0.3, which="both")
    ax.set_title("Paper's figure 7: computational effort over the "
                 "fixed-point tolerance", fontsize=11)
    fig.tight_layout()
    savefig(fig, os.path.join(out, "fig7-effort-vs-tolerance.png"))


def print_events(events, transition):
    print("event  start_s    duration_s  nucleation_m  peak_rate_m/s  "
          "width_m  slip_um  recurrence_s")
    for i, e in enumerate(events):
        flag = "  (transition)" if in_transition(i, e, transition) else ""
        print(f"{e.number:5d}  {e.start:9.4f}  {e.duration:10.4f}  "
              f"{e.nucleation:12.4f}  {e.peak_rate:13.4g}  {e.width:7.4f}  "
              f"{e.slip_um:7.2f}  {e.recurrence:12.4f}{flag}")


# --------------------------------------------------------------------------
def main():
    ap = argparse.ArgumentParser(
        description="PNG versions of the paper's figures 3-7 from rsfcycle "
        "run folders.")
    ap.add_argument("rundirs", nargs="+", metavar="RUNDIR")
    ap.add_argument("--out", help="output folder (default RUNDIR/figures, "
                    "with --fig7 the current folder)")
    ap.add_argument("--events", type=int, default=3,
                    help="number of consecutive events shown (default 3)")
    ap.add_argument("--transition", type=float, default=None,
                    metavar="T", help="figure 5 leaves out the events "
                    "starting before T [s] (default: Output/Transition time "
                    "of parameters.prm, else 0)")
    ap.add_argument("--transition-events", type=int, default=None,
                    metavar="N", help="figure 5 also leaves out the first N "
                    "events (default: Output/Transition events of "
                    "parameters.prm, else 2; 0 if only --transition is "
                    "given)")
    ap.add_argument("--fig7", action="store_true",
                    help="figure 7 from several runs")
    args = ap.parse_args()

    if args.fig7:
        out = args.out or "."
        os.makedirs(out, exist_ok=True)
        fig7(args.rundirs, out)
        return
    if len(args.rundirs) != 1:
        ap.error("one RUNDIR expected (several only with --fig7)")
    rundir = args.rundirs[0]
    out = args.out or os.path.join(rundir, "figures")
    os.makedirs(out, exist_ok=True)

    prm = read_prm(os.path.join(rundir, "parameters.prm"))
    v0 = prm_float(prm, "Wedge/Convergence rate", 50e-6)
    threshold = prm_float(prm, "Output/Event threshold", 10.0)
    patch = patch_extent(prm)
    ts = read_time_series(rundir)
    try:
        profile = read_base_profile(rundir)
    except (RuntimeError, OSError) as err:
        print(f"base-profile.csv unusable ({err}); no figure 4",
              file=sys.stderr)
        profile = None

    events = read_events_csv(rundir)
    if events is not None:
        source = "events from events.csv"
    else:
        events = detect_events(ts, profile, v0, threshold)
        source = ("events.csv missing or empty: events detected by "
                  "plot_wedge.py from time-series.csv and base-profile.csv")
        print(source, file=sys.stderr)
    print(f"{len(events)} events")

    t_last = ts["time_s"][-1]
    if profile is not None:
        t_last = min(t_last, profile[1][-1])
    window, shown = event_window(events, t_last, args.events)
    n_shown = len(shown)

    # The transition as in rsfcycle's summary (Output subsection).
    n_trans = args.transition_events
    if n_trans is None:
        n_trans = 0 if args.transition is not None else int(
            prm_float(prm, "Output/Transition events", 2))
    t_trans = args.transition
    if t_trans is None:
        t_trans = prm_float(prm, "Output/Transition time", 0.0)
    transition = (n_trans, t_trans)
    print(f"transition: the first {n_trans} events and those starting "
          f"before t = {t_trans:g} s are left out of figure 5")

    fig3(ts, events, window, out, n_shown, prm)
    if profile is not None:
        fig4(profile, events, window, v0, patch, out, n_shown)
    fig5(events, transition, source, out)
    fig6(ts, events, window, out, n_shown, prm)
    print_events(events, transition)


if __name__ == "__main__":
    main()
