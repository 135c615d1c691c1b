# SPDX-License-Identifier: LGPL-2.1-or-later
"""SCycle (https://github.com/kali-allison/SCycle) as the peer of SEAS
BP1-FD: its input for the benchmark, its output read and reduced to the
event catalogue (rsfcycle.catalog), a time series and SEAS-style files.

    python3 -m rsfcycle.peers.scycle input RUN [--h 0.05] ...
    python3 -m rsfcycle.peers.scycle stats RUN [--csv SERIES.csv] [--seas DIR]

`input` writes RUN/bp1fd.in and the PETSc binary grid and initial
conditions RUN/ICs/{y,z,psi,prestress,tauQS,tau} (and RUN/output/),
following SCycle's SEAS_benchmarks/BP1 (BP1.in, createICs.m) with the
momentum balance switched to quasidynamic_and_dynamic. `stats` reads a
finished run: the event table from the per-step log (SCycle built with
VERBOSE=1), the fault profiles of output/data_1D.h5 (h5py, Debian's
python3-h5py), the series for the comparison (--csv) and SEAS-style files
(--seas: fltst_dpXXX and devol.dat as BP1 names them).

SCycle's units: lengths km, stresses MPa, mu GPa, rho g/cm^3, slip m,
velocities m/s, time s. The grid: spacing h on [0, hz] in depth and
[0, hy] across, then nz2 (ny2) cells growing by a constant ratio to lz
(ly) (createICs.m's grid helper is not in SCycle's repository). Rate and
state acts on 0 - 40 km, the fault below creeps at V_p (`lockedVals`).
Quasi-dynamic phases use radiation damping and RK43; SCycle switches to
the wave equation when the maximum slip rate exceeds trigger_qd2fd (once
it has been below limit_qd) and back below trigger_fd2qd (once above
limit_fd).
"""

import argparse
import os
import re
import struct
import sys

from rsfcycle import catalog

URL = "https://github.com/kali-allison/SCycle"
COMMIT = "74a132f6d280f550dd7469faa7b1039a52b24156"
YEAR = catalog.YEAR  # SCycle's output is in s; years of 365.25 days

# BP1 in SCycle's units (Erickson et al. 2020; BP1-FD has the same values)
RHO = 2.670  # g/cm^3
CS = 3.464  # km/s
MU = RHO * CS ** 2  # GPa: 32.03812032
SIGMA = 50.0  # MPa
A0, AMAX, B = 0.010, 0.025, 0.015
H, HTRANS = 15.0, 3.0  # km
DC = 0.008  # m
F0, V0 = 0.6, 1e-6
VP = 1e-9
VINIT = VP
WF = 40.0  # km: rate and state on 0 - WF, creep at VP below
ETA = 0.5 * (MU * RHO) ** 0.5  # MPa s/m: mu/(2 c_s) = 4.62444
STATION_DEPTHS_KM = (0, 2.5, 5, 7.5, 10, 12.5, 15, 17.5, 20, 25, 30, 35)
PROFILE_DEPTHS_M = tuple(500.0 * i for i in range(81))  # devol.dat: 0-40 km
VEC_FILE_CLASSID = 1211214  # PETSc's binary Vec
LOG_LINE = re.compile(r"^(\d+): t = (\S+) s, dt = (\S+) (quasidynamic|fully "
                      r"dynamic) \| allowed = (\d), maxVel = ([^,\s]+)")


def grid(h, extent, length, stretched):
    """(coordinates [km], growth ratio): spacing h on [0, extent], then
    `stretched` cells growing by a constant ratio r (the first h r) to
    `length`. Raises ValueError if extent is no multiple of h or the
    ratio cannot be found."""
    import numpy as np
    n1 = int(round(extent / h))
    if abs(n1 * h - extent) > 1e-9:
        raise ValueError(f"{extent} km is no multiple of h = {h} km")
    rest = length - extent

    def f(r):
        return h * r * (r ** stretched - 1.0) / (r - 1.0) - rest

    lo, hi = 1.0 + 1e-12, 2.0
    if not f(lo) < 0 < f(hi):
        raise ValueError(f"{stretched} stretched cells cannot reach "
                         f"{length} km")
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if f(mid) > 0:
            hi = mid
        else:
            lo = mid
    r = 0.5 * (lo + hi)
    x = np.concatenate([h * np.arange(n1 + 1),
                        extent + np.cumsum(h * r ** np.arange(1, stretched
                                                              + 1))])
    x[-1] = length
    return x, r


def petsc_write(path, values):
    """Write a PETSc binary Vec (big-endian class id, size, doubles)."""
    import numpy as np
    v = np.asarray(values, dtype=">f8").ravel()
    with open(path, "wb") as f:
        f.write(struct.pack(">ii", VEC_FILE_CLASSID, v.size))
        f.write(v.tobytes())


def petsc_read(path):
    """A PETSc binary Vec as a numpy array."""
    import numpy as np
    with open(path, "rb") as f:
        classid, size = struct.unpack(">ii", f.read(8))
        if classid != VEC_FILE_CLASSID:
            raise ValueError(f"{path}: not a PETSc binary Vec")
        return np.frombuffer(f.read(8 * size), dtype=">f8").astype(float)


def initial_conditions(z):
    """BP1's a, the state psi (steady sliding at V_init under tau_0) and
    tau_0 [MPa] at the depths z [km]: a dict a, psi, tau0 (a number)."""
    import numpy as np
    a = np.interp(z, [0.0, H, H + HTRANS, max(z[-1], H + HTRANS)],
                  [A0, A0, AMAX, AMAX])
    tau0 = (SIGMA * AMAX * np.arcsinh(VINIT / (2 * V0) * np.exp(
        (F0 + B * np.log(V0 / VINIT)) / AMAX)) + ETA * VINIT)
    psi = a * np.log(2 * V0 / VINIT * np.sinh((tau0 - ETA * VINIT)
                                              / (a * SIGMA)))
    return {"a": a, "psi": psi, "tau0": tau0}


DEFAULTS = {
    "h": 0.05, "hz": 45.0, "hy": 10.0, "lz": 500.0, "ly": 500.0,
    "nz2": 150, "ny2": 150,
    # SCycle does not stop at maxTime: maxNumCycles ends the run
    "max_time": 600 * YEAR, "max_step_count": 1e8,
    "stride1d_qd": 10, "stride1d_fd": 20, "stride2d_qd": 0, "stride2d_fd": 0,
    "trigger_qd2fd": 1e-3, "trigger_fd2qd": 1e-3, "limit_qd": 1e-5,
    "limit_fd": 1e-1, "time_step_tol": 1e-7,
    "momentum": "quasidynamic_and_dynamic",
    # 2 N phases: N = 3 stops right after the dynamic phase of event 3
    "max_num_cycles": 3,
}


def input_text(input_dir, output_dir, ny, nz, ry, rz, **options):
    """The text of the .in file for the grid of ny x nz nodes (growth
    ratios ry, rz) with the options of DEFAULTS (overridden by
    `options`)."""
    o = dict(DEFAULTS, **options)
    eps = 1e-3 * o["h"]  # the 0/0 of a zero-width interval off every node
    return f"""# SCEC SEAS BP1-FD for SCycle (rsfcycle.peers.scycle)
# after SCycle's SEAS_benchmarks/BP1/BP1.in; grid h = {o['h'] * 1e3:.1f} m
# Ny = {ny} (uniform to {o['hy']} km, ratio {ry:.5f})
# Nz = {nz} (uniform to {o['hz']} km, ratio {rz:.5f})

inputDir = {input_dir}
outputDir = {output_dir}

Ny = {ny}
Nz = {nz}
Ly = {o['ly']}
Lz = {o['lz']}
order = 4
gridSpacingType = variableGridSpacing

problemType = strikeSlip
bulkDeformationType = linearElastic
momentumBalanceType = {o['momentum']}
vL = {VP:g}

# rate and state on 0 - {WF:g} km, creep at vL below (locked = -1)
lockedVals = [0 0 -1 -1]
lockedDepths = [0 {WF + eps:.6f} {WF + eps:.6f} {o['lz']}]
stateLaw = agingLaw
f0 = {F0}
v0 = {V0:g}
DcVals = [{DC} {DC}]
DcDepths = [0 {o['lz']}]
aVals = [{A0} {A0} {AMAX} {AMAX}]
aDepths = [0 {H} {H + HTRANS} {o['lz']}]
bVals = [{B} {B}]
bDepths = [0 {o['lz']}]
sNVals = [{SIGMA} {SIGMA}]
sNDepths = [0 {o['lz']}]
rootTol = 1e-12

muVals = [{MU:.8f} {MU:.8f}]
muDepths = [0 {o['lz']}]
rhoVals = [{RHO} {RHO}]
rhoDepths = [0 {o['lz']}]
linSolverTrans = MUMPSCHOLESKY
momBal_computeSxz = 0

# quasi-dynamic phases: free surface everywhere but the fault (BP1.in)
momBal_bcR_qd = freeSurface
momBal_bcT_qd = freeSurface
momBal_bcB_qd = freeSurface
momBal_bcL_qd = symmFault
# fully dynamic phases: free surface on top, absorbing far sides
momBal_bcR_fd = outGoingCharacteristics
momBal_bcT_fd = freeSurface
momBal_bcB_fd = outGoingCharacteristics
momBal_bcL_fd = symmFault

# switching on the maximum slip rate [m/s]
trigger_qd2fd = {o['trigger_qd2fd']:g}
trigger_fd2qd = {o['trigger_fd2qd']:g}
limit_qd = {o['limit_qd']:g}
limit_fd = {o['limit_fd']:g}

timeIntegrator = RK43
timeControlType = PID
timeIntInds = [psi slip]
normType = L2_absolute
timeStepTol = {o['time_step_tol']:g}
initDeltaT = 1e-3
minDeltaT = 1e-3
maxDeltaT = 3.15576e7
initTime = 0
maxTime = {o['max_time']:.6e}
maxStepCount = {o['max_step_count']:.0f}
stride1D_qd = {o['stride1d_qd']}
stride2D_qd = {o['stride2d_qd']}
stride1D_fd = {o['stride1d_fd']}
stride2D_fd = {o['stride2d_fd']}
saveChkpts = 1
strideChkpt = 100000
strideChkpt_fd = 100000
restartFromChkpt = 0
maxNumCycles = {o['max_num_cycles']}
"""


def write_input(folder, **options):
    """Write folder/bp1fd.in, folder/ICs/ (grid and initial conditions)
    and create folder/output/ for the options of DEFAULTS (overridden by
    `options`). Returns a line with the grid and the initial values."""
    import numpy as np
    o = dict(DEFAULTS, **options)
    z, rz = grid(o["h"], o["hz"], o["lz"], o["nz2"])
    y, ry = grid(o["h"], o["hy"], o["ly"], o["ny2"])
    ic = initial_conditions(z)
    base = os.path.abspath(folder)
    input_dir = os.path.join(base, "ICs") + "/"
    output_dir = os.path.join(base, "output") + "/"
    os.makedirs(input_dir, exist_ok=True)
    os.makedirs(output_dir, exist_ok=True)
    # SCycle's body ordering: index = iy Nz + iz (Domain::setFields)
    petsc_write(input_dir + "y", np.repeat(y, len(z)))
    petsc_write(input_dir + "z", np.tile(z, len(y)))
    petsc_write(input_dir + "psi", ic["psi"])
    tau0 = np.full(len(z), ic["tau0"])
    petsc_write(input_dir + "prestress", tau0)  # with eta V_init
    petsc_write(input_dir + "tauQS", tau0)
    petsc_write(input_dir + "tau", tau0 - ETA * VINIT)
    with open(os.path.join(base, "bp1fd.in"), "w", encoding="utf-8") as f:
        f.write(input_text(input_dir, output_dir, len(y), len(z), ry, rz,
                           **options))
    return (f"{base}/bp1fd.in: Ny = {len(y)}, Nz = {len(z)}, "
            f"{len(y) * len(z)} nodes, ratios {ry:.5f}, {rz:.5f}, tau0 = "
            f"{ic['tau0']:.6f} MPa, eta = {ETA:.6f} MPa s/m")


def read_log(path):
    """Every time step of SCycle's screen output (built with VERBOSE=1):
    a dict of arrays step, t [s], dt [s], dynamic (bool: the wave
    equation) and vmax, the maximum slip rate on the fault [m/s]."""
    import numpy as np
    columns = {"step": [], "t": [], "dt": [], "dynamic": [], "vmax": []}
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            m = LOG_LINE.match(line)
            if m:
                columns["step"].append(int(m.group(1)))
                columns["t"].append(float(m.group(2)))
                columns["dt"].append(float(m.group(3)))
                columns["dynamic"].append(m.group(4) == "fully dynamic")
                columns["vmax"].append(float(m.group(6)))
    return {k: np.array(v) for k, v in columns.items()}


def read_profiles(folder):
    """The fault profiles of output/data_1D.h5 (every stride1D steps): a
    dict z [km] (output/data_context.h5), t [s], dynamic (bool), and per
    record and fault node slip [m], V [m/s], tau [MPa], psi. Needs h5py;
    raises ImportError with the package to install."""
    try:
        import h5py
    except ImportError as e:
        raise ImportError("reading SCycle's output needs h5py (Debian: "
                          "python3-h5py)") from e
    out = os.path.join(folder, "output")
    with h5py.File(os.path.join(out, "data_context.h5"), "r") as c:
        z = c["/fault/z"][:].ravel()
    with h5py.File(os.path.join(out, "data_1D.h5"), "r") as f:
        return {"z": z, "t": f["/time/time1D"][:].ravel(),
                "dynamic": f["/time/regime1D"][:].ravel() == 1,
                "slip": f["/fault/slip"][:, :, 0],
                "V": f["/fault/slipVel"][:, :, 0],
                "tau": f["/fault/tau"][:, :, 0],
                "psi": f["/fault/psi"][:, :, 0]}


def events(log, threshold=1e-3, merge=86400.0):
    """The completed events of the log (read_log()) by rsfcycle.catalog:
    rises above the threshold within `merge` seconds of an event's end
    belong to it (the dips around SCycle's switches)."""
    return catalog.detect(log["t"], log["vmax"], threshold, merge)


def event_table(log, found, profiles):
    """The events in Markdown: start [yr], interval, duration, dynamic
    steps, peak slip rate (every step, the log), and from the profile
    records the depth of the peak, the surface slip and the
    hypocentre."""
    import numpy as np
    t1, z, slip, v = (profiles["t"], profiles["z"], profiles["slip"],
                      profiles["V"])
    lines = [f"log: {len(log['t'])} steps to {log['t'][-1] / YEAR:.4f} yr, "
             f"{int(log['dynamic'].sum())} fully dynamic",
             f"profiles: {len(t1)} records, z[0] = {z[0]} km, dz(0) = "
             f"{1e3 * (z[1] - z[0]):.1f} m", "",
             "| # | start [yr] | interval [yr] | duration [s] | dynamic steps "
             "| peak V [m/s] | depth of peak V [km] | surface slip [m] | "
             "hypocentre [km] |", "|---|---|---|---|---|---|---|---|---|"]
    previous = None
    for k, e in enumerate(found, 1):
        i = np.searchsorted(log["t"], e.start)
        j = np.searchsorted(log["t"], e.end)
        ks = min(int(np.searchsorted(t1, e.start)), len(t1) - 1)
        ke = min(int(np.searchsorted(t1, e.end)), len(t1) - 1)
        kb = max(ks - 1, 0)  # the record before the start
        segment = v[kb:ke + 1]
        depth = z[np.unravel_index(np.argmax(segment), segment.shape)[1]]
        interval = "" if previous is None else \
            f"{(e.start - previous) / YEAR:.3f}"
        previous = e.start
        lines.append(f"| {k} | {e.start / YEAR:.4f} | {interval} | "
                     f"{e.end - e.start:.1f} | "
                     f"{int(log['dynamic'][i:j + 1].sum())} | {e.peak:.4f} | "
                     f"{depth:.2f} | {slip[ke, 0] - slip[kb, 0]:.4f} | "
                     f"{z[np.argmax(v[ks])]:.2f} |")
    return "\n".join(lines) + "\n"


def write_series(path, log, profiles):
    """The series of the comparison: t_s, max_slip_rate [m/s] at every
    step (the log) and surface_slip [m] (the shallowest fault node,
    linear in time between the profile records)."""
    import numpy as np
    surface = np.interp(log["t"], profiles["t"], profiles["slip"][:, 0])
    with open(path, "w", encoding="utf-8") as f:
        f.write("t_s,max_slip_rate,surface_slip\n")
        for row in zip(log["t"], log["vmax"], surface):
            f.write("%.10g,%.6e,%.8g\n" % row)


def read_series(path):
    """(t [s], max slip rate [m/s], surface slip [m]) of write_series()'s
    file."""
    import pandas as pd
    d = pd.read_csv(path)
    return (d["t_s"].values, d["max_slip_rate"].values,
            d["surface_slip"].values)


def _header(f, location, fields, element_size):
    f.write("# problem=SEAS Benchmark BP1-FD\n"
            f"# code=SCycle {COMMIT[:7]} + scycle.patch\n"
            f"# element_size={element_size:.0f} m\n")
    if location:
        f.write(f"# location={location}\n")
    for line in fields:
        f.write(line + "\n")


def write_seas(folder, profiles, event_interval=1.0,
               interval=5 * YEAR, threshold=1e-3):
    """SEAS-style files of the profile records in `folder`, as BP1 names
    them: fltst_dpXXX at STATION_DEPTHS_KM (t slip slip_rate shear_stress
    state: s, m, log10 m/s, MPa, log10 s with theta = D_c/V_0 exp((psi -
    f_0)/b)) and devol.dat (the slip at PROFILE_DEPTHS_M every `interval`
    and every `event_interval` while the maximum slip rate exceeds the
    threshold), linear in depth between the grid nodes. Returns the files
    written."""
    import numpy as np
    os.makedirs(folder, exist_ok=True)
    z, t = profiles["z"], profiles["t"]
    size = 1e3 * (z[1] - z[0])
    vmax = profiles["V"].max(axis=1)
    theta = DC / V0 * np.exp((profiles["psi"] - F0) / B)
    written = []
    for d in STATION_DEPTHS_KM:
        path = os.path.join(folder, "fltst_dp%03d" % round(10 * d))
        with open(path, "w", encoding="utf-8") as f:
            _header(f, f"on fault, {d:g} km depth",
                    ["t slip slip_rate shear_stress state"], size)
            for k in range(len(t)):
                def at(field):
                    return np.interp(d, z, field[k])
                f.write("%.10g %.10g %.10g %.10g %.10g\n" % (
                    t[k], at(profiles["slip"]), np.log10(at(profiles["V"])),
                    at(profiles["tau"]), np.log10(at(theta))))
        written.append(path)
    path = os.path.join(folder, "devol.dat")
    depths = np.array(PROFILE_DEPTHS_M)
    with open(path, "w", encoding="utf-8") as f:
        _header(f, "", ["z", "t max_slip_rate slip"], size)
        f.write("0 0 " + " ".join("%.6g" % x for x in depths) + "\n")
        last = -np.inf
        for k in range(len(t)):
            if t[k] - last >= (event_interval if vmax[k] > threshold
                               else interval):
                slip = np.interp(depths / 1e3, z, profiles["slip"][k])
                f.write("%.10g %.6g " % (t[k], np.log10(vmax[k])) +
                        " ".join("%.6g" % x for x in slip) + "\n")
                last = t[k]
    written.append(path)
    return written


def main(argv=None):
    """The command line (the module's documentation)."""
    parser = argparse.ArgumentParser(
        prog="python3 -m rsfcycle.peers.scycle",
        description="SCycle as the peer of SEAS BP1-FD: write its input, or "
        "reduce a finished run to its events, series and SEAS-style files.")
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("input", help="write RUN/bp1fd.in and RUN/ICs/")
    p.add_argument("run")
    for name, value in DEFAULTS.items():
        flag = "--" + name.replace("_", "-")
        p.add_argument(flag, type=type(value), default=value,
                       help=f"(default {value:g})" if not isinstance(
                           value, str) else f"(default {value})")
    s = sub.add_parser("stats", help="event table, series and SEAS-style "
                       "files of a finished run (needs h5py)")
    s.add_argument("run")
    s.add_argument("--threshold", type=float, default=1e-3,
                   help="event threshold [m/s]")
    s.add_argument("--merge", type=float, default=86400.0,
                   help="rises within this many seconds of an event's end "
                   "belong to it [s]")
    s.add_argument("--csv", help="write the series for the comparison here")
    s.add_argument("--seas", help="write fltst_dpXXX and devol.dat here")
    args = parser.parse_args(argv)
    try:
        if args.command == "input":
            options = {k: getattr(args, k) for k in DEFAULTS}
            print(write_input(args.run, **options))
            return 0
        log = read_log(os.path.join(args.run, "log.txt"))
        profiles = read_profiles(args.run)
    except (ValueError, OSError, ImportError) as e:
        print(f"rsfcycle.peers.scycle: {e}", file=sys.stderr)
        return 2
    found = events(log, args.threshold, args.merge)
    print(event_table(log, found, profiles), end="")
    if args.csv:
        write_series(args.csv, log, profiles)
        print(f"wrote {args.csv}: {len(log['t'])} rows")
    if args.seas:
        write_seas(args.seas, profiles)
        print(f"wrote SEAS-style files to {args.seas}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
