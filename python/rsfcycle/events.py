# SPDX-License-Identifier: LGPL-2.1-or-later
"""The event catalogue of a run folder and the cost of its cycles.

    python3 -m rsfcycle.events RUN [--cycles N] [--unit yr]
                               [--length-unit km] [--dip DEG]

prints the catalogue (events.csv; events of the transition marked) and,
over the last N complete cycles (default: all between the first and the
last event start), their number, mean recurrence time, accepted steps and
wall time per cycle (from the progress lines of log.txt, interpolated to
the event starts) and per accepted step the maximum and mean of the
fixed-point iterations, TNNMG iterations and linear (multigrid) cycles of
time-series.csv.

The functions serve the plots (rsfcycle.plot) and the benchmarks: the
catalogue as a list of Event, events found from the time series where a
run has no events.csv, the jump of a time-series column over each event
(the uplift per event), means over the events after a transition, and
the differences between two catalogues.
"""

import argparse
import math
import os
import re
import sys
from dataclasses import dataclass
from typing import List, Optional

from rsfcycle import catalog, run

UM = 1e6  # m -> micrometres


@dataclass
class Event:
    """One row of events.csv (doc/output.md): number, start and end [s],
    duration [s], nucleation position along the base [m], peak slip rate
    [m/s], rupture width [m], slip [µm] and the recurrence time [s] (nan
    for the first event)."""

    number: int
    start: float
    end: float
    duration: float = math.nan
    nucleation: float = math.nan
    peak: float = math.nan
    width: float = math.nan
    slip_um: float = math.nan
    recurrence: float = math.nan


def _value(row, name):
    """A float of a catalogue row, nan where the column is absent or the
    field empty."""
    try:
        value = float(row[name])
    except (KeyError, TypeError, ValueError):
        return math.nan
    return value


def read(folder) -> Optional[List[Event]]:
    """The catalogue of the run folder (events.csv) as a list of Event, or
    None when the folder has no events.csv."""
    if not os.path.exists(os.path.join(folder, "events.csv")):
        return None
    table = run.events(folder)
    events = []
    for i, row in enumerate(table.to_dict("records")):
        number = _value(row, "event")
        events.append(Event(
            number=int(number) if math.isfinite(number) else i + 1,
            start=_value(row, "start_s"), end=_value(row, "end_s"),
            duration=_value(row, "duration_s"),
            nucleation=_value(row, "nucleation_position_m"),
            peak=_value(row, "peak_slip_rate_m_per_s"),
            width=_value(row, "rupture_width_m"),
            slip_um=_value(row, "slip_um"),
            recurrence=_value(row, "recurrence_s")))
    return [e for e in events if math.isfinite(e.start)]


def detect(times, max_rate, v0, threshold, profile=None) -> List[Event]:
    """Events where a run has no events.csv, with the definitions of
    doc/events.md: an event while the largest slip rate exceeds threshold
    × v0 (rsfcycle.catalog.detect on the time series), its nucleation
    position, rupture width and slip from the slip-rate profile
    (rsfcycle.run.Profile; only as fine as its rows, which are dense
    during events)."""
    import numpy as np
    found = catalog.detect(times, max_rate, threshold * v0)
    events = []
    for k, e in enumerate(found):
        event = Event(number=k + 1, start=e.start, end=e.end,
                      duration=e.end - e.start, peak=e.peak)
        if profile is not None:
            inside = (profile.times >= e.start) & (profile.times <= e.end)
            if inside.any():
                rates = profile.rates[inside]
                event.nucleation = profile.positions[np.argmax(rates[0])]
                hit = (rates > threshold * v0).any(axis=0)
                if hit.any():
                    event.width = (profile.positions[hit].max()
                                   - profile.positions[hit].min())
            rows = np.flatnonzero(inside)
            if len(rows) > 1:
                first, last = rows[0], rows[-1] + 1
                integrate = getattr(np, "trapezoid", None) or np.trapz
                slip = integrate(profile.rates[first:last],
                                 profile.times[first:last], axis=0)
                span = profile.times[last - 1] - profile.times[first]
                event.slip_um = (slip.max() - v0 * span) * UM
        if events:
            event.recurrence = event.start - events[-1].start
        events.append(event)
    return events


def transition(parameters, events=None, time=None):
    """(N, T): the summary's transition, the first N events and those
    starting before T seconds (Output/Transition events, default 2;
    Output/Transition time, default 0). Given `time` alone, N is 0."""
    if events is None:
        events = 0 if time is not None else int(float(
            parameters.get("Output/Transition events", 2)))
    if time is None:
        time = float(parameters.get("Output/Transition time", 0))
    return events, time


def in_transition(index, event, rule):
    """Whether the event with this index (from 0) belongs to the
    transition rule (N, T) of transition()."""
    return index < rule[0] or event.start < rule[1]


def jumps(times, values, starts, ends):
    """The change of a time-series column (e.g. uplift_15cm_m) over each
    event: its value at the first row at or after the end minus at the
    first row at or after the start."""
    import numpy as np
    times = np.asarray(times, float)
    values = np.asarray(values, float)

    def at(t):
        i = np.searchsorted(times, np.asarray(t, float), side="left")
        return values[np.minimum(i, len(times) - 1)]
    return at(ends) - at(starts)


def uplift_columns(columns):
    """The observation columns uplift_<N>cm_m of time-series.csv, in
    order."""
    return [c for c in columns if re.fullmatch(r"uplift_\d+cm_m", c)]


def means(folder, skip=8):
    """Means over the events after the first `skip` of the catalogue's
    recurrence_s, peak_slip_rate_m_per_s, slip_um, rupture_width_m,
    duration_s and nucleation_position_m, and of the uplift per event at
    each observation point (uplift_<N>cm_um, the jump of the surface
    displacement from the event's start to its end, µm); `events` is
    their number. Exits with one line when there are fewer than three."""
    table = run.events(folder)
    series = run.time_series(folder)
    after = table.iloc[skip:]
    if len(after) < 3:
        sys.exit(f"{folder}: only {len(table)} events, fewer than "
                 f"{skip + 3}")
    row = {"events": len(after)}
    for column in ("recurrence_s", "peak_slip_rate_m_per_s", "slip_um",
                   "rupture_width_m", "duration_s", "nucleation_position_m"):
        row[column] = float(after[column].dropna().mean())
    for column in uplift_columns(series.columns):
        jump = jumps(series["time_s"], series[column], after["start_s"],
                     after["end_s"])
        row[column[:-2] + "_um"] = float(UM * jump.mean())
    return row


def differences(ours, reference):
    """How far a catalogue (a list of Event) is from a reference one,
    event by event in order: the counts, the largest difference of the
    starts [s] and the largest relative differences of the peak slip rates
    and of the slips."""
    n = min(len(ours), len(reference))
    pairs = list(zip(ours[:n], reference[:n]))

    def largest(values):
        return max(values, default=math.nan)
    return {
        "events": len(ours), "reference_events": len(reference),
        "start": largest(abs(a.start - b.start) for a, b in pairs),
        "peak": largest(abs(a.peak / b.peak - 1) for a, b in pairs
                        if b.peak),
        "slip": largest(abs(a.slip_um / b.slip_um - 1) for a, b in pairs
                        if b.slip_um),
    }


def progress(folder):
    """[(simulated time [s], wall time [s])] of the progress lines of
    log.txt."""
    pattern = re.compile(r"\*\*\* Step \d+: t = ([0-9.e+-]+) s .*wall "
                         r"(\d+)h(\d+)m(\d+)s")
    points = []
    with open(os.path.join(folder, "log.txt"), encoding="utf-8") as f:
        for line in f:
            m = pattern.search(line)
            if m:
                h, mi, s = (int(m.group(i)) for i in (2, 3, 4))
                points.append((float(m.group(1)), 3600 * h + 60 * mi + s))
    return points


def wall_at(points, t):
    """Wall time [s] at simulated time t, linear between the progress
    points; None outside them."""
    for (t0, w0), (t1, w1) in zip(points, points[1:]):
        if t0 <= t <= t1:
            return w0 + (w1 - w0) * (t - t0) / max(t1 - t0, 1e-300)
    return None


def cycles(folder, count=None):
    """The cost of the cycles between event starts (the last `count`, or
    all): cycles, first and last start [s], mean recurrence [s], accepted
    steps per cycle, wall time per cycle [s] (None without progress lines
    around the starts), unknowns (from log.txt) and per accepted step the
    max and mean of fixed_point_iterations, tnnmg_iterations and
    linear_iterations. Exits with one line without a complete cycle."""
    table = run.events(folder)
    starts = [float(t) for t in table["start_s"]]
    if len(starts) < 2:
        sys.exit(f"{folder}: fewer than two events, no complete cycle")
    if count is not None:
        starts = starts[-(count + 1):]
    t0, t1 = starts[0], starts[-1]
    series = run.time_series(folder)
    inside = series[(series["time_s"] > t0) & (series["time_s"] <= t1)]
    n = len(starts) - 1
    points = progress(folder)
    w0, w1 = wall_at(points, t0), wall_at(points, t1)
    with open(os.path.join(folder, "log.txt"), encoding="utf-8") as f:
        unknowns = re.search(r"(\d+) unknowns", f.read())
    out = {"events": len(table), "cycles": n, "first": t0, "last": t1,
           "recurrence": (t1 - t0) / n, "steps_per_cycle": len(inside) / n,
           "wall_per_cycle": (w1 - w0) / n if None not in (w0, w1)
           else None,
           "unknowns": int(unknowns.group(1)) if unknowns else None}
    for column in ("fixed_point_iterations", "tnnmg_iterations",
                   "linear_iterations"):
        values = inside[column]
        out[column] = (int(values.max()), float(values.mean())) \
            if len(values) else (0, math.nan)
    return out


def catalogue_lines(events, rule=(0, 0.0), time_unit="s", length_unit="m",
                    dip=None):
    """The catalogue as aligned text lines; events of the transition rule
    (N, T) marked. time_unit 's' or 'yr' (of 365.25 days); length_unit
    'm' or 'km'; with `dip` [deg] the nucleation depth instead of the
    position along the base."""
    t_scale = catalog.YEAR if time_unit == "yr" else 1.0
    x_scale = 1e3 if length_unit == "km" else 1.0
    along = math.sin(math.radians(dip)) if dip is not None else 1.0
    where = "depth" if dip is not None else "position"
    lines = [f"event  start [{time_unit}]  duration [s]  nucleation {where} "
             f"[{length_unit}]  peak V [m/s]  width [{length_unit}]  "
             f"slip [µm]  recurrence [{time_unit}]"]
    for i, e in enumerate(events):
        mark = "  (transition)" if in_transition(i, e, rule) else ""
        lines.append(
            f"{e.number:5d}  {e.start / t_scale:12.6g}  {e.duration:12.4g}  "
            f"{e.nucleation * along / x_scale:13.4g}  {e.peak:12.4g}  "
            f"{e.width / x_scale:10.4g}  {e.slip_um:9.4g}  "
            f"{e.recurrence / t_scale:14.4g}{mark}")
    return lines


def main(argv=None):
    """python3 -m rsfcycle.events RUN [--cycles N] [--unit s|yr]
    [--length-unit m|km] [--dip DEG]"""
    parser = argparse.ArgumentParser(
        prog="python3 -m rsfcycle.events",
        description="The event catalogue of an rsfcycle run folder and the "
        "cost of its seismic cycles (steps, wall time, iterations).")
    parser.add_argument("run", metavar="RUN", help="the run folder")
    parser.add_argument("--cycles", type=int, metavar="N",
                        help="only the last N complete cycles (default: "
                        "all between the first and the last event start)")
    parser.add_argument("--unit", choices=["s", "yr"], default="s",
                        help="time unit of the catalogue (default s)")
    parser.add_argument("--length-unit", choices=["m", "km"], default="m",
                        help="length unit of the catalogue (default m)")
    parser.add_argument("--dip", type=float, metavar="DEG",
                        help="dip of the contact: the nucleation depth "
                        "instead of the position along it")
    args = parser.parse_args(argv)
    events = read(args.run)
    if events is None:
        sys.exit(f"{args.run}: no events.csv (is it an rsfcycle run "
                 "folder?)")
    rule = transition(run.parameters(args.run))
    print("\n".join(catalogue_lines(events, rule, args.unit,
                                    args.length_unit, args.dip)))
    print()
    stats = cycles(args.run, args.cycles)
    print(f"run folder: {args.run}")
    if stats["unknowns"]:
        print(f"unknowns: {stats['unknowns']}")
    print(f"events: {stats['events']}; cycles measured: {stats['cycles']} "
          f"(event starts {stats['first']:g} to {stats['last']:g} s)")
    print(f"mean recurrence time: {stats['recurrence']:.6g} s")
    print(f"accepted steps per cycle: {stats['steps_per_cycle']:.1f}")
    if stats["wall_per_cycle"] is not None:
        print(f"wall time per cycle: {stats['wall_per_cycle'] / 60:.2f} min")
    for column, label in (("fixed_point_iterations", "fixed-point iterations"),
                          ("tnnmg_iterations", "TNNMG iterations"),
                          ("linear_iterations", "linear cycles")):
        most, mean = stats[column]
        print(f"{label} per step: max {most}, mean {mean:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
