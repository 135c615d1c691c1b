#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Why 90 events in 1000 s where the paper reports 79.

Sensitivity of the 2D laboratory wedge's event sequence (first event,
recurrence, events starting in [0, 1000] s, rupture width, peak slip rate,
slip, uplift per event at 15 / 30 / 45 cm) to every modelling choice the
paper (section 3, Table 1) leaves open or that rsfcycle made itself, and
to Table 1's values within the ranges the paper states, one at a time, on
the default mesh of prm/wedge-2d.prm (2 + 6 refinements, Refinement
distance 3, 16,612 unknowns, δ = ε = 1e-4, TNNMG tolerance 1e-5,
multigrid). Readings the built-in `wedge` scene cannot express run on the
`mesh-file` scene (prm/wedge-2d-mesh.prm, 9,780 unknowns, the same cells
on the patch) and compare with its own default run (`mesh-default`).
Statistics: means over events 9 on (rsfcycle.bench.wedge_statistics).

Stages (from the repository's root, PYTHONPATH=python /usr/bin/python3
benchmarks/paper-events/run.py STAGE ...):

  list           the variants and their readings
  runs           every variant not yet finished in WORK (and `default-vtu`,
                 the default run with snapshots every 20 s to 720 s, for
                 the normal stress), one after the other at nice 19, 4 – 15
                 minutes each; then `table --record`
  table          runs.csv (the finished runs of WORK; the committed rows
                 for the others) and runs.md; --record writes the rows
                 events.*, recurrence.*, first_event.*, peak_slip_rate.*
                 of results.csv
  thresholds     the default run (and others) recounted with other event
                 thresholds, from WORK's time series: thresholds.csv,
                 thresholds.md (no new runs); --record: events.thresholds,
                 duration.*
  figures        figures/sensitivity.png; figures/normal-stress.png when
                 WORK/default-vtu holds the snapshots
  normal-stress  the normal stress the loaded wedge exerts on its base
                 (from a run folder's VTU snapshots) against the gravity
                 equilibrium's, which friction uses (normal_stress.loaded)
"""
import base64
import math
import os
import re
import struct
import zlib

from rsfcycle import bench, events, plot, prm, run

NAME = "paper-events"
HERE = bench.folder(NAME)
FIGURES = os.path.join(HERE, "figures")
RUNS = os.path.join(HERE, "runs.csv")
T_END = 1000.0
LICENCE = "<!-- SPDX-License-Identifier: LGPL-2.1-or-later -->\n"
SKIP = 8  # events left out of the means, as benchmarks/convergence does

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


def _entries(prefix, lines):
    """{'Prefix/Name': value} of 'Name = value' lines."""
    out = {}
    for line in lines:
        name, _, value = line.partition("=")
        out[prefix + name.strip()] = value.strip()
    return out


def wedge(*lines):
    """Entries of subsection Wedge."""
    return _entries("Wedge/", lines)


def friction(*lines):
    """Entries of subsection Mesh file/Friction."""
    return _entries("Mesh file/Friction/", lines)


def mesh_file(*lines):
    """Entries of subsection Mesh file."""
    return _entries("Mesh file/", lines)


# name, base scene ("wedge": prm/wedge-2d.prm, "mesh": prm/wedge-2d-mesh.prm),
# group, the choice, our reading -> this reading, overrides
VARIANTS = [
    ("default", "wedge", "reference", "prm/wedge-2d.prm as shipped",
     "Table 1, our readings", {}),
    ("mesh-default", "mesh", "reference",
     "prm/wedge-2d-mesh.prm as shipped (reference of the mesh-file rows)",
     "Table 1, our readings", {}),
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

# the prescribed normal stress of the sigma-* variants on the patch,
# relative to the gravity equilibrium's there (1.021 rho g h)
SIGMA_LEVEL = {"sigma-cos2": math.cos(DIP) ** 2 / 1.021,
               "sigma-cos": math.cos(DIP) / 1.021, "sigma-equilibrium": 1.0,
               "mesh-default": 1.0, "sigma-x1.05": 1.05, "sigma-x1.10": 1.10,
               "sigma-loaded": 1.30}


NAMES = [v[0] for v in VARIANTS]
REFERENCE = {"wedge": "default", "mesh": "mesh-default"}
BASE = {"wedge": "wedge-2d.prm", "mesh": "wedge-2d-mesh.prm"}
COLUMNS = ["events_1000s", "first_event_s", "recurrence_s",
           "recurrence_min_s", "recurrence_max_s", "rupture_width_m",
           "peak_slip_rate_mm_per_s", "slip_um", "duration_s",
           "uplift_15cm_um", "uplift_30cm_um", "uplift_45cm_um",
           "nucleation_position_m", "unknowns"]
FIELDS = ["name", "scene", "group", "choice", "reading"] + COLUMNS
THRESHOLDS = (1.05, 1.5, 2, 5, 10, 15, 20, 25, 27.5)


def finished(folder):
    """Whether a run folder holds a finished run (its log's summary)."""
    log = os.path.join(folder, "log.txt")
    return os.path.exists(log) and "Summary:" in bench.text(log)


def run_variant(exe, work, name, base, entries, rerun=False):
    """One variant into WORK/name, unless finished (or --rerun); the binary
    runs in the repository's root, where prm/wedge-2d-mesh.prm's mesh path
    resolves."""
    out = os.path.join(work, name)
    if finished(out) and not rerun:
        return
    settings = {"End time": f"{T_END:g}", "Output/Writers": "time series, base profile, events"}
    settings.update(entries)
    path = prm.variant(os.path.join(work, "prm", name + ".prm"),
                       os.path.join(bench.ROOT, "prm", BASE[base]), out,
                       settings)
    print(f"running {name} ...", flush=True)
    bench.run([exe, path], out + ".out", cwd=bench.ROOT, nice=19)


def statistics(folder):
    """A row of runs.csv from a finished run folder."""
    table = run.events(folder)
    if table.empty:  # slow slip below the threshold, or steady sliding
        row = {k: math.nan for k in COLUMNS}
        row["events_1000s"] = 0
        return row
    row = bench.wedge_statistics(folder, SKIP)
    starts = table["start_s"]
    recurrence = table["recurrence_s"].iloc[SKIP:]
    row.update(events_1000s=int(((starts >= 0) & (starts <= T_END)).sum()),
               first_event_s=float(starts.iloc[0]),
               recurrence_min_s=float(recurrence.min()),
               recurrence_max_s=float(recurrence.max()))
    return {k: row[k] for k in COLUMNS}


def read_runs():
    rows = bench.read_table(RUNS)
    for r in rows:
        for k in COLUMNS:
            r[k] = float(r[k])
    return rows


def collect(work):
    """runs.csv from the finished runs in WORK; a variant whose run is not
    there keeps its committed row."""
    previous = {r["name"]: r for r in read_runs()} \
        if os.path.exists(RUNS) else {}
    rows = []
    for name, base, group, choice, reading, _ in VARIANTS:
        folder = os.path.join(work, name)
        if not finished(folder):
            if name in previous:
                rows.append(previous[name])
            continue
        row = statistics(folder)
        row.update(name=name, scene=base, group=group, choice=choice,
                   reading=reading)
        rows.append(row)
    bench.write_table(RUNS, FIELDS, [
        {k: (f"{r[k]:.6g}" if isinstance(r[k], float) else r[k])
         for k in FIELDS} for r in rows])
    return read_runs()


def markdown(rows):
    """runs.md: every variant against its reference."""
    by = {r["name"]: r for r in rows}
    lines = []
    for r in rows:
        scene = "built-in" if r["scene"] == "wedge" else "mesh-file"
        ref = by.get(REFERENCE[r["scene"]])
        if r["events_1000s"] == 0:
            lines.append([f"`{r['name']}`: {r['reading']}", scene, "–",
                          "– (no event above 10 v0)", 0] + ["–"] * 4)
            continue

        def rel(k):
            if ref is None or r is ref or ref[k] == 0:
                return ""
            return f" ({100 * (r[k] / ref[k] - 1):+.1f} %)"
        spread = (f" ({r['recurrence_min_s']:.3f} – "
                  f"{r['recurrence_max_s']:.3f})"
                  if r["recurrence_max_s"] - r["recurrence_min_s"] >
                  1e-3 * r["recurrence_s"] else "")
        count = "" if ref is None or r is ref else \
            f" ({int(r['events_1000s'] - ref['events_1000s']):+d})"
        lines.append([
            f"`{r['name']}`: {r['reading']}", scene,
            f"{r['first_event_s']:.1f}",
            f"{r['recurrence_s']:.3f}{rel('recurrence_s')}{spread}",
            f"{int(r['events_1000s'])}{count}",
            f"{r['rupture_width_m']:.3f}{rel('rupture_width_m')}",
            f"{r['peak_slip_rate_mm_per_s']:.3f}"
            f"{rel('peak_slip_rate_mm_per_s')}",
            f"{r['slip_um']:.1f}{rel('slip_um')}",
            f"{r['uplift_15cm_um']:.1f} / {r['uplift_30cm_um']:.1f} / "
            f"{r['uplift_45cm_um']:.1f}"])
    return bench.markdown(
        ["reading", "scene", "first event [s]", "recurrence [s] (range)",
         "events in 1000 s", "rupture width [m]", "peak slip rate [mm/s]",
         "slip [µm]", "uplift per event 15 / 30 / 45 cm [µm]"], lines)


def record_runs(rows):
    """The rows events.*, recurrence.*, first_event.*, peak_slip_rate.* of
    results.csv that name a variant, from runs.csv (the descriptions
    kept)."""
    from rsfcycle import results
    old = results.read_results(os.path.join(HERE, "results.csv"))
    by = {r["name"]: r for r in rows}
    figures = []
    for key, row in old.items():
        kind, _, name = key.partition(".")
        r = by.get(name)
        if r is None:
            continue
        ref = by[REFERENCE[r["scene"]]] if name != "mesh-default" \
            else by["default"]
        if kind == "events":
            value, unit = f"{int(r['events_1000s'])}", ""
        elif kind == "first_event":
            value, unit = f"{r['first_event_s']:.1f}", "s"
        elif kind == "recurrence" and name == "default":
            value, unit = f"{r['recurrence_s']:.3f}", "s"
        elif kind in ("recurrence", "peak_slip_rate"):
            column = "recurrence_s" if kind == "recurrence" \
                else "peak_slip_rate_mm_per_s"
            value, unit = f"{100 * (r[column] / ref[column] - 1):+.1f}", "%"
        else:
            continue
        figures.append((key, value, unit, row.description))
    bench.record(NAME, figures)


def table(record=False, work=""):
    """runs.csv (WORK's finished runs, the committed rows for the others),
    runs.md.

    record: write the variants' rows of results.csv
    """
    rows = collect(work)
    text = markdown(rows)
    with open(os.path.join(HERE, "runs.md"), "w", encoding="utf-8") as f:
        f.write(LICENCE + text)
    print(text, end="")
    if record:
        record_runs(rows)


def runs(only="", rerun=False, build="", work=""):
    """Run every variant not finished in WORK (and default-vtu), then
    `table --record`.

    only: only these variants, A,B (default-vtu: the run with snapshots)
    rerun: repeat finished runs
    """
    exe = bench.executable(build)
    work = bench.work(work)
    only = [n for n in only.split(",") if n]
    for name, base, group, choice, reading, entries in VARIANTS:
        if not only or name in only:
            run_variant(exe, work, name, base, entries, rerun)
    if not only or "default-vtu" in only:
        run_variant(exe, work, "default-vtu", "wedge", {
            "End time": 720, "Output/Writers": "time series, base profile, events, vtu",
            "Output/Output interval": 20,
            "Output/Event output interval": 20}, rerun)
    table(True, work)


def thresholds(runs="default,sigma-x1.05,a-outside-0.015", record=False,
               work=""):
    """Finished runs recounted with other event thresholds (no new runs).

    Starts are the first accepted step above the threshold (events.csv
    interpolates them).

    runs: the runs recounted, A,B
    record: write events.thresholds and duration.* of results.csv
    """
    v0 = 50e-6
    rows = []
    for name in runs.split(","):
        folder = os.path.join(work, name)
        if not finished(folder):
            bench.die(f"{folder}: no finished run (the stage runs makes it)")
        ts = plot.series(folder)
        rates = run.base_profile(folder)
        for k in THRESHOLDS:
            found = events.detect(ts["time_s"], ts["max_slip_rate_m_per_s"],
                                  v0, k, rates)
            after = found[SKIP:]

            def mean(value):
                return sum(value(e) for e in after) / len(after) \
                    if after else math.nan
            rows.append(dict(
                run=name, threshold_v0=k,
                events_1000s=sum(1 for e in found if 0 <= e.start <= T_END),
                first_event_s=found[0].start if found else math.nan,
                recurrence_s=mean(lambda e: e.recurrence),
                rupture_width_m=mean(lambda e: e.width),
                duration_s=mean(lambda e: e.duration)))
    fields = ["run", "threshold_v0", "events_1000s", "first_event_s",
              "recurrence_s", "rupture_width_m", "duration_s"]
    bench.write_table(os.path.join(HERE, "thresholds.csv"), fields, [
        {k: (f"{r[k]:.6g}" if isinstance(r[k], float) else r[k])
         for k in fields} for r in rows])

    def fmt(x, spec):
        return "–" if x != x else format(x, spec)
    text = bench.markdown(
        ["run", "event: max V above", "events in 1000 s", "first event [s]",
         "recurrence, events 9 - [s]", "rupture width [m]", "duration [s]"],
        [[f"`{r['run']}`", f"{r['threshold_v0']:g} v0", r["events_1000s"],
          fmt(r["first_event_s"], ".1f"), fmt(r["recurrence_s"], ".3f"),
          fmt(r["rupture_width_m"], ".3f"), fmt(r["duration_s"], ".3f")]
         for r in rows])
    with open(os.path.join(HERE, "thresholds.md"), "w",
              encoding="utf-8") as f:
        f.write(LICENCE + text)
    print(text, end="")
    if record:
        default = [r for r in rows if r["run"] == "default"
                   and r["threshold_v0"] <= 25]
        counts = [r["events_1000s"] for r in default]
        duration = {r["threshold_v0"]: r["duration_s"] for r in default}
        from rsfcycle import results
        old = results.read_results(os.path.join(HERE, "results.csv"))
        bench.record(NAME, [
            ("events.thresholds", f"{min(counts)} – {max(counts)}", "",
             old["events.thresholds"].description),
            ("duration.10v0", f"{duration[10]:.3f}", "s",
             old["duration.10v0"].description),
            ("duration.2v0", f"{duration[2]:.3f}", "s",
             old["duration.2v0"].description)])


# The normal stress on the base from VTU snapshots: rsfcycle holds the
# friction's normal stress at the static gravity equilibrium's (doc/model.md
# §5); the loaded wedge's own stress field on the base is
# sigma_n = -sigma_yy at the midpoint of every base face (rotated frame, base
# on y = 0), elastic (K = 50 kPa, nu = 0.3) plus Kelvin-Voigt (eta_b =
# eta_s = 1 / 10 kPa s) stress of the bilinear displacement and velocity.
BULK, POISSON = 5e4, 0.3
SHEAR = 3 * BULK * (1 - 2 * POISSON) / (2 * (1 + POISSON))
LAME = BULK - 2 * SHEAR / 3
VISCOSITY = {0: 1e3, 1: 1e4}  # material id -> eta_s = eta_b [Pa s]
DTYPES = {"Float32": "<f4", "Float64": "<f8", "Int32": "<i4", "UInt8": "u1",
          "Int64": "<i8", "UInt32": "<u4"}
PATCH_ALONG_BASE = (0.163, 0.363)  # [m]


def read_vtu(path):
    """The DataArrays of a deal.II VTU file (binary, zlib-compressed), and
    its TIME."""
    import numpy as np
    text = bench.text(path)
    arrays = {}
    pattern = (r'<DataArray type="(\w+)"(?: Name="([^"]*)")?'
               r'(?: NumberOfComponents="(\d+)")? format="binary">\s*(\S+)'
               r'\s*</DataArray>')
    for m in re.finditer(pattern, text):
        kind, name, components, data = m.groups()
        n_blocks = struct.unpack("<I", base64.b64decode(data[:8])[:4])[0]
        header_b64 = 4 * ((4 * (3 + n_blocks) + 2) // 3)
        header = struct.unpack(f"<{3 + n_blocks}I",
                               base64.b64decode(data[:header_b64]))
        body = base64.b64decode(data[header_b64:])
        raw, offset = b"", 0
        for size in header[3:]:
            raw += zlib.decompress(body[offset:offset + size])
            offset += size
        a = np.frombuffer(raw, dtype=DTYPES[kind])
        if components:
            a = a.reshape(-1, int(components))
        arrays[name or "Points"] = a
    time = re.search(r'Name="TIME"[^>]*>\s*([0-9.eE+-]+)', text)
    arrays["TIME"] = float(time.group(1)) if time else math.nan
    return arrays


def base_stress(path):
    """(rows of (s, sigma_n, tau) at the midpoints of the base faces,
    sorted by s; the snapshot's time)."""
    import numpy as np
    d = read_vtu(path)
    points = d["Points"][:, :2].astype(float)
    u = d["displacement"][:, :2].astype(float)
    v = d["velocity"][:, :2].astype(float)
    cells = d["connectivity"].reshape(-1, 4)
    material = d["material_id"]
    corners = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], float)
    rows = []
    for c, cell in enumerate(cells):
        x = points[cell]
        on_base = np.abs(x[:, 1]) < 1e-9
        if on_base.sum() != 2:
            continue
        xi = corners[on_base].mean(axis=0)  # midpoint of the base face
        dn = np.array([[-(1 - xi[1]), -(1 - xi[0])], [1 - xi[1], -xi[0]],
                       [xi[1], xi[0]], [-xi[1], 1 - xi[0]]])
        dndx = dn @ np.linalg.inv(x.T @ dn)
        gu, gv = u[cell].T @ dndx, v[cell].T @ dndx
        e, ed = 0.5 * (gu + gu.T), 0.5 * (gv + gv.T)
        mid = material[cell[0]] if len(material) == len(points) \
            else material[c]
        eta = VISCOSITY[int(round(float(mid)))]
        syy = (LAME * np.trace(e) + 2 * SHEAR * e[1, 1]
               + eta / 3 * np.trace(ed) + 2 * eta * ed[1, 1])
        sxy = 2 * SHEAR * e[0, 1] + 2 * eta * ed[0, 1]
        rows.append((x[on_base, 0].mean(), -syy, sxy))
    rows.sort()
    return np.array(rows), d["TIME"]


def snapshots(folder):
    """The VTU snapshots of a run folder, in order."""
    where = os.path.join(folder, "solution")
    if not os.path.isdir(where):
        bench.die(f"{where}: no snapshots (a run with vtu in Output/Writers, "
                  "e.g. the stage runs' default-vtu)")
    return [os.path.join(where, f) for f in sorted(os.listdir(where))
            if f.endswith(".vtu")]


def normal_stress(run_folder, times="0,200,400,500,600,700"):
    """The loaded wedge's normal stress on its base over the equilibrium's.

    sigma_n along the base at the snapshots nearest to the times, its
    ratio to the snapshot at t = 0, and that ratio's mean and range on the
    patch (the row normal_stress.loaded).

    run_folder: a run with VTU snapshots (WORK/default-vtu)
    times: snapshot times [s], the nearest are taken
    """
    files = {read_vtu(f)["TIME"]: f for f in snapshots(run_folder)}
    ref, _ = base_stress(files[min(files)])
    patch = (ref[:, 0] >= PATCH_ALONG_BASE[0]) & \
        (ref[:, 0] <= PATCH_ALONG_BASE[1])
    columns = []
    for t in (float(x) for x in times.split(",")):
        rows, time = base_stress(files[min(files, key=lambda k: abs(k - t))])
        columns.append((time, rows[:, 1] / ref[:, 1]))
    print("s [m] along the base | sigma_n at t = 0 [Pa] | ratio to t = 0 "
          "at t = " + ", ".join(f"{c[0]:g}" for c in columns))
    for i in range(0, len(ref), max(1, len(ref) // 40)):
        print(f"{ref[i, 0]:.3f} {ref[i, 1]:8.1f} "
              + " ".join(f"{c[1][i]:6.3f}" for c in columns))
    for time, ratio in columns:
        print(f"t = {time:g} s: ratio on the patch mean "
              f"{ratio[patch].mean():.4f}, range {ratio[patch].min():.4f} "
              f"- {ratio[patch].max():.4f}; s < 0.45 m mean "
              f"{ratio[ref[:, 0] < 0.45].mean():.4f}")


def sensitivity_figure(rows):
    """figures/sensitivity.png: every variant's count, first event,
    recurrence, width, slip and uplift at 30 cm against the references."""
    from rsfcycle.plot import _pyplot, savefig
    plt = _pyplot()
    by = {r["name"]: r for r in rows}
    labels = [r["name"] + (" *" if r["scene"] == "mesh" else "")
              for r in rows]
    y = list(range(len(rows)))[::-1]
    colours = {"reference": "black", "control": "black", "choice": "tab:blue",
               "table": "tab:green", "sensitivity": "tab:gray"}
    panels = [("events_1000s", "events starting in [0, 1000] s"),
              ("first_event_s", "first event [s]"),
              ("recurrence_s", "recurrence (mean, events 9 -) [s]"),
              ("rupture_width_m", "rupture width [m]"),
              ("slip_um", "slip per event [µm]"),
              ("uplift_30cm_um", "uplift per event at 30 cm [µm]")]
    fig, axes = plt.subplots(1, len(panels),
                             figsize=(19, 0.36 * len(rows) + 2.2),
                             sharey=True)
    for ax, (k, title) in zip(axes, panels):
        ax.barh(y, [r[k] for r in rows],
                color=[colours[r["group"]] for r in rows], alpha=0.75)
        for ref, ls in (("default", "-"), ("mesh-default", ":")):
            if ref in by:
                ax.axvline(by[ref][k], color="black", ls=ls, lw=0.8)
        values = [r[k] for r in rows if r[k] == r[k]]  # (no NaN)
        if k == "events_1000s":
            ax.axvline(PAPER_EVENTS, color="tab:red", lw=1.5,
                       label=f"paper: {PAPER_EVENTS}")
            ax.legend(fontsize=8, loc="lower right")
            ax.set_xlim(min(min(values), PAPER_EVENTS) - 10,
                        max(values) + 5)
        elif k != "uplift_30cm_um":
            span = max(values) - min(values)
            ax.set_xlim(max(0, min(values) - 0.3 * span),
                        max(values) + 0.1 * span)
        ax.set_title(title, fontsize=9)
        ax.grid(axis="x", alpha=0.3)
    axes[0].set_yticks(y)
    axes[0].set_yticklabels(labels, fontsize=8)
    fig.suptitle("2D laboratory wedge, one reading at a time (2 + 6 "
                 "refinements, Refinement distance 3: built-in 16,612 "
                 "unknowns; * mesh-file scene, 9,780 unknowns, dotted line "
                 "its reference); δ = ε = 1e-4\n"
                 "blue: modelling choices, green: Table 1 within its "
                 "stated ranges, grey: Table 1 values without a range; "
                 "solid line: prm/wedge-2d.prm", fontsize=9)
    fig.tight_layout()
    savefig(fig, os.path.join(FIGURES, "sensitivity.png"), dpi=110)


def normal_stress_figure(rows, vtu):
    """figures/normal-stress.png: (a) the loaded wedge's normal stress on
    the base over the fixed one (the snapshots of `vtu`), (b) events and
    recurrence against a prescribed normal stress."""
    from rsfcycle.plot import _pyplot, savefig
    plt = _pyplot()
    by = {r["name"]: r for r in rows}
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 4.4))
    files = snapshots(vtu)
    ref, _ = base_stress(files[0])
    for f in files[::5] + [files[-1]]:
        a, t = base_stress(f)
        ax1.plot(a[:, 0], a[:, 1] / ref[:, 1], lw=1, label=f"t = {t:.0f} s")
    ax1.axvspan(*PATCH_ALONG_BASE, color="orange", alpha=0.15, label="patch")
    ax1.set_xlim(0, 1.0)
    ax1.set_ylim(0.8, 1.5)
    ax1.set_xlabel("position along the base from the trench [m]")
    ax1.set_ylabel("σn of the stress field / σn used by friction")
    ax1.set_title("(a) default run: normal stress the loaded wedge exerts "
                  "on the base\n(-σyy at the base faces) relative to the "
                  "fixed gravity-equilibrium value", fontsize=9)
    ax1.legend(fontsize=7, ncol=2)
    ax1.grid(alpha=0.3)
    points = sorted(((SIGMA_LEVEL[n], by[n]) for n in SIGMA_LEVEL if n in by),
                    key=lambda p: p[0])
    x = [p[0] for p in points]
    ax2.plot(x, [p[1]["events_1000s"] for p in points], "o-",
             color="tab:blue", label="events starting in [0, 1000] s")
    ax2.axhline(PAPER_EVENTS, color="tab:red", lw=1,
                label=f"paper: {PAPER_EVENTS}")
    ax2.set_xlabel("prescribed σn on the patch / gravity equilibrium's")
    ax2.set_ylabel("events in 1000 s", color="tab:blue")
    ax3 = ax2.twinx()
    ax3.plot(x, [p[1]["recurrence_s"] for p in points], "s--",
             color="tab:green", label="recurrence")
    ax3.set_ylabel("recurrence (mean, events 9 -) [s]", color="tab:green")
    for level, r in points:
        ax2.annotate(r["name"], (level, r["events_1000s"]), fontsize=7,
                     xytext=(4, 4), textcoords="offset points")
    ax2.set_title("(b) mesh-file scene (9,780 unknowns), normal stress "
                  "prescribed as a multiple of ρ g h", fontsize=9)
    ax2.legend(fontsize=8, loc="upper right")
    ax2.grid(alpha=0.3)
    fig.suptitle("2D laboratory wedge, 2 + 6 refinements at Refinement "
                 "distance 3 (built-in: 16,612 unknowns), δ = ε = 1e-4",
                 fontsize=9)
    fig.tight_layout()
    savefig(fig, os.path.join(FIGURES, "normal-stress.png"), dpi=110)


def figures(work=""):
    """figures/sensitivity.png; figures/normal-stress.png from
    WORK/default-vtu's snapshots."""
    rows = collect(work)
    os.makedirs(FIGURES, exist_ok=True)
    sensitivity_figure(rows)
    vtu = os.path.join(work, "default-vtu")
    if os.path.isdir(os.path.join(vtu, "solution")):
        normal_stress_figure(rows, vtu)
    else:
        print(f"{vtu}: no snapshots, figures/normal-stress.png kept")


def list_():
    """The variants and their readings."""
    for name, base, group, choice, reading, _ in VARIANTS:
        print(f"{name} [{base}, {group}] {choice}: {reading}")


if __name__ == "__main__":
    raise SystemExit(bench.cli(__doc__, NAME, [
        list_, runs, table, thresholds, figures, normal_stress]))
