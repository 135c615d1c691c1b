# SPDX-License-Identifier: LGPL-2.1-or-later
"""The SEAS benchmark files of a run folder: read them, check them against
their benchmark's description (rsfcycle.seas_rules) and pack them for
upload.

    python3 -m rsfcycle.seas check RUN            # one line per problem
    python3 -m rsfcycle.seas check --pack RUN     # and RUN/<upload>.zip

The benchmark is recognised from the files' `# problem=` line. The check
finds every required file and no stray one (a file named like a SEAS
file, fltst_*, srfst_*, blkst_*, *.dat, that the benchmark does not ask
for), and in each file: the header's keys (a modeler's name, the date, the
time-step statistics filled in by a finished run), the field line(s) of
the description, the number of columns, a first row at t = 0 (profiles:
row 1 the positions, then t = 0), times increasing, no NaN or infinity,
and the profiles' positions. Exit status 1 with one line per problem, 0
with "ready to upload: N files".

Only the Python standard library is used, so that the check runs on a
cluster's login node without numpy.
"""

import argparse
import glob
import math
import os
import re
import sys
import zipfile

from rsfcycle import seas_rules

# files of a run folder that are not SEAS files
SEAS_NAME = re.compile(r"^(fltst_|srfst_|blkst_)|\.dat$")


class SeasFile:
    """One SEAS file: its header (key -> value, and the other comment
    lines), its field lines and its data rows (lists of floats, or the
    text of a line that is not numbers)."""

    def __init__(self, path):
        self.path = path
        self.name = os.path.basename(path)
        self.keys = {}
        self.field_lines = []
        self.rows = []
        self.bad_rows = []
        with open(path, encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, start=1):
                line = line.rstrip("\n")
                if line.startswith("#"):
                    match = re.match(r"#\s*([A-Za-z_]+)\s*=(.*)$", line)
                    if match and not self.rows:
                        self.keys[match.group(1)] = match.group(2).strip()
                    continue
                if not line.strip():
                    continue
                words = line.split()
                try:
                    self.rows.append([float(w) for w in words])
                except ValueError:
                    if self.rows:
                        self.bad_rows.append((number, line[:60]))
                    else:
                        self.field_lines.append(words)


def read(path):
    """The rows of a SEAS file as lists of floats (headers and field lines
    skipped)."""
    return SeasFile(path).rows


def table(path):
    """(field names, rows as a numpy array) of a time series or table
    (stations, global.dat, catalog.dat, rupture.dat)."""
    import numpy as np
    f = SeasFile(path)
    names = [w for line in f.field_lines for w in line]
    return names, np.array(f.rows)


def profile(path):
    """(positions, t, log10 max slip rate, values[time, position]) of a
    profile file (slip.dat, devol.dat, slip_2_strike.dat, ...)."""
    import numpy as np
    rows = SeasFile(path).rows
    positions = np.array(rows[0][2:])
    data = np.array(rows[1:])
    return positions, data[:, 0], data[:, 1], data[:, 2:]


def _problem_of(run):
    """The problem line of the run folder's SEAS files (the first found)."""
    for path in sorted(glob.glob(os.path.join(run, "*"))):
        if SEAS_NAME.search(os.path.basename(path)) and os.path.isfile(path):
            problem = SeasFile(path).keys.get("problem")
            if problem:
                return problem
    return None


def _expand(rule, field):
    """The field lines of a rule, FIELD replaced by the file's quantity."""
    return [[field if w == "FIELD" else w for w in line]
            for line in rule.fields]


def _check_file(rule, seas, problems):
    where = seas.name + ": "
    for key in rule.keys:
        if key not in seas.keys or not seas.keys[key]:
            problems.append(where + f"no header line '# {key}=' ({rule.source})")
    for key in ("modeler", "author"):
        if seas.keys.get(key) == "unknown":
            problems.append("the headers' modeler is 'unknown': set "
                            "Output/SEAS/Modeler to your name")
    for key in seas_rules.STEP_KEYS:
        if key in seas.keys and seas.keys[key].startswith("("):
            problems.append("the headers' time steps are not filled in: "
                            "the run did not end (stopped, or still "
                            "running)")
    if "date" in seas.keys and not re.match(r"^\d{4}/\d{2}/\d{2}$",
                                            seas.keys["date"]):
        problems.append(where + f"date '{seas.keys['date']}' is not "
                        "YYYY/MM/DD")
    quantity = os.path.splitext(seas.name)[0]
    for suffix in ("_strike", "_depth"):
        quantity = quantity.replace(suffix, "")
    expected = _expand(rule, quantity)
    if seas.field_lines != expected:
        problems.append(where + "field lines " + " / ".join(
            " ".join(line) for line in seas.field_lines) + ", expected " +
            " / ".join(" ".join(line) for line in expected) +
            f" ({rule.source})")
    for number, text in seas.bad_rows[:1]:
        problems.append(where + f"line {number} is not numbers: '{text}'")
    rows = seas.rows
    if not rows:
        problems.append(where + "no data")
        return
    if any(not math.isfinite(v) for row in rows for v in row):
        problems.append(where + "NaN or infinite values")
    if rule.kind == "table":
        width = len(expected[0])
        if any(len(row) != width for row in rows):
            problems.append(where + f"rows without {width} columns")
        return
    if rule.kind == "profile":
        positions = rows[0]
        first, last, count = rule.positions
        if positions[:2] != [0.0, 0.0] or len(positions) != count + 2 or \
                abs(positions[2] - first) > 1e-6 * max(1, abs(first)) or \
                abs(positions[-1] - last) > 1e-6 * max(1, abs(last)):
            problems.append(where + f"row 1 is not 0 0 and {count} positions "
                            f"from {first:g} to {last:g} m ({rule.source})")
        rows = rows[1:]
        width = len(positions)
    else:
        width = len(expected[0])
    if not rows:
        problems.append(where + "no rows after the positions")
        return
    if any(len(row) != width for row in rows):
        problems.append(where + f"rows without {width} columns")
    if rows[0][0] != 0:
        problems.append(where + f"the first row is at t = {rows[0][0]:g} s, "
                        "not at t = 0")
    times = [row[0] for row in rows]
    if any(b <= a for a, b in zip(times, times[1:])):
        problems.append(where + "times do not increase")


def check(run):
    """(benchmark, the files to upload, problems) of a run folder."""
    if not os.path.isdir(run):
        return None, [], [f"{run}: no such folder"]
    problem = _problem_of(run)
    if problem is None:
        return None, [], [f"{run}: no SEAS files (Output/SEAS/Benchmark)"]
    benchmark = seas_rules.by_problem(problem)
    if benchmark is None:
        known = ", ".join(f"'{b.problem}'" for b in seas_rules.BENCHMARKS)
        return None, [], [f"{run}: problem '{problem}' is none of the "
                          f"benchmarks ({known})"]
    problems = []
    files = []
    expected = {}
    for rule in benchmark.files:
        for name in rule.names:
            expected[name] = rule
            path = os.path.join(run, name)
            if not os.path.isfile(path):
                if not rule.optional:
                    problems.append(f"{name}: missing ({rule.source})")
                continue
            seas = SeasFile(path)
            if seas.keys.get("problem") != benchmark.problem:
                problems.append(f"{name}: problem '{seas.keys.get('problem')}'"
                                f", the others '{benchmark.problem}'")
            _check_file(rule, seas, problems)
            files.append(path)
    # a problem of every file once
    problems = list(dict.fromkeys(problems))
    for path in sorted(glob.glob(os.path.join(run, "*"))):
        name = os.path.basename(path)
        if SEAS_NAME.search(name) and name not in expected:
            problems.append(f"{name}: a file {benchmark.name} does not ask "
                            "for (a stray file: remove it, or rerun with "
                            "--force into a clean folder)")
    return benchmark, files, problems


def pack(run, benchmark, files):
    """Write RUN/<modeler>_rsfcycle-<version>-<element size>m-<benchmark>.zip
    with the files; returns its path."""
    first = SeasFile(files[0])
    modeler = first.keys.get("modeler") or first.keys.get("author") or "unknown"
    version = (first.keys.get("version") or first.keys.get("code_version") or
               "").split()[0]
    size = (first.keys.get("element_size") or "").split()[0]
    name = re.sub(r"[^A-Za-z0-9.+-]+", "_",
                  f"{modeler}_rsfcycle-{version}-{size}m-{benchmark.name}")
    archive = os.path.join(run, name + ".zip")
    with zipfile.ZipFile(archive, "w", zipfile.ZIP_DEFLATED) as z:
        for path in files:
            z.write(path, os.path.basename(path))
    return archive


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="python3 -m rsfcycle.seas",
        description="Check a run folder's SEAS files against their "
        "benchmark's description; --pack writes the archive to upload.")
    parser.add_argument("command", choices=["check"])
    parser.add_argument("run", help="the run folder")
    parser.add_argument("--pack", action="store_true",
                        help="write RUN/<modeler>_rsfcycle-...zip")
    args = parser.parse_args(argv)
    benchmark, files, problems = check(args.run)
    for problem in problems:
        print(problem)
    if problems:
        return 1
    print(f"{benchmark.name}: ready to upload: {len(files)} files")
    for note in benchmark.notes:
        print("note: " + note)
    if args.pack:
        print("written: " + pack(args.run, benchmark, files))
    return 0


if __name__ == "__main__":
    sys.exit(main())
