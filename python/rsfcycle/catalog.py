# SPDX-License-Identifier: LGPL-2.1-or-later
"""Event catalogues from any code's time series, and their comparison:
what the benchmarks set against a peer.

An event is a maximal run of records whose slip rate reaches `threshold`
(the SEAS descriptions: 1 mm/s); a run that starts within `merge` seconds
of the previous one's end continues it (the ringing of a fully dynamic
rupture). The same definition for every code keeps the comparison fair.
"""

from dataclasses import dataclass
from typing import List, Optional

YEAR = 3.15576e7  # s: a year of 365.25 days, as the SEAS descriptions


@dataclass
class Event:
    """One event: start and end [s], peak slip rate [m/s], and the value
    of a chosen series at its end minus at its start (e.g. the surface
    slip [m]), if one was given."""

    start: float
    end: float
    peak: float
    jump: Optional[float] = None
    first: int = 0  # the record before the start (where the jump begins)


def detect(t, v, threshold=1e-3, merge=0.0, series=None) -> List[Event]:
    """The completed events of the records (t [s], v [m/s]); `series`
    (same length) gives each event's jump. An event still running at the
    last record is left out."""
    events = []
    n = len(t)
    i = 0
    while i < n:
        if v[i] < threshold:
            i += 1
            continue
        j = i
        while j < n and v[j] >= threshold:
            j += 1
        if j == n:
            break  # still running at the end
        start = max(i - 1, 0)
        if events and t[i] - events[-1].end <= merge:
            e = events[-1]
            e.end = t[j]
            e.peak = max(e.peak, max(v[i:j]))
            if series is not None:
                e.jump = series[j] - series[e.first]
        else:
            e = Event(t[i], t[j], max(v[i:j]), first=start)
            if series is not None:
                e.jump = series[j] - series[start]
            events.append(e)
        i = j
    return events


def intervals(events):
    """The times between successive starts [s]."""
    return [b.start - a.start for a, b in zip(events, events[1:])]


def relative(a, b):
    """(a - b) / b, or None where b is 0 or missing."""
    if a is None or b is None or b == 0:
        return None
    return (a - b) / b


def compare(ours: List[Event], peer: List[Event]):
    """Rows (index, our start, the peer's start [yr], relative differences
    of start, interval to the next, peak and jump) for the events both
    catalogues have, in order."""
    rows = []
    ours_i, peer_i = intervals(ours), intervals(peer)
    for k in range(min(len(ours), len(peer))):
        a, b = ours[k], peer[k]
        rows.append({
            "event": k + 1,
            "start_yr": a.start / YEAR,
            "peer_start_yr": b.start / YEAR,
            "start": relative(a.start, b.start),
            "interval": relative(ours_i[k], peer_i[k])
            if k < min(len(ours_i), len(peer_i)) else None,
            "peak": relative(a.peak, b.peak),
            "jump": relative(a.jump, b.jump),
        })
    return rows


def percent(x, digits=2):
    """A relative difference as text, "+0.13 %"; "—" for None."""
    if x is None:
        return "\u2014"
    return f"{100 * x:+.{digits}f} %".replace("-", "\u2212")


def markdown(rows, name="rsfcycle", peer="peer"):
    """A comparison table (compare()) in Markdown."""
    lines = [f"| event | {name} start [yr] | {peer} start [yr] | start | "
             "interval | peak slip rate | slip |", "|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['event']} | {r['start_yr']:.3f} | "
                     f"{r['peer_start_yr']:.3f} | {percent(r['start'])} | "
                     f"{percent(r['interval'])} | {percent(r['peak'])} | "
                     f"{percent(r['jump'])} |")
    return "\n".join(lines) + "\n"
