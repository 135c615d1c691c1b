# SPDX-License-Identifier: LGPL-2.1-or-later
"""Cost at equal accuracy: each code runs at its shipped tolerance and at
looser ones; of the runs whose own results are unchanged against its
tightest run (the tightest included) the cheapest, usually the loosest,
is the code's figure, and the ratio of two codes' costs is taken there.

Unchanged means, for an event catalogue, the same number of events with
every start within `within` (relative) of the reference's; for other
results a list of numbers, each within `within` of the reference's.
"""

import math
from typing import Callable, List, Optional, Sequence


def start_of(event):
    """An event's start [s]: a catalog.Event or a dict with 'start'."""
    return event["start"] if isinstance(event, dict) else event.start


def unchanged(events, reference, within=1e-4) -> Optional[float]:
    """The largest relative change of an event's start against the
    reference catalogue, if both have the same number of events and every
    start moved by less than `within`; None otherwise. A start at t = 0
    (an event nucleated at the start) is compared relative to the
    reference's last start."""
    if len(events) != len(reference) or not events:
        return None
    span = abs(start_of(reference[-1])) or 1.0
    worst = max(abs(start_of(a) - start_of(b)) / (abs(start_of(b)) or span)
                for a, b in zip(events, reference))
    return worst if worst < within else None


def unchanged_values(values, reference, within=1e-3) -> Optional[float]:
    """The largest relative change of a list of numbers against the
    reference list (each against max(|reference|, tiny)), if it is below
    `within`; None otherwise (or when the lengths differ)."""
    if len(values) != len(reference) or not values:
        return None
    worst = max(abs(a - b) / max(abs(b), 1e-300) for a, b in zip(values, reference))
    return worst if worst < within else None


def cheapest_unchanged(runs: Sequence, compare: Callable = unchanged, within=1e-4):
    """runs: (name, tolerance, results, cost [s]) in any order. Sorted
    tightest first, each compared with the tightest by `compare(results,
    reference, within)` (None: changed; with within = inf it gives the
    change itself). Returns (the cheapest unchanged run, the tightest
    included; a list of (run, state text))."""
    runs = sorted(runs, key=lambda r: float(r[1]))
    if not runs:
        raise ValueError("no runs to compare")
    reference = runs[0][2]
    chosen, states = runs[0], [(runs[0], "reference")]
    for run in runs[1:]:
        worst = compare(run[2], reference, within)
        if worst is None:
            by = compare(run[2], reference, math.inf)
            states.append((run, "changed" + (f" (by {100 * by:.4f} %)" if by is not None
                                             else " (other events)")))
            continue
        states.append((run, f"unchanged (within {100 * worst:.4f} %)"))
        if run[3] < chosen[3]:
            chosen = run
    return chosen, states


def ratio(ours, peer) -> float:
    """Our cost over the peer's at the two chosen runs."""
    if not peer[3]:
        return math.nan
    return ours[3] / peer[3]


def table(code, states: List) -> str:
    """The runs of one code as printed lines: name, tolerance, cost, state."""
    return "\n".join(f"{code:9} {run[0]:28} tolerance {run[1]:>7}  cost {run[3]:8.1f} s  "
                     f"{state}" for run, state in states)


HBI_EPS = ("1e-6", "1e-5", "1e-4")  # HBI's eps_r: the drivers' and looser


def tolerances(shipped):
    """rsfcycle's step tolerances of a sweep: the shipped one, 3 and 10
    times looser, as text."""
    return [f"{float(shipped) * f:.0e}".replace("e-0", "e-") for f in (1, 3, 10)]
