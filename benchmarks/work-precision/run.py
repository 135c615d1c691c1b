#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Work against precision: the spring-slider against ARKODE, and the 2D
wedge as the paper's figure 7.

Stages (from the repository's root, PYTHONPATH=python /usr/bin/python3
benchmarks/work-precision/run.py STAGE ...):

  slider      prm/spring-slider.prm (quasi-dynamic, k = k_crit / 2, ageing
              law) over 1000 s (4 events) with our scheme (trapezoidal
              Newmark, fixed-point coupling, step doubling) at δ = ε = 1e-2
              ... 1e-8 and ARKODE (implicit ARK) at rtol = 1e-3 ... 1e-10,
              against ARKODE at 1e-12: the error of the slip at 1000 s and
              of the mean recurrence (events 2 – 4); wall time: the shortest
              time loop of 3 runs. ARKODE runs once sampled every second
              (slip, wall time) and once densely (recurrence). Writes
              runs.csv, runs.md and figures/work-precision.png (about a
              minute)
  wedge-runs  prm/wedge-2d.prm at 3 global + 2 local refinements with
              tests/wedge-2d-pinned.prm (Refinement distance 1.5), 0 – 600
              s, step doubling, direct correction: --series eps (ε = 1e-3
              ... 1e-7 at δ = 1e-5) or --series delta (δ = ε = 1e-3 ...
              1e-7) into WORK/wedge-SERIES-TOL (1 – 10 minutes each)
  wedge       the table of such runs against the one with the smallest
              tolerance (wall time, steps, spatial problems, total TNNMG
              iterations, the largest relative error over the events of
              recurrence, peak slip rate and slip) and a figure: --series
              eps draws doc/figures/fig7-effort-vs-tolerance.png (the
              paper's figure 7), --series delta
              doc/figures/work-precision-wedge-delta.png
"""
import math
import os
import re

from rsfcycle import bench, events, prm, run, wedge_plots

NAME = "work-precision"
HERE = bench.folder(NAME)
END_TIME = 1000
L = 1e-5  # the slider's characteristic slip [m]
SERIES = {"eps": "fixed-point tolerance ε at δ = 1e-5",
          "delta": "δ = ε"}
FIGURES = {"eps": "fig7-effort-vs-tolerance.png",
           "delta": "work-precision-wedge-delta.png"}


def slider_run(exe, work, label, integrator, tol, spacing=0.01):
    """One spring-slider run (3 times); the slip at END_TIME and the mean
    recurrence of its last line, its steps, events and shortest time
    loop."""
    out = os.path.join(work, label)
    path = prm.variant(out + ".prm", os.path.join(bench.ROOT, "prm",
                                                  "spring-slider.prm"), out, {
        "End time": END_TIME,
        "Time stepping/Integrator": "arkode" if integrator == "arkode"
        else "implicit",
        "Time stepping/Controller": "step-doubling",
        "Time stepping/Tolerance": f"{tol:g}",
        "Time stepping/Minimum step": "1e-14",
        "Solver/Fixed-point tolerance": f"{tol:g}",
        "Output/Progress interval": "1e9",
        "Spring slider/Reference sample spacing": f"{spacing:g}"})
    wall, output = bench.repeat_loop(exe, path, out + ".log")
    final = re.search(r"Final: slip = (\S+) m.*mean recurrence time = (\S+) s",
                      output)
    # ARKODE's own steps where it samples at fixed times
    steps = re.search(r"Summary: (\d+) steps(?:, (\d+) internal steps)?",
                      output)
    return dict(name=label, integrator=integrator, tol=tol,
                slip=float(final.group(1)), period=float(final.group(2)),
                steps=int(steps.group(2) or steps.group(1)),
                events=len(re.findall(r"event \d+ starts", output)),
                wall=wall)


def slider(build="", work=""):
    """The spring-slider against ARKODE: runs.csv, runs.md, the figure."""
    exe = bench.executable(build)
    work = bench.work(work)
    ref = slider_run(exe, work, "reference", "arkode", 1e-12)
    rows = [slider_run(exe, work, f"ours-{e}", "step-doubling", 10.0 ** -e)
            for e in range(2, 9)]
    for e in range(3, 11):
        # slip and wall time sampled once per second, so that ARKODE takes
        # its own steps; the recurrence densely (every 0.01 L/V)
        r = slider_run(exe, work, f"arkode-{e}", "arkode", 10.0 ** -e,
                       spacing=0)
        dense = slider_run(exe, work, f"arkode-dense-{e}", "arkode",
                           10.0 ** -e)
        r.update(period=dense["period"], dense_wall=dense["wall"],
                 dense_steps=dense["steps"])
        rows.append(r)
    for r in rows:
        r["slip_error"] = abs(r["slip"] - ref["slip"])
        r["period_error"] = abs(r["period"] - ref["period"])
    with open(os.path.join(HERE, "runs.csv"), "w") as f:
        f.write("integrator,tolerance,steps,events,wall time [s],"
                "slip error [m],period error [s]\n")
        for r in rows:
            f.write(f"{r['integrator']},{r['tol']:g},{r['steps']},"
                    f"{r['events']},{r['wall']:.4g},{r['slip_error']:.3e},"
                    f"{r['period_error']:.3e}\n")
    text = (f"Reference (ARKODE, rtol 1e-12): slip at {END_TIME} s = "
            f"{ref['slip'] * 1e6:.6f} um, recurrence time = "
            f"{ref['period']:.6f} s, {ref['steps']} steps, "
            f"{ref['wall']:.3g} s.\n\n" + bench.markdown(
                ["integrator", "tolerance", "steps", "events",
                 "wall time [s]", "slip error [um]", "slip error / L",
                 "period error [s]", "period error / T",
                 "dense-sampled: steps, wall time [s]"],
                [[r["integrator"], f"{r['tol']:g}", r["steps"], r["events"],
                  f"{r['wall']:.3g}", f"{r['slip_error'] * 1e6:.2e}",
                  f"{r['slip_error'] / L:.1e}", f"{r['period_error']:.2e}",
                  f"{r['period_error'] / ref['period']:.1e}",
                  f"{r['dense_steps']}, {r['dense_wall']:.3g}"
                  if "dense_wall" in r else "-"] for r in rows]))
    with open(os.path.join(HERE, "runs.md"), "w") as f:
        f.write("<!-- SPDX-License-Identifier: LGPL-2.1-or-later -->\n" + text)
    print(text, end="")
    slider_figure(rows)


def slider_figure(rows):
    """figures/work-precision.png: both errors against the time loop."""
    from rsfcycle.plot import _pyplot, savefig
    plt = _pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, key, label in [(axes[0], "slip_error",
                            "error of slip at 1000 s [m]"),
                           (axes[1], "period_error",
                            "error of recurrence time [s]")]:
        for integrator, style in [("step-doubling", "o-"), ("arkode", "s--")]:
            chosen = [r for r in rows if r["integrator"] == integrator]
            walls = [r.get("dense_wall", r["wall"]) if key == "period_error"
                     else r["wall"] for r in chosen]
            ax.loglog(walls, [max(r[key], 1e-16) for r in chosen], style,
                      label="ours (delta = epsilon)"
                      if integrator == "step-doubling" else "ARKODE (rtol)")
            for w, r in zip(walls, chosen):
                ax.annotate(f"{r['tol']:.0e}", (w, max(r[key], 1e-16)),
                            fontsize=6)
        ax.set_xlabel("wall time of the time loop [s]")
        ax.set_ylabel(label)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.suptitle("Spring-slider work-precision (prm/spring-slider.prm, "
                 "1000 s, 4 events)")
    fig.tight_layout()
    os.makedirs(os.path.join(HERE, "figures"), exist_ok=True)
    savefig(fig, os.path.join(HERE, "figures", "work-precision.png"),
            dpi=120)


TOLERANCES = (1e-3, 1e-4, 1e-5, 1e-6, 1e-7)


def wedge_runs(series: tuple(SERIES) = "eps", build="", work=""):
    """The 2D wedge's runs of a series into WORK/wedge-SERIES-TOL.

    series: eps (ε at δ = 1e-5) or delta (δ = ε)
    """
    exe = bench.executable(build)
    work = bench.work(work)
    for tol in TOLERANCES:
        out = os.path.join(work, f"wedge-{series}-{tol:g}")
        delta = tol if series == "delta" else 1e-5
        path = bench.wedge_variant(out + ".prm", out, 2, 600, {
            "Mesh/Global refinements": 3,
            "Time stepping/Controller": "step-doubling",
            "Time stepping/Tolerance": f"{delta:g}",
            "Solver/Fixed-point tolerance": f"{tol:g}",
            "Solver/Linear correction": "direct"})
        print(f"running {out} ...", flush=True)
        bench.rsfcycle(exe, [path], out + ".log")


def read_wedge(folder):
    """A wedge run's tolerances, time loop, counts and catalogue."""
    parameters = run.parameters(folder)
    c = bench.step_counts(run.time_series(folder))
    return {"folder": folder,
            "eps": float(parameters["Solver/Fixed-point tolerance"]),
            "delta": float(parameters["Time stepping/Tolerance"]),
            "wall": run.section_time(folder, "Time stepping") or math.nan,
            "steps": c["steps"], "problems": c["spatial_problems"],
            "work": c["all_linear_iterations"],
            "events": events.read(folder) or []}


def largest_error(a, b, key):
    """The largest relative difference of an event quantity ('recurrence',
    'peak', 'slip_um'), events matched by index."""
    errors = [abs(getattr(x, key) / getattr(y, key) - 1)
              for x, y in zip(a["events"], b["events"])
              if getattr(y, key) and math.isfinite(getattr(x, key))
              and math.isfinite(getattr(y, key))]
    return max(errors, default=math.nan)


def wedge(*run_folder, series: tuple(SERIES) = "eps", work=""):
    """The table and the figure of a series of wedge runs.

    run_folder: runs that differ in the tolerance (default: WORK's)
    series: eps (ε at δ = 1e-5) or delta (δ = ε)
    """
    folders = run_folder or [os.path.join(work, f"wedge-{series}-{t:g}")
                             for t in TOLERANCES]
    runs = sorted((read_wedge(f) for f in folders), key=lambda r: -r["eps"])
    ref = runs[-1]
    keys = (("recurrence", "recurrence"), ("peak", "peak slip rate"),
            ("slip_um", "slip"))
    first = "ε = δ" if series == "delta" else "ε"
    rows = []
    for r in runs:
        cells = [f"{r['eps']:g}", f"{r['wall']:.1f}", r["steps"],
                 r["problems"], r["work"], len(r["events"])]
        cells += ["reference"] * 3 if r is ref else \
            [f"{largest_error(r, ref, k):.1e}" for k, _ in keys]
        rows.append(cells)
    print(bench.markdown([first, "wall [s]", "steps", "spatial problems",
                          "work (TNNMG its)", "events",
                          "max rel. error recurrence", "peak slip rate",
                          "slip"], rows), end="")
    out = os.path.join(bench.ROOT, "doc", "figures", FIGURES[series])
    if series == "eps":
        wedge_plots.fig7([r["folder"] for r in runs], os.path.dirname(out))
        return
    from rsfcycle.plot import _pyplot, savefig
    plt = _pyplot()
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    ax[0].semilogx([r["eps"] for r in runs], [r["work"] for r in runs], "o-")
    ax[0].set_xlabel("δ = ε")
    ax[0].set_ylabel("total TNNMG iterations (all spatial problems)")
    others = [r for r in runs if r is not ref]
    for key, label in keys:
        ax[1].loglog([r["wall"] for r in others],
                     [max(largest_error(r, ref, key), 1e-16)
                      for r in others], "o-", label=label)
    ax[1].set_xlabel("wall time of the time loop [s]")
    ax[1].set_ylabel(f"max relative error vs δ = ε = {ref['eps']:g}")
    ax[1].legend()
    fig.tight_layout()
    savefig(fig, out, dpi=120)


if __name__ == "__main__":
    raise SystemExit(bench.cli(__doc__, NAME, [slider, wedge_runs, wedge]))
