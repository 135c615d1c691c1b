#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Mesh convergence of the laboratory wedges' event statistics.

The 2D wedge (prm/wedge-2d.prm, Table 1) with 2 global and K local
refinements toward the patch, local extrapolation at δ = ε = DELTA, the
multigrid correction with TNNMG tolerance DELTA / 10, until EVENTS events
have ended; runs at DELTA / 10 at the levels TIGHT show whether the
time-step tolerance limits. Per run, over the events after the first 8:
mean recurrence, peak slip rate, slip, rupture width, duration, uplift per
event at 15 / 30 / 45 cm (the jump of the surface displacement over the
event), nucleation position; unknowns, cells on the patch, time loop. From
the three finest runs of a series: the observed order p = log2(|d1| /
|d2|) of the last two changes and the Richardson limit q + d2 / (2^p − 1),
refused ("–") when the changes do not shrink geometrically.

The refinement law: `band` (the finest cells widened by BAND metres along
the base, LAYERS layers per level around them) or `centre` (centre
closer than DISTANCE diameters); the law is part of the run's name and
of its table file runs-<law>.csv.

Stages (from the repository's root, PYTHONPATH=python /usr/bin/python3
benchmarks/convergence/run.py STAGE ...):

  runs      the 2D series of one law into WORK (runs already finished are
            kept), then runs-<law>.csv and its table; hours: 2 + 6 at
            D = 3 takes 9 minutes, 2 + 9 at D = 1.5 34 minutes (one core
            each)
  table     the table of runs-<law>.csv with the Richardson limits
  grading   every law's runs at 2 + LEVEL (the README's grading table),
            with the order in the refinement distance D
  figures   doc/figures/convergence-2d.png (the series in K of --series)
            and doc/figures/convergence-2d-grading.png
  against   a run folder's statistics against the converged values (e.g.
            output-wedge-2d); --record writes them as the rows mesh.default.*
  runs-3d   prm/wedge-3d-paper.prm on 2 ranks and prm/wedge-3d.prm on one,
            δ = ε = 1e-4, until 13 events (hours each)
  three-d   the 3D table from those two run folders (results rows 3d.*)
"""
import concurrent.futures
import math
import os
import re

from rsfcycle import bench, events, prm, run

NAME = "convergence"
HERE = bench.folder(NAME)
TRANSITION = 8
QUANTITIES = [  # column of runs-*.csv, label, unit
    ("recurrence_s", "recurrence", "s"),
    ("peak_slip_rate_m_per_s", "peak slip rate", "mm/s"),  # stored in mm/s
    ("slip_um", "slip", "µm"),
    ("rupture_width_m", "rupture width", "m"),
    ("duration_s", "duration", "s"),
    ("uplift_15cm_um", "uplift 15 cm", "µm"),
    ("uplift_30cm_um", "uplift 30 cm", "µm"),
    ("uplift_45cm_um", "uplift 45 cm", "µm"),
    ("nucleation_position_m", "nucleation", "m"),
]
FIELDS = ["run", "level", "delta"] + [c for c, *_ in QUANTITIES] + \
    ["events", "unknowns", "patch_cell_mm", "steps", "wall_s"]
# The best estimate of the converged values (results rows converged.*: the
# limits in D at 2 + 6 plus the change 2 + 6 -> 2 + 9 at D = 1.5; ±1 %),
# in the units of QUANTITIES.
CONVERGED = {
    "recurrence_s": 5.26, "peak_slip_rate_m_per_s": 1.37, "slip_um": 188.0,
    "rupture_width_m": 0.380, "uplift_15cm_um": 51.9,
    "uplift_30cm_um": 16.6, "uplift_45cm_um": -6.41,
}


def law_tag(law, band, layers, distance):
    """The law's name in runs and files: band0.2x1, centre1.5, ..."""
    if law == "band":
        return f"band{band:g}x{layers:g}"
    return f"centre{distance:g}"


def law_entries(law, band, layers, distance):
    """The Mesh entries of the law."""
    if law == "band":
        return {"Mesh/Refinement law": "band",
                "Mesh/Refinement band": f"{band:g}",
                "Mesh/Refinement band layers": f"{layers:g}"}
    return {"Mesh/Refinement law": "centre distance",
            "Mesh/Refinement distance": f"{distance:g}"}


def runs_file(tag):
    return os.path.join(HERE, f"runs-{tag}.csv")


def one_run(exe, work, law, events_, rerun, level, delta):
    """One run of the series (skipped when its summary.txt exists and not
    rerun); law: (law, band, layers, distance). Returns its folder."""
    out = os.path.join(work, f"{law_tag(*law)}-2+{level}-delta{delta:g}")
    entries = {"Stop after events": events_,
               "Time stepping/Controller": "local-extrapolation",
               "Time stepping/Tolerance": f"{delta:g}",
               "Solver/Fixed-point tolerance": f"{delta:g}",
               "Solver/Linear correction": "multigrid",
               "Solver/TNNMG tolerance": f"{delta / 10:g}"}
    entries.update(law_entries(*law))
    path = bench.wedge_variant(out + ".prm", out, level, 1000, entries)
    if rerun or not os.path.exists(os.path.join(out, "summary.txt")):
        bench.rsfcycle(exe, [path], out + ".log")
    return out


def statistics_row(folder):
    """A row of runs-*.csv from a run folder (the peak slip rate in
    mm/s)."""
    row = bench.wedge_statistics(folder, TRANSITION)
    row["peak_slip_rate_m_per_s"] = row["peak_slip_rate_mm_per_s"]
    return row


def read_runs(path):
    rows = bench.read_table(path)
    for r in rows:
        for k, v in r.items():
            if k != "run":
                r[k] = float(v)
    return rows


def richardson(rows, column):
    """Observed order and limit from the three finest resolutions; (None,
    None) outside the asymptotic range."""
    q = [r[column] for r in rows[-3:]]
    if len(q) < 3:
        return None, None
    d1, d2 = q[1] - q[0], q[2] - q[1]
    if d1 == 0 or d2 == 0 or d1 * d2 < 0 or abs(d2) >= abs(d1):
        return None, None
    p = math.log2(abs(d1) / abs(d2))
    if p < 0.5:
        return None, None  # changes shrink too slowly to extrapolate
    return p, q[2] + d2 / (2 ** p - 1)


def richardson_table(series, names, order_label):
    """Order, limit and every run's distance from it, per quantity."""
    rows = []
    for column, label, unit in QUANTITIES:
        p, limit = richardson(series, column)
        if limit is None:
            rows.append([f"{label} [{unit}]", "–", "–"]
                        + [f"{r[column]:.4g}" for r in series])
        else:
            rows.append([f"{label} [{unit}]", f"{p:.2f}", f"{limit:.4g}"]
                        + [f"{100 * (r[column] / limit - 1):+.1f} %"
                           for r in series])
    return bench.markdown(["quantity", order_label, "Richardson limit"]
                          + names, rows)


def series_table(rows, delta):
    series = sorted([r for r in rows if r["delta"] == delta],
                    key=lambda r: r["level"])
    table = bench.markdown(
        ["mesh", "unknowns", "patch cells [mm]"]
        + [f"{label} [{unit}]" for _, label, unit in QUANTITIES]
        + ["steps", "wall [s]"],
        [[f"2 + {int(r['level'])}, δ = {r['delta']:g}", int(r["unknowns"]),
          f"{r['patch_cell_mm']:.2f}"]
         + [f"{r[c]:.4g}" for c, *_ in QUANTITIES]
         + [int(r["steps"]), f"{r['wall_s']:.0f}"]
         for r in sorted(rows, key=lambda r: (r["level"], -r["delta"]))])
    return table + "\n" + richardson_table(
        series, [f"2 + {int(r['level'])}" for r in series],
        "observed order")


def runs(law: ("band", "centre") = "band", band=0.2, layers=1.0,
         distance=1.5, delta=1e-5, levels="4,5,6,7,8,9", events=16,
         tight="5", jobs=2, rerun=False, build="", work=""):
    """Run a 2D series of one law into WORK, then runs-<law>.csv, its table.

    law: the refinement law toward the patch
    band: the band law's width W [m] of the finest cells along the base
    layers: the band law's layers L of each coarser size
    distance: the centre law's refinement distance D
    delta: δ = ε of the runs
    levels: local refinements K of the series
    events: events each run goes to
    tight: levels also run at δ / 10
    jobs: runs at a time
    rerun: repeat finished runs
    """
    exe = bench.executable(build)
    bench.work(work)
    law_ = (law, band, layers, distance)
    jobs_ = [(int(k), delta) for k in levels.split(",")] + \
        [(int(k), delta / 10) for k in tight.split(",") if k]
    jobs_.sort(key=lambda j: (-j[0], j[1]))  # the slowest first
    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        list(pool.map(lambda j: one_run(exe, work, law_, events, rerun, *j),
                      jobs_))
    tag = law_tag(*law_)
    rows = []
    for name in sorted(os.listdir(work)):
        m = re.fullmatch(re.escape(tag) + r"-2\+(\d+)-delta(\S+)", name)
        folder = os.path.join(work, name)
        if m and os.path.exists(os.path.join(folder, "summary.txt")):
            row = statistics_row(folder)
            row.update(run=name, level=int(m.group(1)),
                       delta=float(m.group(2)))
            rows.append(row)
    bench.write_table(runs_file(tag), FIELDS, rows)
    print(series_table(read_runs(runs_file(tag)), delta))


def table(law: ("band", "centre") = "band", band=0.2, layers=1.0,
          distance=1.5, delta=1e-5):
    """The table of runs-<law>.csv with the Richardson limits.

    law: the refinement law toward the patch (band: band0.2x1 by default)
    """
    print(series_table(read_runs(runs_file(law_tag(law, band, layers,
                                                   distance))), delta))


def runs_at_level(level, delta, family=""):
    """Every law's runs at 2 + level and tolerance delta, by unknowns."""
    import glob
    rows = []
    for path in glob.glob(os.path.join(HERE, f"runs-{family}*.csv")):
        tag = os.path.basename(path)[len("runs-"):-len(".csv")]
        for r in read_runs(path):
            if int(r["level"]) == level and r["delta"] == delta:
                r["tag"] = tag
                rows.append(r)
    return sorted(rows, key=lambda r: r["unknowns"])


def grading(level=6, delta=1e-5):
    """Every law's runs at 2 + LEVEL, with the order in D.

    level: local refinements
    """
    rows = runs_at_level(level, delta)
    print(bench.markdown(
        [f"2 + {level}: law", "unknowns"]
        + [f"{label} [{unit}]" for _, label, unit in QUANTITIES]
        + ["wall [s]"],
        [[r["tag"], int(r["unknowns"])]
         + [f"{r[c]:.4g}" for c, *_ in QUANTITIES] + [f"{r['wall_s']:.0f}"]
         for r in rows]))
    centre = sorted([r for r in rows if r["tag"].startswith("centre")],
                    key=lambda r: float(r["tag"][len("centre"):]))
    d = [float(r["tag"][len("centre"):]) for r in centre]
    if len(centre) >= 3 and all(b == 2 * a for a, b in zip(d[-3:], d[-2:])):
        print(richardson_table(centre, [f"centre {x:g}" for x in d],
                               "order in the distance"))


def figures(series="series-centre1.5-9d80414.csv", level=6, delta=1e-5):
    """doc/figures/convergence-2d.png and convergence-2d-grading.png.

    series: the runs file of the series in K
    level: the grading figure's local refinements
    """
    from rsfcycle.plot import _pyplot, savefig
    plt = _pyplot()
    name = series
    rows = read_runs(os.path.join(HERE, name))
    series = sorted([r for r in rows if r["delta"] == delta],
                    key=lambda r: r["level"])
    tight = [r for r in rows if r["delta"] < delta]
    fig, axes = plt.subplots(3, 3, figsize=(11, 9))
    for ax, (column, label, unit) in zip(axes.flat, QUANTITIES):
        ax.semilogx([r["patch_cell_mm"] for r in series],
                    [r[column] for r in series], "o-",
                    label=f"δ = {delta:g}")
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
    fig.suptitle("2D wedge: event statistics against the mesh (2 global + "
                 f"K local refinements, {name})")
    fig.tight_layout()
    savefig(fig, os.path.join(bench.ROOT, "doc", "figures",
                              "convergence-2d.png"), dpi=110)

    fig, axes = plt.subplots(3, 3, figsize=(11, 9))
    for family, marker in (("centre", "o-"), ("band", "s--")):
        rows = runs_at_level(level, delta, family)
        for ax, (column, label, unit) in zip(axes.flat, QUANTITIES):
            ax.semilogx([r["unknowns"] for r in rows],
                        [r[column] for r in rows], marker,
                        label="centre distance 1.5 / 3 / 6"
                        if family == "centre" else
                        "band 0.2 m, 2 / 4 / 8 layers")
            ax.set_title(f"{label} [{unit}]")
            ax.set_xlabel("unknowns")
    for ax in axes.flat:
        ax.legend(fontsize=7)
    fig.suptitle(f"2D wedge, 2 + {level} refinements: event statistics "
                 "against the grading")
    fig.tight_layout()
    savefig(fig, os.path.join(bench.ROOT, "doc", "figures",
                              "convergence-2d-grading.png"), dpi=110)


KEYS = {"recurrence_s": "recurrence", "peak_slip_rate_m_per_s":
        "peak_slip_rate", "slip_um": "slip", "rupture_width_m":
        "rupture_width", "uplift_15cm_um": "uplift_15cm",
        "uplift_30cm_um": "uplift_30cm", "uplift_45cm_um": "uplift_45cm"}


def against(run_folder, record=False):
    """A run folder's statistics against the converged values.

    run_folder: e.g. output-wedge-2d
    record: write them as the rows mesh.default.* of results.csv
    """
    row = statistics_row(run_folder)
    print(f"{run_folder}: {row['unknowns']} unknowns, {row['events']} events "
          f"after the first {TRANSITION}")
    figures_ = []
    for column, label, unit in QUANTITIES:
        line = f"  {label:15s} {row[column]:10.4g} {unit}"
        if column in CONVERGED:
            change = 100 * (row[column] / CONVERGED[column] - 1)
            line += (f"   converged {CONVERGED[column]:g} {unit}: "
                     f"{change:+.1f} %")
            figures_.append((f"mesh.default.{KEYS[column]}",
                             f"{change:+.1f}", "%",
                             f"prm/wedge-2d.prm from converged: {label}"))
        print(line)
    if record:
        from rsfcycle import results
        ranks = re.search(r"MPI ranks: (\d+)",
                          bench.text(os.path.join(run_folder, "log.txt")))
        old = results.read_results(os.path.join(HERE, "results.csv"))
        figures_ = [(k, v, u, old[k].description if k in old else d)
                    for k, v, u, d in figures_]
        bench.record(NAME, figures_, ranks.group(1) if ranks else 1)


def runs_3d(build="", work=""):
    """prm/wedge-3d-paper.prm on 2 ranks, prm/wedge-3d.prm on one, 13 events."""
    exe = bench.executable(build)
    bench.work(work)
    entries = {"Stop after events": 13, "Time stepping/Tolerance": "1e-4",
               "Solver/Fixed-point tolerance": "1e-4",
               "Solver/TNNMG tolerance": "1e-5",
               "Output/Writers": "time series, base profile, events"}
    for name, ranks in (("wedge-3d-paper", 2), ("wedge-3d", 1)):
        out = os.path.join(work, name)
        path = prm.variant(out + ".prm", os.path.join(bench.ROOT, "prm",
                                                      name + ".prm"),
                           out, entries)
        print(f"running prm/{name}.prm on {ranks} ranks ...", flush=True)
        bench.run(bench.mpirun(ranks, [exe, path]), out + ".log",
                  env=bench.mpi_environment())


def three_d_row(folder, first, last):
    """Means over events first .. last (from 1) of a 3D run, its first
    periodic event (consecutive recurrences within 0.2 %), iterations per
    step and wall time per cycle."""
    table = run.events(folder)
    chosen = table.iloc[first - 1:last]
    v0 = float(run.parameters(folder)["Wedge/Convergence rate"])
    recurrence = table["recurrence_s"].tolist()
    periodic = next((i + 1 for i in range(1, len(recurrence) - 1)
                     if all(abs(b / a - 1) < 2e-3 for a, b in
                            zip(recurrence[i:-1], recurrence[i + 1:]))),
                    None)
    cycles = events.cycles(folder, last - first)
    return {"recurrence": chosen["recurrence_s"].mean(),
            "peak": chosen["peak_slip_rate_m_per_s"].mean() / v0,
            "slip": chosen["slip_um"].mean(),
            "width": chosen["rupture_width_m"].mean(),
            "duration": chosen["duration_s"].mean(), "periodic": periodic,
            "fixed_point": cycles["fixed_point_iterations"][0],
            "cycles": cycles["linear_iterations"][0],
            "wall": cycles["wall_per_cycle"],
            "unknowns": cycles["unknowns"]}


def three_d(paper_run, default_run, first=11, last=13):
    """The 3D table from the two run folders (rows 3d.*).

    paper_run: the run of prm/wedge-3d-paper.prm
    default_run: the run of prm/wedge-3d.prm
    first: the first event of the means
    last: the last event of the means
    """
    paper = three_d_row(paper_run, first, last)
    default = three_d_row(default_run, first, last)
    labels = [("recurrence", "recurrence [s]"),
              ("peak", "peak slip rate [v0]"), ("slip", "slip [µm]"),
              ("width", "rupture width [m]"), ("duration", "duration [s]")]
    rows = [[label, f"{paper[k]:.4g}", f"{default[k]:.4g}",
             f"{100 * (default[k] / paper[k] - 1):+.1f} %"]
            for k, label in labels]
    for k, label in (("periodic", "first periodic event"),
                     ("fixed_point", "fixed-point iterations per step, max"),
                     ("cycles", "V-cycles per step, max"),
                     ("unknowns", "unknowns")):
        rows.append([label, paper[k], default[k], ""])
    rows.append(["wall time per cycle [min]",
                 f"{(paper['wall'] or math.nan) / 60:.1f}",
                 f"{(default['wall'] or math.nan) / 60:.1f}", ""])
    print(f"events {first} – {last}:")
    print(bench.markdown(["quantity", "paper resolution", "default mesh",
                          "default from paper"], rows))


if __name__ == "__main__":
    raise SystemExit(bench.cli(__doc__, NAME, [
        runs, table, grading, figures, against, runs_3d, three_d]))
