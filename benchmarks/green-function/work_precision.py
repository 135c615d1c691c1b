#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Work-precision of the Green's-function method on SEAS BP1-QD.

Runs prm/seas-bp1-qd.prm at 50 m cells (Mesh/Local refinements = 5, 800
fault nodes) from t = 0 to END years (default 520: five events) with

  - the Green's-function method (Runge-Kutta, dense operator) at the
    relative tolerances --rk (default 1e-4 ... 1e-7);
  - the H-matrix at the compression tolerances --compression (default
    1e-2 ... 1e-8), each at the Runge-Kutta tolerance --rk-for-compression
    (default 1e-7, so that the time integration does not hide the
    compression's error);
  - the Green's-function method with the implicit step on the fault
    (Integrator = implicit: the trapezoidal step, step-doubling and
    fixed-point tolerance both equal to each of --implicit, TNNMG
    tolerance 1e-8, dense operator), if --implicit is given;
  - the volume method at the .prm's shipped volume settings (implicit
    trapezoidal step, delta = epsilon = 1e-5, TNNMG 1e-8, multigrid), if
    --volume is given;

and a reference: the Green's-function method, dense, tolerance --reference
(default 1e-9). All solve the same semi-discrete problem (the same mesh,
stiffness, weights, damping and law), so the differences from the
reference are the time integration's and the compression's errors.

Per run: the first event's start and the last interval between event
starts (the recurrence), their relative errors against the reference, the
process's wall and CPU time (rusage of the child). One run at a time, on
one core (taskset --cpu-list CPU, default 0); the other core's load is
the caller's to keep quiet (say so when quoting the figures).

Usage (from the repository root):
  /usr/bin/python3 benchmarks/green-function/work_precision.py build/rsfcycle \
      [--out DIR] [--end 520] [--volume] [--implicit 1e-3,1e-4,...]
      [--only LABEL,...] [--cpu N]
Writes DIR/runs.csv (appending, one row per run label; an existing label
is not run again), DIR/work-precision.png and prints the table; DIR
defaults to benchmarks/green-function/runs/work-precision (not tracked).
The committed table of these runs is benchmarks/green-function/
work-precision.csv.
"""
import argparse
import csv
import os
import resource
import subprocess
import time

YEAR = 365.25 * 24 * 3600


def prm_text(root, out, end_years, lines):
    return "\n".join(
        [f"include {root}/prm/seas-bp1-qd.prm",
         f"set Output directory = {out}",
         "set Overwrite output = true",
         f"set End time = {end_years * YEAR:.6e}",
         "subsection Mesh", "  set Local refinements = 5", "end"] + lines) + "\n"


def green(tol, storage="dense", compression=None):
    lines = ["subsection Solver", "  set Bulk = green-function",
             f"  set Green operator storage = {storage}"]
    if compression is not None:
        lines.append(f"  set Green compression tolerance = {compression:g}")
    lines += ["end", "subsection Time stepping",
              "  set Integrator = runge-kutta", f"  set Tolerance = {tol:g}",
              "end"]
    return lines


def green_implicit(tol):
    return ["subsection Solver", "  set Bulk = green-function",
            "  set Green operator storage = dense",
            f"  set Fixed-point tolerance = {tol:g}", "end",
            "subsection Time stepping", "  set Integrator = implicit",
            f"  set Tolerance = {tol:g}", "end"]


VOLUME = ["subsection Solver", "  set Bulk = volume", "end",
          "subsection Time stepping", "  set Integrator = implicit", "end"]


def run(exe, prm, log, cpu):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    cmd = [exe, prm]
    if subprocess.run(["which", "taskset"], capture_output=True).returncode == 0:
        cmd = ["taskset", "--cpu-list", str(cpu)] + cmd
    with open(log, "w") as f:
        subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT, check=True)
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def events(folder):
    rows = list(csv.DictReader(open(os.path.join(folder, "events.csv"))))
    # the SEAS threshold's events (1 mm/s) with a full rupture: BP1's
    # events are all full ruptures; small aftershocks near the patch's
    # bottom (rupture width 200 m) are left out
    return [float(r["start_s"]) for r in rows if float(r["rupture_width_m"]) > 5e3]


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("exe")
    p.add_argument("--out", default="benchmarks/green-function/runs/work-precision")
    p.add_argument("--end", type=float, default=520.)
    p.add_argument("--rk", default="1e-4,1e-5,1e-6,1e-7")
    p.add_argument("--compression", default="1e-2,1e-3,1e-4,1e-6,1e-8")
    p.add_argument("--rk-for-compression", type=float, default=1e-7)
    p.add_argument("--reference", type=float, default=1e-9)
    p.add_argument("--volume", action="store_true")
    p.add_argument("--implicit", default="",
                   help="tolerances of the implicit step on the fault, e.g. 1e-3,1e-4")
    p.add_argument("--only", default="")
    p.add_argument("--cpu", type=int, default=0, help="the core to pin to")
    a = p.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    exe = os.path.abspath(a.exe)
    os.makedirs(os.path.join(a.out, "runs"), exist_ok=True)

    runs = [("reference", "reference", green(a.reference))]
    runs += [(f"rk-{t}", "Runge-Kutta tolerance", green(float(t)))
             for t in a.rk.split(",")]
    runs += [(f"hmatrix-{c}", "H-matrix tolerance",
              green(a.rk_for_compression, "h-matrix", float(c)))
             for c in a.compression.split(",") if c]
    runs += [(f"implicit-{t}", "implicit step on the fault",
              green_implicit(float(t)))
             for t in a.implicit.split(",") if t]
    if a.volume:
        runs.append(("volume", "volume (shipped)", VOLUME))
    only = set(a.only.split(",")) - {""}

    runs_file = os.path.join(a.out, "runs.csv")
    done = {}
    if os.path.exists(runs_file):
        done = {r["label"]: r for r in csv.DictReader(open(runs_file))}
    fields = ["label", "family", "wall_s", "cpu_s", "first_event_s",
              "last_interval_s", "n_events"]
    for label, family, lines in runs:
        if label in done or (only and label not in only):
            continue
        folder = os.path.abspath(os.path.join(a.out, "runs", label))
        prm = folder + ".prm"
        open(prm, "w").write(prm_text(root, folder, a.end, lines))
        wall, cpu = run(exe, prm, folder + ".log", a.cpu)
        e = events(folder)
        row = {"label": label, "family": family, "wall_s": f"{wall:.2f}",
               "cpu_s": f"{cpu:.2f}", "first_event_s": f"{e[0]:.6f}",
               "last_interval_s": f"{e[-1] - e[-2]:.6f}" if len(e) > 1 else "nan",
               "n_events": len(e)}
        new = not os.path.exists(runs_file)
        with open(runs_file, "a") as f:
            w = csv.DictWriter(f, fields)
            if new:
                w.writeheader()
            w.writerow(row)
        done[label] = row
        print(label, row, flush=True)

    ref = done["reference"]
    t0, r0 = float(ref["first_event_s"]), float(ref["last_interval_s"])
    print(f"reference (Runge-Kutta {a.reference:g}, dense): first event "
          f"{t0 / YEAR:.6f} yr, last interval {r0 / YEAR:.6f} yr, "
          f"{ref['n_events']} events, CPU {float(ref['cpu_s']):.1f} s")
    print("| run | CPU [s] | wall [s] | events | first event error | recurrence error |")
    print("|---|---|---|---|---|---|")
    table = []
    for label, family, _ in runs:
        if label == "reference" or label not in done:
            continue
        r = done[label]
        e1 = abs(float(r["first_event_s"]) - t0) / t0
        e2 = abs(float(r["last_interval_s"]) - r0) / r0
        table.append((label, family, float(r["cpu_s"]), e1, e2))
        print(f"| {label} | {float(r['cpu_s']):.1f} | {float(r['wall_s']):.1f} | "
              f"{r['n_events']} | {e1:.2e} | {e2:.2e} |")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(10, 4), sharey=False)
    markers = {"Runge-Kutta tolerance": "o-", "H-matrix tolerance": "s-",
               "implicit step on the fault": "^-",
               "volume (shipped)": "*"}
    for ax, k, name in ((axes[0], 3, "first event"), (axes[1], 4, "recurrence")):
        for family, style in markers.items():
            pts = [(t[2], max(t[k], 1e-12), t[0]) for t in table if t[1] == family]
            if not pts:
                continue
            ax.loglog([q[0] for q in pts], [q[1] for q in pts], style,
                      label=family, markersize=9 if family.startswith("volume") else 5)
            for q in pts:
                ax.annotate(q[2].split("-", 1)[-1], (q[0], q[1]), fontsize=7,
                            xytext=(3, 3), textcoords="offset points")
        ax.set_xlabel("CPU time of the run [s]")
        ax.set_ylabel(f"relative error of the {name}")
        ax.set_title(f"BP1-QD 50 m, {a.end:g} years: {name}")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "work-precision.png"), dpi=120)


if __name__ == "__main__":
    main()
