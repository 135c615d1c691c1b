#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Linear corrections and rate/state couplings of rsfcycle, compared in one run.

For each refinement depth of the 2D wedge (prm/wedge-2d.prm with
`Global refinements` = 2 and `Local refinements` = DEPTHS):
  1. preload: one run from t = 0 to T0 (just before the first event, at
     ~529 s) with the direct correction; it ends with a checkpoint;
  2. the window [T0, T1] (with the first two events) is resumed from copies
     of that checkpoint once per alternative:
       multigrid, direct, amg (fixed-point coupling, eps = delta = 1e-5),
     and, on the depth EXPLICIT_DEPTH, explicit decoupling at
     delta = 1e-5, 1e-6, 1e-7 against the fixed-point iteration at
     eps = delta = 1e-5 and 1e-7 (the reference for the event times).
Only the window is measured: wall time, time steps, spatial problems
(TNNMG solves), fixed-point iterations per step (max, mean), TNNMG
iterations and multigrid cycles per step and per spatial problem (max,
mean), time per cycle per unknown. All runs share the machine in this one
script, so the ratios are what to read; runs.csv holds every row,
doc/figures/solvers-cost.png the cost
against N.

Usage: benchmarks/solvers/run.py [BUILD_DIR] [--depths 2,3,4,5,6]
                                 [--work DIR] [--reuse-preload]
                                 [--variants multigrid,direct] [--append]
       benchmarks/solvers/run.py --table    (markdown tables of runs.csv)
       benchmarks/solvers/run.py --plot     (doc/figures/solvers-cost.png)
"""
import csv
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.dirname(HERE))
import common  # noqa: E402  (benchmarks/common.py)
T0, T1 = 520.0, 540.0
EXPLICIT_DEPTH = 3


def arg(name, default):
    if name in sys.argv:
        return sys.argv[sys.argv.index(name) + 1]
    return default


BUILD = next((a for a in sys.argv[1:] if not a.startswith("--") and
              a not in (arg("--depths", ""), arg("--work", ""),
                        arg("--variants", ""))),
             os.path.join(ROOT, "build"))
EXE = os.path.join(BUILD, "rsfcycle")
DEPTHS = [int(d) for d in arg("--depths", "2,3,4,5").split(",")]
WORK = arg("--work", os.path.join(HERE, "work"))
# reuse existing preload checkpoints of WORK (same depths, same T0)
REUSE = "--reuse-preload" in sys.argv
# AMG is compared on the coarser meshes only (it crawls beyond, see README)
AMG_MAX_DEPTH = 5
# --append: keep the rows of runs.csv for other depths;
# --variants a,b: run only these alternatives
APPEND = "--append" in sys.argv
ONLY = [v for v in arg("--variants", "").split(",") if v]


def base_prm(depth, out, end, extra=""):
    return common.wedge_prm(ROOT, depth, out, end, extra)


def run(args, log):
    return common.run(EXE, args, log)


set_entry = common.set_entry


def window(depth, name, entries):
    pre = os.path.join(WORK, f"pre-{depth}")
    out = os.path.join(WORK, f"{name}-{depth}")
    shutil.rmtree(out, ignore_errors=True)
    shutil.copytree(pre, out)
    prm = os.path.join(out, "parameters.prm")
    set_entry(prm, "End time", T1)
    set_entry(prm, "Output directory", out)
    for key, value in entries.items():
        set_entry(prm, key, value)
    wall = run(["--resume", out], out + ".log")
    rows = [r for r in csv.DictReader(open(os.path.join(out,
                                                        "time-series.csv")))
            if float(r["time_s"]) > T0 + 1e-9]
    log = open(out + ".log").read()
    n = int(log.split(" unknowns")[0].split()[-1])
    # the time loop alone (TimerOutput section "Time stepping"): without
    # the program start and the set-up, which do not scale with the cycles
    stepping = common.stepping_time(log)
    fp = [int(r["fixed_point_iterations"]) for r in rows]
    tn = [int(r["tnnmg_iterations"]) for r in rows]
    li = [int(r["linear_iterations"]) for r in rows]
    problems = sum(int(r["spatial_problems"]) for r in rows)
    all_tn = sum(int(r["all_tnnmg_iterations"]) for r in rows)
    all_li = sum(int(r["all_linear_iterations"]) for r in rows)
    events = [e for e in csv.DictReader(open(os.path.join(out, "events.csv")))
              if float(e["start_s"]) > T0]
    return dict(depth=depth, name=name, unknowns=n, wall_s=round(wall, 2),
                steps=len(rows), spatial_problems=problems,
                fp_max=max(fp), fp_mean=round(sum(fp) / len(fp), 2),
                tnnmg_per_step_max=max(tn),
                tnnmg_per_step_mean=round(sum(tn) / len(tn), 2),
                cycles_per_step_max=max(li),
                cycles_per_step_mean=round(sum(li) / len(li), 2),
                cycles_per_problem_mean=round(all_li / problems, 2),
                all_tnnmg=all_tn, all_cycles=all_li,
                time_stepping_s=stepping,
                us_per_cycle_per_unknown=round(1e6 * stepping / all_li / n,
                                               4),
                events=len(events),
                event_starts=" ".join(e["start_s"] for e in events))


def main():
    os.makedirs(WORK, exist_ok=True)
    results = []
    if APPEND:
        results = [r for r in csv.DictReader(open(os.path.join(HERE,
                                                               "runs.csv")))
                   if int(r["depth"]) not in DEPTHS]
    for depth in DEPTHS:
        pre = os.path.join(WORK, f"pre-{depth}")
        prm = os.path.join(WORK, f"pre-{depth}.prm")
        open(prm, "w").write(base_prm(depth, pre, T0, """subsection Solver
  set Linear correction = direct
end"""))
        if REUSE and os.path.exists(os.path.join(pre, "checkpoint.bin")):
            print(f"depth {depth}: reusing the preload in {pre}", flush=True)
        else:
            t = run([prm], pre + ".log")
            print(f"depth {depth}: preload to {T0} s in {t:.0f} s",
                  flush=True)
        variants = {
            "multigrid": {"Linear correction": "multigrid"},
            # every velocity solve to TNNMG tolerance, 2 cycles per
            # correction: the settings before the inexact fixed point
            "multigrid-exact": {"Linear correction": "multigrid",
                                "Inner tolerance factor": 0,
                                "Linear correction cycles": 2},
            "direct": {"Linear correction": "direct"},
        }
        if depth <= AMG_MAX_DEPTH:
            variants["amg"] = {"Linear correction": "amg"}
        if depth == EXPLICIT_DEPTH:
            for d in ["1e-5", "1e-6", "1e-7"]:
                variants[f"explicit-{d}"] = {"Linear correction": "multigrid",
                                             "Coupling": "explicit",
                                             "Tolerance": d}
            variants["fixed-point-1e-7"] = {"Linear correction": "multigrid",
                                            "Tolerance": "1e-7",
                                            "Fixed-point tolerance": "1e-7",
                                            "Inner tolerance factor": 0}
        for name, entries in variants.items():
            if ONLY and name not in ONLY:
                continue
            entries = dict(entries)
            entries.setdefault("Linear correction cycles", 1)
            entries.setdefault("Inner tolerance factor", 0.3)
            entries.setdefault("TNNMG tolerance", "1e-6")
            r = window(depth, name, entries)
            results.append(r)
            print(r, flush=True)
            with open(os.path.join(HERE, "runs.csv"), "w") as f:
                w = csv.DictWriter(f, fieldnames=list(results[0].keys()))
                w.writeheader()
                w.writerows(results)
    plot(results)


def plot(results):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for name in ["multigrid", "direct", "amg"]:
        rows = [r for r in results if r["name"] == name]
        if not rows:
            continue
        n = [r["unknowns"] for r in rows]
        ax[0].loglog(n, [r["wall_s"] for r in rows], "o-", label=name)
        ax[1].semilogx(n, [r["cycles_per_step_mean"] for r in rows], "o-",
                       label=name + " (mean)")
        ax[1].semilogx(n, [r["cycles_per_step_max"] for r in rows], "x--",
                       label=name + " (max)")
    ax[0].set_xlabel("unknowns N")
    ax[0].set_ylabel(f"wall time of [{T0:g}, {T1:g}] s [s]")
    ax[0].legend()
    ax[1].set_xlabel("unknowns N")
    ax[1].axhline(16, ls=":", color="k", label="the paper's bound, 16")
    ax[1].set_yscale("log")
    ax[1].set_ylabel("linear cycles per time step")
    ax[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "doc", "figures", "solvers-cost.png"),
                dpi=120)


def table(rows):
    """Markdown tables of runs.csv (for the README)."""
    print("| depth | N | correction | wall [s] | steps | FP max/mean | "
          "TNNMG/step mean | cycles/step max/mean | µs/cycle/N | "
          "wall / multigrid |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    mg = {r["depth"]: float(r["wall_s"]) for r in rows
          if r["name"] == "multigrid"}
    for r in rows:
        if r["name"] not in ("multigrid", "multigrid-exact", "direct",
                             "amg"):
            continue
        print(f"| {r['depth']} | {r['unknowns']} | {r['name']} | "
              f"{r['wall_s']} | {r['steps']} | {r['fp_max']}/{r['fp_mean']} "
              f"| {r['tnnmg_per_step_mean']} | {r['cycles_per_step_max']}/"
              f"{r['cycles_per_step_mean']} | "
              f"{r['us_per_cycle_per_unknown']} | "
              f"{float(r['wall_s']) / mg[r['depth']]:.2f} |")
    print()
    ref = [r for r in rows if r["name"] == "fixed-point-1e-7"]
    if not ref:
        return
    t_ref = [float(x) for x in ref[0]["event_starts"].split()]
    depth = ref[0]["depth"]
    print("| coupling | tolerance | wall [s] | steps | spatial problems | "
          "max error of the event starts [ms] |")
    print("|---|---|---|---|---|---|")
    for r in rows:
        if r["depth"] != depth or r["name"] in ("direct", "amg",
                                                "multigrid-exact"):
            continue
        t = [float(x) for x in r["event_starts"].split()]
        err = max(abs(a - b) for a, b in zip(t, t_ref)) * 1e3
        name = "fixed-point" if r["name"] in ("multigrid",
                                              "fixed-point-1e-7") \
            else "explicit"
        tol = "1e-5"
        for prefix in ("explicit-", "fixed-point-"):
            if r["name"].startswith(prefix):
                tol = r["name"][len(prefix):]
        print(f"| {name} | {tol} | {r['wall_s']} | {r['steps']} | "
              f"{r['spatial_problems']} | {err:.2f} |")


if __name__ == "__main__":
    if "-h" in sys.argv or "--help" in sys.argv:
        print(__doc__)
        sys.exit(0)
    if "--table" in sys.argv:
        table(list(csv.DictReader(open(os.path.join(HERE, "runs.csv")))))
    elif "--plot" in sys.argv:
        rows = list(csv.DictReader(open(os.path.join(HERE, "runs.csv"))))
        for r in rows:
            for key in ["unknowns", "wall_s", "cycles_per_step_mean",
                        "cycles_per_step_max"]:
                r[key] = float(r[key])
        plot(rows)
    else:
        main()
