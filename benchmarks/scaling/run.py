#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Distributed runs on 1, 2 (and 4, oversubscribed) MPI ranks, one after
the other in one invocation:

  2d     prm/wedge-2d-paper.prm (2 + 8 refinements, 30,232 unknowns) from
         t = 0 to --end-2d (default 530 s: the loading and the first events)
  3d     prm/wedge-3d.prm (2 + 3 refinements, 54,543 unknowns) from t = 0
         to --end-3d (default 40 s of the loading ramp)
  big    the 3D wedge at 3 + 3 refinements (230k unknowns), --end-big
         seconds (default 0.05 s: a few steps) on 2 ranks: set-up, memory
         per rank, time per cycle and unknown
  small  prm/wedge-2d.prm at 3 + 3 refinements (2,416 unknowns) over
         1000 s with the multigrid correction, for the event catalogue on
         every number of ranks (stage catalogues)

Every run uses the multigrid correction and writes no VTU. Per run
(runs.csv): the time loop (TimerOutput "Time stepping") and the set-up,
the per-rank minimum and maximum of the TNNMG sections, the maximum
resident memory per rank (/usr/bin/time), steps, spatial problems, TNNMG
iterations per spatial problem, multigrid cycles per TNNMG iteration,
fixed-point iterations per step (max), the events. Runs of one invocation
share the machine: read the ratios. The million-unknown run of the README
(4 + 3 refinements, Refinement distance 2, 9 GB per rank) is run by hand.

Stages (from the repository's root, PYTHONPATH=python /usr/bin/python3
benchmarks/scaling/run.py STAGE ...):

  runs        the parts on the ranks (all parts: about 15 minutes plus
              the small runs' 1000 s); rows of earlier invocations kept
  table       the table of runs.csv
  figures     figures/scaling.png: speed-up and iterations against ranks
  catalogues  the event catalogues of runs on several ranks against the
              first (exit 1 if they differ by more than 1 ms, 0.5 %)
"""
import math
import os
import re
import shutil

from rsfcycle import bench, events, prm, results, run

NAME = "scaling"
HERE = bench.folder(NAME)
RUNS = os.path.join(HERE, "runs.csv")
FIELDS = ["case", "ranks", "unknowns", "end_time_s", "wall_s", "loop_s",
          "setup_s", "steps", "problems", "tnnmg_per_problem",
          "cycles_per_tnnmg", "max_fixed_point", "events", "first_start_s",
          "peak_log10_v_over_v0", "max_rss_mb_per_rank", "smoother_s_min_max",
          "correction_s_min_max", "line_search_s_min_max", "imbalance",
          "commit"]
PARTS = {  # base file, entries
    "2d": ("wedge-2d-paper.prm", {}),
    "3d": ("wedge-3d.prm", {"Stop after events": 0}),
    "big": ("wedge-3d.prm", {"Stop after events": 0,
                             "Mesh/Global refinements": 3,
                             "Mesh/Local refinements": 3}),
    "small": ("wedge-2d.prm", {"Mesh/Global refinements": 3,
                               "Mesh/Local refinements": 3,
                               "Solver/Linear correction": "multigrid"}),
}


def min_max(log, name):
    """min/max of a section over the ranks, or rank 0's time twice."""
    spread = bench.timer_spread(log, name)
    if spread is None:
        t = bench.timer_sections(log).get(name, math.nan)
        spread = (t, t)
    return f"{spread[0]:.3g}/{spread[1]:.3g}"


def one_run(exe, case, ranks, end, work):
    """One run of a part on `ranks` ranks; its row of runs.csv."""
    out = os.path.join(work, f"{case}-{ranks}")
    base, entries = PARTS[case]
    settings = {"End time": end, "Output/Writers": "time series, base profile, events",
                "Output/Progress interval": "1e9",
                "Output/Checkpoint minutes": "1e6"}
    settings.update(entries)
    path = prm.variant(out + ".prm", os.path.join(bench.ROOT, "prm", base),
                       out, settings)
    wall, _ = bench.run(bench.mpirun(ranks, ["/usr/bin/time", "-f",
                                             "max_rss_kb %M", exe, path]),
                        out + ".log", env=bench.mpi_environment())
    log = bench.text(out + ".log")
    sections = bench.timer_sections(log)
    rss = [int(x) / 1024 for x in re.findall(r"max_rss_kb (\d+)", log)]
    summary = re.search(r"Summary: (\d+) steps, (\d+) spatial problems, (\d+) "
                        r"events.*max fixed-point iterations (\d+)", log)
    counts = bench.step_counts(run.time_series(out))
    problems = int(summary.group(2))
    found = events.read(out) or []
    v0 = float(run.parameters(out)["Wedge/Convergence rate"])
    imbalance = re.search(r"workload imbalance over the ranks: ([0-9.]+)",
                          log)
    setup = sum(sections.get(s, 0) for s in
                ("Setup", "Normal stress", "Linear correction setup"))
    tnnmg = counts["all_tnnmg_iterations"]
    cycles = counts["all_linear_iterations"]
    peak = max((e.peak for e in found), default=math.nan)
    return dict(
        case=case, ranks=ranks, unknowns=bench.mesh(log)["unknowns"],
        end_time_s=end, wall_s=f"{wall:.1f}",
        loop_s=f"{sections.get('Time stepping', math.nan):.2f}",
        setup_s=f"{setup:.2f}", steps=summary.group(1), problems=problems,
        tnnmg_per_problem=f"{tnnmg / problems:.3f}",
        cycles_per_tnnmg=f"{cycles / max(tnnmg, 1):.3f}",
        max_fixed_point=summary.group(4), events=summary.group(3),
        first_start_s=f"{found[0].start:.17g}" if found else "",
        peak_log10_v_over_v0=f"{math.log10(peak / v0):.5f}" if found else "",
        max_rss_mb_per_rank="/".join(f"{x:.0f}" for x in rss),
        smoother_s_min_max=min_max(log, "TNNMG: nonlinear smoother"),
        correction_s_min_max=min_max(log, "TNNMG: linear correction"),
        line_search_s_min_max=min_max(log, "TNNMG: line search"),
        imbalance=imbalance.group(1) if imbalance else "1",
        commit=results.run_context(bench.ROOT)["commit"])


def runs(parts="2d,3d,big", ranks="1,2,4", end_2d=530.0, end_3d=40.0,
         end_big=0.05, build="", work=""):
    """The parts on 1, 2 and 4 ranks, one after the other, into runs.csv.

    parts: of 2d, 3d, big, small
    ranks: the numbers of ranks (big: 2 only)
    end_2d: end time of 2d [s]
    end_3d: end time of 3d [s]
    end_big: end time of big [s]
    """
    work = bench.work(work)
    exe = os.path.join(work, "rsfcycle")  # a copy: rebuilding cannot touch it
    shutil.copy(bench.executable(build), exe)
    numbers = [int(r) for r in ranks.split(",")]
    ends = {"2d": end_2d, "3d": end_3d, "big": end_big, "small": 1000}
    rows = []
    for case in parts.split(","):
        for n in (numbers if case != "big" else [2]):
            row = one_run(exe, case, n, ends[case], work)
            print(", ".join(f"{k}={row[k]}" for k in FIELDS), flush=True)
            rows.append(row)
    done = {(r["case"], str(r["ranks"])) for r in rows}
    old = [r for r in bench.read_table(RUNS)
           if (r["case"], r["ranks"]) not in done] \
        if os.path.exists(RUNS) else []
    bench.write_table(RUNS, FIELDS, old + rows)
    table()


def table():
    """The table of runs.csv."""
    rows = bench.read_table(RUNS)
    head = ["case", "ranks", "unknowns", "loop_s", "speed-up", "steps",
            "problems", "tnnmg_per_problem", "cycles_per_tnnmg",
            "max_fixed_point", "events", "first_start_s",
            "peak_log10_v_over_v0", "max_rss_mb_per_rank",
            "smoother_s_min_max", "correction_s_min_max", "imbalance"]
    for r in rows:
        one = [x for x in rows if x["case"] == r["case"] and x["ranks"] == "1"]
        r["speed-up"] = (f"{float(one[0]['loop_s']) / float(r['loop_s']):.2f}"
                         if one else "")
    print(bench.markdown(head, [[r[h] for h in head] for r in rows]), end="")


def figures():
    """figures/scaling.png: speed-up and iterations against the ranks."""
    from rsfcycle.plot import _pyplot, savefig
    plt = _pyplot()
    rows = bench.read_table(RUNS)
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for case, marker in (("2d", "o"), ("3d", "s")):
        chosen = sorted((r for r in rows if r["case"] == case),
                        key=lambda r: int(r["ranks"]))
        if not chosen:
            continue
        n = [int(r["ranks"]) for r in chosen]
        t = [float(r["loop_s"]) for r in chosen]
        label = f"{case} wedge, {chosen[0]['unknowns']} unknowns"
        ax[0].plot(n, [t[0] / x for x in t], marker + "-", label=label)
        ax[1].plot(n, [float(r["tnnmg_per_problem"]) for r in chosen],
                   marker + "-", label=label + ": TNNMG/problem")
        ax[1].plot(n, [float(r["cycles_per_tnnmg"]) for r in chosen],
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
    savefig(fig, os.path.join(HERE, "figures", "scaling.png"), dpi=120)


def catalogues(reference_run, *run):
    """events.csv of runs on several ranks against the first's.

    Agreement: the same count, starts within 1 ms, peak slip rates and
    slips within 0.5 %; exit 1 otherwise.

    reference_run: e.g. WORK/small-1
    run: the others, e.g. WORK/small-2 WORK/small-3
    """
    reference = events.read(reference_run) or []
    print(f"{reference_run}: {len(reference)} events")
    agree = True
    for folder in run:
        d = events.differences(events.read(folder) or [], reference)
        good = (d["events"] == d["reference_events"] and d["start"] <= 1e-3
                and d["peak"] <= 5e-3 and d["slip"] <= 5e-3)
        agree = agree and good
        print(f"{folder}: {d['events']} events, starts within "
              f"{1e3 * d['start']:.3f} ms, peak slip rates within "
              f"{100 * d['peak']:.4f} %, slips within {100 * d['slip']:.4f} "
              f"% ({'agree' if good else 'DIFFER'}: same count, 1 ms, 0.5 %)")
    return 0 if agree else 1


if __name__ == "__main__":
    raise SystemExit(bench.cli(__doc__, NAME, [runs, table, figures,
                                               catalogues]))
