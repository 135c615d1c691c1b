# SPDX-License-Identifier: LGPL-2.1-or-later
"""tandem (github.com/TEAR-ERC/tandem: discontinuous Galerkin in a finite
box, discrete Green's functions) as a peer for SEAS BP3-QD: its parameter
file, and its output converted to the benchmark's files.

    python3 -m rsfcycle.peers.tandem input OUTDIR --mesh bp3.msh --dip 60 --sense thrust
    python3 -m rsfcycle.peers.tandem convert RUN

The input is tandem's own BP3 example (examples/tandem/2d/bp3.lua, the
scenario bp3_d{dip}_{reverse|normal}) with the benchmark's outputs: the 12
fault stations fltst_dpXXX (down-dip distance in 100 m), the maximum slip
rate (tandem's fault_scalar_output, global_) and the surface stations at
x = +8 and -8 km (srfst_fn+08, srfst_fn-08).

tandem writes CSV files: a '#' title line, a quoted header ("Time",
"state", "slip0", "traction0", "slip-rate0", "normal-stress" on the fault;
"Time", "u0", "u1" at a domain probe; "Time", "VMax" for the scalar). On
the fault, `state` is tandem's state variable psi (psi = f0 + b ln(V0
theta / L)), `traction0` the absolute shear traction, negative in thrust,
`normal-stress` the absolute normal stress [MPa], positive in compression;
slip and slip rate are positive in thrust. At a probe, y is up.

The conversion writes the files in the layout rsfcycle writes for BP3
(doc/seas.md): fltst_dpXXX `t slip slip_rate shear_stress normal_stress
state` (slip rate and state as log10, the shear stress positive in
thrust, MPa), srfst_fn+08 and srfst_fn-08 `t disp_1 disp_2 vel_1 vel_2`
(disp_2 positive down, the velocities by finite differences of the
displacement), and global.dat `t max_slip_rate` (log10), the maximum slip
rate that BP3's files do not carry.
"""

import argparse
import glob
import math
import os
import sys

# the benchmark's fault stations: down-dip distances in units of 100 m
STATIONS = (0, 25, 50, 75, 100, 125, 150, 175, 200, 250, 300, 350)
# the surface stations tandem writes: name -> x [km]
SURFACE = {"fn+08": 8.0, "fn-08": -8.0}
# BP3's friction constants (b, L [m], f0, V0 [m/s]): psi -> log10 theta
BP3_FRICTION = {"b": 0.015, "L": 0.008, "f0": 0.6, "V0": 1e-6}
# 1500 years of 365 days [s], BP3-QD's duration
FINAL_TIME = 4.7304e10
# the longest time between two output rows between events [s] (0.3 yr)
SAMPLE = 9460800.0


def scenario(dip=60, sense="thrust"):
    """The name of tandem's bp3.lua scenario: bp3_d{dip}_reverse (thrust)
    or bp3_d{dip}_normal; bp3_d90 at 90 degrees (thrust and normal
    faulting mirror each other)."""
    if sense not in ("thrust", "normal"):
        raise ValueError(f"sense '{sense}': thrust or normal")
    if dip == 90:
        return "bp3_d90"
    return f"bp3_d{dip}_{'reverse' if sense == 'thrust' else 'normal'}"


def fault_probes(dip=60):
    """The fault stations as (name, x, y) in tandem's coordinates [km]: the
    fault runs from the origin down dip, y up."""
    angle = math.radians(dip)
    return [(f"dp{d:03d}", d / 10 * math.cos(angle), -d / 10 * math.sin(angle))
            for d in STATIONS]


def input_toml(mesh, dip=60, sense="thrust", final_time=FINAL_TIME,
               resume=False, sample=SAMPLE):
    """The text of tandem's parameter file for BP3-QD: the mesh file (a
    name relative to the run folder), the scenario (scenario()), the
    discrete Green's functions (mode QDGreen) kept in gf/ for a second run
    on the same mesh, the time loop checkpointed to checkpoint/ every 10
    CPU minutes (resume: start from the last one), and the outputs at most
    `sample` seconds apart."""
    probes = ",\n".join(
        f'    {{ name = "{name}", x = [{x:.15g}, {y:.15g}] }}'
        for name, x, y in fault_probes(dip))
    surface = ",\n".join(
        f'    {{ name = "{name}", x = [{x:.1f}, 0.0] }}'
        for name, x in SURFACE.items())
    load = ('load_directory = "checkpoint/last_checkpoint.txt"\n'
            if resume else "")
    return f"""final_time = {final_time:.0f}
mesh_file = "{mesh}"
lib = "bp3.lua"
scenario = "{scenario(dip, sense)}"
mode = "QDGreen"
type = "elasticity"
ref_normal = [1, 0]
boundary_linear = true

[gf_checkpoint]
prefix = "gf"

[ts_checkpoint]
freq_cputime = 10
{load}
[fault_probe_output]
prefix = "fltst_"
t_max = {sample:.0f}
probes = [
{probes}
]

[fault_scalar_output]
prefix = "global_"
t_max = {sample:.0f}

[domain_probe_output]
prefix = "srfst_"
t_max = {sample:.0f}
probes = [
{surface}
]
"""


def write_input(outdir, mesh, dip=60, sense="thrust", final_time=FINAL_TIME,
                resume=False):
    """Write OUTDIR/bp3.toml (input_toml()); returns its path."""
    path = os.path.join(outdir, "bp3.toml")
    with open(path, "w", encoding="utf-8") as f:
        f.write(input_toml(mesh, dip, sense, final_time, resume))
    return path


def read_csv(path):
    """(column names, rows as a numpy array) of one of tandem's CSV files.

    A row cut short by a run still writing is left out. A run continued
    from a checkpoint appends rows from the checkpoint's time on, after
    the rows the interrupted run wrote past it: where the time goes back,
    the rows at and after the new row's time are dropped, so that the
    continued run's rows are kept and the times increase."""
    import numpy as np
    names, rows = [], []
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("#"):
                continue
            if line.startswith('"'):
                names = [w.strip().strip('"') for w in line.split(",")]
                continue
            try:
                row = [float(w) for w in line.split(",")]
            except ValueError:
                continue
            if names and len(row) != len(names):
                continue
            while rows and rows[-1][0] >= row[0]:
                rows.pop()
            rows.append(row)
    if not names:
        raise ValueError(f"{path}: no header line (is it tandem's output?)")
    return names, np.array(rows).reshape(-1, len(names))


def _column(names, rows, name, path):
    if name not in names:
        raise ValueError(f"{path}: no column '{name}' (columns: "
                         f"{', '.join(names)})")
    return rows[:, names.index(name)]


def fault_station(path, friction=BP3_FRICTION):
    """A fault station's file as an array of rows (t [s], slip [m], log10
    |slip rate| [m/s], shear stress [MPa] positive in thrust, normal stress
    [MPa] positive in compression, log10 state [s]): theta = L / V0 exp((psi
    - f0) / b) with the friction constants given (BP3's by default)."""
    import numpy as np
    names, rows = read_csv(path)
    psi = _column(names, rows, "state", path)
    log10_theta = (math.log10(friction["L"] / friction["V0"]) +
                   (psi - friction["f0"]) / (friction["b"] * math.log(10)))
    rate = np.abs(_column(names, rows, "slip-rate0", path))
    return np.column_stack([
        rows[:, 0], _column(names, rows, "slip0", path),
        np.log10(np.maximum(rate, 1e-300)),
        -_column(names, rows, "traction0", path),
        _column(names, rows, "normal-stress", path), log10_theta])


def surface_station(path):
    """A surface probe's file as an array of rows (t [s], disp_1 [m]
    positive in +x, disp_2 [m] positive down, vel_1, vel_2 [m/s]); the
    velocities are finite differences of the displacement (tandem's probe
    has none), second order inside, first order at the ends."""
    import numpy as np
    names, rows = read_csv(path)
    t = rows[:, 0]
    u1 = _column(names, rows, "u0", path)
    u2 = -_column(names, rows, "u1", path)
    if len(t) > 1:
        v1, v2 = np.gradient(u1, t), np.gradient(u2, t)
    else:
        v1, v2 = np.zeros_like(u1), np.zeros_like(u2)
    return np.column_stack([t, u1, u2, v1, v2])


def max_slip_rate(path):
    """(t [s], maximum slip rate [m/s]) of tandem's global_.csv."""
    names, rows = read_csv(path)
    return rows[:, 0], _column(names, rows, "VMax", path)


def _write(path, fields, rows, keys):
    """A SEAS-style file: '# key=value' lines, the field line, the rows."""
    with open(path, "w", encoding="utf-8") as f:
        for key, value in keys.items():
            f.write(f"# {key}={value}\n")
        f.write(" ".join(fields) + "\n")
        for row in rows:
            f.write(" ".join(f"{v:.15e}" for v in row) + "\n")
    return path


def write_seas(run, out=None, version="", element_size=""):
    """Convert the tandem run folder RUN into BP3's files in OUT (RUN by
    default): fltst_dpXXX for each fltst_dpXXX.csv, srfst_fn+08 and
    srfst_fn-08, global.dat (module documentation). `version` (tandem's
    commit) and `element_size` (e.g. '250 m, degree 4') go into the
    headers. Works on a run that is still going. Returns the paths
    written."""
    import numpy as np
    out = out or run
    os.makedirs(out, exist_ok=True)
    keys = {"problem": "SEAS Benchmark BP3-QD", "code": "tandem",
            "version": version, "element_size": element_size}
    written = []
    for path in sorted(glob.glob(os.path.join(run, "fltst_dp*.csv"))):
        name = os.path.basename(path)[:-len(".csv")]
        written.append(_write(
            os.path.join(out, name),
            ["t", "slip", "slip_rate", "shear_stress", "normal_stress",
             "state"], fault_station(path),
            dict(keys, location=f"on fault, {int(name[8:]) / 10:g} km down "
                 "dip (converted from tandem)")))
    for name in SURFACE:
        path = os.path.join(run, f"srfst_{name}.csv")
        if os.path.exists(path):
            written.append(_write(
                os.path.join(out, f"srfst_{name}"),
                ["t", "disp_1", "disp_2", "vel_1", "vel_2"],
                surface_station(path),
                dict(keys, location=f"off fault, observation point {name} "
                     "(converted from tandem)")))
    path = os.path.join(run, "global_.csv")
    if os.path.exists(path):
        t, v = max_slip_rate(path)
        written.append(_write(
            os.path.join(out, "global.dat"), ["t", "max_slip_rate"],
            np.column_stack([t, np.log10(np.maximum(v, 1e-300))]),
            dict(keys, location="frictional domain (converted from "
                 "tandem)")))
    if not written:
        raise ValueError(f"{run}: no tandem output (fltst_dp*.csv, "
                         "srfst_*.csv, global_.csv)")
    return written


def main(argv=None):
    """python3 -m rsfcycle.peers.tandem input|convert ..."""
    parser = argparse.ArgumentParser(
        prog="python3 -m rsfcycle.peers.tandem",
        description="tandem's BP3-QD parameter file, and its output as "
        "BP3's files.")
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("input", help="write OUTDIR/bp3.toml and print the "
                       "scenario's name")
    p.add_argument("outdir")
    p.add_argument("--mesh", required=True,
                   help="the mesh file, relative to OUTDIR")
    p.add_argument("--dip", type=int, choices=(30, 60, 90), default=60)
    p.add_argument("--sense", choices=("thrust", "normal"), default="thrust")
    p.add_argument("--final-time", type=float, default=FINAL_TIME,
                   help="s (default: 1500 years of 365 days)")
    p.add_argument("--resume", action="store_true",
                   help="continue from OUTDIR/checkpoint/last_checkpoint.txt")
    p = sub.add_parser("convert", help="write BP3's files from RUN's CSV "
                       "files, into RUN")
    p.add_argument("run")
    p.add_argument("--version", default="", help="tandem's commit")
    p.add_argument("--element-size", default="",
                   help="e.g. '250 m, degree 4'")
    args = parser.parse_args(argv)
    if args.command == "input":
        write_input(args.outdir, args.mesh, args.dip, args.sense,
                    args.final_time, args.resume)
        print(scenario(args.dip, args.sense))
        return 0
    try:
        written = write_seas(args.run, version=args.version,
                             element_size=args.element_size)
    except (OSError, ValueError) as error:
        print(error, file=sys.stderr)
        return 1
    print(f"{args.run}: {len(written)} files")
    return 0


if __name__ == "__main__":
    sys.exit(main())
