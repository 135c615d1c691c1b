#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Mesh convergence of the 2D wedge's event statistics.

The 2D wedge (prm/wedge-2d.prm, Table 1) with 2 global and K local
refinements toward the patch (the patch's cells halve with every K), the
default controller (local extrapolation) at delta = epsilon = DELTA, the
geometric multigrid correction with TNNMG tolerance epsilon / 10, run until
EVENTS events have ended (`Stop after events`). Runs at delta / 10 at the
levels TIGHT show whether the time-step tolerance limits.

Per resolution, over the events after the transition (the first TRANSITION
events dropped): mean recurrence time, peak slip rate, slip, rupture width,
duration, uplift per event at 15/30/45 cm (the jump of the surface
displacement from the event's start to its end), nucleation position; and
the unknowns, the cells on the patch, the wall time. From the three finest
resolutions: the observed order p = log2(|d1| / |d2|) of the last two
changes d1, d2 and the Richardson limit q + d2 / (2^p - 1); every resolution
is then given as its distance from that limit.

The refinement law is `Mesh/Refinement law = band` (the finest cells on
the patch widened by BAND metres along the base, LAYERS layers of cells per
level around them) unless `--law centre` asks for the `centre distance` law
(centre closer than DISTANCE diameters, `--distance`, default 1.5). The law and its parameters are part of
the run's name; the tables and the figure take the runs of one law.

Runs are kept in WORK/<name>/ and not repeated if their summary.txt exists
(`--rerun` repeats them); runs-<law>.csv and the table hold every finished
run in WORK, so that the series can be extended run by run (`--levels 10`).

Usage: benchmarks/convergence/run.py [BUILD_DIR] [--levels 4,5,6,7,8,9]
           [--delta 1e-5] [--events 16] [--tight 5] [--jobs 2] [--work DIR]
           [--law band|centre] [--band 0.2] [--layers 1] [--distance 1.5]
           [--rerun]
       benchmarks/convergence/run.py --table | --plot  [--law ...]
       benchmarks/convergence/run.py --grading K   # every law at 2 + K
       benchmarks/convergence/run.py --plot-grading K
       benchmarks/convergence/run.py --against RUNDIR
           # a run folder's statistics against the converged values (the
           # CONVERGED table below), e.g. output-wedge-2d of README command 1
"""
import concurrent.futures
import csv
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.dirname(HERE))
import common  # noqa: E402  (benchmarks/common.py)

TRANSITION = 8
QUANTITIES = [  # column, label, unit, scale
    ("recurrence_s", "recurrence", "s", 1.0),
    ("peak_slip_rate_m_per_s", "peak slip rate", "mm/s", 1e3),
    ("slip_um", "slip", "µm", 1.0),
    ("rupture_width_m", "rupture width", "m", 1.0),
    ("duration_s", "duration", "s", 1.0),
    ("uplift_15cm_um", "uplift 15 cm", "µm", 1.0),
    ("uplift_30cm_um", "uplift 30 cm", "µm", 1.0),
    ("uplift_45cm_um", "uplift 45 cm", "µm", 1.0),
    ("nucleation_position_m", "nucleation", "m", 1.0),
]

# The best estimate of the converged values (README: the limits in the
# refinement distance at 2 + 6 plus the change 2 + 6 -> 2 + 9 at distance
# 1.5; +-1 %), in the units of QUANTITIES' labels.
CONVERGED = {
    "recurrence_s": 5.26,
    "peak_slip_rate_m_per_s": 1.37,
    "slip_um": 188.0,
    "rupture_width_m": 0.380,
    "uplift_15cm_um": 51.9,
    "uplift_30cm_um": 16.6,
    "uplift_45cm_um": -6.41,
}


def arg(name, default):
    if name in sys.argv:
        return sys.argv[sys.argv.index(name) + 1]
    return default


OPTS = ("--against", "--grading", "--plot-grading", "--levels", "--delta", "--events", "--jobs", "--work", "--tight",
        "--law", "--band", "--layers", "--distance")
BUILD = next((a for i, a in enumerate(sys.argv[1:], 1)
              if not a.startswith("--") and sys.argv[i - 1] not in OPTS),
             os.path.join(ROOT, "build"))
EXE = os.path.join(BUILD, "rsfcycle")
LEVELS = [int(k) for k in arg("--levels", "4,5,6,7,8,9").split(",")]
DELTA = float(arg("--delta", "1e-5"))
EVENTS = int(arg("--events", "16"))
JOBS = int(arg("--jobs", "2"))
TIGHT = [int(k) for k in arg("--tight", "5").split(",") if k]
WORK = arg("--work", os.path.join(HERE, "work"))
LAW = arg("--law", "band")
BAND = float(arg("--band", "0.2"))
LAYERS = float(arg("--layers", "1"))
DISTANCE = float(arg("--distance", "1.5"))
LAW_TAG = f"band{BAND:g}x{LAYERS:g}" if LAW == "band" else \
    f"centre{DISTANCE:g}"
RESULTS = os.path.join(HERE, f"runs-{LAW_TAG}.csv")
FIGURE = os.path.join(ROOT, "doc", "figures", f"convergence-2d-{LAW_TAG}.png")
MESH = f"""subsection Mesh
  set Refinement law         = band
  set Refinement band        = {BAND:g}
  set Refinement band layers = {LAYERS:g}
end
""" if LAW == "band" else f"""subsection Mesh
  set Refinement law      = centre distance
  set Refinement distance = {DISTANCE:g}
end
"""


def run_name(level, delta):
    return f"{LAW_TAG}-2+{level}-delta{delta:g}"


def make_prm(level, delta):
    d = os.path.join(WORK, run_name(level, delta))
    prm = d + ".prm"
    with open(prm, "w") as f:
        f.write(common.wedge_prm(ROOT, level, d, 1000, f"""
set Stop after events = {EVENTS}
subsection Time stepping
  set Controller = local-extrapolation
  set Tolerance  = {delta:g}
end
subsection Solver
  set Fixed-point tolerance = {delta:g}
  set Linear correction     = multigrid
  set TNNMG tolerance       = {delta / 10:g}
end
{MESH}"""))
    return d, prm


def run(level, delta):
    d, prm = make_prm(level, delta)
    if os.path.exists(os.path.join(d, "summary.txt")) and \
            "--rerun" not in sys.argv:
        return d
    common.run(EXE, [prm], d + ".log")
    return d


def event_statistics(d):
    """Means over the events after the transition, and the run's cost."""
    events = list(csv.DictReader(open(os.path.join(d, "events.csv"))))
    series = list(csv.DictReader(open(os.path.join(d, "time-series.csv"))))
    times = [float(r["time_s"]) for r in series]

    def at(t, column):  # the first row at or after t
        lo, hi = 0, len(times) - 1
        while lo < hi:
            mid = (lo + hi) // 2
            if times[mid] < t:
                lo = mid + 1
            else:
                hi = mid
        return float(series[lo][column])

    for e in events:
        for cm in (15, 30, 45):
            col = f"uplift_{cm}cm_m"
            e[f"uplift_{cm}cm_um"] = 1e6 * (at(float(e["end_s"]), col) -
                                            at(float(e["start_s"]), col))
    after = events[TRANSITION:]
    if len(after) < 3:
        sys.exit(f"{d}: only {len(events)} events")
    row = {"events": len(after)}
    for column, _, _, scale in QUANTITIES:
        values = [float(e[column]) for e in after if e[column] != ""]
        row[column] = scale * sum(values) / len(values)
    log = open(os.path.join(d, "log.txt")).read()
    row["unknowns"] = int(re.search(r"(\d+) unknowns", log).group(1))
    row["patch_cell_mm"] = 1e3 * float(
        re.search(r"Cell diameters: (\S+) m", log).group(1))
    row["wall_s"] = common.stepping_time(log)
    row["steps"] = len(series)
    return row


def write_runs(rows):
    keys = ["run", "level", "delta"] + [c for c, *_ in QUANTITIES] + \
        ["events", "unknowns", "patch_cell_mm", "steps", "wall_s"]
    with open(RESULTS, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        for r in rows:
            w.writerow({k: r[k] for k in keys})


def read_runs():
    rows = list(csv.DictReader(open(RESULTS)))
    for r in rows:
        for k, v in r.items():
            if k != "run":
                r[k] = float(v)
    return rows


def richardson(rows, column):
    """Observed order and limit from the three finest resolutions."""
    q = [r[column] for r in rows[-3:]]
    if len(q) < 3:
        return None, None
    d1, d2 = q[1] - q[0], q[2] - q[1]
    if d1 == 0 or d2 == 0 or d1 * d2 < 0 or abs(d2) >= abs(d1):
        return None, None  # not (yet) in the asymptotic range
    p = math.log2(abs(d1) / abs(d2))
    if p < 0.5:
        return None, None  # changes shrink too slowly to extrapolate
    return p, q[2] + d2 / (2 ** p - 1)


def richardson_table(series, names, order_label):
    """Order, limit and every run's distance from it, per quantity."""
    print(f"| quantity | {order_label} | Richardson limit | "
          + " | ".join(names) + " |")
    print("|---" * (len(names) + 3) + "|")
    for column, label, unit, _ in QUANTITIES:
        p, limit = richardson(series, column)
        if limit is None:
            print(f"| {label} [{unit}] | – | – | "
                  + " | ".join(f"{r[column]:.4g}" for r in series) + " |")
            continue
        print(f"| {label} [{unit}] | {p:.2f} | {limit:.4g} | "
              + " | ".join(f"{100 * (r[column] / limit - 1):+.1f} %"
                           for r in series) + " |")


def runs_at_level(level, family=""):
    """Every law's runs at 2 + level and tolerance DELTA, by unknowns."""
    import glob
    rows = []
    for path in glob.glob(os.path.join(HERE, f"runs-{family}*.csv")):
        tag = os.path.basename(path)[len("runs-"):-len(".csv")]
        for r in csv.DictReader(open(path)):
            if int(float(r["level"])) == level and float(r["delta"]) == DELTA:
                r = {k: (v if k == "run" else float(v)) for k, v in r.items()}
                r["tag"] = tag
                rows.append(r)
    return sorted(rows, key=lambda r: r["unknowns"])


def table():
    rows = read_runs()
    series = sorted([r for r in rows if r["delta"] == DELTA],
                    key=lambda r: r["level"])
    print("| mesh | unknowns | patch cells [mm] | "
          + " | ".join(f"{label} [{unit}]" for _, label, unit, _ in QUANTITIES)
          + " | steps | wall [s] |")
    print("|---" * (len(QUANTITIES) + 5) + "|")
    for r in sorted(rows, key=lambda r: (r["level"], -r["delta"])):
        print(f"| 2 + {int(r['level'])}, δ = {r['delta']:g} | "
              f"{int(r['unknowns'])} | {r['patch_cell_mm']:.2f} | "
              + " | ".join(f"{r[c]:.4g}" for c, *_ in QUANTITIES)
              + f" | {int(r['steps'])} | {r['wall_s']:.0f} |")
    print()
    richardson_table(series, [f"2 + {int(r['level'])}" for r in series],
                     "observed order")


def grading(level):
    """The runs of every law at one level: the effect of the grading."""
    rows = runs_at_level(level)
    print(f"| 2 + {level}: law | unknowns | "
          + " | ".join(f"{label} [{unit}]" for _, label, unit, _ in QUANTITIES)
          + " | wall [s] |")
    print("|---" * (len(QUANTITIES) + 3) + "|")
    for r in rows:
        print(f"| {r['tag']} | {int(r['unknowns'])} | "
              + " | ".join(f"{r[c]:.4g}" for c, *_ in QUANTITIES)
              + f" | {r['wall_s']:.0f} |")
    # Richardson in the grading: centre-distance runs with doubling distance
    centre = sorted([r for r in rows if r["tag"].startswith("centre")],
                    key=lambda r: float(r["tag"][len("centre"):]))
    d = [float(r["tag"][len("centre"):]) for r in centre]
    if len(centre) >= 3 and all(b == 2 * a for a, b in zip(d[-3:], d[-2:])):
        print()
        richardson_table(centre, [f"centre {x:g}" for x in d],
                         "order in the distance")


def plot_grading(level):
    """Event statistics at 2 + K against the unknowns, one line per law."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(3, 3, figsize=(11, 9))
    for family, marker in (("centre", "o-"), ("band", "s--")):
        rows = runs_at_level(level, family)
        for ax, (column, label, unit, _) in zip(axes.flat, QUANTITIES):
            ax.semilogx([r["unknowns"] for r in rows],
                        [r[column] for r in rows], marker,
                        label="centre distance 1.5 / 3 / 6"
                        if family == "centre" else
                        "band 0.2 m, 2 / 4 / 8 layers")
            ax.set_title(f"{label} [{unit}]")
            ax.set_xlabel("unknowns")
    for ax in axes.flat:
        ax.legend(fontsize=7)
    fig.suptitle(f"2D wedge, 2 + {level} refinements (patch cells 2.6 – "
                 "3.0 mm): event statistics against the grading")
    fig.tight_layout()
    out = os.path.join(ROOT, "doc", "figures", "convergence-2d-grading.png")
    fig.savefig(out, dpi=110)
    print(out)


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = read_runs()
    delta = DELTA
    series = sorted([r for r in rows if r["delta"] == delta],
                    key=lambda r: r["level"])
    fig, axes = plt.subplots(3, 3, figsize=(11, 9))
    for ax, (column, label, unit, _) in zip(axes.flat, QUANTITIES):
        h = [r["patch_cell_mm"] for r in series]
        ax.semilogx(h, [r[column] for r in series], "o-",
                    label=f"δ = {delta:g}")
        tight = [r for r in rows if r["delta"] < delta]
        if tight:
            ax.semilogx([r["patch_cell_mm"] for r in tight],
                        [r[column] for r in tight], "s", label="δ / 10")
        p, limit = richardson(series, column)
        if limit is not None:
            ax.axhline(limit, color="gray", ls="--",
                       label=f"Richardson (p = {p:.1f})")
        ax.set_xlabel("cell size on the patch [mm]")
        ax.set_title(f"{label} [{unit}]")
        ax.invert_xaxis()
        ax.legend(fontsize=7)
    fig.suptitle("2D wedge: event statistics against the mesh "
                 f"(2 global + K local refinements, {LAW_TAG})")
    fig.tight_layout()
    fig.savefig(FIGURE, dpi=110)
    print(FIGURE)


def against(d):
    """A run folder's event statistics (means after the first TRANSITION
    events) and their distance from the converged values."""
    row = event_statistics(d)
    print(f"{d}: {row['unknowns']} unknowns, {row['events']} events after "
          f"the first {TRANSITION}")
    for column, label, unit, scale in QUANTITIES:
        line = f"  {label:15s} {row[column]:10.4g} {unit}"
        if column in CONVERGED:
            rel = row[column] / CONVERGED[column] - 1
            line += (f"   converged {CONVERGED[column]:g} {unit}: "
                     f"{100 * rel:+.1f} %")
        print(line)


def main():
    if "-h" in sys.argv or "--help" in sys.argv:
        return print(__doc__)
    if "--against" in sys.argv:
        return against(arg("--against", ""))
    if "--table" in sys.argv:
        return table()
    if "--plot" in sys.argv:
        return plot()
    if "--grading" in sys.argv:
        return grading(int(arg("--grading", "6")))
    if "--plot-grading" in sys.argv:
        return plot_grading(int(arg("--plot-grading", "6")))
    os.makedirs(WORK, exist_ok=True)
    jobs = [(k, DELTA) for k in LEVELS] + [(k, DELTA / 10) for k in TIGHT]
    # the finest (slowest) first, so that the pool ends together
    jobs.sort(key=lambda j: (-j[0], j[1]))
    with concurrent.futures.ThreadPoolExecutor(JOBS) as pool:
        list(pool.map(lambda j: run(*j), jobs))
    # every finished run in WORK, also those of earlier invocations
    rows = []
    for name in sorted(os.listdir(WORK)):
        m = re.fullmatch(re.escape(LAW_TAG) + r"-2\+(\d+)-delta(\S+)", name)
        if m and os.path.exists(os.path.join(WORK, name, "summary.txt")):
            row = event_statistics(os.path.join(WORK, name))
            row.update(run=name, level=int(m.group(1)),
                       delta=float(m.group(2)))
            rows.append(row)
    write_runs(rows)
    table()


if __name__ == "__main__":
    main()
