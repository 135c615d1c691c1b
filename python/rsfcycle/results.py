# SPDX-License-Identifier: LGPL-2.1-or-later
"""One source for every figure: benchmarks' results files and the documents
that quote them.

Each benchmark folder ``benchmarks/NAME/`` keeps its measured figures in
``results.csv``, one figure per row::

    key,value,unit,commit,date,cores,load,description

- ``key``: a name unique in the file (letters, digits, ``. _ -``);
- ``value``, ``unit``: the figure as a reader sees it (``-0.17`` and ``%``
  read "−0.17 %"; the unit ``x`` reads as a factor, "0.64×");
- ``commit``, ``date``: the rsfcycle commit that computed it and the day;
- ``cores``: the cores the run used; ``load``: the cores the machine's
  other work kept busy when the run started (machine_load()), or a word
  such as ``idle`` or ``shared``;
- ``description``: what the figure is, in a few words.

A document quotes a figure inline as ``<!--r NAME:KEY-->TEXT<!--/r-->``
(the comment is invisible in rendered Markdown); a block
``<!--results NAME:PREFIX-->`` … ``<!--/results-->`` holds the table of the
rows whose key starts with PREFIX; ``<!--seas-table-->`` …
``<!--/seas-table-->`` in README.md holds the SEAS table, one row per
problem, from the rows ``PROBLEM.cells``, ``.events``, ``.cost``,
``.peer``, ``.recurrence``, ``.peak_slip_rate`` of every results file.

``python3 -m rsfcycle.results check`` fails (exit 1, one line per problem)
when a document differs from what its results files give;
``python3 -m rsfcycle.results write`` rewrites the quotes and tables.
"""

import csv
import datetime
import glob
import io
import os
import re
import subprocess
import sys
import time
from dataclasses import dataclass, fields

COLUMNS = ["key", "value", "unit", "commit", "date", "cores", "load",
           "description"]
KEY = re.compile(r"^[A-Za-z0-9_.-]+$")
INLINE = re.compile(r"<!--r ([A-Za-z0-9_.-]+):([A-Za-z0-9_.-]+)-->([^<`]*?)"
                    r"<!--/r-->", re.S)
BLOCK = re.compile(r"(<!--results ([A-Za-z0-9_.-]+)(?::([A-Za-z0-9_.-]*))?"
                   r"-->\n)(.*?)(<!--/results-->)", re.S)
SEAS = re.compile(r"(<!--seas-table-->\n)(.*?)(<!--/seas-table-->)", re.S)
RULES = re.compile(r"(<!--seas-rules-->\n)(.*?)(<!--/seas-rules-->)", re.S)
# The SEAS problems in benchmark order, and the table's cells
PROBLEMS = ["bp1-qd", "bp1-fd", "bp2-qd", "bp3-qd", "bp3-fd", "bp4-qd",
            "bp5-qd", "bp5-fd", "bp6-qd-a", "bp6-qd-s", "bp7-qd",
            "bp8-qd-gs", "bp8-qd-pw"]
SEAS_COLUMNS = ["cells", "events", "cost", "peer", "recurrence",
                "peak_slip_rate"]
MAX_CELL = 120
# A measured duration in prose (min, h) or a ratio (×) outside a quote
TIMING = re.compile(r"(?<![\w.])\d+(?:\.\d+)?\s?(?:min|minutes|h|hours)\b"
                    r"|(?<![\w.])\d+(?:\.\d+)?×(?!\s*\d)")


@dataclass
class Row:
    """One figure of a results file (see the module's documentation)."""

    key: str
    value: str
    unit: str = ""
    commit: str = ""
    date: str = ""
    cores: str = ""
    load: str = ""
    description: str = ""

    def text(self):
        """The figure as a document shows it: "−0.17 %", "0.64×", "25 m"."""
        value = self.value
        if re.match(r"^-\d", value):
            value = "\u2212" + value[1:]
        if self.unit == "x":
            return value + "\u00d7"
        return value + (" " + self.unit if self.unit else "")


class ResultsError(Exception):
    """A results file that cannot be read, with the file and the line."""


def read_results(path):
    """The rows of a results file as a dict key -> Row, in file order.

    Raises ResultsError naming the file and line of a malformed row."""
    rows = {}
    with open(path, newline="", encoding="utf-8") as f:
        reader = csv.reader(line for line in f if not line.startswith("#"))
        header = next(reader, None)
        if header != COLUMNS:
            raise ResultsError(f"{path}: the header must be "
                               f"{','.join(COLUMNS)}")
        for number, values in enumerate(reader, start=2):
            if not values:
                continue
            if len(values) != len(COLUMNS):
                raise ResultsError(f"{path}:{number}: {len(values)} columns, "
                                   f"{len(COLUMNS)} expected")
            row = Row(*values)
            if not KEY.match(row.key):
                raise ResultsError(f"{path}:{number}: bad key '{row.key}'")
            if row.key in rows:
                raise ResultsError(f"{path}:{number}: key '{row.key}' twice")
            if row.date and not re.match(r"^\d{4}-\d{2}-\d{2}$", row.date):
                raise ResultsError(f"{path}:{number}: date '{row.date}' is "
                                   "not YYYY-MM-DD")
            rows[row.key] = row
    return rows


def write_results(path, rows):
    """Write rows (an iterable of Row) as a results file."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(COLUMNS)
    for row in rows:
        writer.writerow([getattr(row, f.name) for f in fields(Row)])
    with open(path, "w", encoding="utf-8") as f:
        f.write(out.getvalue())


def run_context(root=None):
    """commit, date and load of a run started now (for a driver's rows)."""
    root = root or repository_root()
    try:
        commit = subprocess.run(
            ["git", "-C", root, "describe", "--always", "--dirty",
             "--abbrev=7"], capture_output=True, text=True,
            check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        commit = "unknown"
    return {"commit": commit, "date": datetime.date.today().isoformat(),
            "load": f"{machine_load():.2f}"}


def machine_load(seconds=2.0):
    """The cores the machine's other work keeps busy now: the busy share
    of all cores over `seconds` (from /proc/stat) times their number; the
    1-minute load average where /proc/stat is absent."""
    def sample():
        with open("/proc/stat") as f:
            values = [int(v) for v in f.readline().split()[1:]]
        idle = values[3] + (values[4] if len(values) > 4 else 0)
        return sum(values), idle

    try:
        total0, idle0 = sample()
        time.sleep(seconds)
        total1, idle1 = sample()
    except OSError:
        return os.getloadavg()[0]
    busy = 1 - (idle1 - idle0) / max(1, total1 - total0)
    return busy * (os.cpu_count() or 1)


def record(folder, key, value, unit="", description="", cores=1,
           context=None):
    """Set one figure of ``folder/results.csv`` (created if absent), keeping
    the other rows; ``context`` (from run_context) gives commit, date and
    load of the run that measured it."""
    path = os.path.join(folder, "results.csv")
    rows = read_results(path) if os.path.exists(path) else {}
    context = context or run_context()
    rows[key] = Row(key, str(value), unit, context["commit"],
                    context["date"], str(cores), context["load"],
                    description)
    write_results(path, rows.values())


def repository_root():
    """The repository's root: the folder above python/."""
    return os.path.dirname(os.path.dirname(os.path.dirname(
        os.path.abspath(__file__))))


def all_results(root):
    """{NAME: rows} for every benchmarks/NAME/results.csv."""
    results = {}
    for path in sorted(glob.glob(os.path.join(root, "benchmarks", "*",
                                              "results.csv"))):
        results[os.path.basename(os.path.dirname(path))] = read_results(path)
    return results


def results_table(rows, prefix):
    """The Markdown table of the rows whose key starts with prefix."""
    lines = ["| quantity | value | run |", "|---|---|---|"]
    for row in rows.values():
        if row.key.startswith(prefix):
            run = ", ".join(part for part in (
                row.commit, row.date,
                f"{row.cores} core{'s' if row.cores != '1' else ''}"
                if row.cores else "", f"load {row.load}" if row.load else "")
                if part)
            lines.append(f"| {row.description or row.key} | {row.text()} "
                         f"| {run} |")
    return "\n".join(lines) + "\n"


def seas_table(results):
    """README.md's SEAS table: one row per problem in benchmark order, from
    the rows PROBLEM.{cells,events,cost,peer,recurrence,peak_slip_rate}."""
    header = ("| problem | file | cells | events | cost | peer "
              "| recurrence | peak slip rate | details |")
    lines = [header, "|" + "---|" * 9]
    problems = []
    for problem in PROBLEMS:
        for name, rows in results.items():
            if f"{problem}.cells" in rows:
                problems.append((problem, name, rows))
    for problem, name, rows in problems:
        cells = [problem.upper(), f"`prm/seas-{problem}.prm`"]
        for column in SEAS_COLUMNS:
            row = rows.get(f"{problem}.{column}")
            text = row.text() if row else "\u2014"
            if column == "cost" and row and row.cores:
                text += f", {row.cores} core{'s' if row.cores != '1' else ''}"
            cells.append(text)
        cells.append(f"[{name}](benchmarks/{name}/README.md)")
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def documents(root):
    """The Markdown files that may quote results."""
    paths = [os.path.join(root, "README.md")]
    paths += sorted(glob.glob(os.path.join(root, "doc", "*.md")))
    paths += sorted(glob.glob(os.path.join(root, "benchmarks", "**",
                                           "*.md"), recursive=True))
    return [p for p in paths if os.path.exists(p)]


def process(text, results, where):
    """(new text, problems) for one document: quotes and tables refreshed
    from the results; a problem for each quote that differs or names a
    figure no results file holds."""
    problems = []

    def lookup(name, key):
        rows = results.get(name)
        if rows is None:
            problems.append(f"{where}: no results file benchmarks/{name}/"
                            "results.csv")
            return None
        if key not in rows:
            problems.append(f"{where}: benchmarks/{name}/results.csv has no "
                            f"figure '{key}'")
            return None
        return rows[key]

    def inline(match):
        row = lookup(match.group(1), match.group(2))
        if row is None:
            return match.group(0)
        if match.group(3) != row.text():
            problems.append(f"{where}: {match.group(1)}:{match.group(2)} "
                            f"reads '{match.group(3)}', its results file "
                            f"'{row.text()}'")
        return f"<!--r {match.group(1)}:{match.group(2)}-->{row.text()}" \
               "<!--/r-->"

    def block(match):
        name, prefix = match.group(2), match.group(3) or ""
        if name not in results:
            problems.append(f"{where}: no results file benchmarks/{name}/"
                            "results.csv")
            return match.group(0)
        table = results_table(results[name], prefix)
        if match.group(4) != table:
            problems.append(f"{where}: the table of {name}:{prefix} differs "
                            "from its results file")
        return match.group(1) + table + match.group(5)

    def seas(match):
        table = seas_table(results)
        if match.group(2) != table:
            problems.append(f"{where}: the SEAS table differs from the "
                            "results files")
        for line in table.splitlines()[2:]:
            for cell in line.strip("|").split(" | "):
                if len(cell.strip()) > MAX_CELL:
                    problems.append(f"{where}: SEAS table cell over "
                                    f"{MAX_CELL} characters: {cell.strip()}")
        return match.group(1) + table + match.group(3)

    def rules(match):
        from rsfcycle import seas_rules
        table = seas_rules.markdown() + "\n"
        if match.group(2) != table:
            problems.append(f"{where}: the SEAS file rules differ: the "
                            "table differs from seas_rules.py")
        return match.group(1) + table + match.group(3)

    text = INLINE.sub(inline, text)
    text = BLOCK.sub(block, text)
    text = SEAS.sub(seas, text)
    text = RULES.sub(rules, text)
    return text, problems


def unquoted_timings(text, where):
    """Durations and ratios in prose that no quote marks (a figure that
    does not come from a results file); fenced code is skipped."""
    problems = []
    stripped = INLINE.sub("", BLOCK.sub("", SEAS.sub("", RULES.sub("", text))))
    fenced = False
    for number, line in enumerate(stripped.split("\n"), start=1):
        if line.lstrip().startswith("```"):
            fenced = not fenced
            continue
        if fenced:
            continue
        for match in TIMING.finditer(line):
            problems.append(f"{where}: '{match.group(0)}' is not quoted "
                            "from a results file")
    return problems


def check(root, write=False, only=()):
    """All problems of the repository's documents; rewrite them if write
    (only the documents under the paths of ``only``, if given)."""
    try:
        results = all_results(root)
    except ResultsError as error:
        return [str(error)]
    problems = []
    for path in documents(root):
        where = os.path.relpath(path, root)
        if only and not any(where.startswith(os.path.normpath(o))
                            for o in only):
            continue
        with open(path, encoding="utf-8") as f:
            text = f.read()
        new, found = process(text, results, where)
        if write and new != text:
            with open(path, "w", encoding="utf-8") as f:
                f.write(new)
            found = [p for p in found if "reads '" not in p
                     and "differs" not in p]
        problems += found
        if where == "README.md" or where.startswith("doc" + os.sep):
            problems += unquoted_timings(new, where)
    return problems


def main(argv=None):
    """python3 -m rsfcycle.results check|write [--root ROOT] [PATH ...]"""
    import argparse
    parser = argparse.ArgumentParser(
        prog="python3 -m rsfcycle.results",
        description="Check (or rewrite) the figures that README.md, doc/ "
        "and the benchmark READMEs quote against the benchmarks' "
        "results.csv files.")
    parser.add_argument("command", choices=["check", "write"])
    parser.add_argument("paths", nargs="*", help="only the documents under "
                        "these paths (relative to the root)")
    parser.add_argument("--root", default=repository_root(),
                        help="the repository's root")
    args = parser.parse_args(argv)
    root = args.root
    problems = check(root, write=args.command == "write", only=args.paths)
    for problem in problems:
        print(problem)
    if problems:
        return 1
    print("every quoted figure matches its results file")
    return 0


if __name__ == "__main__":
    sys.exit(main())
