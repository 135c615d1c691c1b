#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""SEAS BP8-QD-GS and BP8-QD-PW: rsfcycle's resolution, the pore pressure
against its closed form, the Peaceman well's limit, the body's extent and
the cost; the results.csv of benchmarks/seas-bp8/README.md.

From the repository's root, with the package on the path:

  PYTHONPATH=python /usr/bin/python3 benchmarks/seas-bp8/run.py COMMAND ...

  runs     the runs below into WORK/NAME, one at a time on one rank each
           (--ranks N for N; about 35 min in all on one core; --only GROUP
           or NAME ... for some of them):
             gs       gs-40m, gs-20m, gs-10m: prm/seas-bp8-qd-gs.prm with
                      fault and fluid cells of 40, 20, 10 m, 30 days
             pw       pw-40m, pw-20m, pw-10m: prm/seas-bp8-qd-pw.prm alike,
                      to 1 hour (below the time where sigma_0 - p reaches 0
                      at the well's node at every cell size)
             stop     pw-40m-stop, pw-20m-stop: the well for 30 days, which
                      stops where sigma_0 - p reaches 0 (with exit status
                      1 and its SEAS files finished at the last step)
             probe    probe-40m, probe-20m, probe-10m: the well for 30
                      days with fluid cells of 40, 20, 10 m on 40 m fault
                      cells, sigma_0 = 1 GPa and steps of at most 600 s:
                      the pressure at the well's node, which does not
                      depend on the slip, and when it exceeds BP8's
                      sigma_0 = 25 MPa
             domain   dom-free-y500 ... dom-rigid-y2000: GS at 20 m with
                      the far side y = Ly at 500, 1000, 2000 m, free slip
                      (the shipped condition, whose Ly is 1600 m) or a
                      rigid wall; dom-free-xz6400: the shipped body with
                      x and z at +-6400 m; box-xz500-y500, box-xz1500-y500,
                      box-xz500-y2000: EQquasi's boxes (x and z faces
                      traction free at +-Lxz, rigid walls at y = +-Ly)
             cost     gs-10m-2ranks, pw-10m-2ranks: gs-10m and pw-10m on 2
                      MPI ranks
           The meshes of the domain study are made with gmsh from
           prm/meshes/seas-bp5.geo into WORK/meshes.
  results  the figures of the run folders present into results.csv
           (rsfcycle.results.record), every finished run through the SEAS
           checker (rsfcycle.seas.check)

WORK is --work (default benchmarks/seas-bp8/runs). Days of 86400 s; the
centre is the station fltst_strk+000dp+000 (the injection point), the
edge fltst_strk-200dp+000 (EQquasi's "edge"); slips are slip_2 at 30
days. The closed form of the Gaussian source is the infinite plane's
summed over the source's images in the no-flux walls of Omega_f (as test
fault_diffusion_gaussian evaluates it).
"""

import json
import math
import os
import re
import subprocess
import sys

import numpy as np

from rsfcycle import bench, catalog, prm, results, seas
from rsfcycle import run as run_folder
from rsfcycle.peers import hbi

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = results.repository_root()
DAY = 86400.0
HOUR = 3600.0
END = 30 * DAY
CENTRE = "fltst_strk+000dp+000.dat"
EDGE = "fltst_strk-200dp+000.dat"
MODELER = "rsfcycle benchmarks/seas-bp8"
CELLS = {"40m": (1, 40), "20m": (2, 20), "10m": (3, 10)}  # refinements, m
PW_END = HOUR
STOP_TIMEOUT = 1800  # s of wall time for a run to the well's limit
PROBE_SIGMA = 1e9  # Pa: the probes' normal stress, which no pressure here reaches
PROBE_STEP = 600  # s: their largest step (rows of the stations), the fluid's step
RIGID = "1: contact, 2: load, 3: free, 4: free, 5: creep, 6: free"

# BP8's hydraulics (Table 1) for the closed form
Q0, T_OFF, L_INJ, HALF = 0.003, 100 * HOUR, 50.0, 400.0
BETA, PHI, K, ETA_F, L_F = 1e-8, 0.1, 5e-14, 1e-3, 1.0
ALPHA = K / (PHI * BETA * ETA_F)
SIGMA0 = 25e6
EQ_WINDOW = (25000.0, 100000.0)  # s: the times of EQquasi's pressure errors


def run_list():
    """{name: (variant, cells, extra entries, ranks, group, mesh)}; mesh
    (Lxz, Ly, wall) or None for the shipped mesh."""
    runs = {}
    for c in CELLS:
        runs[f"gs-{c}"] = ("gs", c, {}, 1, "gs", None)
    for c in CELLS:
        runs[f"pw-{c}"] = ("pw", c, {"End time": PW_END}, 1, "pw", None)
    for c in ("40m", "20m"):
        runs[f"pw-{c}-stop"] = ("pw", c, {}, 1, "stop", None)
    for c in CELLS:
        runs[f"probe-{c}"] = ("pw", "40m", {"Mesh file/Friction/Pore fluid/Cell size":
                                            CELLS[c][1], "Mesh file/Friction/Normal stress":
                                            PROBE_SIGMA, "Time stepping/Maximum step":
                                            PROBE_STEP}, 1, "probe", None)
    for wall in ("free", "rigid"):
        for ly in (500, 1000, 2000):
            runs[f"dom-{wall}-y{ly}"] = ("gs", "20m", {}, 1, "domain", (3200, ly, wall))
    runs["dom-free-xz6400"] = ("gs", "20m", {}, 1, "domain", (6400, 1600, "free"))
    for lxz, ly in ((500, 500), (1500, 500), (500, 2000)):
        runs[f"box-xz{lxz}-y{ly}"] = ("gs", "20m", {}, 1, "domain", (lxz, ly, "rigid"))
    runs["gs-10m-2ranks"] = ("gs", "10m", {}, 2, "cost", None)
    runs["pw-10m-2ranks"] = ("pw", "10m", {"End time": PW_END}, 2, "cost", None)
    return runs


def mesh(work, lxz, ly):
    """WORK/meshes/bp8-xzLXZ-yLY.msh from seas-bp5.geo (BP7's parameters
    with the extents changed), made once."""
    path = os.path.join(work, "meshes", f"bp8-xz{lxz}-y{ly}.msh")
    if not os.path.exists(path):
        os.makedirs(os.path.dirname(path), exist_ok=True)
        numbers = dict(whole=1, X=400, W=400, h=80, Lx=lxz, Ly=ly, Lz=lxz)
        command = ["gmsh", "-3", "-format", "msh2"]
        for k, v in numbers.items():
            command += ["-setnumber", k, str(v)]
        command += ["-o", path, os.path.join(ROOT, "prm", "meshes", "seas-bp5.geo")]
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    return path


def entries(name, spec, work):
    variant, cells, extra, _, _, box = spec
    refinements, size = CELLS[cells]
    out = {"Mesh/Local refinements": refinements,
           "Mesh file/Friction/Pore fluid/Cell size": size,
           "Output/SEAS/Modeler": MODELER}
    if box:
        lxz, ly, wall = box
        out["Mesh file/File"] = mesh(work, lxz, ly)
        if wall == "rigid":
            out["Mesh file/Boundary roles"] = RIGID
    out.update(extra)
    return out


def launch(binary, base, folder, values, ranks, timeout=None):
    """rsfcycle on the variant of `base` into FOLDER (bench.run_variant,
    but a run that stops with an error is kept and reported); returns
    (wall time [s], exit status)."""
    folder = os.path.abspath(folder)
    path = prm.variant(folder + ".prm", os.path.join(ROOT, base), folder, values)
    context = results.run_context(ROOT)
    command = [binary, "--force", path]
    if ranks > 1:
        command = bench.mpirun(ranks, command)
    seconds, status = bench.run(command, folder + ".log", env=bench.mpi_environment(),
                                timeout=timeout, check=False)
    context["cores"] = ranks
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "run-context.json"), "w", encoding="utf-8") as f:
        json.dump(context, f)
    return seconds, status


def runs(args):
    """rsfcycle's runs into --work (about 35 min on one core)."""
    binary = os.path.abspath(args.binary or os.path.join(ROOT, "build", "rsfcycle"))
    if not os.path.isfile(binary):
        raise FileNotFoundError(f"{binary}: not built (bash quickstart.sh), or give --binary")
    chosen = run_list()
    if args.only:
        chosen = {n: s for n, s in chosen.items() if n in args.only or s[4] in args.only}
    for name, spec in chosen.items():
        base = f"prm/seas-bp8-qd-{spec[0]}.prm"
        folder = os.path.join(args.work, name)
        timeout = STOP_TIMEOUT if spec[4] == "stop" else None
        ranks = spec[3] if spec[4] == "cost" else args.ranks
        seconds, status = launch(binary, base, folder, entries(name, spec, args.work),
                                 ranks, timeout)
        print(f"{name}: {seconds:.0f} s, exit status {status}")


# ---------------------------------------------------------------- closed form

def e1(x):
    """The exponential integral E1(x), x > 0 (series below 1, continued
    fraction above)."""
    if x > 700:
        return 0.0
    if x <= 1:
        total, term = -math.log(x) - 0.5772156649015329, 1.0
        for i in range(1, 200):
            term *= -x / i
            total -= term / i
            if abs(term / i) < 1e-17 * abs(total):
                break
        return total
    b, c, d = x + 1, 1e300, 1 / (x + 1)
    h = d
    for i in range(1, 500):
        a = -i * i
        b += 2
        d = 1 / (a * d + b)
        c = b + a / c
        h *= c * d
        if abs(c * d - 1) < 1e-16:
            break
    return h * math.exp(-x)


def plane(r, t):
    """The Gaussian source's pressure [Pa] at distance r from it after t
    of constant injection Q0 in the infinite plane."""
    if t <= 0:
        return 0.0
    a = Q0 * ETA_F / (4 * math.pi * K * L_F)
    v0, v = L_INJ ** 2, L_INJ ** 2 + 2 * ALPHA * t
    if r == 0:
        return a * math.log(v / v0)
    return a * (e1(r * r / (2 * v)) - e1(r * r / (2 * v0)))


def closed_form(x2, x3, t):
    """p [Pa] at (x2, x3) and t in Omega_f with no flux across its edges
    and the shut-in at T_OFF: the images at 2 l (i, j), |i|, |j| <= 3."""
    total = 0.0
    for i in range(-3, 4):
        for j in range(-3, 4):
            r = math.hypot(x2 - 2 * HALF * i, x3 - 2 * HALF * j)
            total += plane(r, t) - plane(r, t - T_OFF)
    return total


# ---------------------------------------------------------------- readers

def station(folder, name, field):
    """(t, values) of a station's column."""
    names, rows = seas.table(os.path.join(folder, name))
    return rows[:, 0], rows[:, names.index(field)]


def at_end(folder, name, field):
    t, v = station(folder, name, field)
    return float(v[-1]), float(t[-1])


def contact_nodes(folder):
    log = bench.text(os.path.join(folder, "log.txt"))
    found = re.search(r"(\d+) contact nodes", log)
    return int(found.group(1)) if found else None


def steps(folder):
    found = re.search(r"num_time_steps=(\d+)",
                      bench.text(os.path.join(folder, CENTRE)))
    return int(found.group(1)) if found else None


def stop_time(folder):
    """The time [s] where the run stopped for sigma_0 - p <= 0, or None."""
    found = re.search(r"at t = ([0-9.e+-]+) s the pore pressure left the fault node",
                      bench.text(folder + ".log"))
    return float(found.group(1)) if found else None


def context(folder):
    """(context, cores) of a run folder, the commit the binary's (its
    log.txt's version line), not the working tree's at the run."""
    ctx, cores = bench.context_of(folder)
    found = re.search(r"commit ([0-9a-f]{7})[0-9a-f]*(-dirty)?",
                      run_folder.version(folder))
    if found:
        ctx = dict(ctx, commit=found.group(1) + (found.group(2) or ""))
    return ctx, cores


def error_between(folder, start, end):
    """The centre's largest relative pressure error against the closed
    form over the rows between start and end [s]."""
    t, p = station(folder, CENTRE, "pore_pressure")
    return max(abs(1e6 * p[k] - closed_form(0.0, 0.0, t[k])) / closed_form(0.0, 0.0, t[k])
               for k in range(len(t)) if start <= t[k] <= end)


def pressure_errors(folder):
    """The centre's pore pressure against the closed form: (relative
    error at the last row at or before the shut-in, that row's time [s]
    and closed-form value [Pa], the largest error over the run relative
    to p at the shut-in)."""
    t, p = station(folder, CENTRE, "pore_pressure")
    exact = np.array([closed_form(0.0, 0.0, s) for s in t])
    k = int(np.searchsorted(t, T_OFF, side="right")) - 1
    shut = closed_form(0.0, 0.0, T_OFF)
    return (abs(1e6 * p[k] - exact[k]) / exact[k], float(t[k]), float(exact[k]),
            float(np.max(np.abs(1e6 * p - exact))) / shut)


def peak(folder):
    """(max slip rate [m/s], its day) of global.dat."""
    _, g = seas.table(os.path.join(folder, "global.dat"))
    k = int(np.argmax(g[:, 1]))
    return 10 ** g[k, 1], g[k, 0] / DAY


def events(folder):
    _, g = seas.table(os.path.join(folder, "global.dat"))
    return len(catalog.detect(g[:, 0], 10 ** g[:, 1]))


def slips(folder):
    """(centre, edge) slip_2 [m] at the end, and the end [s]."""
    centre, end = at_end(folder, CENTRE, "slip_2")
    edge, _ = at_end(folder, EDGE, "slip_2")
    return centre, edge, end


def finished(folder):
    """Whether a run folder's run ended: at its end time (summary.txt) or
    where the well stopped it."""
    return (os.path.exists(os.path.join(folder, "summary.txt"))
            or (os.path.exists(folder + ".log") and stop_time(folder) is not None))


def checked(folder):
    """The SEAS checker's problems of a run folder (empty: it passes)."""
    _, _, problems = seas.check(folder)
    return problems


# ---------------------------------------------------------------- results

def crossings(t, values, level):
    """(the first time values rise to level, the last time they fall
    below it) [s], linear between rows; None if they never reach it."""
    high = np.nonzero(values >= level)[0]
    if len(high) == 0:
        return None
    i, j = high[0], high[-1]
    up = t[i] if i == 0 else np.interp(level, values[i - 1:i + 1], t[i - 1:i + 1])
    down = t[j] if j == len(t) - 1 else np.interp(level, values[j + 1:j - 1:-1],
                                                    t[j + 1:j - 1:-1])
    return float(up), float(down)


def sci(x, digits=4):
    """3.087e-7 rather than 3.087e-07."""
    return re.sub(r"e([+-])0*(\d)", r"e\1\2", f"{x:.{digits - 1}e}")


def pct(x, digits=2):
    return hbi.signed(100 * x, digits)


def order(e_coarse, e_fine, h_coarse, h_fine):
    return math.log(e_coarse / e_fine) / math.log(h_coarse / h_fine)


def results_(args):
    """results.csv from the run folders in --work."""
    work = args.work
    found = {n: os.path.join(work, n) for n in run_list() if finished(os.path.join(work, n))}
    if not found:
        raise FileNotFoundError(f"{work}: no run folder (run.py runs)")

    def have(*names):
        return all(n in found for n in names)

    # the SEAS checker on every finished run
    passing, failing = [], []
    for name, folder in found.items():
        problems = checked(folder)
        (failing if problems else passing).append(name)
        for problem in problems:
            print(f"{name}: {problem}")
    first = found.get("gs-10m") or next(iter(found.values()))
    hbi.record(HERE, [("check.seas", f"{len(passing)} of {len(passing) + len(failing)} pass",
                       "", "the runs (those the well stops included) through the SEAS checker "
                       "(rsfcycle.seas check)" + (": " + ", ".join(failing) + " fail"
                                                  if failing else ""))], *context(first))

    # GS: resolution and the pressure against the closed form
    gs = {c: found[f"gs-{c}"] for c in CELLS if f"gs-{c}" in found}
    errors = {}
    for c, folder in gs.items():
        centre, edge, end = slips(folder)
        err, t_row, exact, worst = pressure_errors(folder)
        errors[c] = err
        v, day = peak(folder)
        wall, loop, operator = hbi.rsfcycle_times(folder)
        rows = [
            (f"gs{c[:-1]}.slip_centre", f"{1e3 * centre:.2f}", "mm",
             f"GS, {c[:-1]} m: slip at the centre after 30 days"),
            (f"gs{c[:-1]}.slip_edge", f"{1e3 * edge:.2f}", "mm",
             f"GS, {c[:-1]} m: slip at (x2, x3) = (-200, 0) m after 30 days"),
            (f"gs{c[:-1]}.ratio", f"{edge / centre:.3f}", "",
             f"GS, {c[:-1]} m: edge/centre slip"),
            (f"gs{c[:-1]}.p_error", f"{100 * err:.3f}", "%",
             f"GS, {c[:-1]} m: pore pressure at the centre against the closed form at "
             f"t = {t_row:.0f} s, the last row before the shut-in ({exact / 1e6:.3f} MPa)"),
            (f"gs{c[:-1]}.p_error_eq", f"{100 * error_between(folder, *EQ_WINDOW):.2f}",
             "%", f"GS, {c[:-1]} m: the centre's largest pressure error against the closed "
             "form from 25000 to 100000 s (the times of EQquasi's table)"),
            (f"gs{c[:-1]}.p_error_max", f"{100 * worst:.3f}", "%",
             f"GS, {c[:-1]} m: largest difference at the centre over the 30 days, "
             "relative to the closed form at the shut-in"),
            (f"gs{c[:-1]}.peak", sci(v), "m/s",
             f"GS, {c[:-1]} m: the fault's maximum slip rate, at day {day:.2f}"),
            (f"gs{c[:-1]}.steps", f"{steps(folder)}", "",
             f"GS, {c[:-1]} m: time steps over the 30 days"),
        ]
        if wall:
            rows += [(f"gs{c[:-1]}.cost", hbi.duration(wall), "",
                      f"GS, {c[:-1]} m: the whole run on one rank"),
                     (f"gs{c[:-1]}.operator", f"{operator:.0f}", "s",
                      f"GS, {c[:-1]} m: the Green's functions (TimerOutput)"),
                     (f"gs{c[:-1]}.loop", f"{loop:.0f}", "s",
                      f"GS, {c[:-1]} m: the time loop (TimerOutput)")]
        hbi.record(HERE, rows, *context(folder))
    if have("gs-40m", "gs-20m", "gs-10m"):
        ctx = context(gs["10m"])
        o1 = order(errors["40m"], errors["20m"], 40, 20)
        o2 = order(errors["20m"], errors["10m"], 20, 10)
        c = {k: slips(v) for k, v in gs.items()}
        hbi.record(HERE, [
            ("gs.p_order", f"{o1:.2f} and {o2:.2f}", "",
             "GS: observed order of the centre's pressure error, 40 to 20 m and 20 to 10 m"),
            ("gs.p_shut_in", f"{closed_form(0, 0, T_OFF) / 1e6:.3f}", "MPa",
             "GS: closed form at the centre at the shut-in (100 h), the walls' images included"),
            ("gs.centre_40_10", pct(c["40m"][0] / c["10m"][0] - 1), "%",
             "GS: centre slip at 40 m against 10 m"),
            ("gs.centre_20_10", pct(c["20m"][0] / c["10m"][0] - 1), "%",
             "GS: centre slip at 20 m against 10 m"),
            ("gs.edge_20_10", pct(c["20m"][1] / c["10m"][1] - 1), "%",
             "GS: edge slip at 20 m against 10 m"),
        ], *ctx)

    # PW: to 1 hour at three cell sizes, and where the well stops the run
    for c in CELLS:
        name = f"pw-{c}"
        if name not in found:
            continue
        folder = found[name]
        p_well, end = at_end(folder, CENTRE, "pore_pressure")
        centre, _ = at_end(folder, CENTRE, "slip_2")
        wall, loop, operator = hbi.rsfcycle_times(folder)
        rows = [
            (f"pw{c[:-1]}.p_well", f"{p_well:.3f}", "MPa",
             f"PW, {c[:-1]} m: pore pressure at the well's node at t = {end / HOUR:g} h"),
            (f"pw{c[:-1]}.slip_centre", f"{1e3 * centre:.4f}", "mm",
             f"PW, {c[:-1]} m: slip at the well at t = {end / HOUR:g} h"),
        ]
        if wall:
            rows.append((f"pw{c[:-1]}.cost", hbi.duration(wall), "",
                         f"PW, {c[:-1]} m, to {end / HOUR:g} h: the whole run on one rank "
                         f"(operator {operator:.0f} s)"))
        hbi.record(HERE, rows, *context(folder))
    for c in ("40m", "20m"):
        name = f"pw-{c}-stop"
        if name in found:
            t_stop = stop_time(found[name])
            if t_stop is None:
                continue
            p_gs = closed_form(0, 0, t_stop) / 1e6
            hbi.record(HERE, [(f"pw{c[:-1]}.stop", f"{t_stop / HOUR:.1f}", "h",
                               f"PW, {c[:-1]} m: the run stops where sigma_0 - p reaches 0 "
                               f"at the well's node, at t = {t_stop:.0f} s (GS's centre "
                               f"then {p_gs:.1f} MPa)")], *context(found[name]))

    # the well's node: when its pressure exceeds sigma_0
    for c in CELLS:
        name = f"probe-{c}"
        if name not in found:
            continue
        t, p = station(found[name], CENTRE, "pore_pressure")
        above = crossings(t, 1e6 * p, SIGMA0)
        k = int(np.argmax(p))
        span = (f"from {above[0] / HOUR:.2f} h to {above[1] / HOUR:.2f} h" if above
                else "never")
        hbi.record(HERE, [
            (f"pw{c[:-1]}.p_max", f"{p[k]:.1f}", "MPa",
             f"PW, fluid cells of {c[:-1]} m: the largest pressure at the well's node, "
             f"at t = {t[k] / HOUR:.1f} h"),
            (f"pw{c[:-1]}.above", span, "", f"PW, fluid cells of {c[:-1]} m: the well's "
             "node above sigma_0 = 25 MPa"),
        ], *context(found[name]))

    # the body's extent at 20 m
    domain = []
    for name in sorted(found):
        if name.startswith(("dom-", "box-")) or name == "gs-20m":
            centre, edge, _ = slips(found[name])
            key = "dom.shipped" if name == "gs-20m" else "dom." + (
                name[4:] if name.startswith("dom-") else name).replace("-", "_")
            label = ("x, z +-3200 m, free slip at y = 1600 m (the shipped body)"
                     if name == "gs-20m" else describe(name))
            domain += [(key, f"{edge / centre:.3f}", "", f"GS, 20 m, {label}: edge/centre slip"),
                       (key + ".centre", f"{1e3 * centre:.2f}", "mm",
                        f"GS, 20 m, {label}: slip at the centre"),
                       (key + ".edge", f"{1e3 * edge:.2f}", "mm",
                        f"GS, 20 m, {label}: slip at (-200, 0) m")]
    if "box-xz500-y500" in found:
        v, day = peak(found["box-xz500-y500"])
        domain.append(("dom.box_xz500_y500.peak", sci(v), "m/s", "GS, 20 m, x, y, z +-500 m "
                       f"(EQquasi's box): the fault's maximum slip rate, at day {day:.2f}"))
    if domain:
        hbi.record(HERE, domain, *context(found.get("gs-20m") or first))

    # cost on 2 ranks against one
    for variant, span in (("gs", "30 days"), ("pw", "the first hour")):
        name = f"{variant}-10m-2ranks"
        if not have(name):
            continue
        wall, loop, operator = hbi.rsfcycle_times(found[name])
        key, what = f"cost.{variant}10_2ranks", f"{variant.upper()}, 10 m"
        hbi.record(HERE, [
            (key, hbi.duration(wall), "", f"{what}, {span} on 2 ranks, the whole run"),
            (key + "_operator", f"{operator:.0f}", "s",
             f"{what}, 2 ranks: the Green's functions"),
            (key + "_loop", f"{loop:.0f}", "s", f"{what}, 2 ranks: the time loop"),
        ], *context(found[name]))

    # the SEAS table's rows
    if have("gs-10m"):
        folder = found["gs-10m"]
        v, day = peak(folder)
        n = events(folder)
        table = [
            ("bp8-qd-gs.cells", "10", "m", f"fault and fluid cells ({contact_nodes(folder)} "
             "contact nodes)"),
            ("bp8-qd-gs.events", "none in 30 d (aseismic)" if n == 0 else f"{n} in 30 d",
             "", "events (max V >= 1 mm/s)"),
            ("bp8-qd-gs.peer", "none; EQquasi's published figures", "",
             "no peer run here: EQquasi's published BP8 figures (50 m) are compared in "
             "the README"),
            ("bp8-qd-gs.recurrence", f"no events; p(0) at 100 h {100 * errors['10m']:.3f} % "
             "from the closed form", "", "the centre's pore pressure against the closed "
             "form at the last row before the shut-in"),
            ("bp8-qd-gs.peak_slip_rate", f"no peer; {sci(v, 3)} m/s at day {day:.2f}", "",
             "the fault's maximum slip rate (no peer)"),
        ]
        wall, _, _ = hbi.rsfcycle_times(folder)
        table.append(("bp8-qd-gs.cost", hbi.duration(wall), "",
                      "30 days at 10 m, operator included"))
        hbi.record(HERE, table, *context(folder))
    if have("pw-10m"):
        folder = found["pw-10m"]
        wall, _, _ = hbi.rsfcycle_times(folder)
        # where sigma_0 - p reaches 0 at the well: the probes' crossing
        stops = {}
        for c in CELLS:
            if f"probe-{c}" in found:
                t, p = station(found[f"probe-{c}"], CENTRE, "pore_pressure")
                above = crossings(t, 1e6 * p, SIGMA0)
                if above:
                    stops[c] = above[0] / HOUR
        v, day = peak(folder)
        hbi.record(HERE, [
            ("bp8-qd-pw.cells", "10", "m", f"fault and fluid cells ({contact_nodes(folder)} "
             "contact nodes)"),
            ("bp8-qd-pw.events", "none to 1 h", "", "events (max V >= 1 mm/s) in the "
             "hour run"),
            ("bp8-qd-pw.cost", hbi.duration(wall) + " for 1 h", "", "the first hour at 10 m, "
             "operator included"),
            ("bp8-qd-pw.peer", "none", "", "no peer"),
            ("bp8-qd-pw.recurrence", "the run stops: σ̄₀ − p = 0 at the well"
             + (f" after {stops['10m']:.2f} h" if "10m" in stops else "")
             + (" (" + ", ".join(f"{c[:-1]} m: {stops[c]:.2f} h" for c in ("20m", "40m")
                                 if c in stops) + ")" if "20m" in stops else ""), "",
             "the well's node reaches p = sigma_0 long before 30 days at every cell size "
             "run (the probes)"),
            ("bp8-qd-pw.peak_slip_rate", f"no peer; {sci(v, 3)} m/s in the first hour", "",
             "the fault's maximum slip rate over the hour run (no peer)"),
        ], *context(folder))


def describe(name):
    """The body of a domain run, in words."""
    if name == "dom-free-xz6400":
        return "x, z +-6400 m, free slip at y = 1600 m"
    m = re.match(r"dom-(free|rigid)-y(\d+)", name)
    if m:
        wall = "free slip" if m.group(1) == "free" else "a rigid wall"
        return f"x, z +-3200 m, {wall} at y = {m.group(2)} m"
    m = re.match(r"box-xz(\d+)-y(\d+)", name)
    return f"x, z +-{m.group(1)} m traction free, a rigid wall at y = {m.group(2)} m"


def only(p):
    groups = sorted({s[4] for s in run_list().values()})
    p.add_argument("--only", nargs="+", metavar="GROUP_OR_NAME",
                   choices=groups + list(run_list()),
                   help="some of the runs: " + ", ".join(groups) + " or run names")
    p.set_defaults(ranks=1)


def main(argv=None):
    return hbi.driver(__doc__, HERE, "bp8", dict(runs=runs, results=results_),
                      dict(runs=only), argv=argv)


if __name__ == "__main__":
    sys.exit(main())
