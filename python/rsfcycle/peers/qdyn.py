# SPDX-License-Identifier: LGPL-2.1-or-later
"""QDYN (https://github.com/ydluo/qdyn) as the peer of SEAS BP1-QD and
BP2-QD: its input for the benchmark, its output read and reduced to the
event catalogue (rsfcycle.catalog) and a thinned time series.

    python3 -m rsfcycle.peers.qdyn input RUN [--n 2048] [--dc 8e-3] ...
    python3 -m rsfcycle.peers.qdyn stats RUN [--md OUT.md] [--csv OUT.csv]

`input` writes RUN/qdyn.in through QDYN's own Python wrapper
(src/pyqdyn.py of the clone given by --qdyn-src or QDYN_SRC, loaded from
there and not copied) and RUN/iot_depths.txt, the output elements.
`stats` reads a finished run: the event table (Markdown, and the events
as numbers in OUT_events.csv) and the thinned series OUT.csv.

The set-up (checked in QDYN's source at commit e06edb1):

- MESHDIM = 1, FAULT_TYPE = 1: a 1D fault in a 2D antiplane medium, a
  vertical strike-slip fault (fault_stress.f90: kernel 0.5 MU |k|).
- FINITE = 3: the slip rate is mirrored about the top edge of element 1
  (a free surface at z = 0); friction acts on 0 < z < L only and the
  kernel acts on V - V_PL, so below L the fault creeps at exactly V_PL.
  Element i (1-based) has its centre at depth (i - 1/2) L/N; N must be a
  power of 2 (QDYN's FFT, fftsg.f90): L = 40 km gives 19.53125 m (2048)
  or 39.0625 m (1024), never 25 m. With L > W_f (`lf`) the elements below
  W_f get a = a_deep, b = 0, MU_SS = 40 a_deep: a pseudo-creeping zone.
- MU = rho c_s^2, VS = c_s: radiation damping eta = MU/(2 VS).
- RNS_LAW = 2 (the regularised law of the SEAS benchmarks), MU_SS = f_0,
  V_SS = V_0 = 1e-6 m/s; THETA_LAW = 1 (ageing law); V_PL = V_p; QDYN's
  V_0 (the initial slip rate) = V_p; TH_0 from BP1's tau_0 and theta_0
  (QDYN sets the initial stress to tau_0 - eta V_init).
- TMAX in QDYN's years of 365 days (YEAR), NSTOP = 0; SOLVER = 2
  (Runge-Kutta-Fehlberg 4(5)) with relative tolerance ACC. The run ends
  with "RK45 error [8]: invalid input parameters" at TMAX (exit status 0).
- Output: output_vmax and output_ot_<i> every NTOUT_OT steps at the
  elements nearest STATION_DEPTHS_KM; OX_DYN = 1 with thresholds 1e-3
  m/s: output_dyn_max_<k> per event k (from 0), DYN_SKIP = -1.
"""

import argparse
import glob
import importlib.util
import os
import sys

from rsfcycle import catalog
from rsfcycle.peers import PeerNotFound, source

YEAR = 365.0 * 24 * 3600.0  # QDYN's year (constants.f90) [s]
URL = "https://github.com/ydluo/qdyn"
COMMIT = "e06edb1db4d402fbc4581e086a019d30e433cc56"

# BP1 (Erickson et al. 2020); BP2 is BP1 with D_c = 4 mm
RHO = 2670.0
VS = 3464.0
MU = RHO * VS ** 2  # 32.04 GPa
ETA = MU / (2 * VS)
SIGMA = 50e6
A0, AMAX, B = 0.010, 0.025, 0.015
F0 = 0.6
V0 = 1e-6  # BP1's reference slip rate: QDYN's V_SS
VP = 1e-9  # plate rate: QDYN's V_PL
VINIT = VP  # initial slip rate: QDYN's V_0
H, HTRANS = 15e3, 3e3
STATION_DEPTHS_KM = (0, 2.5, 5, 7.5, 10, 12.5, 15, 17.5, 20, 25, 30, 35)
THRESHOLD = 1e-3  # [m/s], the SEAS event threshold

VMAX_COLUMNS = ["t", "ivmax", "v", "theta", "tau", "dtau_dt", "slip",
                "sigma"]
OT_COLUMNS = ["t", "pot", "pot_rate", "v", "theta", "tau", "dtau_dt",
              "slip", "sigma"]
DYN_COLUMNS = ["x", "y", "z", "t_rup", "tau_max", "t_vmax", "vmax"]
EVENT_COLUMNS = ["k", "t_start_yr", "t_end_yr", "duration_s", "peak_V",
                 "t_peak_yr", "z_peak_km", "hypo_km", "surf_slip_m",
                 "rup_top_km", "rup_bot_km"]


def load_pyqdyn(qdyn_src=None):
    """QDYN's wrapper class `qdyn` from the clone `qdyn_src` (or
    $QDYN_SRC): src/pyqdyn.py loaded from its file. Raises PeerNotFound
    if the clone is not given or has no src/pyqdyn.py."""
    path = source("QDYN_SRC", qdyn_src, "src/pyqdyn.py", URL)
    spec = importlib.util.spec_from_file_location(
        "pyqdyn", os.path.join(path, "src", "pyqdyn.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.qdyn


def _tag(depth_km):
    """A station depth as it appears in column names: 7.5 -> '7p5'."""
    return ("%g" % depth_km).replace(".", "p")


def bp1_fault(n=2048, length=40e3, dc=8e-3, lf=40e3, a_deep=1.0):
    """BP1's fault on QDYN's N elements over `length` [m]: a dict with the
    element-centre depths z [m], a, b, the initial state theta0 [s], the
    mask `deep` of the elements below `lf` (pseudo-creeping), tau0 [Pa]
    and `iot`, the element (0-based) nearest each of STATION_DEPTHS_KM.
    Raises ValueError unless n is a power of 2."""
    import numpy as np
    if n < 1 or n & (n - 1):
        raise ValueError(f"N = {n} is not a power of 2 (QDYN's FFT)")
    z = (np.arange(n) + 0.5) * length / n
    a = A0 + (AMAX - A0) * (z - H) / HTRANS
    a[z < H] = A0
    a[z >= H + HTRANS] = AMAX
    b = np.full(n, B)
    deep = z > lf
    a[deep] = a_deep
    b[deep] = 0.0
    # tau_0 for steady sliding at V_init with a_max; theta_0 such that
    # sigma F(V_init, theta_0) = tau_0 - eta V_init
    tau0 = (SIGMA * AMAX * np.arcsinh(
        VINIT / (2 * V0) * np.exp((F0 + B * np.log(V0 / VINIT)) / AMAX))
        + ETA * VINIT)
    rsf = ~deep
    theta0 = np.empty(n)
    theta0[rsf] = (dc / V0) * np.exp(
        (a[rsf] / B) * np.log(2 * V0 / VINIT * np.sinh(
            (tau0 - ETA * VINIT) / (a[rsf] * SIGMA))) - F0 / B)
    theta0[deep] = dc / VINIT  # b = 0 there: the state does not matter
    iot = [int(np.argmin(np.abs(z - d * 1e3))) for d in STATION_DEPTHS_KM]
    return {"z": z, "a": a, "b": b, "theta0": theta0, "deep": deep,
            "tau0": tau0, "iot": iot}


def bp1_settings(n=2048, length=40e3, tmax_yr=3000.0, dc=8e-3, acc=1e-8,
                 solver=2, ntout_ot=1, ntout_ox=1000, nxout=16,
                 nxout_dyn=1):
    """The settings of pyqdyn's `qdyn.settings()` for BP1 (the module's
    documentation explains each)."""
    return {
        "MESHDIM": 1, "FINITE": 3, "N": n, "L": length,
        "W": 50e3,  # unused with FINITE = 3
        "MU": MU, "LAM": MU,  # LAM unused in 2D
        "VS": VS,  # radiation damping eta = MU/(2 VS)
        "SIGMA": SIGMA, "V_PL": VP,
        "TMAX": tmax_yr * YEAR, "NSTOP": 0,
        "DTTRY": 1e-3, "DTMAX": 0, "ACC": acc, "SOLVER": solver,
        "FAULT_TYPE": 1, "IC": 0,
        "NTOUT_OT": ntout_ot, "NTOUT": ntout_ox, "NXOUT": nxout,
        "OX_SEQ": 0, "OX_DYN": 1, "NXOUT_DYN": nxout_dyn,
        "DYN_TH_ON": THRESHOLD, "DYN_TH_OFF": THRESHOLD,
        "DYN_SKIP": -1,  # QDYN skips the events with count <= DYN_SKIP
        "V_TH": THRESHOLD,
        "SET_DICT_RSF": {
            "RNS_LAW": 2,  # regularised rate and state (friction.f90)
            "THETA_LAW": 1,  # ageing law
            "A": A0, "B": B, "DC": dc, "MU_SS": F0, "V_SS": V0,
            "V_0": VINIT, "TH_0": 1.0, "V1": 0.01, "V2": 1e-7, "CO": 0.0,
        },
    }


def write_stations(path, fault):
    """iot_depths.txt: per station its nominal depth [km], its element
    (0-based) and that element's centre depth [m]."""
    with open(path, "w", encoding="utf-8") as f:
        f.write("# target_depth_km element_index(0-based) "
                "element_centre_depth_m\n")
        for d, i in zip(STATION_DEPTHS_KM, fault["iot"]):
            f.write("%g %d %.4f\n" % (d, i, fault["z"][i]))


def write_input(folder, qdyn_src=None, n=2048, length=40e3, lf=40e3,
                a_deep=1.0, tmax_yr=3000.0, dc=8e-3, acc=1e-8, solver=2,
                ntout_ot=1, ntout_ox=1000, nxout=16, nxout_dyn=1):
    """Write folder/qdyn.in (by pyqdyn of the clone, load_pyqdyn()) and
    folder/iot_depths.txt for BP1 (dc = 4e-3, tmax_yr = 1200: BP2).
    Returns a line with the cell size, tau0 and the cells per
    process-zone size L_b = mu D_c/(sigma b)."""
    qdyn = load_pyqdyn(qdyn_src)
    fault = bp1_fault(n, length, dc, lf, a_deep)
    p = qdyn()
    p.settings(bp1_settings(n, length, tmax_yr, dc, acc, solver, ntout_ot,
                            ntout_ox, nxout, nxout_dyn))
    p.render_mesh()
    p.mesh_dict["A"][:] = fault["a"]
    p.mesh_dict["B"][:] = fault["b"]
    p.mesh_dict["TH_0"][:] = fault["theta0"]
    if fault["deep"].any():
        # QDYN integrates dV/dt from stress rates: the friction level
        # below lf does not matter, only the logarithmic regime
        p.mesh_dict["MU_SS"][fault["deep"]] = 40.0 * a_deep
    p.mesh_dict["IOT"][:] = 0
    p.mesh_dict["IOT"][fault["iot"]] = 1
    p.mesh_dict["X"][:] = fault["z"]  # not read for MESHDIM = 1
    os.makedirs(folder, exist_ok=True)
    cwd = os.getcwd()
    os.chdir(folder)  # pyqdyn writes qdyn.in into the working directory
    try:
        p.write_input()
    finally:
        os.chdir(cwd)
    write_stations(os.path.join(folder, "iot_depths.txt"), fault)
    dz = length / n
    lb = MU * dc / (SIGMA * B)
    return (f"dz = {dz:.4f} m, N = {n}, L = {length:.1f} m, tau0 = "
            f"{fault['tau0'] / 1e6:.6f} MPa, eta = {ETA:.6e} Pa s/m, "
            f"L_b = {lb:.1f} m = {lb / dz:.1f} cells")


def _columns(path, names):
    import pandas as pd
    return pd.read_csv(path, comment="#", header=None, sep=r"\s+",
                       names=names)


def read_mesh(folder):
    """(N, L [m]) of a run folder's qdyn.in."""
    with open(os.path.join(folder, "qdyn.in"), encoding="utf-8") as f:
        lines = f.readlines()
    return int(lines[1].split()[0]), float(lines[2].split()[0])


def read_run(folder):
    """A finished run: a dict with n, length [m], t [s], vmax [m/s],
    ivmax (1-based element of the maximum), surface_slip [m] (element 1),
    and `stations` {depth [km]: DataFrame of output_ot_<i> (OT_COLUMNS)}.
    Rows are cut to the steps both output_vmax and output_ot_0 have;
    raises ValueError if their times differ."""
    import numpy as np
    n, length = read_mesh(folder)
    vmax = _columns(os.path.join(folder, "output_vmax"), VMAX_COLUMNS)
    iot = _columns(os.path.join(folder, "iot_depths.txt"),
                   ["zt_km", "i0", "zc_m"])
    stations = {float(r.zt_km): _columns(
        os.path.join(folder, "output_ot_%d" % r.i0), OT_COLUMNS)
        for r in iot.itertuples()}
    surface = stations[0.0]
    steps = min(len(surface), len(vmax))
    t = vmax["t"].values[:steps]
    if not np.allclose(surface["t"].values[:steps], t, rtol=1e-12,
                       atol=1e-6):
        raise ValueError(f"{folder}: the times of output_vmax and "
                         "output_ot_0 differ")
    return {"n": n, "length": length, "t": t,
            "vmax": vmax["v"].values[:steps],
            "ivmax": vmax["ivmax"].values.astype(int)[:steps],
            "surface_slip": surface["slip"].values[:steps],
            "stations": stations, "folder": folder}


def events(run, threshold=THRESHOLD):
    """The completed events of a run (read_run()): (a list of
    catalog.Event with the surface slip as jump, their table as a
    DataFrame of EVENT_COLUMNS). The table adds the depth of the peak
    slip rate, the hypocentre (the element of the maximum at the start)
    and the rupture's extent (elements whose peak in output_dyn_max_<k>
    exceeds the threshold during the event). Depths are element centres
    [km]; times in QDYN's years."""
    import numpy as np
    import pandas as pd
    t, vmax, ivmax = run["t"], run["vmax"], run["ivmax"]
    n = run["n"]
    dz = run["length"] / n
    found = catalog.detect(t, vmax, threshold, series=run["surface_slip"])
    dynmax = sorted(glob.glob(os.path.join(run["folder"],
                                           "output_dyn_max_*")),
                    key=lambda s: int(s.rsplit("_", 1)[1]))
    rows = []
    for k, e in enumerate(found):
        s = int(np.searchsorted(t, e.start))
        j = int(np.searchsorted(t, e.end))
        peak = s + int(np.argmax(vmax[s:j + 1]))
        row = {"k": k + 1, "t_start_yr": e.start / YEAR,
               "t_end_yr": e.end / YEAR, "duration_s": e.end - e.start,
               "peak_V": e.peak, "t_peak_yr": t[peak] / YEAR,
               "z_peak_km": (ivmax[peak] - 0.5) * dz / 1e3,
               "hypo_km": (ivmax[s] - 0.5) * dz / 1e3,
               "surf_slip_m": e.jump, "rup_top_km": np.nan,
               "rup_bot_km": np.nan}
        if k < len(dynmax):
            dm = _columns(dynmax[k], DYN_COLUMNS)
            # QDYN's along-fault coordinate x_i = (i - N/2 - 1/2) dz
            i1 = np.rint(dm["x"].values / dz + n / 2 + 0.5).astype(int)
            tv = dm["t_vmax"].values
            ok = ((dm["vmax"].values > threshold) & (tv >= e.start - 1.0)
                  & (tv <= e.end + 1.0))
            if ok.any():
                z = (i1[ok] - 0.5) * dz
                row["rup_top_km"] = (z.min() - dz / 2) / 1e3
                row["rup_bot_km"] = (z.max() + dz / 2) / 1e3
        rows.append(row)
    return found, pd.DataFrame(rows, columns=EVENT_COLUMNS)


def report(run, table, regular_from=3):
    """The event table in Markdown with the first event's start, every
    interval, the mean interval and the means of peak slip rate, surface
    slip, hypocentre and duration from event `regular_from` (1-based)
    on."""
    import numpy as np
    t = run["t"]
    dz = run["length"] / run["n"]
    out = [f"run: {run['folder']}   N = {run['n']}, L = "
           f"{run['length']:.1f} m, dz = {dz:.4f} m",
           f"output steps: {len(t)}, simulated time: {t[-1] / YEAR:.3f} yr"
           " (QDYN's years of 365 days)",
           f"events (max V > {THRESHOLD:g} m/s): {len(table)}"]
    if not len(table):
        return "\n".join(out) + "\n"
    out += ["", "| # | start [yr] | interval [yr] | duration [s] | peak V "
            "[m/s] | hypocentre [km] | depth of peak V [km] | surface slip "
            "[m] | rupture [km] |", "|---|---|---|---|---|---|---|---|---|"]
    previous = None
    for ev in table.itertuples():
        interval = "" if previous is None else \
            "%.3f" % (ev.t_start_yr - previous)
        previous = ev.t_start_yr
        rupture = "" if np.isnan(ev.rup_top_km) else \
            "%.2f-%.2f" % (ev.rup_top_km, ev.rup_bot_km)
        out.append("| %d | %.4f | %s | %.1f | %.4f | %.3f | %.3f | %.4f | "
                   "%s |" % (ev.k, ev.t_start_yr, interval, ev.duration_s,
                             ev.peak_V, ev.hypo_km, ev.z_peak_km,
                             ev.surf_slip_m, rupture))
    starts = table.t_start_yr.values
    out += ["", "first event's start: %.4f yr" % starts[0]]
    if len(starts) > 1:
        gaps = np.diff(starts)
        out.append("intervals [yr]: " + ", ".join("%.3f" % x for x in gaps))
        late = gaps[regular_from - 1:]
        if len(late):
            out.append("mean interval between events %d..%d: %.4f yr (std "
                       "%.4f yr, n = %d)" % (regular_from, len(starts),
                                             late.mean(), late.std(),
                                             len(late)))
        rest = table[table.k >= regular_from]
        if len(rest):
            out.append("mean over events %d..%d: peak V %.4f m/s, surface "
                       "slip %.4f m, hypocentre %.3f km, duration %.1f s"
                       % (regular_from, rest.k.max(), rest.peak_V.mean(),
                          rest.surf_slip_m.mean(), rest.hypo_km.mean(),
                          rest.duration_s.mean()))
    return "\n".join(out) + "\n"


def series(run, found=(), max_rows=50000):
    """The thinned time series of a run as a DataFrame: t_yr (QDYN's
    years), max_slip_rate [m/s], surface_slip [m], and per station depth
    Z [km] V_Zkm [m/s] and tau_MPa_Zkm (QDYN's tau = tau_0 + tau_qs -
    eta V). About max_rows rows: half evenly spaced in the step index
    (which resolves the events), half in time, plus the records around
    each event's start and end (`found`) and the last step."""
    import numpy as np
    import pandas as pd
    t = run["t"]
    steps = len(t)
    stride = max(1, int(np.ceil(2 * steps / max_rows)))
    keep = np.zeros(steps, bool)
    keep[::stride] = True
    grid = np.linspace(t[0], t[-1], max(2, max_rows // 2))
    keep[np.clip(np.searchsorted(t, grid), 0, steps - 1)] = True
    for e in found:
        keep[e.first] = True
        keep[np.clip(np.searchsorted(t, [e.start, e.end]), 0,
                     steps - 1)] = True
    keep[-1] = True
    columns = {"t_yr": t / YEAR, "max_slip_rate": run["vmax"],
               "surface_slip": run["surface_slip"]}
    for depth, d in sorted(run["stations"].items()):
        columns["V_%skm" % _tag(depth)] = d["v"].values[:steps]
        columns["tau_MPa_%skm" % _tag(depth)] = d["tau"].values[:steps] / 1e6
    return pd.DataFrame(columns)[keep]


def read_series(path):
    """(t [s], max slip rate [m/s], surface slip [m]) of a series written
    by `stats --csv` (t_yr in QDYN's years)."""
    import pandas as pd
    d = pd.read_csv(path)
    return (d["t_yr"].values * YEAR, d["max_slip_rate"].values,
            d["surface_slip"].values)


def read_station(path, depth_km):
    """(t [s], log10 slip rate [m/s], shear stress [MPa]) at the station
    `depth_km` of a series written by `stats --csv`."""
    import numpy as np
    import pandas as pd
    d = pd.read_csv(path)
    tag = _tag(depth_km)
    if "V_%skm" % tag not in d:
        raise KeyError(f"{path}: no station at {depth_km:g} km")
    return (d["t_yr"].values * YEAR, np.log10(d["V_%skm" % tag].values),
            d["tau_MPa_%skm" % tag].values)


def read_events(path):
    """The events of an event table written by `stats --md` (its
    OUT_events.csv) as catalog.Event (times in s, jump the surface
    slip)."""
    import pandas as pd
    d = pd.read_csv(path)
    return [catalog.Event(r.t_start_yr * YEAR, r.t_end_yr * YEAR, r.peak_V,
                          r.surf_slip_m) for r in d.itertuples()]


def main(argv=None):
    """The command line (the module's documentation)."""
    parser = argparse.ArgumentParser(
        prog="python3 -m rsfcycle.peers.qdyn",
        description="QDYN as the peer of SEAS BP1-QD/BP2-QD: write its "
        "input, or reduce a finished run to its event table and series.")
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("input", help="write RUN/qdyn.in and "
                       "RUN/iot_depths.txt")
    p.add_argument("run")
    p.add_argument("--qdyn-src", help="QDYN clone (default: $QDYN_SRC)")
    p.add_argument("--n", type=int, default=2048,
                   help="elements, a power of 2 (2048: 19.53 m on 40 km)")
    p.add_argument("--length", type=float, default=40e3,
                   help="length of the mesh [m]")
    p.add_argument("--lf", type=float, default=40e3,
                   help="W_f [m]: below it a pseudo-creeping zone")
    p.add_argument("--a-deep", type=float, default=1.0,
                   help="a of the pseudo-creeping zone")
    p.add_argument("--tmax-yr", type=float, default=3000.0,
                   help="simulated years of 365 days (BP2: 1200)")
    p.add_argument("--dc", type=float, default=8e-3,
                   help="D_c [m] (BP2: 4e-3)")
    p.add_argument("--acc", type=float, default=1e-8, help="QDYN's ACC")
    p.add_argument("--solver", type=int, default=2, help="QDYN's SOLVER")
    s = sub.add_parser("stats", help="event table and thinned series of a "
                       "finished run")
    s.add_argument("run")
    s.add_argument("--md", help="write the table here, the events to "
                   "OUT_events.csv")
    s.add_argument("--csv", help="write the thinned series here")
    s.add_argument("--regular-from", type=int, default=3,
                   help="first event (1-based) of the means")
    s.add_argument("--max-rows", type=int, default=50000)
    args = parser.parse_args(argv)
    try:
        if args.command == "input":
            print(write_input(args.run, args.qdyn_src, args.n, args.length,
                              args.lf, args.a_deep, args.tmax_yr, args.dc,
                              args.acc, args.solver))
            return 0
        run = read_run(args.run)
    except (PeerNotFound, ValueError, FileNotFoundError) as e:
        print(f"rsfcycle.peers.qdyn: {e}", file=sys.stderr)
        return 2
    found, table = events(run)
    text = report(run, table, args.regular_from)
    print(text, end="")
    if args.md:
        with open(args.md, "w", encoding="utf-8") as f:
            f.write(text)
        table.to_csv(os.path.splitext(args.md)[0] + "_events.csv",
                     index=False)
    if args.csv:
        d = series(run, found, args.max_rows)
        d.to_csv(args.csv, index=False, float_format="%.10g")
        print(f"wrote {args.csv} ({len(d)} rows)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
