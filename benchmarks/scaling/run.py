#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Distributed runs on 1, 2 (and 4, oversubscribed) MPI ranks, side by side
in one invocation:

  2d   prm/wedge-2d-paper.prm (2 + 8 refinements, 30,232 unknowns) from
       t = 0 to --end-2d (default 530 s: the interseismic loading and the
       first events);
  3d   prm/wedge-3d.prm (2 + 3 refinements, 54,543 unknowns) from t = 0 to
       --end-3d (default 40 s of the loading ramp);
  big  the 3D wedge at 3 global + 3 local refinements (230k unknowns),
       --end-big seconds (default 0.05 s: a few time steps) on 2 ranks:
       set-up, memory per rank, time per multigrid cycle and unknown. The
       1.15M-unknown run of README.md is the same at 4 + 3 refinements with
       Refinement distance = 2 (9 GB per rank: run by hand).

Every run uses the multigrid linear correction (the default of both .prm
files) and writes no VTU. Reported per run: wall time of the time loop
(TimerOutput "Time stepping") and of the set-up, the per-rank minimum and
maximum of every TimerOutput section, maximum resident memory per rank
(/usr/bin/time), steps, spatial problems, TNNMG iterations per spatial
problem, multigrid cycles per TNNMG iteration, fixed-point iterations per
step (max) and the events (start, peak slip rate, slip). Runs of one
invocation follow each other on the same machine: read the ratios.

Usage: benchmarks/scaling/run.py [BUILD_DIR] --work DIR [--parts 2d,3d,big]
           [--ranks 1,2,4] [--end-2d T] [--end-3d T] [--end-big T]
       benchmarks/scaling/run.py --table | --plot
DIR (or the environment's SCALING_WORK) holds the run folders and a copy of
the binary. Runs: benchmarks/scaling/runs.csv (one row per run, rows of
earlier invocations kept); --plot draws benchmarks/scaling/figures/
scaling.png.
"""
import csv
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
RUNS = os.path.join(HERE, "runs.csv")
FIELDS = ["case", "ranks", "unknowns", "end_time_s", "wall_s", "loop_s",
          "setup_s", "steps", "problems", "tnnmg_per_problem",
          "cycles_per_tnnmg", "max_fixed_point", "events", "first_start_s",
          "peak_log10_v_over_v0", "max_rss_mb_per_rank", "smoother_s_min_max",
          "correction_s_min_max", "line_search_s_min_max", "imbalance",
          "commit"]


def mpi_env():
    env = dict(os.environ)
    env["OMPI_ALLOW_RUN_AS_ROOT"] = "1"
    env["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] = "1"
    return env


def prm_text(case, end, out):
    if case == "2d":
        base, extra = "wedge-2d-paper.prm", ""
    elif case == "3d":
        base, extra = "wedge-3d.prm", "set Stop after events = 0\n"
    else:
        base = "wedge-3d.prm"
        extra = ("set Stop after events = 0\nsubsection Mesh\n"
                 "  set Global refinements = 3\n"
                 "  set Local refinements = 3\nend\n")
    return (f"include {ROOT}/prm/{base}\nset End time = {end}\n"
            f"set Output directory = {out}\nset Overwrite output = true\n"
            f"{extra}subsection Output\n  set Write VTU = false\n"
            "  set Progress interval = 1e9\n  set Checkpoint minutes = 1e6\n"
            "end\n")


def section(log, name):
    """Total wall time of a TimerOutput section of the first rank [s]."""
    m = re.search(r"\| " + re.escape(name) + r"\s+\|\s+\d+\s+\|\s+"
                  r"([0-9.e+-]+)s", log)
    return float(m.group(1)) if m else float("nan")


def min_max(log, name):
    """min/max over ranks from print_wall_time_statistics, or the one
    rank's time twice."""
    m = re.search(r"\| " + re.escape(name) + r"\s+\|\s+\d+\s+\|\s+"
                  r"([0-9.e+-]+)s\s+\d+\s+\|\s+[0-9.e+-]+s\s+\|\s+"
                  r"([0-9.e+-]+)s", log)
    if m:
        return f"{float(m.group(1)):.3g}/{float(m.group(2)):.3g}"
    t = section(log, name)
    return f"{t:.3g}/{t:.3g}"


def one_run(exe, case, ranks, end, work):
    name = f"{case}-{ranks}"
    out = os.path.join(work, name)
    prm = os.path.join(work, name + ".prm")
    open(prm, "w").write(prm_text(case, end, out))
    log_file = os.path.join(work, name + ".log")
    command = ["mpirun", "--oversubscribe", "-np", str(ranks),
               "/usr/bin/time", "-f", "max_rss_kb %M", exe, prm]
    start = time.time()
    with open(log_file, "w") as f:
        subprocess.run(command, stdout=f, stderr=subprocess.STDOUT,
                       check=True, env=mpi_env())
    wall = time.time() - start
    log = open(log_file).read()
    rss = [int(x) / 1024 for x in re.findall(r"max_rss_kb (\d+)", log)]
    unknowns = int(re.search(r"(\d+) unknowns", log).group(1))
    summary = re.search(r"Summary: (\d+) steps, (\d+) spatial problems, (\d+) "
                        r"events.*max fixed-point iterations (\d+)", log)
    rows = list(csv.DictReader(open(os.path.join(out, "time-series.csv"))))
    tnnmg = sum(int(r["all_tnnmg_iterations"]) for r in rows)
    cycles = sum(int(r["all_linear_iterations"]) for r in rows)
    problems = int(summary.group(2))
    events = list(csv.DictReader(open(os.path.join(out, "events.csv"))))
    v0 = 5e-5  # Wedge/Convergence rate of both .prm files
    peak = max((float(e["peak_slip_rate_m_per_s"]) for e in events),
               default=float("nan"))
    imbalance = re.search(r"workload imbalance over the ranks: ([0-9.]+)",
                          log)
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short",
                             "HEAD"], capture_output=True,
                            text=True).stdout.strip()
    import math
    return dict(
        case=case, ranks=ranks, unknowns=unknowns, end_time_s=end,
        wall_s=f"{wall:.1f}", loop_s=f"{section(log, 'Time stepping'):.2f}",
        setup_s=f"{section(log, 'Setup') + section(log, 'Normal stress') + section(log, 'Linear correction setup'):.2f}",
        steps=summary.group(1), problems=problems,
        tnnmg_per_problem=f"{tnnmg / problems:.3f}",
        cycles_per_tnnmg=f"{cycles / max(tnnmg, 1):.3f}",
        max_fixed_point=summary.group(4), events=summary.group(3),
        first_start_s=(events[0]["start_s"] if events else ""),
        peak_log10_v_over_v0=(f"{math.log10(peak / v0):.5f}"
                              if events else ""),
        max_rss_mb_per_rank="/".join(f"{x:.0f}" for x in rss),
        smoother_s_min_max=min_max(log, "TNNMG: nonlinear smoother"),
        correction_s_min_max=min_max(log, "TNNMG: linear correction"),
        line_search_s_min_max=min_max(log, "TNNMG: line search"),
        imbalance=(imbalance.group(1) if imbalance else "1"),
        commit=commit)


def main():
    args = sys.argv[1:]
    if "-h" in args or "--help" in args:
        print(__doc__)
        return
    if "--table" in args:
        return table()
    if "--plot" in args:
        return plot()
    opts = {"--parts": "2d,3d,big", "--ranks": "1,2,4", "--end-2d": "530",
            "--end-3d": "40", "--end-big": "0.05",
            "--work": os.environ.get("SCALING_WORK", "")}
    build = os.path.join(ROOT, "build")
    i = 0
    while i < len(args):
        if args[i] in opts:
            opts[args[i]] = args[i + 1]
            i += 2
        else:
            build = args[i]
            i += 1
    work = opts["--work"]
    if not work:
        sys.exit("run.py: where should the runs go? Give --work DIR or set "
                 "SCALING_WORK=DIR")
    os.makedirs(work, exist_ok=True)
    exe = os.path.join(work, "rsfcycle")
    shutil.copy(os.path.join(build, "rsfcycle"), exe)
    ranks = [int(r) for r in opts["--ranks"].split(",")]
    results = []
    for case in opts["--parts"].split(","):
        end = float(opts["--end-" + case])
        for n in (ranks if case != "big" else [2]):
            row = one_run(exe, case, n, end, work)
            print(", ".join(f"{k}={row[k]}" for k in FIELDS), flush=True)
            results.append(row)
    old = []
    if os.path.exists(RUNS):
        done = {(r["case"], r["ranks"]) for r in
                ({"case": x["case"], "ranks": str(x["ranks"])}
                 for x in results)}
        old = [r for r in csv.DictReader(open(RUNS))
               if (r["case"], r["ranks"]) not in done]
    with open(RUNS, "w", newline="") as f:
        w = csv.DictWriter(f, FIELDS)
        w.writeheader()
        for r in old + results:
            w.writerow(r)


def table():
    rows = list(csv.DictReader(open(RUNS)))
    head = ["case", "ranks", "unknowns", "loop_s", "speed-up", "steps",
            "problems", "tnnmg_per_problem", "cycles_per_tnnmg",
            "max_fixed_point", "events", "first_start_s",
            "peak_log10_v_over_v0", "max_rss_mb_per_rank",
            "smoother_s_min_max", "correction_s_min_max", "imbalance"]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for r in rows:
        one = [x for x in rows if x["case"] == r["case"] and x["ranks"] == "1"]
        r["speed-up"] = (f"{float(one[0]['loop_s']) / float(r['loop_s']):.2f}"
                         if one else "")
        print("| " + " | ".join(str(r[h]) for h in head) + " |")


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = list(csv.DictReader(open(RUNS)))
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for case, marker in (("2d", "o"), ("3d", "s")):
        sel = sorted((r for r in rows if r["case"] == case),
                     key=lambda r: int(r["ranks"]))
        if not sel:
            continue
        n = [int(r["ranks"]) for r in sel]
        t = [float(r["loop_s"]) for r in sel]
        label = f"{case} wedge, {sel[0]['unknowns']} unknowns"
        ax[0].plot(n, [t[0] / x for x in t], marker + "-", label=label)
        ax[1].plot(n, [float(r["tnnmg_per_problem"]) for r in sel],
                   marker + "-", label=label + ": TNNMG/problem")
        ax[1].plot(n, [float(r["cycles_per_tnnmg"]) for r in sel],
                   marker + "--", label=label + ": cycles/TNNMG")
    ax[0].plot([1, 2], [1, 2], "k:", label="ideal")
    ax[0].axvspan(2.5, 4.5, color="0.9")
    ax[0].text(2.6, 1.05, "4 ranks on 2 cores\n(oversubscribed)", fontsize=8)
    ax[0].set_xlabel("MPI ranks")
    ax[0].set_ylabel("speed-up of the time loop")
    ax[0].legend(fontsize=7)
    ax[1].set_xlabel("MPI ranks")
    ax[1].set_ylabel("iterations")
    ax[1].legend(fontsize=7)
    fig.tight_layout()
    os.makedirs(os.path.join(HERE, "figures"), exist_ok=True)
    fig.savefig(os.path.join(HERE, "figures", "scaling.png"), dpi=120)


if __name__ == "__main__":
    main()
