#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Work-precision of the spring-slider: error against wall time.

Runs the stick-slip spring-slider of prm/spring-slider.prm (quasi-dynamic,
k = k_crit / 2, ageing law) over 1000 s (4 events) with
  - our scheme (Newmark, fixed-point coupling, step doubling) at
    delta = epsilon = 1e-2 ... 1e-8, and
  - SUNDIALS ARKODE (implicit ARK, adaptive) at relative tolerances
    1e-3 ... 1e-10,
and compares each with the reference, ARKODE at 1e-12: the error of the
slip at t = 1000 s and of the mean recurrence time (events 2-4). The wall
time is that of the time loop as the run reports it (without program
start-up and parameter parsing). Writes runs.csv, its table runs.md and
figures/work-precision.png.

    /usr/bin/python3 benchmarks/work-precision/run.py [path/to/rsfcycle]
"""
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
if "-h" in sys.argv or "--help" in sys.argv:
    print(__doc__)
    sys.exit(0)
EXE = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build",
                                                          "rsfcycle")
WORK = os.path.join(HERE, "runs")
END_TIME = 1000
REPEAT = 3  # wall time: the minimum of this many runs


def run(name, integrator, tol, spacing=0.01):
    d = os.path.join(WORK, name)
    prm = os.path.join(WORK, name + ".prm")
    with open(prm, "w") as f:
        f.write(f"""include {ROOT}/prm/spring-slider.prm
set End time = {END_TIME}
set Output directory = {d}
set Overwrite output = true
subsection Time stepping
  set Integrator = {"arkode" if integrator == "arkode" else "implicit"}
  set Controller   = step-doubling
  set Tolerance    = {tol:g}
  set Minimum step = 1e-14
end
subsection Solver
  set Fixed-point tolerance = {tol:g}
end
subsection Output
  set Progress interval = 1e9
end
subsection Spring slider
  set Reference sample spacing = {spacing:g}
end
""")
    walls = []
    for _ in range(REPEAT):
        out = subprocess.run([EXE, prm], capture_output=True, text=True,
                             check=True).stdout
        walls.append(float(re.search(r"Wall time of the time loop: (\S+) s",
                                     out).group(1)))
    final = re.search(r"Final: slip = (\S+) m.*mean recurrence time = (\S+) s",
                      out)
    summary = re.search(r"Summary: (\d+) (steps|ARKODE steps)", out)
    events = len(re.findall(r"event \d+ starts", out))
    return dict(name=name, integrator=integrator, tol=tol,
                slip=float(final.group(1)), period=float(final.group(2)),
                steps=int(summary.group(1)), events=events, wall=min(walls))


def main():
    os.makedirs(WORK, exist_ok=True)
    ref = run("reference", "arkode", 1e-12)  # dense: period and slip
    rows = []
    for e in range(2, 9):
        rows.append(run(f"ours-{e}", "step-doubling", 10.0**-e))
    for e in range(3, 11):
        # slip error and wall time: sampled once per second only, so that
        # ARKODE takes its own steps; period error: densely sampled (every
        # 0.01 L/V) to resolve the event starts, which costs extra steps
        r = run(f"arkode-{e}", "arkode", 10.0**-e, spacing=0)
        dense = run(f"arkode-dense-{e}", "arkode", 10.0**-e)
        r["period"] = dense["period"]
        r["dense_wall"] = dense["wall"]
        r["dense_steps"] = dense["steps"]
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

    lines = [
        f"Reference (ARKODE, rtol 1e-12): slip at {END_TIME} s = "
        f"{ref['slip'] * 1e6:.6f} um, recurrence time = "
        f"{ref['period']:.6f} s, {ref['steps']} steps, "
        f"{ref['wall']:.3g} s.", "",
        "| integrator | tolerance | steps | events | wall time [s] | "
        "slip error [um] | slip error / L | period error [s] | "
        "period error / T | dense-sampled: steps, wall time [s] |",
        "|---|---|---|---|---|---|---|---|---|---|"]
    L = 1e-5
    for r in rows:
        lines.append(
            f"| {r['integrator']} | {r['tol']:g} | {r['steps']} | "
            f"{r['events']} | {r['wall']:.3g} | {r['slip_error'] * 1e6:.2e} | "
            f"{r['slip_error'] / L:.1e} | {r['period_error']:.2e} | "
            f"{r['period_error'] / ref['period']:.1e} | " +
            (f"{r['dense_steps']}, {r['dense_wall']:.3g} |"
             if "dense_wall" in r else "- |"))
    table = "\n".join(lines)
    with open(os.path.join(HERE, "runs.md"), "w") as f:
        f.write("<!-- SPDX-License-Identifier: LGPL-2.1-or-later -->\n" +
                table + "\n")
    print(table)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, key, label in [(axes[0], "slip_error", "error of slip at 1000 s [m]"),
                           (axes[1], "period_error",
                            "error of recurrence time [s]")]:
        for integ, style in [("step-doubling", "o-"), ("arkode", "s--")]:
            rs = [r for r in rows if r["integrator"] == integ]
            # ARKODE's period error comes from its densely sampled run
            walls = [r.get("dense_wall", r["wall"]) if key == "period_error"
                     else r["wall"] for r in rs]
            ax.loglog(walls, [max(r[key], 1e-16) for r in rs], style,
                      label="ours (delta = epsilon)" if integ ==
                      "step-doubling" else "ARKODE (rtol)")
            for w, r in zip(walls, rs):
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
    fig.savefig(os.path.join(HERE, "figures", "work-precision.png"), dpi=120)


if __name__ == "__main__":
    main()
