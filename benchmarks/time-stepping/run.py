#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
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
machine, so ratios are what to read. Writes runs.csv and
doc/figures/time-stepping.png; `--table` prints the table of README.md.

Local extrapolation runs with its default (Step sizes = ladder, Doubling
threshold 1) at every tolerance, and with threshold 0.5 and with free step
sizes at the looser ones; the wedge also with the multigrid correction
(ladder and free, 1e-5), since free step sizes need new matrices.

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


def variant(controller, tol, steps="ladder", threshold=1.0, extrapolate=True,
            correction="direct"):
    """One run's settings; `steps`, `threshold` and `extrapolate` are
    local extrapolation's (Step sizes, Doubling threshold, Extrapolated
    start), `correction` the wedge's Linear correction."""
    if controller == "step-doubling":
        steps, threshold, extrapolate = "", "", ""
    return dict(controller=controller, tolerance=tol, step_sizes=steps,
                doubling_threshold=threshold, extrapolated_start=extrapolate,
                correction=correction)


def name(v):
    if v["controller"] == "step-doubling":
        n = f"step-doubling-{v['tolerance']:g}"
    else:
        n = (f"local-extrapolation-{v['step_sizes']}"
             + (f"-{v['doubling_threshold']:g}"
                if v["step_sizes"] == "ladder" else "")
             + f"-{v['tolerance']:g}"
             + ("" if v["extrapolated_start"] else "-old-start"))
    return n + ("" if v["correction"] == "direct" else "-" + v["correction"])


def variants(tolerances, loose):
    """Step doubling and local extrapolation (ladder, Doubling threshold 1:
    the default) at `tolerances`; the ladder with threshold 0.5 and free
    step sizes at the `loose` ones; the default without extrapolated start
    at 1e-6."""
    return ([variant("step-doubling", t) for t in tolerances]
            + [variant("local-extrapolation", t) for t in tolerances]
            + [variant("local-extrapolation", t, threshold=0.5)
               for t in loose]
            + [variant("local-extrapolation", t, steps="free")
               for t in loose]
            + [variant("local-extrapolation", 1e-6, extrapolate=False)])


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
RUNS = os.path.join(HERE, "runs.csv")


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
def slider_prm(name, controller, tol, extrapolate=True, arkode=False,
               steps="ladder", threshold=1.0):
    d = os.path.join(WORK, "slider", name)
    prm = d + ".prm"
    with open(prm, "w") as f:
        f.write(f"""include {ROOT}/prm/spring-slider.prm
set End time = 5000
set Output directory = {d}
set Overwrite output = true
subsection Time stepping
  set Integrator = {"arkode" if arkode else "implicit"}
  set Controller         = {controller}
  set Extrapolated start = {str(extrapolate).lower()}
  set Step sizes         = {steps}
  set Doubling threshold = {threshold:g}
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
    for v in variants([1e-5, 1e-6, 1e-7], [1e-5, 1e-6, 1e-7]):
        d, prm = slider_prm(name(v), v["controller"], v["tolerance"],
                            v["extrapolated_start"] is not False,
                            steps=v["step_sizes"] or "ladder",
                            threshold=v["doubling_threshold"] or 1.0)
        walls = []
        for _ in range(3):
            run([prm], d + ".log")
            log = open(d + ".log").read()
            walls.append(float(re.search(r"Wall time of the time loop: (\S+)",
                                         log).group(1)))
        ts = list(csv.DictReader(open(os.path.join(d, "time-series.csv"))))
        e = slider_events(d)
        row = dict(case="slider", **dict(v, correction=""), wall_s=min(walls),
                   **counts(ts),
                   error_start=abs(e["first"] - ref["first"]),
                   error_peak=abs(e["peak"] / ref["peak"] - 1),
                   error_period=abs(e["period"] / ref["period"] - 1),
                   error_slip="")
        print(row, flush=True)
        rows.append(row)
    return rows


# ----------------------------------------------------------------- wedge
def wedge_window(v):
    pre = os.path.join(WORK, f"wedge-pre-{DEPTH}")
    out = os.path.join(WORK, f"wedge-{DEPTH}-{name(v)}")
    shutil.rmtree(out, ignore_errors=True)
    shutil.copytree(pre, out)
    prm = os.path.join(out, "parameters.prm")
    entries = {"End time": T1, "Output directory": out,
               "Controller": v["controller"],
               "Linear correction": v["correction"],
               "Tolerance": f"{v['tolerance']:g}",
               "Fixed-point tolerance": f"{v['tolerance']:g}"}
    if v["controller"] == "local-extrapolation":
        entries.update({
            "Extrapolated start": str(v["extrapolated_start"]).lower(),
            "Step sizes": v["step_sizes"],
            "Doubling threshold": f"{v['doubling_threshold']:g}"})
    for key, value in entries.items():
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
            f.write(common.wedge_prm(
                ROOT, DEPTH, pre, T0,
                "subsection Time stepping\n"
                "  set Controller = step-doubling\nend\n"))
        t = run([prm], pre + ".log")
        print(f"preload to {T0} s: {t:.0f} s", flush=True)
    _, ref_counts, ref = wedge_window(variant("step-doubling", 1e-8))
    print("reference", ref_counts, len(ref), "events", flush=True)
    rows = []
    todo = variants([1e-4, 1e-5, 1e-6, 1e-7], [1e-4, 1e-5, 1e-6])
    todo += [variant("local-extrapolation", 1e-5, steps=s,
                     correction="multigrid") for s in ("ladder", "free")]
    for v in todo:
        _, c, ev = wedge_window(v)
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
        row = dict(case=f"wedge-2+{DEPTH}", **v, **c, **err)
        print(row, flush=True)
        rows.append(row)
    return rows


FIELDS = ["case", "controller", "tolerance", "step_sizes",
          "doubling_threshold", "extrapolated_start", "correction", "steps",
          "spatial_problems", "fp_per_step", "tnnmg_per_problem", "wall_s",
          "error_start", "error_peak", "error_period", "error_slip"]


def label(r):
    if r["controller"] == "step-doubling":
        return "step doubling"
    lab = ("local extrapolation, " + r["step_sizes"]
           + (f" {float(r['doubling_threshold']):g}"
              if r["step_sizes"] == "ladder" else ""))
    return lab + ("" if r["extrapolated_start"] == "True" else ", old start")


def table():
    rows = list(csv.DictReader(open(RUNS)))
    print("| case | controller | correction | δ = ε | steps | "
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
        print(f"| {r['case']} | {label(r)} | {r['correction'] or '–'} | "
              f"{g('tolerance')} | {r['steps']} | "
              f"{r['spatial_problems']} | {g('fp_per_step')} | "
              f"{g('tnnmg_per_problem')} | {g('wall_s')} | "
              f"{g('error_start')} | {g('error_peak')} | "
              f"{g('error_period')} | {g('error_slip')} |")
    ratios(rows)


def interpolate(points, error):
    """log-log interpolation of (error, cost) pairs to `error`; None
    outside their range."""
    points = sorted(points)
    for (e0, c0), (e1, c1) in zip(points, points[1:]):
        if e0 <= error <= e1 and e0 < e1:
            w = math.log(error / e0) / math.log(e1 / e0)
            return math.exp((1 - w) * math.log(c0) + w * math.log(c1))
    return None


def ratios(rows):
    """Equal accuracy: each local-extrapolation variant's spatial problems
    and wall time interpolated to step doubling's error, as a fraction of
    step doubling's."""
    print()
    print("| case | error | step doubling δ | variant | problems ratio | "
          "wall ratio |")
    print("|---|---|---|---|---|---|")
    for case in sorted({r["case"] for r in rows}, reverse=True):
        key = "error_period" if case == "slider" else "error_peak"
        sel = [r for r in rows if r["case"] == case
               and r["correction"] in ("", "direct")
               and r["extrapolated_start"] != "False"]
        for sd in [r for r in sel if r["controller"] == "step-doubling"]:
            for lab in sorted({label(r) for r in sel} - {"step doubling"}):
                pts = [r for r in sel if label(r) == lab]
                e = float(sd[key])
                p = interpolate([(float(r[key]), float(r["spatial_problems"]))
                                 for r in pts], e)
                w = interpolate([(float(r[key]), float(r["wall_s"]))
                                 for r in pts], e)
                if p is None:
                    continue
                print(f"| {case} | {key[6:]} {e:.3g} | "
                      f"{float(sd['tolerance']):g} | {lab} | "
                      f"{p / float(sd['spatial_problems']):.3f} | "
                      f"{w / float(sd['wall_s']):.3f} |")


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = [r for r in csv.DictReader(open(RUNS))
            if r["extrapolated_start"] != "False"
            and r["correction"] in ("", "direct")]
    cases = sorted({r["case"] for r in rows}, reverse=True)
    fig, axes = plt.subplots(len(cases), 2, figsize=(11, 4.5 * len(cases)),
                             squeeze=False)
    for i, case in enumerate(cases):
        # the wedge's event starts are quantised by the steps at the onset
        # (table): its peak slip rates show the convergence
        key = "error_period" if case == "slider" else "error_peak"
        ylabel = ("relative error of the recurrence time" if case == "slider"
                  else "max relative error of the peak slip rates")
        labels = sorted({label(r) for r in rows if r["case"] == case},
                        key=lambda lab: (lab != "step doubling", lab))
        for lab, marker in zip(labels, "osd^v"):
            sel = [r for r in rows if r["case"] == case and label(r) == lab]
            sel.sort(key=lambda r: float(r["tolerance"]))
            for j, x in enumerate(["spatial_problems", "wall_s"]):
                axes[i][j].loglog([float(r[x]) for r in sel],
                                  [float(r[key]) for r in sel],
                                  marker + "-", label=lab)
                for r in sel:
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
    fig.savefig(os.path.join(ROOT, "doc", "figures", "time-stepping.png"),
                dpi=110)


def main():
    if "-h" in sys.argv or "--help" in sys.argv:
        return print(__doc__)
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
    if os.path.exists(RUNS):  # keep the rows of parts not rerun
        done = {r["case"] for r in rows}
        keep = [r for r in csv.DictReader(open(RUNS))
                if r["case"] not in done]
    with open(RUNS, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        w.writeheader()
        for r in keep + rows:
            w.writerow(r)
    plot()
    table()


if __name__ == "__main__":
    main()
