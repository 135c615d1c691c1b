# SPDX-License-Identifier: LGPL-2.1-or-later
"""Cost at equal accuracy: each code runs at its shipped tolerance and at
looser ones; the loosest run whose own results are unchanged against its
tightest run is the code's figure, and the ratio of two codes' wall times
is taken there.

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
    start moved by less than `within`; None otherwise."""
    if len(events) != len(reference) or not events:
        return None
    worst = max(abs(start_of(a) - start_of(b)) / abs(start_of(b))
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


def loosest(runs: Sequence, compare: Callable = unchanged):
    """runs: (name, tolerance, results, wall [s]) in any order. Sorted
    tightest first, each compared with the tightest by `compare` (None:
    changed). Returns (the loosest unchanged run, or the tightest when
    every looser one changed; a list of (run, state text))."""
    runs = sorted(runs, key=lambda r: float(r[1]))
    if not runs:
        raise ValueError("no runs to compare")
    reference = runs[0][2]
    chosen, states = runs[0], [(runs[0], "reference")]
    for run in runs[1:]:
        worst = compare(run[2], reference)
        if worst is None:
            states.append((run, "changed"))
            continue
        states.append((run, f"unchanged (within {100 * worst:.4f} %)"))
        if chosen is runs[0] or float(run[1]) > float(chosen[1]):
            chosen = run
    return chosen, states


def ratio(ours, peer) -> float:
    """Our wall time over the peer's at the two chosen runs."""
    if not peer[3]:
        return math.nan
    return ours[3] / peer[3]


def table(code, states: List) -> str:
    """The runs of one code as printed lines: name, tolerance, wall, state."""
    return "\n".join(f"{code:9} {run[0]:28} tolerance {run[1]:>7}  wall {run[3]:8.1f} s  "
                     f"{state}" for run, state in states)


# ------------------------------------------- the HBI benchmarks' `equal`

HBI_EPS = ("1e-6", "1e-5", "1e-4")  # HBI's eps_r: the drivers' and looser


def tolerances(shipped):
    """rsfcycle's step tolerances of a sweep: the shipped one, 3 and 10
    times looser, as text."""
    return [f"{float(shipped) * f:.0e}".replace("e-0", "e-") for f in (1, 3, 10)]


def rsfcycle_cost(folder, reference):
    """rsfcycle's cost of a run [s]: its time loop plus the operator's
    build as the sweep's reference run measured it (the looser runs read
    the operator from the reference's file)."""
    from rsfcycle.peers import hbi
    _, loop, _ = hbi.rsfcycle_times(folder)
    _, _, operator = hbi.rsfcycle_times(reference)
    return (loop or math.nan) + (operator or 0.0)


def hbi_command(args, here, benchmark, base, shipped, results_of, label="",
                hbi_options=None, compare=unchanged):
    """A driver's `equal` command for a benchmark with HBI as its peer:
    with --run, rsfcycle's sweep (`base` at `shipped` and looser
    tolerances, one rank, the operator built once) and HBI's (HBI_EPS)
    run side by side into WORK/equal, one core each; then each code's
    loosest unchanged run (`results_of(folder)` gives what `compare`
    compares) and the ratio of the two costs go to results.csv
    (equal.<label>*). The rsfcycle cost is its time loop plus the
    operator's build; HBI's is its whole run."""
    import os
    from concurrent.futures import ThreadPoolExecutor
    from rsfcycle.peers import hbi
    work = os.path.join(args.work, "equal")
    tag = label + "." if label else ""
    ours = [(f"rsfcycle-{tag}{t}", t) for t in tolerances(shipped)]
    peers = [(f"hbi-{tag}{e}", e) for e in HBI_EPS]
    reference = os.path.join(work, ours[0][0])
    if args.run:
        def sweep_ours():
            for name, t in ours:
                folder = os.path.join(work, name)
                if os.path.exists(os.path.join(folder, "log.txt")):
                    continue
                entries = {"Time stepping/Tolerance": t}
                if name != ours[0][0]:
                    entries["Solver/Green operator file"] = os.path.join(
                        reference, "green-operator.bin")
                hbi.run_rsfcycle(base, folder, entries, 1, args.binary)

        def sweep_peer():
            binary = hbi.build(hbi.source(args.hbi_src), hbi.patch_files(benchmark),
                               args.prefix, args.nice)
            for name, e in peers:
                folder = os.path.join(work, name)
                if not os.path.exists(os.path.join(folder, "timing.txt")):
                    hbi.run(benchmark, folder, binary, args.nice, eps=e,
                            **(hbi_options or {}))

        os.makedirs(work, exist_ok=True)
        with ThreadPoolExecutor(2) as pool:
            for job in [pool.submit(sweep_ours), pool.submit(sweep_peer)]:
                job.result()
    found = {"rsfcycle": [], "HBI": []}
    for name, t in ours:
        folder = os.path.join(work, name)
        if os.path.exists(os.path.join(folder, "log.txt")):
            found["rsfcycle"].append((name, t, results_of(folder),
                                      rsfcycle_cost(folder, reference), folder))
    for name, e in peers:
        folder = os.path.join(work, name)
        if os.path.exists(os.path.join(folder, "timing.txt")):
            found["HBI"].append((name, e, results_of(folder), hbi.hbi_time(folder)[0],
                                 folder))
    for code, runs in found.items():
        if not runs:
            raise FileNotFoundError(f"{work}: no {code} run of the sweep "
                                    "(run.py equal --run)")
    chosen = {}
    for code, runs in found.items():
        chosen[code], states = loosest(runs, compare)
        print(table(code, states))
    a, b = chosen["rsfcycle"], chosen["HBI"]
    x = ratio(a, b)
    print(f"equal accuracy: {a[0]} over {b[0]}: {x:.2f}x")
    what = f" ({label})" if label else ""
    rows = [(f"equal.{tag}rsfcycle", a[1], "", "rsfcycle's loosest step tolerance with "
             f"its results unchanged{what}, of " + ", ".join(r[1] for r in found["rsfcycle"])),
            (f"equal.{tag}rsfcycle_cost", hbi.duration(a[3]), "",
             f"rsfcycle's time loop at {a[1]} and the operator's build, one rank{what}"),
            (f"equal.{tag}ratio", f"{x:.2f}", "x", "rsfcycle's cost over HBI's at equal "
             f"accuracy, side by side, one core each{what}")]
    hbi.record(here, rows, *hbi.context_of(a[4]))
    hbi.record(here, [(f"equal.{tag}hbi", b[1], "", "HBI's loosest eps_r with its "
                       f"results unchanged{what}, of " + ", ".join(r[1] for r in found["HBI"])),
                      (f"equal.{tag}hbi_cost", hbi.duration(b[3]), "",
                       f"HBI's whole run at eps_r {b[1]}, one core{what}")],
               *hbi.context_of(b[4]))
    return 0
