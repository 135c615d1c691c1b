#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Linear corrections and rate/state couplings of rsfcycle, compared.

For each refinement depth of the 2D wedge (prm/wedge-2d.prm with 2 global
and DEPTH local refinements, rsfcycle.bench.wedge_variant):
  1. preload: one run from t = 0 to 520 s (just before the first event)
     with the direct correction; it ends with a checkpoint;
  2. the window [520, 540] s (two or three events) is resumed from a copy
     of that checkpoint once per alternative: multigrid, multigrid-exact
     (every velocity solve to the TNNMG tolerance, 2 cycles), direct, amg
     (depth ≤ 5), and at depth 3 explicit decoupling at δ = 1e-5, 1e-6,
     1e-7 and the fixed point at ε = δ = 1e-7 (the reference of the event
     starts). The paper's step doubling at ε = δ = 1e-5, TNNMG tolerance
     1e-6, one cycle per correction, Inner tolerance factor 0.3 unless the
     variant says otherwise.
Only the window is measured: wall time, steps, spatial problems,
fixed-point iterations per step (max, mean), TNNMG iterations and cycles
per step and per spatial problem, the time loop per cycle and unknown.
All runs of one invocation share the machine: read the ratios.

Stages (from the repository's root, PYTHONPATH=python /usr/bin/python3
benchmarks/solvers/run.py STAGE ...):

  runs       preloads and windows of the depths into WORK, runs.csv, the
             figure (depths 2 – 6: about 15 minutes on one core; depth 7
             adds about 10)
  table      the README's two tables from runs.csv
  figures    doc/figures/solvers-cost.png from runs.csv
  paper-run  prm/wedge-2d-paper.prm over 1000 s with the paper's step
             doubling at δ = ε = 1e-5 and the multigrid correction (about
             2 h 15 min), then its cost per cycle (rsfcycle.events): the
             rows paper_run.*
"""
import os

from rsfcycle import bench, events, prm, run

NAME = "solvers"
HERE = bench.folder(NAME)
RUNS = os.path.join(HERE, "runs.csv")
FIGURE = os.path.join(bench.ROOT, "doc", "figures", "solvers-cost.png")
T0, T1 = 520.0, 540.0
EXPLICIT_DEPTH = 3
AMG_MAX_DEPTH = 5  # AMG crawls beyond (README)
WINDOW = {"Time stepping/Controller": "step-doubling",
          "Solver/Linear correction cycles": 1,
          "Solver/Inner tolerance factor": 0.3,
          "Solver/TNNMG tolerance": "1e-6"}


def alternatives(depth):
    """The alternatives run at a depth: name -> entries."""
    out = {"multigrid": {"Solver/Linear correction": "multigrid"},
           "multigrid-exact": {"Solver/Linear correction": "multigrid",
                               "Solver/Inner tolerance factor": 0,
                               "Solver/Linear correction cycles": 2},
           "direct": {"Solver/Linear correction": "direct"}}
    if depth <= AMG_MAX_DEPTH:
        out["amg"] = {"Solver/Linear correction": "amg"}
    if depth == EXPLICIT_DEPTH:
        for delta in ("1e-5", "1e-6", "1e-7"):
            out[f"explicit-{delta}"] = {
                "Solver/Linear correction": "multigrid",
                "Solver/Coupling": "explicit",
                "Time stepping/Tolerance": delta}
        out["fixed-point-1e-7"] = {"Solver/Linear correction": "multigrid",
                                   "Time stepping/Tolerance": "1e-7",
                                   "Solver/Fixed-point tolerance": "1e-7",
                                   "Solver/Inner tolerance factor": 0}
    return out


def window(exe, work, depth, name, entries):
    """One alternative over the window; its row of runs.csv."""
    out = os.path.join(work, f"{name}-{depth}")
    settings = dict(WINDOW, **{"End time": T1})
    settings.update(entries)
    wall = bench.resume(exe, os.path.join(work, f"pre-{depth}"), out,
                        settings, out + ".log")
    counts = bench.step_counts(run.time_series(out), after=T0)
    log = bench.text(out + ".log")
    n = bench.mesh(log)["unknowns"]
    # the time loop alone, without the start and the set-up
    stepping = bench.timer_sections(log)["Time stepping"]
    starts = [e.start for e in events.read(out) or [] if e.start > T0]
    steps = counts["steps"]
    problems = counts["spatial_problems"]
    fp, tn, li = (counts[c] for c in ("fixed_point_iterations",
                                      "tnnmg_iterations",
                                      "linear_iterations"))
    return dict(depth=depth, name=name, unknowns=n, wall_s=round(wall, 2),
                steps=steps, spatial_problems=problems, fp_max=fp[0],
                fp_mean=round(fp[1], 2), tnnmg_per_step_max=tn[0],
                tnnmg_per_step_mean=round(tn[1], 2),
                cycles_per_step_max=li[0],
                cycles_per_step_mean=round(li[1], 2),
                cycles_per_problem_mean=round(
                    counts["all_linear_iterations"] / problems, 2),
                all_tnnmg=counts["all_tnnmg_iterations"],
                all_cycles=counts["all_linear_iterations"],
                time_stepping_s=stepping,
                us_per_cycle_per_unknown=round(
                    1e6 * stepping / counts["all_linear_iterations"] / n, 4),
                events=len(starts),
                event_starts=" ".join(f"{t:.17g}" for t in starts))


FIELDS = ["depth", "name", "unknowns", "wall_s", "steps", "spatial_problems",
          "fp_max", "fp_mean", "tnnmg_per_step_max", "tnnmg_per_step_mean",
          "cycles_per_step_max", "cycles_per_step_mean",
          "cycles_per_problem_mean", "all_tnnmg", "all_cycles",
          "time_stepping_s", "us_per_cycle_per_unknown", "events",
          "event_starts"]


def runs(depths="2,3,4,5", variants="", append=False, reuse_preload=False,
         build="", work=""):
    """Preloads and windows of the depths into WORK, runs.csv, the figure.

    depths: local refinements
    variants: only these alternatives, A,B
    append: keep the rows of runs.csv for other depths
    reuse_preload: reuse WORK's preload checkpoints
    """
    exe = bench.executable(build)
    work = bench.work(work)
    depths = [int(d) for d in depths.split(",")]
    only = [v for v in variants.split(",") if v]
    rows = [r for r in bench.read_table(RUNS) if int(r["depth"]) not in
            depths] if append else []
    for depth in depths:
        pre = os.path.join(work, f"pre-{depth}")
        if reuse_preload and os.path.exists(os.path.join(
                pre, "checkpoint.bin")):
            print(f"depth {depth}: reusing the preload in {pre}", flush=True)
        else:
            path = bench.wedge_variant(pre + ".prm", pre, depth, T0, {
                "Time stepping/Controller": "step-doubling",
                "Solver/Linear correction": "direct"})
            t = bench.rsfcycle(exe, [path], pre + ".log")
            print(f"depth {depth}: preload to {T0:g} s in {t:.0f} s",
                  flush=True)
        for name, entries in alternatives(depth).items():
            if only and name not in only:
                continue
            row = window(exe, work, depth, name, entries)
            rows.append(row)
            print(row, flush=True)
            bench.write_table(RUNS, FIELDS, rows)
    figures()


def table():
    """The README's two tables from runs.csv."""
    rows = bench.read_table(RUNS)
    mg = {r["depth"]: float(r["wall_s"]) for r in rows
          if r["name"] == "multigrid"}
    print(bench.markdown(
        ["depth", "N", "correction", "wall [s]", "steps", "FP max/mean",
         "TNNMG/step mean", "cycles/step max/mean", "µs/cycle/N",
         "wall / multigrid"],
        [[r["depth"], r["unknowns"], r["name"], r["wall_s"], r["steps"],
          f"{r['fp_max']}/{r['fp_mean']}", r["tnnmg_per_step_mean"],
          f"{r['cycles_per_step_max']}/{r['cycles_per_step_mean']}",
          r["us_per_cycle_per_unknown"],
          f"{float(r['wall_s']) / mg[r['depth']]:.2f}"]
         for r in rows if r["name"] in ("multigrid", "multigrid-exact",
                                        "direct", "amg")]))
    ref = [r for r in rows if r["name"] == "fixed-point-1e-7"]
    if not ref:
        return
    t_ref = [float(x) for x in ref[0]["event_starts"].split()]
    lines = []
    for r in rows:
        if r["depth"] != ref[0]["depth"] or r["name"] in (
                "direct", "amg", "multigrid-exact"):
            continue
        t = [float(x) for x in r["event_starts"].split()]
        error = max(abs(a - b) for a, b in zip(t, t_ref)) * 1e3
        coupling = "fixed-point" if r["name"] in (
            "multigrid", "fixed-point-1e-7") else "explicit"
        tolerance = "1e-5"
        for prefix in ("explicit-", "fixed-point-"):
            if r["name"].startswith(prefix):
                tolerance = r["name"][len(prefix):]
        lines.append([coupling, tolerance, r["wall_s"], r["steps"],
                      r["spatial_problems"], f"{error:.2f}"])
    print(bench.markdown(["coupling", "tolerance", "wall [s]", "steps",
                          "spatial problems",
                          "max error of the event starts [ms]"], lines),
          end="")


def figures():
    """doc/figures/solvers-cost.png from runs.csv."""
    from rsfcycle.plot import _pyplot, savefig
    plt = _pyplot()
    rows = bench.read_table(RUNS)
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for name in ("multigrid", "direct", "amg"):
        chosen = [r for r in rows if r["name"] == name]
        if not chosen:
            continue
        n = [float(r["unknowns"]) for r in chosen]
        ax[0].loglog(n, [float(r["wall_s"]) for r in chosen], "o-",
                     label=name)
        ax[1].semilogx(n, [float(r["cycles_per_step_mean"]) for r in chosen],
                       "o-", label=name + " (mean)")
        ax[1].semilogx(n, [float(r["cycles_per_step_max"]) for r in chosen],
                       "x--", label=name + " (max)")
    ax[0].set_xlabel("unknowns N")
    ax[0].set_ylabel(f"wall time of [{T0:g}, {T1:g}] s [s]")
    ax[0].legend()
    ax[1].set_xlabel("unknowns N")
    ax[1].axhline(16, ls=":", color="k", label="the paper's bound, 16")
    ax[1].set_yscale("log")
    ax[1].set_ylabel("linear cycles per time step")
    ax[1].legend(fontsize=7)
    fig.tight_layout()
    savefig(fig, FIGURE, dpi=120)


def paper_run(build="", work=""):
    """prm/wedge-2d-paper.prm with step doubling at 1e-5, then its cycles.

    The rows paper_run.* of results.csv.
    """
    exe = bench.executable(build)
    out = os.path.join(bench.work(work), "paper-step-doubling")
    path = prm.variant(out + ".prm", os.path.join(
        bench.ROOT, "prm", "wedge-2d-paper.prm"), out, {
            "Time stepping/Controller": "step-doubling",
            "Time stepping/Tolerance": "1e-5",
            "Solver/Fixed-point tolerance": "1e-5",
            "Solver/Linear correction": "multigrid",
            "Output/Writers": "time series, base profile, events"})
    wall = bench.rsfcycle(exe, [path], out + ".log")
    stats = events.cycles(out)
    print(f"{out}: {wall:.0f} s, {stats['cycles']} cycles, fixed-point "
          f"iterations per step max {stats['fixed_point_iterations'][0]}, "
          f"V-cycles per step max {stats['linear_iterations'][0]}")
    bench.record(NAME, [
        ("paper_run.wall", f"{wall:.0f}", "s", "prm/wedge-2d-paper.prm "
         "(30,232 unknowns) with step doubling at δ = 1e-5: 1000 s"),
        ("paper_run.fixed_point_max",
         str(stats["fixed_point_iterations"][0]), "", "the same, over its "
         f"{stats['cycles']} cycles: fixed-point iterations per step, max"),
        ("paper_run.cycles_max", str(stats["linear_iterations"][0]), "",
         f"the same, over its {stats['cycles']} cycles: V-cycles per step, "
         "max")])


if __name__ == "__main__":
    raise SystemExit(bench.cli(__doc__, NAME, [runs, table, figures,
                                               paper_run]))
