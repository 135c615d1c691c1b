#!/usr/bin/python3
"""Step-size controllers side by side: the paper's step doubling against
step doubling with local extrapolation, at several tolerances, on

  (a) the quasi-dynamic spring-slider (prm/spring-slider.prm, initial slip
      rate 1.01 v0) over 5000 s against ARKODE at relative tolerance 1e-12
      (densely sampled): mean recurrence time (events 2..), peak slip rate
      (max over events 2..) and the start of the first event;
  (b) the 2D wedge (prm/wedge-2d.prm with 2 global and DEPTH local
      refinements) over the window [T0, T1] with three events, resumed from
      one preload checkpoint (step doubling, 1e-5, 0 -> T0), against step
      doubling at delta = epsilon = 1e-8: event starts, peak slip rates and
      slips of the window's events.

Every run has Fixed-point tolerance = Tolerance. Reported per run: spatial
problems, steps, wall time of the time loop (TimerOutput "Time stepping";
the spring-slider: the minimum of 3 runs), fixed-point and TNNMG iterations
per spatial problem, and the errors. All runs of one invocation share the
machine, so ratios are what to read. Writes results.csv and
doc/figures/time-stepping.png; `--table` prints the table of README.md.

Usage: benchmarks/time-stepping/run.py [BUILD_DIR] [--parts slider,wedge]
           [--depth 6] [--work DIR] [--reuse-preload]
       benchmarks/time-stepping/run.py --table | --plot
"""
import csv
import math
import os
import re
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.dirname(HERE))
import common  # noqa: E402  (benchmarks/common.py)
T0, T1 = 520.0, 545.0
TOLERANCES = [1e-5, 1e-6, 1e-7]
CONTROLLERS = ["step-doubling", "local-extrapolation"]


def arg(name, default):
    if name in sys.argv:
        return sys.argv[sys.argv.index(name) + 1]
    return default


OPTS = ("--parts", "--depth", "--work")
BUILD = next((a for i, a in enumerate(sys.argv[1:], 1)
              if not a.startswith("--") and sys.argv[i - 1] not in OPTS),
             os.path.join(ROOT, "build"))
EXE = os.path.join(BUILD, "rsfcycle")
PARTS = arg("--parts", "slider,wedge").split(",")
DEPTH = int(arg("--depth", "6"))
WORK = arg("--work", os.path.join(HERE, "work"))
REUSE = "--reuse-preload" in sys.argv
RESULTS = os.path.join(HERE, "results.csv")


def run(args, log):
    return common.run(EXE, args, log)


stepping_time = common.stepping_time
set_entry = common.set_entry


def counts(rows):
    problems = sum(int(r["spatial_problems"]) for r in rows)
    fp = sum(int(r["fixed_point_iterations"]) for r in rows)
    tn = sum(int(r["all_tnnmg_iterations"]) for r in rows)
    return dict(steps=len(rows), spatial_problems=problems,
                fp_per_step=round(fp / len(rows), 3),
                tnnmg_per_problem=round(tn / problems, 3))


# ---------------------------------------------------------------- slider
def slider_prm(name, controller, tol, extrapolate=True, arkode=False):
    d = os.path.join(WORK, "slider", name)
    prm = d + ".prm"
    with open(prm, "w") as f:
        f.write(f"""include {ROOT}/prm/spring-slider.prm
set End time = 5000
set Output directory = {d}
set Overwrite output = true
subsection Time stepping
  set Controller         = {controller}
  set Extrapolated start = {str(extrapolate).lower()}
  set Tolerance          = {tol:g}
  set Minimum step       = 1e-14
end
subsection Solver
  set Fixed-point tolerance = {tol:g}
end
subsection Output
  set Progress interval = 1e9
end
subsection Spring slider
  set Initial slip rate = 1.01e-6
  set Integrator        = {"arkode" if arkode else "newmark"}
end
""")
    return d, prm


def slider_events(d):
    ev = list(csv.DictReader(open(os.path.join(d, "events.csv"))))
    starts = [float(e["start_s"]) for e in ev]
    peaks = [float(e["peak_slip_rate_m_per_s"]) for e in ev[1:]]
    period = (starts[-1] - starts[1]) / (len(starts) - 2)
    return dict(period=period, peak=max(peaks), first=starts[0],
                events=len(ev))


def slider_part():
    os.makedirs(os.path.join(WORK, "slider"), exist_ok=True)
    d, prm = slider_prm("reference", "step-doubling", 1e-12, arkode=True)
    run([prm], d + ".log")
    ref = slider_events(d)
    rows = []
    variants = [(c, t, True) for c in CONTROLLERS for t in TOLERANCES]
    variants.append(("local-extrapolation", 1e-6, False))
    for controller, tol, extrapolate in variants:
        name = f"{controller}-{tol:g}" + ("" if extrapolate else "-old-start")
        d, prm = slider_prm(name, controller, tol, extrapolate)
        walls = []
        for _ in range(3):
            run([prm], d + ".log")
            log = open(d + ".log").read()
            walls.append(float(re.search(r"Wall time of the time loop: (\S+)",
                                         log).group(1)))
        ts = list(csv.DictReader(open(os.path.join(d, "time-series.csv"))))
        e = slider_events(d)
        row = dict(case="slider", controller=controller, tolerance=tol,
                   extrapolated_start=extrapolate, wall_s=min(walls),
                   **counts(ts),
                   error_start=abs(e["first"] - ref["first"]),
                   error_peak=abs(e["peak"] / ref["peak"] - 1),
                   error_period=abs(e["period"] / ref["period"] - 1),
                   error_slip="")
        print(row, flush=True)
        rows.append(row)
    return rows


# ----------------------------------------------------------------- wedge
def wedge_window(name, controller, tol, extrapolate=True):
    pre = os.path.join(WORK, f"wedge-pre-{DEPTH}")
    out = os.path.join(WORK, f"wedge-{DEPTH}-{name}")
    shutil.rmtree(out, ignore_errors=True)
    shutil.copytree(pre, out)
    prm = os.path.join(out, "parameters.prm")
    for key, value in {"End time": T1, "Output directory": out,
                       "Controller": controller,
                       "Extrapolated start": str(extrapolate).lower(),
                       "Tolerance": f"{tol:g}",
                       "Fixed-point tolerance": f"{tol:g}"}.items():
        set_entry(prm, key, value)
    run(["--resume", out], out + ".log")
    log = open(out + ".log").read()
    rows = [r for r in csv.DictReader(open(os.path.join(out,
                                                        "time-series.csv")))
            if float(r["time_s"]) > T0 + 1e-9]
    events = [e for e in csv.DictReader(open(os.path.join(out, "events.csv")))
              if float(e["start_s"]) > T0]
    return out, dict(wall_s=stepping_time(log), **counts(rows)), events


def wedge_part():
    pre = os.path.join(WORK, f"wedge-pre-{DEPTH}")
    if not (REUSE and os.path.exists(os.path.join(pre, "checkpoint.bin"))):
        os.makedirs(WORK, exist_ok=True)
        prm = pre + ".prm"
        with open(prm, "w") as f:
            f.write(common.wedge_prm(ROOT, DEPTH, pre, T0))
        t = run([prm], pre + ".log")
        print(f"preload to {T0} s: {t:.0f} s", flush=True)
    _, ref_counts, ref = wedge_window("reference", "step-doubling", 1e-8)
    print("reference", ref_counts, len(ref), "events", flush=True)
    rows = []
    variants = [(c, t, True) for c in CONTROLLERS for t in TOLERANCES]
    variants.append(("local-extrapolation", 1e-6, False))
    for controller, tol, extrapolate in variants:
        name = f"{controller}-{tol:g}" + ("" if extrapolate else "-old-start")
        _, c, ev = wedge_window(name, controller, tol, extrapolate)
        n = min(len(ev), len(ref))
        err = dict(
            error_start=max(abs(float(ev[i]["start_s"]) -
                                float(ref[i]["start_s"])) for i in range(n)),
            error_peak=max(abs(float(ev[i]["peak_slip_rate_m_per_s"]) /
                               float(ref[i]["peak_slip_rate_m_per_s"]) - 1)
                           for i in range(n)),
            error_slip=max(abs(float(ev[i]["slip_um"]) /
                               float(ref[i]["slip_um"]) - 1)
                           for i in range(n)),
            error_period="")
        if len(ev) != len(ref):
            err["error_start"] = math.inf  # an event missed or added
        row = dict(case=f"wedge-2+{DEPTH}", controller=controller,
                   tolerance=tol, extrapolated_start=extrapolate, **c, **err)
        print(row, flush=True)
        rows.append(row)
    return rows


FIELDS = ["case", "controller", "tolerance", "extrapolated_start", "steps",
          "spatial_problems", "fp_per_step", "tnnmg_per_problem", "wall_s",
          "error_start", "error_peak", "error_period", "error_slip"]


def table():
    rows = list(csv.DictReader(open(RESULTS)))
    print("| case | controller | δ = ε | extrapolated start | steps | "
          "spatial problems | FP/step | TNNMG/problem | wall [s] | "
          "start error [s] | peak error | period error | slip error |")
    print("|" + "---|" * 13)
    for r in rows:
        def g(k):
            v = r[k]
            try:
                return f"{float(v):.3g}"
            except ValueError:
                return v or "–"
        start = ("–" if r["controller"] == "step-doubling" else
                 "yes" if r["extrapolated_start"] == "True" else "no")
        print(f"| {r['case']} | {r['controller']} | {g('tolerance')} | "
              f"{start} | {r['steps']} | "
              f"{r['spatial_problems']} | {g('fp_per_step')} | "
              f"{g('tnnmg_per_problem')} | {g('wall_s')} | "
              f"{g('error_start')} | {g('error_peak')} | "
              f"{g('error_period')} | {g('error_slip')} |")


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = [r for r in csv.DictReader(open(RESULTS))
            if r["extrapolated_start"] == "True"]
    cases = sorted({r["case"] for r in rows}, reverse=True)
    fig, axes = plt.subplots(len(cases), 2, figsize=(10, 4 * len(cases)),
                             squeeze=False)
    for i, case in enumerate(cases):
        # the wedge's event starts are quantised by the steps at the onset
        # (table): its peak slip rates show the convergence
        key = "error_period" if case == "slider" else "error_peak"
        label = ("relative error of the recurrence time" if case == "slider"
                 else "max relative error of the peak slip rates")
        for controller, marker in zip(CONTROLLERS, "os"):
            sel = [r for r in rows
                   if r["case"] == case and r["controller"] == controller]
            for j, x in enumerate(["spatial_problems", "wall_s"]):
                axes[i][j].loglog([float(r[x]) for r in sel],
                                  [float(r[key]) for r in sel],
                                  marker + "-", label=controller)
                for r in sel:
                    axes[i][j].annotate(f"{float(r['tolerance']):g}",
                                        (float(r[x]), float(r[key])),
                                        fontsize=7)
        for j, x in enumerate(["spatial problems", "wall time [s]"]):
            axes[i][j].set_xlabel(x)
            axes[i][j].set_ylabel(label)
            axes[i][j].set_title(case)
            axes[i][j].grid(True, which="both", alpha=0.3)
            axes[i][j].legend()
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "doc", "figures", "time-stepping.png"),
                dpi=110)


def main():
    if "--table" in sys.argv:
        return table()
    if "--plot" in sys.argv:
        return plot()
    rows = []
    if "slider" in PARTS:
        rows += slider_part()
    if "wedge" in PARTS:
        rows += wedge_part()
    keep = []
    if os.path.exists(RESULTS):  # keep the rows of parts not rerun
        done = {r["case"] for r in rows}
        keep = [r for r in csv.DictReader(open(RESULTS))
                if r["case"] not in done]
    with open(RESULTS, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        w.writeheader()
        for r in keep + rows:
            w.writerow(r)
    plot()
    table()


if __name__ == "__main__":
    main()
