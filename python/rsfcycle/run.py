# SPDX-License-Identifier: LGPL-2.1-or-later
"""Readers of an rsfcycle run folder (doc/output.md): time-series.csv,
base-profile.csv, events.csv, summary.txt, parameters.prm and the version
line of log.txt.

    from rsfcycle import run
    ts = run.time_series("output-wedge-2d")      # a pandas DataFrame
    ev = run.events("output-wedge-2d")
    v0 = float(run.parameters("output-wedge-2d")["Wedge/Convergence rate"])
"""

import os
import re
from dataclasses import dataclass
from typing import Optional


def _path(folder, name):
    path = os.path.join(folder, name)
    if not os.path.exists(path):
        raise FileNotFoundError(f"{path}: not found (is {folder} an "
                                "rsfcycle run folder?)")
    return path


def _csv(folder, name):
    import pandas as pd
    return pd.read_csv(_path(folder, name))


def time_series(folder):
    """time-series.csv: one row per accepted step (time_s, step_size_s, the
    solver counts, max_slip_rate_m_per_s, the observation columns)."""
    return _csv(folder, "time-series.csv")


@dataclass
class Profile:
    """base-profile.csv (doc/output.md): the positions of the contact
    nodes along the base [m], their lateral coordinate z [m] (3D; None in
    2D), the output times [s] (strictly increasing) and the slip rates
    [m/s], one row per time."""

    positions: "object"
    z: Optional["object"]
    times: "object"
    rates: "object"


def base_profile(folder):
    """The slip-rate profile of a run folder (base-profile.csv: `#`
    comment lines, a row `time_s,` with the positions along the base, in
    3D a row `z_m,` with the lateral coordinates, then one row per output
    time), as a Profile; rows cut short (a file being written) are left
    out."""
    import numpy as np
    import pandas as pd
    path = os.path.join(folder, "base-profile.csv")
    if not os.path.exists(path):
        raise FileNotFoundError(f"{path}: not found (is {folder} an "
                                "rsfcycle run folder?)")
    positions = z = None
    skip = 0
    with open(path, encoding="utf-8") as f:
        for line in f:
            fields = line.strip().split(",")
            if line.startswith("#") or not line.strip():
                skip += 1
            elif fields[0] == "time_s":
                positions = np.array([float(x) for x in fields[1:]])
                skip += 1
            elif fields[0] == "z_m":
                z = np.array([float(x) for x in fields[1:]])
                skip += 1
            else:
                break
    if positions is None:
        raise ValueError(f"{path}: no row of positions (time_s, ...)")
    table = pd.read_csv(path, skiprows=skip, header=None,
                        names=range(len(positions) + 1),
                        on_bad_lines="skip", low_memory=False)
    data = table.apply(pd.to_numeric, errors="coerce").dropna().to_numpy()
    times, rates = data[:, 0], data[:, 1:]
    keep = np.concatenate(([True], np.diff(times) > 0)) if len(times) else \
        np.zeros(0, bool)
    return Profile(positions, z, times[keep], rates[keep])


def events(folder):
    """events.csv: one row per completed event (start_s, end_s,
    duration_s, nucleation_position_m, peak_slip_rate_m_per_s,
    rupture_width_m, slip_um, recurrence_s, start_yr and the moment)."""
    return _csv(folder, "events.csv")


def parameters(folder_or_file):
    """The entries of parameters.prm (or any .prm without includes) as a
    dict 'Subsection/Entry' -> value text; top-level entries by name."""
    path = folder_or_file
    if os.path.isdir(path):
        path = _path(path, "parameters.prm")
    entries, sections = {}, []
    with open(path, encoding="utf-8") as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line.startswith("subsection "):
                sections.append(line[len("subsection "):].strip())
            elif line == "end" and sections:
                sections.pop()
            elif line.startswith("set "):
                name, _, value = line[4:].partition("=")
                entries["/".join(sections + [name.strip()])] = value.strip()
    return entries


def summary(folder):
    """summary.txt as a dict: steps, problems (spatial problems or
    right-hand sides), min_step, max_step, max_fixed_point, events, and
    the medians of the catalogue's lines (recurrence_time, ...) where the
    run had events after the transition."""
    with open(_path(folder, "summary.txt"), encoding="utf-8") as f:
        text = f.read()
    out = {}
    for key, pattern in (("steps", r"Steps: (\d+)"),
                         ("problems", r"^[A-Z][^:\n]*: (\d+)\nStep size"),
                         ("events", r"Events: (\d+) completed")):
        m = re.search(pattern, text, re.M)
        if m:
            out[key] = int(m.group(1))
    m = re.search(r"Step size: ([0-9.e+-]+) s to ([0-9.e+-]+) s", text)
    if m:
        out["min_step"], out["max_step"] = float(m.group(1)), float(m.group(2))
    m = re.search(r"Max fixed-point iterations per step: (\d+)", text)
    if m:
        out["max_fixed_point"] = int(m.group(1))
    for name, value in re.findall(r"^  ([a-z ]+?)\s+median ([0-9.e+-]+|nan)",
                                  text, re.M):
        out[name.strip().replace(" ", "_")] = float(value)
    return out


def version(folder):
    """The first line of log.txt: rsfcycle's version, commit, deal.II and
    build type of the run."""
    with open(_path(folder, "log.txt"), encoding="utf-8") as f:
        return f.readline().strip()


_PROGRESS = re.compile(r"^\*\*\* Step (\d+):.*, wall (\d+)h(\d+)m(\d+)s")
_RESUMED = re.compile(r"^Resumed from the checkpoint at t = \S+ s, step (\d+)")
_TOTAL = re.compile(r"Total wallclock time elapsed since start\s*\|"
                    r"\s*([0-9.e+]+)s")


def wall_time(folder):
    """TimerOutput's total wall time of the run [s] (log.txt), or None."""
    with open(_path(folder, "log.txt"), encoding="utf-8") as f:
        found = _TOTAL.findall(f.read())
    return float(found[-1]) if found else None


def resumed_wall_time(folder):
    """The wall time [s] of a run that may have been resumed (log.txt):
    each segment (the start, then each "Resumed from the checkpoint ...,
    step N") counts to its last progress line ("*** Step K: ... wall
    XhYYmZZs") at or before the step the next segment resumed from (the
    steps after that checkpoint were taken again), the last segment to its
    TimerOutput total, else to its last progress line; None without
    progress lines."""
    segments = [[]]  # per segment: (step, wall s) of its progress lines
    resumed_at = []  # the step each later segment resumed from
    total = None
    with open(_path(folder, "log.txt"), encoding="utf-8") as f:
        for line in f:
            if m := _PROGRESS.match(line):
                h, mi, sec = (int(x) for x in m.group(2, 3, 4))
                segments[-1].append((int(m.group(1)), 3600 * h + 60 * mi + sec))
            elif m := _RESUMED.match(line):
                resumed_at.append(int(m.group(1)))
                segments.append([])
                total = None
            elif m := _TOTAL.search(line):
                total = float(m.group(1))
    if not any(segments):
        return None
    wall = 0.0
    for lines, step in zip(segments, resumed_at):
        wall += max((w for k, w in lines if k <= step), default=0)
    last = segments[-1]
    return wall + (total if total is not None else
                   (last[-1][1] if last else 0))


def section_time(folder, section):
    """The wall time of one TimerOutput section (e.g. 'Time stepping') [s],
    the last table's, or None."""
    with open(_path(folder, "log.txt"), encoding="utf-8") as f:
        found = re.findall(r"\|\s*" + re.escape(section) +
                           r"\s*\|\s*\d+\s*\|\s*([0-9.e+-]+)s", f.read())
    return float(found[-1]) if found else None
