#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Work against precision for the 2D wedge (the paper's figure 7, extended).
Plots: wedge-fig7.png (or $WEDGE_PLOT), wedge-mesh.png.

Usage: wedge.py RUNDIR [RUNDIR ...]   (run folders of rsfcycle that differ
only in the fixed-point tolerance; the one with the smallest tolerance is the
reference). For each run: the fixed-point tolerance, wall time of the time
loop (log.txt), accepted steps, spatial problems, the work of all spatial
problems (sum of all_linear_iterations = TNNMG iterations with the direct
correction), and the relative error of the recurrence time, peak slip rate
and slip of every event (matched by index; the maximum over events) against
the reference. Prints a Markdown table and writes wedge-fig7.png.

       wedge.py --mesh RUNDIR [RUNDIR ...]   (runs that differ in the mesh;
the finest is the reference): unknowns, wall time, steps, work, events, and
the last event's recurrence time, peak slip rate, rupture width and slip
with their relative differences to the finest mesh (the number of events by
a given time differs between meshes, so events are not matched by index).
"""
import csv
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def prm_value(rundir, name):
    with open(os.path.join(rundir, "parameters.prm")) as f:
        for line in f:
            m = re.match(r"\s*set\s+" + re.escape(name) + r"\s*=\s*(\S+)", line)
            if m:
                return float(m.group(1))
    return float("nan")


def wall_time(rundir):
    with open(os.path.join(rundir, "log.txt")) as f:
        for line in f:
            m = re.search(r"\| Time stepping\s+\|\s+\d+\s+\|\s+([0-9.e+]+)s", line)
            if m:
                return float(m.group(1))
    return float("nan")


def read(rundir):
    with open(os.path.join(rundir, "time-series.csv")) as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(rundir, "events.csv")) as f:
        events = list(csv.DictReader(f))
    return {
        "dir": rundir,
        "eps": prm_value(rundir, "Fixed-point tolerance"),
        "delta": prm_value(rundir, "Tolerance"),
        "wall": wall_time(rundir),
        "steps": len(rows),
        "problems": sum(int(r["spatial_problems"]) for r in rows),
        "work": sum(int(r.get("all_linear_iterations") or r["linear_iterations"])
                    for r in rows),
        "events": events,
    }


def max_rel_error(run, ref, key):
    errors = []
    for a, b in zip(run["events"], ref["events"]):
        if a[key] and b[key]:
            errors.append(abs(float(a[key]) - float(b[key])) / abs(float(b[key])))
    return max(errors) if errors else float("nan")


def unknowns(rundir):
    with open(os.path.join(rundir, "log.txt")) as f:
        for line in f:
            m = re.search(r"Mesh: .* (\d+) unknowns", line)
            if m:
                return int(m.group(1))
    return 0


def mesh_series(dirs):
    runs = []
    for d in dirs:
        r = read(d)
        r["unknowns"] = unknowns(d)
        runs.append(r)
    runs.sort(key=lambda r: r["unknowns"])
    ref = runs[-1]["events"][-1]
    keys = ("recurrence_s", "peak_slip_rate_m_per_s", "rupture_width_m",
            "slip_um")
    print("| unknowns | wall [s] | steps | work (TNNMG its) | events | last "
          "event: recurrence [s] | peak slip rate [m/s] | width [m] | "
          "slip [um] | max rel. difference to the finest |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in runs:
        e = r["events"][-1]
        diff = max(abs(float(e[k]) - float(ref[k])) / abs(float(ref[k]))
                   for k in keys)
        print(f"| {r['unknowns']} | {r['wall']:.1f} | {r['steps']} | "
              f"{r['work']} | {len(r['events'])} | "
              + " | ".join(f"{float(e[k]):.4g}" for k in keys)
              + f" | {diff:.1e} |")
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    n = [r["unknowns"] for r in runs]
    ax[0].loglog(n, [r["work"] for r in runs], "o-", label="TNNMG iterations")
    ax[0].loglog(n, [r["wall"] for r in runs], "s-", label="wall time [s]")
    ax[0].set_xlabel("unknowns")
    ax[0].set_title("work over 0 - 600 s")
    ax[0].legend()
    for k, label in zip(keys, ("recurrence", "peak slip rate", "width",
                               "slip")):
        ax[1].semilogx(n, [float(r["events"][-1][k]) / float(ref[k])
                           for r in runs], "o-", label=label)
    ax[1].set_xlabel("unknowns")
    ax[1].set_ylabel("last event, relative to the finest mesh")
    ax[1].legend()
    fig.tight_layout()
    fig.savefig("wedge-mesh.png", dpi=120)
    print("wrote wedge-mesh.png")


def main(dirs):
    runs = sorted((read(d) for d in dirs), key=lambda r: -r["eps"])
    ref = min(runs, key=lambda r: r["eps"])
    print("| ε | δ | wall [s] | steps | spatial problems | work (TNNMG its) "
          "| events | max rel. error recurrence | peak slip rate | slip |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in runs:
        cells = [f"{r['eps']:g}", f"{r['delta']:g}", f"{r['wall']:.1f}",
                 str(r["steps"]),
                 str(r["problems"]), str(r["work"]), str(len(r["events"]))]
        if r is ref:
            cells += ["reference"] * 3
        else:
            cells += [f"{max_rel_error(r, ref, k):.1e}" for k in
                      ("recurrence_s", "peak_slip_rate_m_per_s", "slip_um")]
        print("| " + " | ".join(cells) + " |")
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    eps = [r["eps"] for r in runs]
    ax[0].semilogx(eps, [r["work"] for r in runs], "o-")
    ax[0].set_xlabel("fixed-point tolerance ε")
    ax[0].set_ylabel("total TNNMG iterations (all spatial problems)")
    ax[0].set_title("the paper's figure 7")
    others = [r for r in runs if r is not ref]
    for key, label in (("recurrence_s", "recurrence"),
                       ("peak_slip_rate_m_per_s", "peak slip rate"),
                       ("slip_um", "slip")):
        ax[1].loglog([r["wall"] for r in others],
                     [max(max_rel_error(r, ref, key), 1e-16) for r in others],
                     "o-", label=label)
    ax[1].set_xlabel("wall time of the time loop [s]")
    ax[1].set_ylabel(f"max relative error vs ε = {ref['eps']:g}")
    ax[1].legend()
    fig.tight_layout()
    name = os.environ.get("WEDGE_PLOT", "wedge-fig7.png")
    fig.savefig(name, dpi=120)
    print(f"wrote {name}")


if __name__ == "__main__":
    if sys.argv[1:2] in (["-h"], ["--help"]):
        print(__doc__)
        sys.exit(0)
    if not sys.argv[1:] or sys.argv[1:] == ["--mesh"]:
        sys.exit("wedge.py: give the run folders: "
                 "wedge.py [--mesh] RUNDIR [RUNDIR ...]")
    if sys.argv[1:2] == ["--mesh"]:
        mesh_series(sys.argv[2:])
    else:
        main(sys.argv[1:])
