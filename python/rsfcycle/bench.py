# SPDX-License-Identifier: LGPL-2.1-or-later
"""Helpers of the benchmark drivers (benchmarks/NAME/run.py): the command
line every driver shares, running rsfcycle and timing it, reading what a
run printed (TimerOutput's table, the mesh, the time loop), parameter
files of the 2D wedge and of resumed windows, tables.

A driver runs from the repository's root as

    PYTHONPATH=python /usr/bin/python3 benchmarks/NAME/run.py STAGE ...

with its scratch runs in --work (default benchmarks/NAME/runs/, not
tracked) and the build in --build (default build/). Shell drivers source
the same conventions from python/rsfcycle/bench.sh (die, help_if_asked).
"""

import argparse
import csv
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time

from rsfcycle import prm, results

ROOT = results.repository_root()


def folder(name):
    """benchmarks/NAME of the repository."""
    return os.path.join(ROOT, "benchmarks", name)


def die(message, status=2):
    """One line on standard error, then exit (2: something the driver
    needs is missing)."""
    print(f"{os.path.basename(sys.argv[0] or 'run.py')}: {message}",
          file=sys.stderr)
    sys.exit(status)


def _option_help(function):
    """{parameter: help} from the lines `name: text` of a stage
    function's docstring."""
    found = {}
    for line in (function.__doc__ or "").splitlines():
        m = re.match(r"^\s+([a-z_]+): (.+)$", line)
        if m:
            found[m.group(1)] = m.group(2)
    return found


def cli(doc, name, functions, argv=None):
    """The driver's command line: one stage per function (its name with
    - for _, a trailing _ dropped), parsed and run. A stage's parameters
    make its arguments: one without a default is a positional argument
    (*rest: any number), one annotated "?" an optional positional, a
    default True/False a flag, a tuple annotation the choices, else an
    option of the default's type; `build` (default build/) and `work`
    (default benchmarks/NAME/runs/, not tracked) are the build folder and
    the scratch folder. Help texts: the docstring's first paragraph, and
    its lines `parameter: text`. Returns the stage's return value
    (an exit status or None)."""
    import inspect
    main = argparse.ArgumentParser(
        prog=f"benchmarks/{name}/run.py",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description=doc,
        epilog="Run from the repository's root: PYTHONPATH=python "
        f"/usr/bin/python3 benchmarks/{name}/run.py STAGE --help")
    stages = main.add_subparsers(dest="stage", required=True,
                                 metavar="STAGE")
    defaults = {"build": os.path.join(ROOT, "build"),
                "work": os.path.join(folder(name), "runs")}
    fixed = {"build": "the build folder or the rsfcycle binary (default "
                      "build/)",
             "work": f"scratch run folders (default benchmarks/{name}/"
                     "runs/, not tracked)"}
    for function in functions:
        summary = " ".join((function.__doc__ or "").strip().split("\n\n")[0]
                           .split())
        sub = stages.add_parser(function.__name__.rstrip("_").replace(
            "_", "-"), help=summary or None,
            description=(function.__doc__ or "").strip(),
            formatter_class=argparse.RawDescriptionHelpFormatter)
        helps = _option_help(function)
        for p in inspect.signature(function).parameters.values():
            flag = "--" + p.name.rstrip("_").replace("_", "-")
            if p.kind is p.VAR_POSITIONAL:
                sub.add_argument(p.name, nargs="*", metavar=p.name.upper(),
                                 help=helps.get(p.name))
            elif p.name in defaults:
                sub.add_argument(flag, default=defaults[p.name],
                                 metavar="DIR", help=fixed[p.name])
            elif p.annotation == "?":
                sub.add_argument(p.name, nargs="?", default=p.default,
                                 metavar=p.name.upper(),
                                 help=helps.get(p.name))
            elif p.default is p.empty:
                kind = p.annotation if callable(p.annotation) and \
                    p.annotation is not p.empty else str
                sub.add_argument(p.name, type=kind, metavar=p.name.upper(),
                                 help=helps.get(p.name))
            elif isinstance(p.default, bool):
                sub.add_argument(flag, action="store_true", dest=p.name,
                                 help=helps.get(p.name))
            else:
                extra = {"choices": p.annotation} \
                    if isinstance(p.annotation, tuple) else \
                    {"type": type(p.default),
                     "metavar": p.name.rstrip("_").upper()}
                sub.add_argument(flag, default=p.default, **extra,
                                 dest=p.name,
                                 help=(helps.get(p.name, "") + (
                                     f" (default {p.default})"
                                     if p.default != "" else "")).strip())
        sub.set_defaults(function=function)
    args = vars(main.parse_args(argv))
    function = args.pop("function")
    args.pop("stage")
    parameters = list(inspect.signature(function).parameters.values())
    positional = []
    for k, p in enumerate(parameters):
        if p.kind is p.VAR_POSITIONAL:  # what precedes it goes by position
            positional = [args.pop(q.name) for q in parameters[:k]] + \
                list(args.pop(p.name))
    return function(*positional, **args)


def executable(build):
    """The rsfcycle binary of a build folder (or the binary given); exits
    with one line when it is not built."""
    path = build if os.path.isfile(build) else os.path.join(build,
                                                            "rsfcycle")
    if not os.access(path, os.X_OK):
        die(f"{path}: not built (cmake -S . -B build && cmake --build "
            "build)")
    return os.path.abspath(path)


def environment(variable, what):
    """The value of an environment variable that locates a peer; exits
    with one line when it is not set."""
    value = os.environ.get(variable)
    if not value:
        die(f"set {variable} to {what}")
    return value


def work(path):
    """The scratch folder, created."""
    os.makedirs(path, exist_ok=True)
    return os.path.abspath(path)


def mpi_environment():
    """The environment for mpirun (Open MPI also as root)."""
    return dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
                OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def mpirun(ranks, command):
    """The command on `ranks` MPI ranks (oversubscribing allowed)."""
    return ["mpirun", "--oversubscribe", "-np", str(ranks)] + list(command)


def run(command, log, cwd=None, nice=None, timeout=None, env=None,
        check=True):
    """Run a command with its screen output to the file `log`; returns
    (wall time [s], exit status). `nice` lowers its priority; after
    `timeout` seconds it is stopped (status 124)."""
    command = [str(c) for c in command]
    if nice is not None:
        command = ["nice", "-n", str(nice)] + command
    start = time.monotonic()
    with open(log, "w") as out:
        try:
            status = subprocess.run(command, stdout=out,
                                    stderr=subprocess.STDOUT, cwd=cwd,
                                    env=env, timeout=timeout,
                                    check=check).returncode
        except subprocess.TimeoutExpired:
            status = 124
    return time.monotonic() - start, status


def rsfcycle(exe, arguments, log, **options):
    """Run rsfcycle with `arguments` (run() options); the wall time [s]."""
    return run([exe] + list(arguments), log, **options)[0]


def run_variant(exe, base, folder, entries=None, ranks=1, log=None):
    """Write FOLDER.prm (rsfcycle.prm.variant of the parameter file `base`
    with `entries`, its output folder FOLDER) and run `exe --force` on it
    on `ranks` MPI ranks, the screen output to `log` (default FOLDER.log).
    FOLDER/run-context.json then keeps the commit, the date and the load
    measured before the run started, and the ranks (context_of reads it),
    also when the run was stopped by Ctrl-C or SIGTERM (it has written its
    checkpoint: `rsfcycle --resume FOLDER` goes on). Returns the wall time
    [s]; raises CalledProcessError if the run failed."""
    folder = os.path.abspath(folder)
    path = prm.variant(folder + ".prm", base, folder, entries)
    context = results.run_context(ROOT)
    command = [exe, "--force", path]
    if ranks > 1:
        command = mpirun(ranks, command)
    # Ctrl-C at the terminal reaches rsfcycle, which writes its checkpoint
    # and stops; this process waits for it instead of stopping first (its
    # handler is not inherited by rsfcycle)
    previous = signal.signal(signal.SIGINT, lambda number, frame: None)
    try:
        seconds, status = run(command, log or folder + ".log",
                              env=mpi_environment(), check=False)
    finally:
        signal.signal(signal.SIGINT, previous)
    stopped = status in (128 + signal.SIGINT, 128 + signal.SIGTERM)
    if status != 0 and not stopped:
        raise subprocess.CalledProcessError(status, command)
    if stopped:
        print(f"{folder}: stopped; rsfcycle --resume {folder} goes on")
    context["cores"] = ranks
    with open(os.path.join(folder, "run-context.json"), "w",
              encoding="utf-8") as f:
        json.dump(context, f)
    return seconds


def context_of(folder):
    """(context, cores) of an rsfcycle run folder for results.record:
    commit, date, load and ranks from run-context.json (run_variant); else
    the commit and ranks of its log.txt, the day its log.txt was last
    written and no load."""
    path = os.path.join(folder, "run-context.json")
    if os.path.exists(path):
        with open(path, encoding="utf-8") as f:
            context = json.load(f)
        return context, int(context.pop("cores", 1))
    log = os.path.join(folder, "log.txt")
    words = text(log) if os.path.exists(log) else ""
    commit = re.search(r"commit ([0-9a-f]{7,}(?:-dirty)?)", words)
    ranks = re.search(r"MPI ranks: (\d+)", words)
    stamp = os.path.getmtime(log if os.path.exists(log) else folder)
    context = {"commit": commit.group(1)[:7] + ("-dirty" if commit.group(
        1).endswith("-dirty") else "") if commit else "unknown",
               "date": time.strftime("%Y-%m-%d", time.localtime(stamp)),
               "load": ""}
    return context, int(ranks.group(1)) if ranks else 1


def text(path):
    """A file's text."""
    with open(path, encoding="utf-8", errors="replace") as f:
        return f.read()


def duration(seconds):
    """(value, unit) as results.csv writes wall times: '9 min 05' s,
    '6 h 02' min."""
    seconds = int(round(seconds))
    if seconds < 3600:
        return f"{seconds // 60} min {seconds % 60:02d}", "s"
    return f"{seconds // 3600} h {seconds % 3600 // 60:02d}", "min"


def timer_sections(log):
    """{section: wall time [s]} of the first TimerOutput table in a run's
    screen output (on several ranks: rank 0's)."""
    sections = {}
    for name, seconds in re.findall(r"^\|\s*([^|]*?)\s*\|\s*\d+\s*\|\s*"
                                    r"([0-9.e+-]+)s\s*\|", log, re.M):
        sections.setdefault(name, float(seconds))
    total = re.search(r"Total wallclock time elapsed since start\s*\|\s*"
                      r"([0-9.e+-]+)s", log)
    if total:
        sections["Total"] = float(total.group(1))
    return sections


def timer_spread(log, section):
    """(min, max) over the ranks of a TimerOutput section, from the
    statistics table of a run on several ranks; None without one."""
    m = re.search(r"\|\s*" + re.escape(section) + r"\s+\|\s+\d+\s+\|\s+"
                  r"([0-9.e+-]+)s\s+\d+\s+\|\s+[0-9.e+-]+s\s+\|\s+"
                  r"([0-9.e+-]+)s", log)
    return (float(m.group(1)), float(m.group(2))) if m else None


def loop_time(log):
    """'Wall time of the time loop: X s' of a run's screen output [s], or
    None."""
    m = re.search(r"Wall time of the time loop: (\S+) s", log)
    return float(m.group(1)) if m else None


def mesh(log):
    """The mesh of a run's screen output or log.txt: cells, levels,
    unknowns, contact_nodes and the smallest and largest cell diameter
    [m] (cell_min, cell_max), those it states."""
    out = {}
    m = re.search(r"Mesh: (\d+) cells, (\d+) levels, (\d+) unknowns, "
                  r"(\d+) contact nodes", log)
    if m:
        out.update(zip(("cells", "levels", "unknowns", "contact_nodes"),
                       (int(x) for x in m.groups())))
    elif re.search(r"(\d+) unknowns", log):
        out["unknowns"] = int(re.search(r"(\d+) unknowns", log).group(1))
    m = re.search(r"Cell diameters: ([0-9.e+-]+) m to ([0-9.e+-]+) m", log)
    if m:
        out["cell_min"], out["cell_max"] = float(m.group(1)), \
            float(m.group(2))
    return out


def wedge_variant(path, out, depth, end, entries=None, pinned=True):
    """A parameter file of the 2D wedge for the benchmarks' measurements:
    prm/wedge-2d.prm with tests/wedge-2d-pinned.prm (Refinement distance
    1.5, δ = ε = 1e-5, direct correction) unless not `pinned`, 2 global
    and `depth` local refinements, End time `end`, no VTU, no progress
    lines, no timed checkpoints, then `entries` ('Subsection/Entry' ->
    value). Returns the path."""
    settings = {"End time": end, "Mesh/Global refinements": 2,
                "Mesh/Local refinements": depth,
                "Output/Writers": "time series, base profile, events",
                "Output/Progress interval": "1e9",
                "Output/Checkpoint minutes": "1e6"}
    settings.update(entries or {})
    includes = [os.path.join(ROOT, "tests", "wedge-2d-pinned.prm")] \
        if pinned else []
    return prm.variant(path, os.path.join(ROOT, "prm", "wedge-2d.prm"), out,
                       settings, includes)


def resume(exe, preload, out, entries, log):
    """Continue the run folder `preload` (which ends with a checkpoint) in
    a copy `out` with other entries: out/parameters.prm includes the
    preload's and sets `entries`; then rsfcycle --resume out. Returns the
    wall time [s]."""
    shutil.rmtree(out, ignore_errors=True)
    shutil.copytree(preload, out)
    os.replace(os.path.join(out, "parameters.prm"),
               os.path.join(out, "preload.prm"))
    prm.variant(os.path.join(out, "parameters.prm"),
                os.path.join(out, "preload.prm"), out, entries)
    return rsfcycle(exe, ["--resume", out], log)


def repeat_loop(exe, prm_file, log, repeat=3):
    """Run a parameter file `repeat` times; (the shortest 'Wall time of
    the time loop' [s], the last run's screen output)."""
    walls = []
    for _ in range(repeat):
        rsfcycle(exe, [prm_file], log)
        walls.append(loop_time(text(log)))
    return min(w for w in walls if w is not None), text(log)


def step_counts(series, after=None):
    """Counts of a time series (rsfcycle.run.time_series) over the rows
    after the time `after`: steps, spatial problems, fixed-point, TNNMG
    and linear iterations per step (max, mean), their totals over all
    spatial problems."""
    if after is not None:
        series = series[series["time_s"] > after + 1e-9]
    steps = len(series)
    out = {"steps": steps,
           "spatial_problems": int(series["spatial_problems"].sum())}
    for column in ("fixed_point_iterations", "tnnmg_iterations",
                   "linear_iterations"):
        out[column] = (int(series[column].max()) if steps else 0,
                       float(series[column].mean()) if steps else 0.0)
    for column in ("all_tnnmg_iterations", "all_linear_iterations"):
        out[column] = int(series[column].sum())
    return out


def read_table(path):
    """A CSV file as a list of dicts (the values as text)."""
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def write_table(path, fields, rows):
    """Write rows (dicts) as a CSV file with the columns `fields`."""
    with open(path, "w", newline="", encoding="utf-8") as f:
        writer = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)


def markdown(header, rows):
    """A Markdown table: the header cells and rows of cells."""
    lines = ["| " + " | ".join(str(h) for h in header) + " |",
             "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines) + "\n"


def record(name, figures, cores=1, context=None):
    """Write figures [(key, value, unit, description)] into
    benchmarks/NAME/results.csv with the run's context (commit, date,
    load; rsfcycle.results.run_context by default)."""
    context = context or results.run_context(ROOT)
    for key, value, unit, description in figures:
        results.record(folder(name), key, value, unit, description, cores,
                       context)


def wedge_statistics(folder, skip=8):
    """The event statistics of a 2D wedge run folder that the convergence
    and sensitivity studies compare: rsfcycle.events.means over the events
    after the first `skip`, the peak slip rate also in mm/s
    (peak_slip_rate_mm_per_s), and the run's unknowns, smallest cell
    (patch_cell_mm), time loop (wall_s, TimerOutput "Time stepping") and
    accepted steps."""
    from rsfcycle import events, run
    row = events.means(folder, skip)
    row["peak_slip_rate_mm_per_s"] = 1e3 * row["peak_slip_rate_m_per_s"]
    found = mesh(text(os.path.join(folder, "log.txt")))
    row["unknowns"] = found.get("unknowns")
    row["patch_cell_mm"] = 1e3 * found["cell_min"] if "cell_min" in found \
        else None
    row["wall_s"] = run.section_time(folder, "Time stepping")
    row["steps"] = len(run.time_series(folder))
    return row
