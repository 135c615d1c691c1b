#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Stiff and extreme cases of the spring-slider.

Every case is prm/spring-slider.prm (quasi-dynamic stick-slip block:
a = 0.01, b = 0.015, mu* = 0.6, V* = 1e-6 m/s, L = 1e-5 m,
|sigma_n| = 1e6 Pa, k = k_crit / 2 = 2.5e8 Pa/m, eta = 5e6 Pa s/m,
v0 = 1e-6 m/s, ageing law, delta = epsilon = 1e-5) with one parameter (or
one coherent group of parameters) pushed to an extreme, run quasi-dynamic
(Mass = 0) and, where inertia can matter, dynamic (Mass = 1e6 kg/m^2),
one case at a time under a wall-clock timeout (60 s; 10 s for the
Runge-Kutta, where a crawling run writes millions of rows). Per case: the
outcome (finished / stopped, with the one-line diagnosis / timeout /
crashed), the accepted steps, the smallest and largest step, the wall time
of the process and of the time loop, and whether any field of
time-series.csv, events.csv or the "Final:" line is non-finite.

Stages (from the repository's root, PYTHONPATH=python /usr/bin/python3
benchmarks/stiff/run.py STAGE ...):

  list   the cases
  runs   every case (or the cases named) into WORK; without names it
         writes runs.csv and its table runs.md (with --integrator
         runge-kutta: runs-runge-kutta.*); about 15 s of CPU with the
         implicit step, a few minutes with the Runge-Kutta
"""
import csv
import math
import os
import re

from rsfcycle import bench, prm

NAME = "stiff"
HERE = bench.folder(NAME)
DYN_MASS = 1e6  # [kg/m^2] for the dynamic variants

BASE = {
    "Mass": 0, "Stiffness": 2.5e8, "Normal stress": 1e6, "Cohesion": 0,
    "Radiation damping": 5e6, "Load point velocity": 1e-6,
    "Velocity step time": 1e300, "Velocity step factor": 1,
    "a": 0.01, "b": 0.015, "mu star": 0.6, "V star": 1e-6, "L": 1e-5,
    "Initial slip rate": 2e-6, "Initial state": 0,
}


def kcrit(p):
    return (p["b"] - p["a"]) * p["Normal stress"] / p["L"]


CASES = []  # (name, what, end time, maximum step, spring-slider entries)


def case(name, what, end, dynamic=False, k_over_kc=None, max_step=None,
         **kw):
    p = dict(BASE)
    p.update({k.replace("_", " "): v for k, v in kw.items()})
    if k_over_kc is not None:
        p["Stiffness"] = k_over_kc * kcrit(p)
    if max_step is None:  # the characteristic time L / v0
        max_step = p["L"] / p["Load point velocity"]
    CASES.append((name, what, end, max_step, p))
    if dynamic:
        q = dict(p)
        q["Mass"] = DYN_MASS
        CASES.append((name + "-dyn", what + ", dynamic", end, max_step, q))


def matrix():
    case("base", "prm/spring-slider.prm, k = kc/2", 500, dynamic=True)
    # a down to 1e-4, mu*/a = 1000 (b - a = 0.015 kept)
    case("a1e-4-mu0.1", "a = 1e-4, b = 0.0151, mu* = 0.1 (mu*/a = 1000), "
         "k = kc/2", 500, dynamic=True, k_over_kc=0.5,
         a=1e-4, b=0.0151, mu_star=0.1)
    case("a8e-4-mu0.8", "a = 8e-4, b = 0.0158, mu* = 0.8 (mu*/a = 1000), "
         "k = kc/2", 500, dynamic=True, k_over_kc=0.5,
         a=8e-4, b=0.0158, mu_star=0.8)
    # L from 1e-8 to 1e-2 m (k = kc/2 follows L)
    case("L1e-8", "L = 1e-8 m, k = kc/2 = 2.5e11", 0.5, dynamic=True,
         k_over_kc=0.5, L=1e-8)
    case("L1e-2", "L = 1e-2 m, k = kc/2 = 2.5e5", 5e5, dynamic=True,
         k_over_kc=0.5, L=1e-2)
    # b - a from -0.02 to +0.05
    case("b-a=-0.02", "a = 0.035, b = 0.015 (strengthening), k = 2.5e8",
         500, a=0.035, b=0.015)
    case("b-a=0", "a = b = 0.015 (neutral, kc = 0), k = 2.5e8", 500,
         a=0.015, b=0.015)
    case("b-a=+0.05", "a = 0.01, b = 0.06, k = kc/2 = 2.5e9", 500,
         dynamic=True, k_over_kc=0.5, b=0.06)
    # cohesion 0 and 1e3 Pa at |sigma_n| = 1e4 Pa (mu sigma_n ~ 6e3 Pa)
    case("coh0-sn1e4", "C = 0, sigma_n = 1e4, k = kc/2 = 2.5e6", 500,
         k_over_kc=0.5, Normal_stress=1e4)
    case("coh1e3-sn1e4", "C = 1e3 Pa, sigma_n = 1e4, k = kc/2 = 2.5e6", 500,
         dynamic=True, k_over_kc=0.5, Normal_stress=1e4, Cohesion=1e3)
    # cohesion above the driving stress: V(0) = 0, so the prestress is 0 and
    # the spring stress k v0 t = 2.5 Pa/s * t stays below C = 1e3 Pa until
    # t = 400 s: the block must stay stuck (slip = 0) ...
    case("coh1e3-stuck", "C = 1e3 > k v0 t (<= 500 Pa), V(0) = 0, "
         "sigma_n = 1e4, k = 2.5e6", 200, dynamic=True, k_over_kc=0.5,
         Normal_stress=1e4, Cohesion=1e3, Initial_slip_rate=0)
    # ... and start to slide once k v0 t passes C
    case("coh1e3-release", "as coh1e3-stuck, to t = 5000 s "
         "(k v0 t passes C at 400 s)", 5000, k_over_kc=0.5,
         Normal_stress=1e4, Cohesion=1e3, Initial_slip_rate=0)
    # v0 from 1e-12 to 1e-2 m/s (V* = 1e-6 kept); as in the base case the
    # state starts steady at v0 (alpha = ln(V*/v0)) and V(0) = 2 v0
    case("v0=1e-12", "v0 = 1e-12 m/s, V(0) = 2e-12, steady state at v0, "
         "k = kc/2", 1e9, dynamic=True, Load_point_velocity=1e-12,
         Initial_slip_rate=2e-12,
         Initial_state=math.log(1e-6 / 1e-12))
    case("v0=1e-2", "v0 = 1e-2 m/s, V(0) = 2e-2, steady state at v0, "
         "k = kc/2", 1, dynamic=True, Load_point_velocity=1e-2,
         Initial_slip_rate=2e-2, Initial_state=math.log(1e-6 / 1e-2))
    # load-point velocity step 1e-10 -> 1e-2 m/s from steady sliding, on the
    # stable spring k = 2 kc; the step at 10 L/v0, then 1000 L/v_new
    case("vstep-1e8", "v0 = 1e-10 -> 1e-2 m/s at t = 1e6 s, k = 2 kc, "
         "steady start", 1e6 + 1, dynamic=True, k_over_kc=2,
         Load_point_velocity=1e-10, Initial_slip_rate=1e-10,
         Initial_state=math.log(1e-6 / 1e-10), Velocity_step_time=1e6,
         Velocity_step_factor=1e8)
    # very stiff and very soft spring
    case("k=1e12", "k = 1e12 Pa/m (2000 kc)", 500, dynamic=True,
         Stiffness=1e12)
    case("k=1e-3kc", "k = 1e-3 kc = 5e5 Pa/m", 2e5, dynamic=True,
         k_over_kc=1e-3)


def write_prm(work, integrator, name, end, max_step, p):
    """The case's parameter file: prm/spring-slider.prm with the case's
    end time, maximum step and Spring slider entries."""
    out = os.path.join(work, name)
    entries = {"End time": f"{end:.15g}",
               "Time stepping/Integrator": integrator,
               "Time stepping/Controller": "step-doubling",
               "Time stepping/Adaptive": "true",
               "Time stepping/Tolerance": "1e-5",
               "Time stepping/Initial step": "1e-3",
               "Time stepping/Minimum step": "1e-14",
               "Time stepping/Maximum step": f"{max_step:.15g}",
               "Solver/State law": "ageing",
               "Solver/Coupling": "fixed-point",
               "Solver/Fixed-point tolerance": "1e-5",
               "Solver/Maximum fixed-point iterations": 20,
               "Output/Event threshold": 10,
               "Output/Progress interval": "1e9",
               "Output/Checkpoint steps": 0,
               "Output/Checkpoint minutes": 0}
    entries.update({f"Spring slider/{k}": (v if isinstance(v, str)
                                           else f"{v:.15g}")
                    for k, v in p.items()})
    path = prm.variant(out + ".prm", os.path.join(bench.ROOT, "prm",
                                                  "spring-slider.prm"),
                       out, entries)
    return path, out


def nonfinite(path):
    """First non-finite (or unparsable) field of a CSV: 'no' or where."""
    if not os.path.exists(path):
        return "no file"
    with open(path) as f:
        rows = list(csv.reader(f))
    header = rows[0] if rows else []
    for i, row in enumerate(rows[1:], start=2):
        for j, x in enumerate(row):
            bad = re.search(r"nan|inf", x, re.I)
            try:
                bad = bad or not math.isfinite(float(x))
            except ValueError:
                bad = True
            if bad:
                col = header[j] if j < len(header) else j
                return f"yes: '{x}' in column '{col}', line {i}"
    return "no"


def run(exe, work, integrator, timeout, name, what, end, max_step, p):
    """One case under the timeout; its row."""
    path, d = write_prm(work, integrator, name, end, max_step, p)
    wall, rc = bench.run([exe, path], d + ".log", timeout=timeout,
                         check=False)
    out = bench.text(d + ".log")
    if rc == 0 and "Final:" in out:
        outcome = "finished"
    elif rc in (124, 137):
        outcome = f"timeout ({timeout} s)"
    elif rc < 0 or rc > 128:
        outcome = f"crashed (exit {rc})"
    else:
        lines = [line.strip() for line in out.splitlines()
                 if re.match(r"(Error:|rsfcycle: error:)", line.strip())]
        outcome = (f"stopped: {lines[0]}" if lines else
                   f"stopped (exit {rc}, no diagnosis)")
    ts = os.path.join(d, "time-series.csv")
    steps, hmin, hmax, slip, vmax = 0, float("nan"), float("nan"), None, None
    if os.path.exists(ts):
        with open(ts) as f:
            rows = list(csv.DictReader(f))
        steps = len(rows)
        hs = []
        for r in rows:
            try:
                hs.append(float(r["step_size_s"]))
            except ValueError:
                pass
        if hs:
            hmin, hmax = min(hs), max(hs)
        if rows:
            slip = rows[-1]["slip_m"]
            vmax = max((float(r["slip_rate_m_per_s"]) for r in rows),
                       key=lambda v: (math.isfinite(v), abs(v)))
    fp = re.search(r"max fixed-point iterations (\d+)", out)
    fp = fp.group(1) if fp else "-"
    m = re.search(r"Summary: (\d+) steps", out)
    if m and int(m.group(1)) != steps:
        outcome += f" (summary says {m.group(1)} steps)"
    final = re.search(r"^Final:.*$", out, re.M)
    other = []
    ev = nonfinite(os.path.join(d, "events.csv"))
    if ev.startswith("yes"):
        other.append("events.csv " + ev)
    if final and re.search(r"nan|inf", final.group(0), re.I):
        other.append("Final line: " + final.group(0))
    events = len(re.findall(r"event \d+ starts", out))
    warned = re.search(r"\*\*\* Warning: .*?\(step (\S+) s at t = (\S+) s",
                       out)
    if warned:
        outcome += (f"; warned (stability-limited, crawling) at t = "
                    f"{warned.group(2)} s, step {warned.group(1)} s")
    loop = re.search(r"Wall time of the time loop: (\S+) s", out)
    loop = float(loop.group(1)) if loop else float("nan")
    return dict(name=name, what=what, end=end, outcome=outcome, steps=steps,
                hmin=hmin, hmax=hmax, wall=wall, loop=loop,
                nonfinite=nonfinite(ts),
                other="; ".join(other), events=events, fp=fp, slip=slip,
                vmax=vmax,
                final=final.group(0) if final else "")


def runs(*case, integrator: ("implicit", "runge-kutta") = "implicit",
         build="", work=""):
    """Run the cases into WORK; without names also runs.csv and runs.md.

    case: only these cases (then no tables are written)
    integrator: the implicit step, or ARKODE's explicit Dormand-Prince 5(4)
    """
    exe = bench.executable(build)
    work = bench.work(work)
    # an explicit method that crawls writes a row per step: ten seconds
    # show it
    timeout = 10 if integrator == "runge-kutta" else 60
    matrix()
    rows = []
    for c in CASES:
        if case and c[0] not in case:
            continue
        r = run(exe, work, integrator, timeout, *c)
        rows.append(r)
        print(f"{r['name']:<20} {r['outcome'][:90]:<40} steps {r['steps']:>7}"
              f" h {r['hmin']:.3g}..{r['hmax']:.3g} wall {r['wall']:.2f} s"
              f" fp {r['fp']} events {r['events']} Vmax {r['vmax']} nonfinite "
              f"{r['nonfinite']} {r['other']}", flush=True)
    if case:
        return
    suffix = "" if integrator == "implicit" else "-" + integrator
    with open(os.path.join(HERE, f"runs{suffix}.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "set-up", "end time [s]", "outcome", "steps",
                    "min step [s]", "max step [s]", "wall time [s]",
                    "time loop [s]", "max fixed-point iterations", "events",
                    "max slip rate [m/s]", "final slip [m]",
                    "non-finite in time-series.csv", "other non-finite"])
        for r in rows:
            w.writerow([r["name"], r["what"], f"{r['end']:g}", r["outcome"],
                        r["steps"], f"{r['hmin']:.3g}", f"{r['hmax']:.3g}",
                        f"{r['wall']:.2f}", f"{r['loop']:.3g}", r["fp"],
                        r["events"],
                        f"{r['vmax']:.3g}" if r["vmax"] is not None else "",
                        r["slip"] or "", r["nonfinite"], r["other"]])
    lines = ["| case | set-up | end time [s] | outcome | steps | "
             "min step [s] | max step [s] | wall time [s] | time loop [s] | "
             "max FP its | "
             "events | "
             "max V [m/s] | non-finite in time-series.csv |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        vm = f"{r['vmax']:.3g}" if r["vmax"] is not None else "-"
        nf = r["nonfinite"] + (f" ({r['other']})" if r["other"] else "")
        lines.append(f"| {r['name']} | {r['what']} | {r['end']:g} | "
                     f"{r['outcome']} | {r['steps']} | {r['hmin']:.3g} | "
                     f"{r['hmax']:.3g} | {r['wall']:.2f} | {r['loop']:.3g} | "
                     f"{r['fp']} | "
                     f"{r['events']} | "
                     f"{vm} | {nf} |")
    table = "\n".join(lines)
    with open(os.path.join(HERE, f"runs{suffix}.md"), "w") as f:
        f.write("<!-- SPDX-License-Identifier: LGPL-2.1-or-later -->\n" +
                table + "\n")
    print(table)


def list_():
    """The cases."""
    matrix()
    for name, what, end, max_step, p in CASES:
        print(f"{name:<16} {what} (to {end:g} s)")


if __name__ == "__main__":
    raise SystemExit(bench.cli(__doc__, NAME, [list_, runs]))
