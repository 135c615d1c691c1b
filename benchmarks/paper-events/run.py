#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Why 90 events in 1000 s where the paper reports 79.

Sensitivity of the 2D laboratory wedge's event sequence (first-event time,
recurrence, events starting in [0, 1000] s, rupture width, peak slip rate,
slip, uplift per event at 15 / 30 / 45 cm) to every modelling choice the
paper (Pipping et al. 2016, section 3, Table 1) leaves open or that
rsfcycle made itself, and to Table 1's values within the ranges the paper
states, one at a time, on the default mesh of prm/wedge-2d.prm (2 global +
6 local refinements, Refinement distance 3, 16,612 unknowns, delta =
epsilon = 1e-4, TNNMG tolerance 1e-5, multigrid correction).

Readings that the built-in `wedge` scene cannot express (a prescribed
normal stress, another direction of gravity, an initial state, mu* on the
patch alone) run on the `mesh-file` scene with prm/wedge-2d-mesh.prm (the
same wedge from prm/meshes/wedge-2d.geo, 9,780 unknowns, the same cells on
the patch); they are compared with that scene's own default run
(`mesh-default`), not with the built-in's.

Every variant is a small .prm that includes prm/wedge-2d.prm (or
prm/wedge-2d-mesh.prm) and overrides one thing. Run folders live outside
the repository, in WORK/<name>/ (`--work WORK` or the environment's
PAPER_EVENTS_WORK; required to run, for --thresholds and for the
normal-stress figure); a run is not repeated when its log.txt ends with the
run's summary (`--rerun` repeats it). Runs go one after the other, on one
process, under nice.

The event definition (the threshold of doc/events.md) does not change the
dynamics: its alternatives are evaluated from the default run's
time-series.csv and base-profile.csv (`--thresholds`).

Usage (from anywhere; the binary runs in the repository's root, where
prm/wedge-2d-mesh.prm's mesh path resolves):
  benchmarks/paper-events/run.py [--exe BINARY] --work DIR [--only a,b]
                                 [--rerun]     # run what is missing, table
  benchmarks/paper-events/run.py --table [--work DIR]   # runs.csv, runs.md
  benchmarks/paper-events/run.py --plot        # figures/*.png
  benchmarks/paper-events/run.py --thresholds [--thresholds-run a,b]
                                 # event definitions (thresholds.*)
  benchmarks/paper-events/run.py --list        # the variants and readings
"""
import csv
import importlib.util
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
sys.path.insert(0, HERE)


def arg(name, default):
    if name in sys.argv:
        return sys.argv[sys.argv.index(name) + 1]
    return default


# the table was made with the binary of commit 487b033 (its default run is
# bitwise that of bc0b158, README.md); a new run uses the build's
EXE = arg("--exe", os.path.join(ROOT, "build", "rsfcycle"))
WORK = arg("--work", os.environ.get("PAPER_EVENTS_WORK", ""))
T_END = 1000.0
RUNS = os.path.join(HERE, "runs.csv")
LICENCE = "<!-- SPDX-License-Identifier: LGPL-2.1-or-later -->\n"


def work():
    """The run folders' location; exits with one line when not given."""
    if not WORK:
        sys.exit("run.py: where are the run folders? Give --work DIR or set "
                 "PAPER_EVENTS_WORK=DIR")
    return WORK
FIGURES = os.path.join(HERE, "figures")

# The paper's counts (section 3.2): 79 simulated events, 50 in the
# laboratory, both over T = 1000 s (Table 1).
PAPER_EVENTS = 79

DIP = math.atan(0.27)
G = 9.81
# prm/wedge-2d-mesh.prm's patch (mesh coordinates x, y of the .geo)
PATCH = ("x >= 0.35 - 0.2 * 1 / sqrt(1 + 0.27^2) - 1e-9 && "
         "x <= 0.35 + 1e-9")
# the weight of the vertical column above a base point (x, -0.27 x) of the
# .geo per unit area [Pa]: 900 kg/m^3 above y = -0.21, 1000 below
COLUMN = "9.81 * (900 * min(-y, 0.21) + 1000 * max(-y - 0.21, 0))"

# Plane stress (sigma_zz = 0) in plane-strain form: the same shear modulus,
# lambda* = 2 lambda G / (lambda + 2 G); with K = 5e4 Pa, nu = 0.3:
# G = 23077 Pa, lambda = 34615 Pa -> lambda* = 19780 Pa, i.e. K* = lambda* +
# 2 G / 3 = 35165 Pa and nu* = nu / (1 + nu) = 0.230769. The viscous
# tensor the same way (eta_b = eta_s = eta: lambda_v = eta / 3 -> 2 eta / 7,
# eta_b* = 20 eta / 21).
_K, _NU = 5e4, 0.3
_G = 3 * _K * (1 - 2 * _NU) / (2 * (1 + _NU))
_LAM = _K - 2 * _G / 3
_LAM_PS = 2 * _LAM * _G / (_LAM + 2 * _G)
K_PLANE_STRESS = _LAM_PS + 2 * _G / 3
NU_PLANE_STRESS = _NU / (1 + _NU)
ETA_B_PLANE_STRESS = 20.0 / 21.0  # times eta
# Viscosity tensor proportional to the elasticity tensor (one relaxation
# time per region): eta_b / eta_s = K / G
K_OVER_G = _K / _G


def wedge(*lines):
    """Entries of subsection Wedge."""
    return "subsection Wedge\n" + "".join(f"  set {s}\n" for s in lines) + \
        "end\n"


def friction(*lines):
    """Entries of subsection Mesh file/Friction."""
    return ("subsection Mesh file\n  subsection Friction\n"
            + "".join(f"    set {s}\n" for s in lines) + "  end\nend\n")


def mesh_file(*lines):
    return "subsection Mesh file\n" + "".join(f"  set {s}\n" for s in lines) \
        + "end\n"


# name, base scene ("wedge": prm/wedge-2d.prm, "mesh": prm/wedge-2d-mesh.prm),
# group, the choice, our reading -> this reading, overrides
VARIANTS = [
    ("default", "wedge", "reference", "prm/wedge-2d.prm as shipped",
     "Table 1, our readings", ""),
    ("mesh-default", "mesh", "reference",
     "prm/wedge-2d-mesh.prm as shipped (reference of the mesh-file rows)",
     "Table 1, our readings", ""),
    # -- choices the paper leaves open or that we made --------------------
    ("cohesion-0", "wedge", "choice", "cohesion C in (10)",
     "C = 10 Pa added to the friction stress -> C = 0",
     wedge("Cohesion = 0")),
    ("sigma-cos", "mesh", "choice", "normal stress on the base",
     "gravity equilibrium, frictionless base, backstop fixed "
     "(1.02 rho g h on the patch) -> rho g h cos(dip) prescribed",
     friction(f"Normal stress = {COLUMN} * cos(atan(0.27))")),
    ("sigma-cos2", "mesh", "choice", "normal stress on the base",
     "gravity equilibrium -> rho g h cos^2(dip) prescribed (the normal "
     "component of the column's weight per base area)",
     friction(f"Normal stress = {COLUMN} * cos(atan(0.27))^2")),
    ("sigma-equilibrium", "mesh", "control", "normal stress on the base",
     "the gravity equilibrium's own values -> their fit 1.021 rho g h "
     "prescribed (does prescribing change anything by itself?)",
     friction(f"Normal stress = 1.021 * {COLUMN}")),
    ("sigma-x1.05", "mesh", "choice", "normal stress on the base",
     "gravity equilibrium -> 1.05 x its fit (1.072 rho g h) prescribed",
     friction(f"Normal stress = 1.05 * 1.021 * {COLUMN}")),
    ("sigma-x1.10", "mesh", "choice", "normal stress on the base",
     "gravity equilibrium -> 1.10 x its fit (1.123 rho g h) prescribed",
     friction(f"Normal stress = 1.10 * 1.021 * {COLUMN}")),
    ("sigma-loaded", "mesh", "choice", "normal stress on the base",
     "gravity equilibrium (held fixed) -> the normal stress of the loaded, "
     "cycling wedge (normal_stress.py at 510 - 650 s: 1.30 x the "
     "equilibrium's up to s = 0.45 m, 1.10 beyond 0.6 m) prescribed",
     friction(f"Normal stress = 1.021 * {COLUMN} * "
              "if(x <= 0.4345, 1.30, if(x >= 0.5793, 1.10, "
              "1.30 - 0.20 * (x - 0.4345) / 0.1448))")),
    ("gravity-normal", "mesh", "choice", "direction of gravity",
     "vertical in the physical frame, rotated with the wedge -> g "
     "perpendicular to the base (the base frame's -y, no down-dip part); "
     "uplift then along the base normal",
     mesh_file("Gravity = %.9f, %.9f" % (-G * math.sin(DIP),
                                          -G * math.cos(DIP)))),
    ("bulk-viscosity-0", "wedge", "choice", "bulk viscosity",
     "eta_b = eta_s = eta -> eta_b = 0 (eta a shear viscosity only)",
     wedge("Bulk viscosity upper = 0", "Bulk viscosity lower = 0")),
    ("bulk-viscosity-KG", "wedge", "choice", "bulk viscosity",
     "eta_b = eta_s -> eta_b = (K/G) eta_s = 2.17 eta (viscous tensor "
     "proportional to the elastic one)",
     wedge(f"Bulk viscosity upper = {1e3 * K_OVER_G:.6g}",
           f"Bulk viscosity lower = {1e4 * K_OVER_G:.6g}")),
    ("plane-stress", "wedge", "choice", "2D reduction of the 10 cm width",
     "plane strain -> plane stress (K = 35.2 kPa, nu = 0.231, eta_b = "
     "0.95 eta: the same in-plane moduli)",
     wedge(f"Bulk modulus = {K_PLANE_STRESS:.6g}",
           f"Poisson ratio = {NU_PLANE_STRESS:.6g}",
           f"Bulk viscosity upper = {1e3 * ETA_B_PLANE_STRESS:.6g}",
           f"Bulk viscosity lower = {1e4 * ETA_B_PLANE_STRESS:.6g}")),
    ("ramp-1s", "wedge", "choice", "ramp t0",
     "t0 = 100 s (Table 1) -> t0 = 1 s (almost a step)",
     wedge("Ramp time = 1")),
    ("theta0-aged", "mesh", "choice", "initial state",
     "theta0 = L/V* = 0.45 s (steady at v0) -> theta0 = 1000 s (healed "
     "at rest)",
     friction("Initial state = 1000")),
    ("theta0-weak", "mesh", "choice", "initial state",
     "theta0 = L/V* -> theta0 = 0.1 L/V* = 0.045 s",
     friction("Initial state = 0.045")),
    # -- Table 1 within the stated ranges ----------------------------------
    ("mu-star-patch-0.8", "mesh", "table", "mu* (experiment: 0.7 - 0.8)",
     "0.7 everywhere -> 0.8 on the patch (the experiment column)",
     friction(f"Reference friction coefficient = if({PATCH}, 0.8, 0.7)")),
    ("a-patch-0.001", "wedge", "table", "a on the patch (<= 0.002)",
     "0.002 -> 0.001 (b - a = 0.015 kept)", wedge("Patch a = 0.001")),
    ("a-outside-0.010", "wedge", "table", "a off the patch (0.010 - 0.020)",
     "0.020 -> 0.010 (b - a = -0.015 kept)", wedge("Outside a = 0.010")),
    ("a-outside-0.015", "wedge", "table", "a off the patch (0.010 - 0.020)",
     "0.020 -> 0.015 (b - a = -0.015 kept; the middle of the range)",
     wedge("Outside a = 0.015")),
    ("ba-outside-0.010", "wedge", "table",
     "b - a off the patch (-0.020 - -0.010)", "-0.015 -> -0.010",
     wedge("Outside b - a = -0.010")),
    ("ba-outside-0.020", "wedge", "table",
     "b - a off the patch (-0.020 - -0.010)", "-0.015 -> -0.020",
     wedge("Outside b - a = -0.020")),
    # -- Table 1 values without a stated range (sensitivity only) ---------
    ("nu-0.35", "wedge", "sensitivity", "Poisson ratio (simulation 0.3)",
     "0.3 -> 0.35 (K kept: G 28 % lower)", wedge("Poisson ratio = 0.35")),
    ("nu-0.25", "wedge", "sensitivity", "Poisson ratio (simulation 0.3)",
     "0.3 -> 0.25 (K kept: G 30 % higher)", wedge("Poisson ratio = 0.25")),
    ("L-30um", "wedge", "sensitivity", "L (simulation 22.5 um)",
     "22.5 um -> 30 um", wedge("Characteristic slip distance = 30e-6")),
    ("eta-upper-10k", "wedge", "sensitivity",
     "viscosity of the upper region (experiment: unknown)",
     "1 kPa s -> 10 kPa s (as the lower region)",
     wedge("Shear viscosity upper = 1e4", "Bulk viscosity upper = 1e4")),
]
NAMES = [v[0] for v in VARIANTS]
REFERENCE = {"wedge": "default", "mesh": "mesh-default"}


def prm_text(name, base, overrides):
    src = "prm/wedge-2d.prm" if base == "wedge" else "prm/wedge-2d-mesh.prm"
    return f"""# benchmarks/paper-events/run.py: variant {name}
include {ROOT}/{src}
set Output directory = {os.path.join(work(), name)}
set End time         = {T_END:g}
subsection Output
  set Write VTU = false
end
{overrides}"""


def finished(d):
    log = os.path.join(d, "log.txt")
    return os.path.exists(log) and "Summary:" in open(log).read()


def run(name, base, overrides):
    d = os.path.join(work(), name)
    if finished(d) and "--rerun" not in sys.argv:
        return
    os.makedirs(os.path.join(WORK, "prm"), exist_ok=True)
    prm = os.path.join(WORK, "prm", name + ".prm")
    open(prm, "w").write(prm_text(name, base, overrides))
    print(f"running {name} ...", flush=True)
    with open(os.path.join(WORK, name + ".out"), "w") as out:
        subprocess.run(["nice", "-n", "19", EXE, "--force", prm], cwd=ROOT,
                       stdout=out, stderr=subprocess.STDOUT, check=True)


def convergence_module():
    """benchmarks/convergence/run.py, for its event_statistics() (means
    over the events after the first 8, uplift per event from
    time-series.csv)."""
    path = os.path.join(ROOT, "benchmarks", "convergence", "run.py")
    spec = importlib.util.spec_from_file_location("convergence_run", path)
    module = importlib.util.module_from_spec(spec)
    argv, sys.argv = sys.argv, [path, "--table"]
    try:
        spec.loader.exec_module(module)
    finally:
        sys.argv = argv
    return module


COLUMNS = ["events_1000s", "first_event_s", "recurrence_s",
           "recurrence_min_s", "recurrence_max_s", "rupture_width_m",
           "peak_slip_rate_mm_per_s", "slip_um", "duration_s",
           "uplift_15cm_um", "uplift_30cm_um", "uplift_45cm_um",
           "nucleation_position_m", "unknowns"]


def statistics(name):
    d = os.path.join(WORK, name)
    events = list(csv.DictReader(open(os.path.join(d, "events.csv"))))
    if not events:
        # no event in 1000 s (slow slip below the threshold, or steady sliding)
        row = {k: float("nan") for k in COLUMNS}
        row.update(events_1000s=0)
        return row
    conv = convergence_module()
    row = conv.event_statistics(d)  # means over events 9, 10, ...
    starts = [float(e["start_s"]) for e in events]
    rec = [float(e["recurrence_s"]) for e in events[conv.TRANSITION:]]
    # event_statistics() gives the peak slip rate in mm/s already
    row["peak_slip_rate_mm_per_s"] = row.pop("peak_slip_rate_m_per_s")
    row.update(events_1000s=sum(1 for t in starts if 0 <= t <= T_END),
               first_event_s=starts[0], recurrence_min_s=min(rec),
               recurrence_max_s=max(rec))
    return {k: row[k] for k in COLUMNS}


def collect():
    """The rows of the finished runs in WORK; a variant whose run folder is
    not (or no longer) there, or every variant without WORK, keeps its row
    of runs.csv."""
    previous = {r["name"]: r for r in read_runs()} \
        if os.path.exists(RUNS) else {}
    rows = []
    for name, base, group, choice, reading, _ in VARIANTS:
        if not WORK or not finished(os.path.join(WORK, name)):
            if name in previous:
                rows.append(previous[name])
            continue
        r = statistics(name)
        r.update(name=name, scene=base, group=group, choice=choice,
                 reading=reading)
        rows.append(r)
    keys = ["name", "scene", "group", "choice", "reading"] + COLUMNS
    with open(RUNS, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{r[k]:.6g}" if isinstance(r[k], float)
                            else r[k]) for k in keys})
    return rows


def read_runs():
    rows = list(csv.DictReader(open(RUNS)))
    for r in rows:
        for k in COLUMNS:
            r[k] = float(r[k])
    return rows


def table(rows=None):
    """The markdown table, printed and written to runs.md."""
    import contextlib
    import io
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        _table(rows)
    open(os.path.join(HERE, "runs.md"), "w").write(LICENCE + buf.getvalue())
    print(buf.getvalue(), end="")


def _table(rows=None):
    rows = rows or read_runs()
    by = {r["name"]: r for r in rows}
    print("| reading | scene | first event [s] | recurrence [s] (range) | "
          "events in 1000 s | rupture width [m] | peak slip rate [mm/s] | "
          "slip [µm] | uplift per event 15 / 30 / 45 cm [µm] |")
    print("|---" * 9 + "|")
    for r in rows:
        ref = by.get(REFERENCE[r["scene"]])
        if r["events_1000s"] == 0:
            print(f"| `{r['name']}`: {r['reading']} | "
                  f"{'built-in' if r['scene'] == 'wedge' else 'mesh-file'} | "
                  "– | – (no event above 10 v0) | 0 | – | – | – | – |")
            continue

        def rel(k):
            if ref is None or r is ref or ref[k] == 0:
                return ""
            return f" ({100 * (r[k] / ref[k] - 1):+.1f} %)"
        spread = (f" ({r['recurrence_min_s']:.3f} – "
                  f"{r['recurrence_max_s']:.3f})"
                  if r["recurrence_max_s"] - r["recurrence_min_s"] >
                  1e-3 * r["recurrence_s"] else "")
        d_events = "" if ref is None or r is ref else \
            f" ({int(r['events_1000s'] - ref['events_1000s']):+d})"
        print(f"| `{r['name']}`: {r['reading']} | "
              f"{'built-in' if r['scene'] == 'wedge' else 'mesh-file'} | "
              f"{r['first_event_s']:.1f} | "
              f"{r['recurrence_s']:.3f}{rel('recurrence_s')}{spread} | "
              f"{int(r['events_1000s'])}{d_events} | "
              f"{r['rupture_width_m']:.3f}{rel('rupture_width_m')} | "
              f"{r['peak_slip_rate_mm_per_s']:.3f}"
              f"{rel('peak_slip_rate_mm_per_s')} | "
              f"{r['slip_um']:.1f}{rel('slip_um')} | "
              f"{r['uplift_15cm_um']:.1f} / {r['uplift_30cm_um']:.1f} / "
              f"{r['uplift_45cm_um']:.1f} |")


THRESHOLDS = (1.05, 1.5, 2, 5, 10, 15, 20, 25, 27.5)


def thresholds(names=("default", "sigma-x1.05", "a-outside-0.015")):
    """Event count, first start, recurrence, width, duration under other
    event definitions, from the runs' time-series.csv (every accepted step:
    max slip rate) and base-profile.csv (rates per node); no new runs.
    Starts are the first accepted step above the threshold (events.csv
    interpolates them). Written to thresholds.csv and thresholds.md."""
    work()
    import plot_wedge
    v0 = 50e-6
    rows = []
    for name in names:
        d = os.path.join(work(), name)
        if not finished(d):
            continue
        ts = plot_wedge.read_time_series(d)
        profile = plot_wedge.read_base_profile(d)
        for k in THRESHOLDS:
            ev = plot_wedge.detect_events(ts, profile, v0, k)
            after = ev[8:]
            mean = (lambda f: sum(f(e) for e in after) / len(after)) \
                if after else (lambda f: float("nan"))
            rows.append(dict(
                run=name, threshold_v0=k,
                events_1000s=sum(1 for e in ev if 0 <= e.start <= T_END),
                first_event_s=ev[0].start if ev else float("nan"),
                recurrence_s=mean(lambda e: e.recurrence),
                rupture_width_m=mean(lambda e: e.width),
                duration_s=mean(lambda e: e.duration)))
    keys = ["run", "threshold_v0", "events_1000s", "first_event_s",
            "recurrence_s", "rupture_width_m", "duration_s"]
    with open(os.path.join(HERE, "thresholds.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{r[k]:.6g}" if isinstance(r[k], float)
                            else r[k]) for k in keys})

    def fmt(x, spec):
        return "–" if x != x else format(x, spec)
    lines = ["| run | event: max V above | events in 1000 s | "
             "first event [s] | recurrence, events 9 - [s] | "
             "rupture width [m] | duration [s] |", "|---" * 7 + "|"]
    for r in rows:
        lines.append(f"| `{r['run']}` | {r['threshold_v0']:g} v0 | "
                     f"{r['events_1000s']} | "
                     f"{fmt(r['first_event_s'], '.1f')} | "
                     f"{fmt(r['recurrence_s'], '.3f')} | "
                     f"{fmt(r['rupture_width_m'], '.3f')} | "
                     f"{fmt(r['duration_s'], '.3f')} |")
    text = "\n".join(lines) + "\n"
    open(os.path.join(HERE, "thresholds.md"), "w").write(LICENCE + text)
    print(text, end="")
    return rows


def plot(rows=None):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = rows or read_runs()
    by = {r["name"]: r for r in rows}
    os.makedirs(FIGURES, exist_ok=True)
    labels = [r["name"] + (" *" if r["scene"] == "mesh" else "")
              for r in rows]
    y = list(range(len(rows)))[::-1]
    colours = {"reference": "black", "control": "black", "choice": "tab:blue",
               "table": "tab:green", "sensitivity": "tab:gray"}
    c = [colours[r["group"]] for r in rows]
    panels = [
        ("events_1000s", "events starting in [0, 1000] s", 1),
        ("first_event_s", "first event [s]", 1),
        ("recurrence_s", "recurrence (mean, events 9 -) [s]", 1),
        ("rupture_width_m", "rupture width [m]", 1),
        ("slip_um", "slip per event [µm]", 1),
        ("uplift_30cm_um", "uplift per event at 30 cm [µm]", 1),
    ]
    fig, axes = plt.subplots(1, len(panels), figsize=(19, 0.36 * len(rows)
                                                      + 2.2), sharey=True)
    for ax, (k, title, scale) in zip(axes, panels):
        ax.barh(y, [scale * r[k] for r in rows], color=c, alpha=0.75)
        for ref, ls in (("default", "-"), ("mesh-default", ":")):
            if ref in by:
                ax.axvline(scale * by[ref][k], color="black", ls=ls, lw=0.8)
        if k == "events_1000s":
            ax.axvline(PAPER_EVENTS, color="tab:red", lw=1.5,
                       label=f"paper: {PAPER_EVENTS}")
            ax.legend(fontsize=8, loc="lower right")
            lo = min(r[k] for r in rows)
            ax.set_xlim(min(lo, PAPER_EVENTS) - 10,
                        max(r[k] for r in rows) + 5)
        elif k in ("first_event_s", "recurrence_s", "rupture_width_m",
                   "slip_um"):
            vals = [r[k] for r in rows if r[k] == r[k]]  # (no NaN)
            span = max(vals) - min(vals)
            ax.set_xlim(max(0, min(vals) - 0.3 * span),
                        max(vals) + 0.1 * span)
        ax.set_title(title, fontsize=9)
        ax.grid(axis="x", alpha=0.3)
    axes[0].set_yticks(y)
    axes[0].set_yticklabels(labels, fontsize=8)
    fig.suptitle("2D laboratory wedge, one reading at a time (2 + 6 "
                 "refinements, Refinement distance 3: built-in 16,612 "
                 "unknowns; * mesh-file scene, 9,780 unknowns, dotted line "
                 "its reference); δ = ε = 1e-4; rsfcycle 487b033 (= bc0b158 on the default run)\n"
                 "blue: modelling choices, green: Table 1 within its "
                 "stated ranges, grey: Table 1 values without a range; "
                 "solid line: prm/wedge-2d.prm", fontsize=9)
    fig.tight_layout()
    out = os.path.join(FIGURES, "sensitivity.png")
    fig.savefig(out, dpi=110)
    print(out)


# the prescribed normal stress of the sigma-* variants on the patch,
# relative to the gravity equilibrium's there (1.021 rho g h)
SIGMA_LEVEL = {"sigma-cos2": math.cos(DIP) ** 2 / 1.021,
               "sigma-cos": math.cos(DIP) / 1.021, "sigma-equilibrium": 1.0,
               "mesh-default": 1.0, "sigma-x1.05": 1.05, "sigma-x1.10": 1.10,
               "sigma-loaded": 1.30}


def plot_normal_stress(rows=None):
    """(a) the normal stress of the loaded wedge on the base relative to
    the fixed one (default-vtu's snapshots), (b) events in 1000 s and
    recurrence against the prescribed normal stress level."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import normal_stress
    rows = rows or read_runs()
    by = {r["name"]: r for r in rows}
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 4.4))
    vtu = os.path.join(WORK, "default-vtu") if WORK else ""
    if os.path.isdir(os.path.join(vtu, "solution")):
        files = normal_stress.snapshots(vtu)
        ref, _ = normal_stress.base_stress(files[0])
        for f in files[::5] + [files[-1]]:
            a, t = normal_stress.base_stress(f)
            ax1.plot(a[:, 0], a[:, 1] / ref[:, 1], lw=1,
                     label=f"t = {t:.0f} s")
        ax1.axvspan(0.163, 0.363, color="orange", alpha=0.15,
                    label="patch")
        ax1.set_xlim(0, 1.0)
        ax1.set_ylim(0.8, 1.5)
        ax1.set_xlabel("position along the base from the trench [m]")
        ax1.set_ylabel("σn of the stress field / σn used by friction")
        ax1.set_title("(a) default run: normal stress the loaded wedge "
                      "exerts on the base\n(-σyy at the base faces) "
                      "relative to the fixed gravity-equilibrium value",
                      fontsize=9)
        ax1.legend(fontsize=7, ncol=2)
        ax1.grid(alpha=0.3)
    pts = sorted(((SIGMA_LEVEL[n], by[n]) for n in SIGMA_LEVEL if n in by),
                 key=lambda p: p[0])
    x = [p[0] for p in pts]
    ax2.plot(x, [p[1]["events_1000s"] for p in pts], "o-", color="tab:blue",
             label="events starting in [0, 1000] s")
    ax2.axhline(PAPER_EVENTS, color="tab:red", lw=1, label="paper: 79")
    ax2.set_xlabel("prescribed σn on the patch / gravity equilibrium's")
    ax2.set_ylabel("events in 1000 s", color="tab:blue")
    ax3 = ax2.twinx()
    ax3.plot(x, [p[1]["recurrence_s"] for p in pts], "s--",
             color="tab:green", label="recurrence")
    ax3.set_ylabel("recurrence (mean, events 9 -) [s]", color="tab:green")
    for level, r in pts:
        ax2.annotate(r["name"], (level, r["events_1000s"]), fontsize=7,
                     xytext=(4, 4), textcoords="offset points")
    ax2.set_title("(b) mesh-file scene (9,780 unknowns), normal stress "
                  "prescribed as a multiple of ρ g h", fontsize=9)
    ax2.legend(fontsize=8, loc="upper right")
    ax2.grid(alpha=0.3)
    fig.suptitle("2D laboratory wedge, 2 + 6 refinements at Refinement "
                 "distance 3 (built-in: 16,612 unknowns), δ = ε = 1e-4, "
                 "rsfcycle 487b033", fontsize=9)
    fig.tight_layout()
    out = os.path.join(FIGURES, "normal-stress.png")
    fig.savefig(out, dpi=110)
    print(out)


def main():
    if "-h" in sys.argv or "--help" in sys.argv:
        print(__doc__)
        return
    if "--list" in sys.argv:
        for name, base, group, choice, reading, over in VARIANTS:
            print(f"{name} [{base}, {group}] {choice}: {reading}")
        return
    if "--thresholds" in sys.argv:
        names = arg("--thresholds-run", "")
        thresholds(names.split(",") if names else
                   ("default", "sigma-x1.05", "a-outside-0.015"))
        return
    if "--table" in sys.argv:
        return table(collect())
    if "--plot" in sys.argv:
        rows = collect()
        plot(rows)
        # panel (a) needs the snapshots of the default-vtu run
        if WORK and os.path.isdir(os.path.join(WORK, "default-vtu",
                                                "solution")):
            plot_normal_stress(rows)
        return
    work()
    only = arg("--only", "")
    for name, base, group, choice, reading, over in VARIANTS:
        if only and name not in only.split(","):
            continue
        run(name, base, over)
    table(collect())


if __name__ == "__main__":
    main()
