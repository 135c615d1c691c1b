#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Step-size controllers, time schemes and the cost of a step.

Controllers: the paper's step doubling against step doubling with local
extrapolation (the default: Step sizes = ladder, Doubling threshold 1) at
several tolerances δ = ε (Fixed-point tolerance = Tolerance), with
threshold 0.5 and free step sizes at the looser ones and without
Extrapolated start at 1e-6, on

  slider  the quasi-dynamic spring-slider (prm/spring-slider.prm, initial
          slip rate 1.01 v0) over 5000 s against ARKODE at relative
          tolerance 1e-12: mean recurrence (events 2 ..), peak slip rate
          (max over events 2 ..), first event's start; wall time: the
          shortest time loop of 3 runs;
  wedge   the 2D wedge (prm/wedge-2d.prm, 2 + DEPTH refinements, direct
          correction, and the multigrid correction with ladder and free
          steps at 1e-5) over [520, 545] s (three events), resumed from one
          preload checkpoint (step doubling, 1e-5), against step doubling at
          δ = ε = 1e-8: event starts, peak slip rates and slips; wall time:
          the time loop.

Stages (from the repository's root, PYTHONPATH=python /usr/bin/python3
benchmarks/time-stepping/run.py STAGE ...):

  runs       the parts into WORK, runs.csv, the figure and the tables
             (slider: a minute; wedge at 2 + 6: about an hour on one core)
  table      every run of runs.csv, then each variant interpolated to step
             doubling's error (the README's table)
  figures    doc/figures/time-stepping.png
  galpha     generalized-α (ρ∞ = 0.8) against the trapezoidal step:
             prm/wedge-2d.prm as shipped (1000 s, twice 5 minutes on 2
             ranks) and prm/wedge-3d.prm at 2 + 2 to the third event (rows
             galpha-*)
  paper-run  prm/wedge-2d-paper.prm as shipped (35 minutes on one core):
             wall time, steps, events, recurrence, iterations (paper_run.*)
  shipped    the step sizes and iterations of a run folder of
             prm/wedge-2d.prm (e.g. output-wedge-2d) against the paper's
             bounds (the rows wedge-2d.*)
"""
import math
import os

from rsfcycle import bench, events, prm, run

NAME = "time-stepping"
HERE = bench.folder(NAME)
RUNS = os.path.join(HERE, "runs.csv")
FIGURE = os.path.join(bench.ROOT, "doc", "figures", "time-stepping.png")
T0, T1 = 520.0, 545.0
FIELDS = ["case", "controller", "tolerance", "step_sizes",
          "doubling_threshold", "extrapolated_start", "correction", "steps",
          "spatial_problems", "fp_per_step", "tnnmg_per_problem", "wall_s",
          "error_start", "error_peak", "error_period", "error_slip"]


def variant(controller, tol, steps="ladder", threshold=1.0, extrapolate=True,
            correction="direct"):
    """One run's settings (steps, threshold, extrapolate: local
    extrapolation's Step sizes, Doubling threshold, Extrapolated start;
    correction: the wedge's Linear correction)."""
    if controller == "step-doubling":
        steps, threshold, extrapolate = "", "", ""
    return dict(controller=controller, tolerance=tol, step_sizes=steps,
                doubling_threshold=threshold, extrapolated_start=extrapolate,
                correction=correction)


def name(v):
    """A run's folder name."""
    if v["controller"] == "step-doubling":
        n = f"step-doubling-{v['tolerance']:g}"
    else:
        n = (f"local-extrapolation-{v['step_sizes']}"
             + (f"-{v['doubling_threshold']:g}"
                if v["step_sizes"] == "ladder" else "")
             + f"-{v['tolerance']:g}"
             + ("" if v["extrapolated_start"] else "-old-start"))
    return n + ("" if v["correction"] in ("direct", "") else
                "-" + v["correction"])


def variants(tolerances, loose):
    """Step doubling and the default local extrapolation at `tolerances`;
    threshold 0.5 and free step sizes at the `loose` ones; the default
    without extrapolated start at 1e-6."""
    return ([variant("step-doubling", t) for t in tolerances]
            + [variant("local-extrapolation", t) for t in tolerances]
            + [variant("local-extrapolation", t, threshold=0.5)
               for t in loose]
            + [variant("local-extrapolation", t, steps="free")
               for t in loose]
            + [variant("local-extrapolation", 1e-6, extrapolate=False)])


def controller_entries(v):
    """The Time stepping and Solver entries of a variant."""
    entries = {"Time stepping/Controller": v["controller"],
               "Time stepping/Tolerance": f"{v['tolerance']:g}",
               "Solver/Fixed-point tolerance": f"{v['tolerance']:g}"}
    if v["controller"] == "local-extrapolation":
        entries.update({
            "Time stepping/Extrapolated start":
                str(v["extrapolated_start"]).lower(),
            "Time stepping/Step sizes": v["step_sizes"],
            "Time stepping/Doubling threshold":
                f"{v['doubling_threshold']:g}"})
    return entries


def counts(series):
    """steps, spatial problems, fixed-point iterations per step, TNNMG
    iterations per spatial problem."""
    c = bench.step_counts(series)
    return dict(steps=c["steps"], spatial_problems=c["spatial_problems"],
                fp_per_step=round(c["fixed_point_iterations"][1], 3),
                tnnmg_per_problem=round(c["all_tnnmg_iterations"]
                                        / c["spatial_problems"], 3))


def slider_run(exe, work, label, entries):
    """One spring-slider run over 5000 s; (its folder, the shortest time
    loop of 3 runs)."""
    out = os.path.join(work, "slider", label)
    settings = {"End time": 5000, "Time stepping/Minimum step": "1e-14",
                "Output/Progress interval": "1e9",
                "Spring slider/Initial slip rate": "1.01e-6"}
    settings.update(entries)
    path = prm.variant(out + ".prm", os.path.join(bench.ROOT, "prm",
                                                  "spring-slider.prm"),
                       out, settings)
    wall, _ = bench.repeat_loop(exe, path, out + ".log")
    return out, wall


def slider_events(folder):
    """Recurrence (events 2 ..), largest peak (events 2 ..), first start."""
    found = events.read(folder)
    starts = [e.start for e in found]
    return dict(period=(starts[-1] - starts[1]) / (len(starts) - 2),
                peak=max(e.peak for e in found[1:]), first=starts[0])


def slider_part(exe, work):
    """The spring-slider's rows."""
    reference, _ = slider_run(exe, work, "reference", {
        "Time stepping/Integrator": "arkode",
        "Time stepping/Controller": "step-doubling",
        "Time stepping/Tolerance": "1e-12",
        "Solver/Fixed-point tolerance": "1e-12"})
    ref = slider_events(reference)
    rows = []
    for v in variants([1e-5, 1e-6, 1e-7], [1e-5, 1e-6, 1e-7]):
        v["correction"] = ""
        entries = controller_entries(v)
        if v["controller"] == "step-doubling":
            entries["Time stepping/Extrapolated start"] = "true"
        folder, wall = slider_run(exe, work, name(v), entries)
        e = slider_events(folder)
        row = dict(case="slider", **v, wall_s=wall,
                   **counts(run.time_series(folder)),
                   error_start=abs(e["first"] - ref["first"]),
                   error_peak=abs(e["peak"] / ref["peak"] - 1),
                   error_period=abs(e["period"] / ref["period"] - 1),
                   error_slip="")
        print(row, flush=True)
        rows.append(row)
    return rows


def wedge_part(exe, work, depth, reuse):
    """The wedge's rows."""
    pre = os.path.join(work, f"wedge-pre-{depth}")
    if not (reuse and os.path.exists(os.path.join(pre, "checkpoint.bin"))):
        path = bench.wedge_variant(pre + ".prm", pre, depth, T0, {
            "Time stepping/Controller": "step-doubling"})
        t = bench.rsfcycle(exe, [path], pre + ".log")
        print(f"preload to {T0:g} s: {t:.0f} s", flush=True)

    def window(v):
        out = os.path.join(work, f"wedge-{depth}-{name(v)}")
        entries = {"End time": T1, "Solver/Linear correction":
                   v["correction"]}
        entries.update(controller_entries(v))
        bench.resume(exe, pre, out, entries, out + ".log")
        wall = bench.timer_sections(bench.text(out + ".log"))["Time stepping"]
        found = [e for e in events.read(out) or [] if e.start > T0]
        return dict(wall_s=wall, **counts(run.time_series(out).query(
            f"time_s > {T0 + 1e-9}"))), found

    _, ref = window(variant("step-doubling", 1e-8))
    rows = []
    todo = variants([1e-4, 1e-5, 1e-6, 1e-7], [1e-4, 1e-5, 1e-6])
    todo += [variant("local-extrapolation", 1e-5, steps=s,
                     correction="multigrid") for s in ("ladder", "free")]
    for v in todo:
        c, found = window(v)
        d = events.differences(found, ref)
        row = dict(case=f"wedge-2+{depth}", **v, **c,
                   error_start=d["start"] if d["events"] ==
                   d["reference_events"] else math.inf,
                   error_peak=d["peak"], error_slip=d["slip"],
                   error_period="")
        print(row, flush=True)
        rows.append(row)
    return rows


def runs(parts="slider,wedge", depth=6, reuse_preload=False, build="",
         work=""):
    """The controllers' runs into WORK, runs.csv, the figure, the tables.

    parts: slider, wedge or both
    depth: the wedge's local refinements
    reuse_preload: reuse WORK's preload checkpoint of the wedge
    """
    exe = bench.executable(build)
    work = bench.work(work)
    os.makedirs(os.path.join(work, "slider"), exist_ok=True)
    rows = []
    if "slider" in parts.split(","):
        rows += slider_part(exe, work)
    if "wedge" in parts.split(","):
        rows += wedge_part(exe, work, depth, reuse_preload)
    done = {r["case"] for r in rows}
    keep = [r for r in bench.read_table(RUNS) if r["case"] not in done] \
        if os.path.exists(RUNS) else []
    bench.write_table(RUNS, FIELDS, keep + rows)
    figures()
    table()


def label(r):
    """A variant's label in tables and the figure."""
    if r["controller"] == "step-doubling":
        return "step doubling"
    text = ("local extrapolation, " + r["step_sizes"]
            + (f" {float(r['doubling_threshold']):g}"
               if r["step_sizes"] == "ladder" else ""))
    return text + ("" if r["extrapolated_start"] == "True" else ", old start")


def interpolate(points, error):
    """log-log interpolation of (error, cost) pairs to `error`; None
    outside their range."""
    points = sorted(points)
    for (e0, c0), (e1, c1) in zip(points, points[1:]):
        if e0 <= error <= e1 and e0 < e1:
            w = math.log(error / e0) / math.log(e1 / e0)
            return math.exp((1 - w) * math.log(c0) + w * math.log(c1))
    return None


def table():
    """Every run of runs.csv, then each variant interpolated to step
    doubling's error (the README's table)."""
    rows = bench.read_table(RUNS)

    def g(r, k):
        try:
            return f"{float(r[k]):.3g}"
        except ValueError:
            return r[k] or "–"
    print(bench.markdown(
        ["case", "controller", "correction", "δ = ε", "steps",
         "spatial problems", "FP/step", "TNNMG/problem", "wall [s]",
         "start error [s]", "peak error", "period error", "slip error"],
        [[r["case"], label(r), r["correction"] or "–", g(r, "tolerance"),
          r["steps"], r["spatial_problems"], g(r, "fp_per_step"),
          g(r, "tnnmg_per_problem"), g(r, "wall_s"), g(r, "error_start"),
          g(r, "error_peak"), g(r, "error_period"), g(r, "error_slip")]
         for r in rows]))
    lines = []
    for case in sorted({r["case"] for r in rows}, reverse=True):
        key = "error_period" if case == "slider" else "error_peak"
        chosen = [r for r in rows if r["case"] == case
                  and r["correction"] in ("", "direct")
                  and r["extrapolated_start"] != "False"]
        for sd in [r for r in chosen if r["controller"] == "step-doubling"]:
            for lab in sorted({label(r) for r in chosen} - {"step doubling"}):
                points = [r for r in chosen if label(r) == lab]
                e = float(sd[key])
                p = interpolate([(float(r[key]),
                                  float(r["spatial_problems"]))
                                 for r in points], e)
                w = interpolate([(float(r[key]), float(r["wall_s"]))
                                 for r in points], e)
                if p is not None:
                    lines.append([case, f"{key[6:]} {e:.3g}",
                                  f"{float(sd['tolerance']):g}", lab,
                                  f"{p / float(sd['spatial_problems']):.3f}",
                                  f"{w / float(sd['wall_s']):.3f}"])
    print(bench.markdown(["case", "error", "step doubling δ", "variant",
                          "problems ratio", "wall ratio"], lines), end="")


def figures():
    """doc/figures/time-stepping.png from runs.csv."""
    from rsfcycle.plot import _pyplot, savefig
    plt = _pyplot()
    rows = [r for r in bench.read_table(RUNS)
            if r["extrapolated_start"] != "False"
            and r["correction"] in ("", "direct")]
    cases = sorted({r["case"] for r in rows}, reverse=True)
    fig, axes = plt.subplots(len(cases), 2, figsize=(11, 4.5 * len(cases)),
                             squeeze=False)
    for i, case in enumerate(cases):
        # the wedge's event starts are quantised by the steps at the
        # onset: its peak slip rates show the convergence
        key = "error_period" if case == "slider" else "error_peak"
        ylabel = ("relative error of the recurrence time" if case == "slider"
                  else "max relative error of the peak slip rates")
        labels = sorted({label(r) for r in rows if r["case"] == case},
                        key=lambda lab: (lab != "step doubling", lab))
        for lab, marker in zip(labels, "osd^v"):
            chosen = sorted((r for r in rows if r["case"] == case
                             and label(r) == lab),
                            key=lambda r: float(r["tolerance"]))
            for j, x in enumerate(["spatial_problems", "wall_s"]):
                axes[i][j].loglog([float(r[x]) for r in chosen],
                                  [float(r[key]) for r in chosen],
                                  marker + "-", label=lab)
                for r in chosen:
                    axes[i][j].annotate(f"{float(r['tolerance']):g}",
                                        (float(r[x]), float(r[key])),
                                        fontsize=7)
        for j, x in enumerate(["spatial problems", "wall time [s]"]):
            axes[i][j].set_xlabel(x)
            axes[i][j].set_ylabel(ylabel)
            axes[i][j].set_title(case)
            axes[i][j].grid(True, which="both", alpha=0.3)
            axes[i][j].legend(fontsize=8)
    fig.tight_layout()
    savefig(fig, FIGURE, dpi=110)


def percent(a, b):
    return f"{100 * (a / b - 1):+.2g} %"


def galpha(build="", work=""):
    """Generalized-α (ρ∞ = 0.8) against the trapezoidal step, 2D and 3D."""
    exe = bench.executable(build)
    work = bench.work(work)
    scheme = {"Solver/Time scheme": "generalized-alpha",
              "Solver/Spectral radius": 0.8}
    folders = {}
    for case, base, ranks, entries in (
            ("2d", "wedge-2d.prm", 2, {}),
            ("3d", "wedge-3d.prm", 1, {"Mesh/Global refinements": 2,
                                       "Mesh/Local refinements": 2,
                                       "Stop after events": 3})):
        for label_, extra in (("theta", {}), ("galpha", scheme)):
            out = os.path.join(work, f"galpha-{case}-{label_}")
            settings = dict(entries, **extra)
            settings["Output/Writers"] = "time series, base profile, events"
            path = prm.variant(out + ".prm", os.path.join(bench.ROOT, "prm",
                                                          base),
                               out, settings)
            print(f"running {out} ...", flush=True)
            bench.run(bench.mpirun(ranks, [exe, path]), out + ".log",
                      env=bench.mpi_environment())
            folders[case, label_] = out
    for case in ("2d", "3d"):
        a = run.events(folders[case, "galpha"])
        b = run.events(folders[case, "theta"])
        print(f"{case}: generalized-α against the trapezoidal step")
        print(f"  first event {percent(a.start_s[0], b.start_s[0])}")
        if case == "2d":
            for column in ("recurrence_s", "peak_slip_rate_m_per_s",
                           "slip_um"):
                change = percent(a[column][9:].median(),
                                 b[column][9:].median())
                print(f"  median {column} (events 10 on) {change}")
        else:
            print("  recurrences 2 and 3 " + ", ".join(
                percent(x, y) for x, y in zip(a.recurrence_s[1:3],
                                              b.recurrence_s[1:3])))
        print("  steps " + percent(len(run.time_series(folders[case,
                                                               "galpha"])),
                                   len(run.time_series(folders[case,
                                                               "theta"]))))


def paper_run(build="", work=""):
    """prm/wedge-2d-paper.prm as shipped: cost, events, iterations."""
    exe = bench.executable(build)
    out = os.path.join(bench.work(work), "wedge-2d-paper")
    path = prm.variant(out + ".prm", os.path.join(
        bench.ROOT, "prm", "wedge-2d-paper.prm"), out)
    wall = bench.rsfcycle(exe, [path], out + ".log")
    stats = events.cycles(out)
    summary = run.summary(out)
    print(f"{out}: {wall / 60:.1f} min, {summary['steps']:,} steps "
          f"({summary['problems']:,} spatial problems), {stats['events']} "
          f"events, mean recurrence over {stats['cycles']} cycles "
          f"{stats['recurrence']:.3f} s, fixed-point iterations per step "
          f"max {stats['fixed_point_iterations'][0]}, TNNMG iterations per "
          f"step max {stats['tnnmg_iterations'][0]}")


def shipped(run_folder):
    """A run of prm/wedge-2d.prm against the paper's bounds.

    Iterations per step in the cycles (after the first event), the largest
    step between events and the smallest in them, the largest step of the
    run (the loading).

    run_folder: e.g. output-wedge-2d
    """
    series = run.time_series(run_folder)
    found = events.read(run_folder)
    cycles = series[series["time_s"] > found[0].start]
    inside = cycles["time_s"].apply(
        lambda t: any(e.start <= t <= e.end for e in found))
    between = cycles[~inside]["step_size_s"].max()
    during = cycles[inside]["step_size_s"].min()
    print(f"{run_folder}: fixed-point iterations per step max "
          f"{int(cycles['fixed_point_iterations'].max())}; TNNMG iterations "
          f"per step in the cycles max {int(cycles['tnnmg_iterations'].max())}"
          f", mean {cycles['tnnmg_iterations'].mean():.2f}; step between "
          f"events {1e3 * between:g} ms, in events {1e3 * during:g} ms "
          f"(ratio {between / during:.0f}); largest step "
          f"{series['step_size_s'].max():g} s")


if __name__ == "__main__":
    raise SystemExit(bench.cli(__doc__, NAME, [
        runs, table, figures, galpha, paper_run, shipped]))
