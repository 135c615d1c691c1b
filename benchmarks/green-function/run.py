#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The Green's-function method on SEAS BP1-QD (prm/seas-bp1-qd.prm):
accuracy and cost against the volume path, of the H-matrix, on several
ranks, and work against precision.

Stages (from the repository's root, PYTHONPATH=python /usr/bin/python3
benchmarks/green-function/run.py STAGE ...):

  first-event     BP1-QD to the end of its first event (Stop after events
                  = 1) at Local refinements LEVELS (3: 200 m, 4: 100 m, 5:
                  50 m, 6: 25 m, the .prm's) with the Green's-function
                  method (Runge-Kutta, the .prm's) and/or the volume path
                  (implicit step), one rank each at nice 19: wall time, the
                  first event's start and peak slip rate (25 m: a minute
                  green, hours volume)
  storage         BP1-QD at 25 m to 222 years with the H-matrix and with the
                  dense operator, one rank: wall times, the stored fraction
                  and the product's error (from the log; 2 minutes)
  ranks           BP1-QD at 25 m to 225 years on 1 and 2 ranks, 3 runs
                  each: median wall times, the first events' difference
                  (4 minutes)
  work-precision  BP1-QD at 50 m (800 fault nodes) from 0 to --end years
                  (520: five events), one run at a time pinned to one core
                  (taskset --cpu-list CPU), against a reference of the same
                  semi-discrete problem (dense, Runge-Kutta 1e-9): the
                  Runge-Kutta at --rk, the H-matrix at --compression (at
                  Runge-Kutta --rk-for-compression), the implicit step on
                  the fault at --implicit, the volume path with --volume.
                  Appends to WORK/work-precision/runs.csv (a label already
                  there is not run again): CPU and wall time, first event,
                  last interval (20 minutes; --volume adds 40)
  table           the README's work-precision table and figures/
                  work-precision.png from runs.csv (default: the committed
                  work-precision.csv)
  okada           the 3D operator against Okada's half-space solution:
                  okada/run.sh OUT (OKADA_SRC locates the peer, okada/
                  README.md)
"""
import csv
import os
import re
import resource
import shutil
import statistics
import subprocess
import time

from rsfcycle import bench, catalog, prm

NAME = "green-function"
HERE = bench.folder(NAME)
BP1 = os.path.join(bench.ROOT, "prm", "seas-bp1-qd.prm")
MESH = os.path.join(bench.ROOT, "prm", "meshes", "seas-bp1.msh")
YEAR = catalog.YEAR
GREEN = {"Time stepping/Integrator": "runge-kutta",
         "Solver/Bulk": "green-function"}
VOLUME = {"Time stepping/Integrator": "implicit", "Solver/Bulk": "volume"}


def bp1(path, out, levels, entries):
    """A BP1-QD variant at Local refinements `levels`, no VTU."""
    settings = {"Mesh file/File": MESH, "Mesh/Local refinements": levels,
                "Output/Writers": "time series, base profile, events"}
    settings.update(entries)
    return prm.variant(path, BP1, out, settings)


def first_event(levels: int, method: "?" = "both", build="", work=""):
    """BP1-QD to the end of its first event, one rank each at nice 19.

    levels: Mesh/Local refinements (3: 200 m ... 6: 25 m, the .prm's)
    method: green, volume or both (default)
    """
    exe = bench.executable(build)
    work = bench.work(work)
    for kind, entries in (("green", GREEN), ("volume", VOLUME)):
        if method not in (kind, "both"):
            continue
        out = os.path.join(work, f"{kind}-{levels}")
        path = bp1(out + ".prm", out, levels,
                   dict(entries, **{"Stop after events": 1}))
        wall, _ = bench.run([exe, path], out + ".log", nice=19)
        with open(os.path.join(out, "events.csv")) as f:
            e = next(csv.DictReader(f))
        line = (f"{kind:6s} refinements {levels}: wall {wall:8.1f} s, "
                f"first event {float(e['start_s']) / YEAR:.4f} yr, peak slip "
                f"rate {float(e['peak_slip_rate_m_per_s']):.4f} m/s, "
                f"nucleation {float(e['nucleation_position_m']) / 1e3:.2f} km")
        print(line, flush=True)
        with open(os.path.join(work, "first-events.txt"), "a") as f:
            f.write(line + "\n")


def storage(build="", work=""):
    """BP1-QD at 25 m to 222 years: H-matrix against dense, one rank."""
    exe = bench.executable(build)
    work = bench.work(work)
    walls = {}
    for kind in ("h-matrix", "dense"):
        out = os.path.join(work, f"storage-{kind}")
        path = bp1(out + ".prm", out, 6, dict(GREEN, **{
            "End time": f"{222 * YEAR:.6e}",
            "Solver/Green operator storage": kind}))
        walls[kind] = bench.rsfcycle(exe, [path], out + ".log")
        operator = re.search(r"Bulk: green-function, operator .*",
                             bench.text(out + ".log"))
        print(f"{kind}: {walls[kind]:.1f} s; "
              f"{operator.group(0) if operator else ''}", flush=True)
    print(f"H-matrix against dense: {walls['h-matrix'] / walls['dense']:.2f}"
          "×")


def ranks(build="", work=""):
    """BP1-QD at 25 m to 225 years on 1 and 2 ranks, 3 runs each."""
    exe = bench.executable(build)
    work = bench.work(work)
    medians, starts = {}, {}
    for n in (1, 2):
        walls = []
        for k in range(3):
            out = os.path.join(work, f"ranks-{n}")
            path = bp1(out + ".prm", out, 6, dict(GREEN, **{
                "End time": f"{225 * YEAR:.6e}"}))
            walls.append(bench.run(bench.mpirun(n, [exe, path]),
                                   out + ".log",
                                   env=bench.mpi_environment())[0])
        medians[n] = statistics.median(walls)
        with open(os.path.join(out, "events.csv")) as f:
            starts[n] = float(next(csv.DictReader(f))["start_s"])
        print(f"{n} rank(s): median wall {medians[n]:.1f} s", flush=True)
    print(f"2 ranks against 1: {medians[2] / medians[1]:.2f}×; first events "
          f"differ by {abs(starts[2] / starts[1] - 1):.1e} (relative)")


def green_implicit(tol):
    """The implicit step on the fault at a tolerance."""
    return {"Solver/Bulk": "green-function",
            "Solver/Green operator storage": "dense",
            "Solver/Fixed-point tolerance": f"{tol:g}",
            "Time stepping/Integrator": "implicit",
            "Time stepping/Tolerance": f"{tol:g}"}


def green(tol, storage_kind="dense", compression=None):
    """The Runge-Kutta at a tolerance, dense or compressed."""
    entries = dict(GREEN, **{"Solver/Green operator storage": storage_kind,
                             "Time stepping/Tolerance": f"{tol:g}"})
    if compression is not None:
        entries["Solver/Green compression tolerance"] = f"{compression:g}"
    return entries


def timed(exe, path, log, cpu):
    """Run pinned to a core (where taskset exists); (wall, CPU) [s]."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    command = [exe, path]
    if shutil.which("taskset"):
        command = ["taskset", "--cpu-list", str(cpu)] + command
    start = time.monotonic()
    with open(log, "w") as f:
        subprocess.run(command, stdout=f, stderr=subprocess.STDOUT,
                       check=True)
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + \
        (after.ru_stime - before.ru_stime)


def full_ruptures(folder):
    """The event starts [s] of full ruptures (width > 5 km: BP1's events;
    small aftershocks at the patch's bottom left out)."""
    with open(os.path.join(folder, "events.csv")) as f:
        return [float(r["start_s"]) for r in csv.DictReader(f)
                if float(r["rupture_width_m"]) > 5e3]


FIELDS = ["label", "family", "wall_s", "cpu_s", "first_event_s",
          "last_interval_s", "n_events"]


def work_precision(end=520.0, rk="1e-4,1e-5,1e-6,1e-7",
                   compression="1e-2,1e-3,1e-4,1e-6,1e-8",
                   rk_for_compression=1e-7, reference=1e-9, implicit="",
                   volume=False, only="", cpu=0, build="", work=""):
    """BP1-QD at 50 m, 0 to END years, one run at a time on one core.

    Appends to WORK/work-precision/runs.csv (a label already there is not
    run again), then the table and the figure.

    end: years
    rk: Runge-Kutta tolerances (dense operator)
    compression: H-matrix compression tolerances
    rk_for_compression: the Runge-Kutta tolerance of the H-matrix runs
    reference: the reference's Runge-Kutta tolerance (dense)
    implicit: tolerances of the implicit step on the fault, e.g. 1e-3,1e-4
    volume: also the volume path at its shipped settings
    only: only these labels, A,B
    cpu: the core to pin to (taskset)
    """
    exe = bench.executable(build)
    work = bench.work(os.path.join(work, "work-precision"))
    runs = [("reference", "reference", green(reference))]
    runs += [(f"rk-{t}", "Runge-Kutta tolerance", green(float(t)))
             for t in rk.split(",") if t]
    runs += [(f"hmatrix-{c}", "H-matrix tolerance",
              green(rk_for_compression, "h-matrix", float(c)))
             for c in compression.split(",") if c]
    runs += [(f"implicit-{t}", "implicit step on the fault",
              green_implicit(float(t))) for t in implicit.split(",") if t]
    if volume:
        runs.append(("volume", "volume (shipped)", VOLUME))
    only = set(only.split(",")) - {""}
    path = os.path.join(work, "runs.csv")
    done = {r["label"]: r for r in bench.read_table(path)} \
        if os.path.exists(path) else {}
    for label, family, entries in runs:
        if label in done or (only and label not in only):
            continue
        out = os.path.join(work, label)
        prm_file = bp1(out + ".prm", out, 5, dict(entries, **{
            "End time": f"{end * YEAR:.6e}"}))
        wall, seconds = timed(exe, prm_file, out + ".log", cpu)
        e = full_ruptures(out)
        done[label] = {"label": label, "family": family,
                       "wall_s": f"{wall:.2f}", "cpu_s": f"{seconds:.2f}",
                       "first_event_s": f"{e[0]:.6f}",
                       "last_interval_s": f"{e[-1] - e[-2]:.6f}"
                       if len(e) > 1 else "nan", "n_events": len(e)}
        bench.write_table(path, FIELDS, done.values())
        print(label, done[label], flush=True)
    table(path)


LABELS = {"rk": "Runge–Kutta", "hmatrix": "H-matrix",
          "implicit": "implicit on the fault"}
NOTES = {"rk-1e-5": " (the `.prm`'s)", "hmatrix-1e-6": " (the default)"}


def short(x):
    """8.7e-05 -> 8.7e-5."""
    return re.sub(r"e([+-])0*(\d)", lambda m: "e" + m.group(1).replace(
        "+", "") + m.group(2), f"{x:.1e}")


def table(runs=os.path.join(HERE, "work-precision.csv")):
    """The README's work-precision table and figures/work-precision.png.

    runs: a runs.csv of the stage work-precision
    """
    rows = bench.read_table(runs)
    ref = next(r for r in rows if r["label"] == "reference")
    t0, r0 = float(ref["first_event_s"]), float(ref["last_interval_s"])
    print(f"reference (Runge-Kutta, dense): first event {t0 / YEAR:.6f} yr, "
          f"last interval {r0 / YEAR:.6f} yr, {ref['n_events']} events, CPU "
          f"{float(ref['cpu_s']):.1f} s")
    points, lines = [], []
    order = ["rk", "hmatrix", "implicit", "volume"]
    for r in sorted(rows, key=lambda r: order.index(r["label"].split("-")[0])
                    if r["label"] != "reference" else -1):
        if r["label"] == "reference":
            continue
        e1 = abs(float(r["first_event_s"]) - t0) / t0
        e2 = abs(float(r["last_interval_s"]) - r0) / r0
        points.append((r["label"], r["family"], float(r["cpu_s"]), e1, e2))
        kind, _, tol = r["label"].partition("-")
        name = (f"{LABELS[kind]} {tol}{NOTES.get(r['label'], '')}"
                if kind in LABELS else "volume method, shipped (trapezoidal, "
                "δ = ε = 1e-5, TNNMG 1e-8)")
        lines.append([name, f"{float(r['cpu_s']):.1f}", short(e1),
                      short(e2)])
    print(bench.markdown(["run", "CPU [s]", "first event error",
                          "recurrence error"], lines), end="")
    from rsfcycle.plot import _pyplot, savefig
    plt = _pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    styles = {"Runge-Kutta tolerance": "o-", "H-matrix tolerance": "s-",
              "implicit step on the fault": "^-", "volume (shipped)": "*"}
    for ax, k, name in ((axes[0], 3, "first event"),
                        (axes[1], 4, "recurrence")):
        for family, style in styles.items():
            chosen = [(p[2], max(p[k], 1e-12), p[0]) for p in points
                      if p[1] == family]
            if not chosen:
                continue
            ax.loglog([q[0] for q in chosen], [q[1] for q in chosen], style,
                      label=family,
                      markersize=9 if family.startswith("volume") else 5)
            for q in chosen:
                ax.annotate(q[2].split("-", 1)[-1], (q[0], q[1]), fontsize=7,
                            xytext=(3, 3), textcoords="offset points")
        ax.set_xlabel("CPU time of the run [s]")
        ax.set_ylabel(f"relative error of the {name}")
        ax.set_title(f"BP1-QD 50 m, 520 years: {name}")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    os.makedirs(os.path.join(HERE, "figures"), exist_ok=True)
    savefig(fig, os.path.join(HERE, "figures", "work-precision.png"),
            dpi=120)


def okada(out, *refinements):
    """The 3D operator against Okada's half-space solution (okada/run.sh).

    out: a new folder for the results
    refinements: Local refinements of the BP5 mesh (default 1 2)
    """
    bench.environment("OKADA_SRC", "a clone of "
                      "https://github.com/tbenthompson/okada_wrapper "
                      "(okada/README.md)")
    return subprocess.run(["bash", os.path.join(HERE, "okada", "run.sh"),
                           out] + list(refinements)).returncode


if __name__ == "__main__":
    raise SystemExit(bench.cli(__doc__, NAME, [
        first_event, storage, ranks, work_precision, table, okada]))
