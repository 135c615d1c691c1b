#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Event table and thinned time series of a QDYN run of SEAS BP1-QD (or
BP2-QD) set up by make_input.py.

Usage:
  stats.py RUNDIR [--md OUT.md] [--csv OUT.csv] [--regular_from_event K]
           [--max_rows 50000]

Reads, in RUNDIR:
  qdyn.in         N and L (element i, 1-based, has its centre at depth
                  (i - 1/2) L/N; element 1 is next to the free surface)
  output_vmax     t, index of the element of maximum slip rate (1-based),
                  and V, theta, tau, dtau/dt, slip, sigma there
  output_ot_<i>   t, potency, potency rate, V, theta, tau, dtau/dt, slip,
                  sigma at element i (0-based)
  iot_depths.txt  the nominal depth of each output_ot_<i>
                  (written by make_input.py)
  output_dyn_max_<k>  per event k (from 0) and element: x, y, z, t_rup,
                  tau_max, t_vmax, vmax
All are written by QDYN at every time step (NTOUT_OT = 1) except
output_dyn_max_<k> (once per event).

Events (the SEAS definition): the maximum slip rate on the fault exceeds
1e-3 m/s; an event starts at the first output step above it and ends at
the first later step below it. Per event: start (in QDYN's years of 365
days), interval to the event before, duration, peak slip rate and the
depth where it occurred, hypocentre (the element of maximum slip rate at
the start step), surface slip (slip of element 1, at the end minus at the
start) and rupture extent (the depth range of the elements whose peak
slip rate in output_dyn_max_<k> exceeded 1e-3 m/s). Depths are element
centres. Printed, and written to OUT.md with the events as numbers in
OUT_events.csv (OUT.md without .md, then _events.csv): the table, the
first-event time, every interval, the mean interval from event K on
(default 3) and the mean peak slip rate, surface slip, hypocentre and
duration of the finished events from K on.

OUT.csv: the time series that compare.py and cycles.py read with --qdyn:
t_yr (QDYN's years of 365 days), max_slip_rate [m/s], surface_slip [m]
(element 1), and for every station depth Z in km (0, 2.5, ..., 35; "."
written "p") V_Zkm [m/s] and tau_MPa_Zkm [MPa] (QDYN's tau = sigma
F(V, theta) = tau_0 + tau_qs - eta V) at the element nearest Z. Thinned to
about --max_rows rows: half evenly spaced in the step index (which
resolves the events, where QDYN's steps cluster), half evenly spaced in
time, plus the first and last step of every event and the last step.
"""
import argparse
import glob
import os

import numpy as np
import pandas as pd

YEAR = 365.0 * 24 * 3600.0  # QDYN's YEAR (constants.f90)
VTH = 1e-3  # [m/s]
VMAX_COLUMNS = ["t", "ivmax", "v", "theta", "tau", "dtau_dt", "slip",
                "sigma"]
OT_COLUMNS = ["t", "pot", "pot_rate", "v", "theta", "tau", "dtau_dt",
              "slip", "sigma"]
DYN_COLUMNS = ["x", "y", "z", "t_rup", "tau_max", "t_vmax", "vmax"]
EVENT_COLUMNS = ["k", "t_start_yr", "t_end_yr", "duration_s", "peak_V",
                 "t_peak_yr", "z_peak_km", "hypo_km", "surf_slip_m",
                 "finished", "rup_top_km", "rup_bot_km"]


def read_columns(path, names):
    return pd.read_csv(path, comment="#", header=None, sep=r"\s+",
                       names=names)


def read_run(rundir):
    """N, L, the output_vmax table and the station tables by depth [km]."""
    with open(os.path.join(rundir, "qdyn.in")) as f:
        lines = f.readlines()
    n = int(lines[1].split()[0])
    length = float(lines[2].split()[0])
    vmax = read_columns(os.path.join(rundir, "output_vmax"), VMAX_COLUMNS)
    stations = read_columns(os.path.join(rundir, "iot_depths.txt"),
                            ["zt_km", "i0", "zc_m"])
    ot = {}
    for _, r in stations.iterrows():
        ot[r.zt_km] = read_columns(
            os.path.join(rundir, "output_ot_%d" % r.i0), OT_COLUMNS)
    return n, length, vmax, ot


def find_events(rundir, n, dz, t, vmax, ivmax, sslip):
    """The events as a table, and the start and end step of each."""
    def depth(i1):  # 1-based element index -> centre depth [m]
        return (np.asarray(i1) - 0.5) * dz

    above = vmax > VTH
    starts = np.where(above & ~np.r_[False, above[:-1]])[0]
    ends = np.where(~above & np.r_[False, above[:-1]])[0]
    dynmax = sorted(glob.glob(os.path.join(rundir, "output_dyn_max_*")),
                    key=lambda s: int(s.rsplit("_", 1)[1]))
    nsteps = len(t)
    events = []
    for k, s in enumerate(starts):
        e = ends[ends > s]
        finished = len(e) > 0
        e = e[0] if finished else nsteps - 1
        ipk = s + int(np.argmax(vmax[s:e + 1]))
        ev = dict(
            k=k + 1,
            t_start_yr=t[s] / YEAR,
            t_end_yr=t[e] / YEAR,
            duration_s=t[e] - t[s],
            peak_V=vmax[ipk],
            t_peak_yr=t[ipk] / YEAR,
            z_peak_km=depth(ivmax[ipk]) / 1e3,
            hypo_km=depth(ivmax[s]) / 1e3,
            surf_slip_m=sslip[e] - sslip[s],
            finished=finished,
            rup_top_km=np.nan, rup_bot_km=np.nan,
        )
        if k < len(dynmax):
            dm = read_columns(dynmax[k], DYN_COLUMNS)
            # QDYN's along-fault coordinate x_i = (i - N/2 - 1/2) dz -> i
            i1 = np.rint(dm["x"].values / dz + n / 2 + 0.5).astype(int)
            tv = dm["t_vmax"].values
            ok = ((dm["vmax"].values > VTH) & (tv >= t[s] - 1.0)
                  & (tv <= t[e] + 1.0))
            if ok.any():
                zz = depth(i1[ok])
                ev["rup_top_km"] = (zz.min() - dz / 2) / 1e3
                ev["rup_bot_km"] = (zz.max() + dz / 2) / 1e3
        events.append(ev)
    return pd.DataFrame(events, columns=EVENT_COLUMNS), starts, ends


def report(rundir, n, length, nsteps, t_end, table, regular_from):
    dz = length / n
    out = ["run: %s   N = %d, L = %.1f m, dz = %.4f m" % (rundir, n, length,
                                                          dz),
           "output steps: %d, simulated time: %.3f yr" % (nsteps,
                                                          t_end / YEAR),
           "number of events (Vmax > 1e-3 m/s): %d" % len(table)]
    if not len(table):
        return out
    out += ["",
            "| # | start [yr] | interval [yr] | duration [s] | peak V [m/s] "
            "| hypocentre depth [km] | depth of peak V [km] | surface slip "
            "[m] | rupture extent [km] |",
            "|---|---|---|---|---|---|---|---|---|"]
    prev = None
    for _, ev in table.iterrows():
        interval = "" if prev is None else "%.3f" % (ev.t_start_yr - prev)
        prev = ev.t_start_yr
        rupture = ("" if np.isnan(ev.rup_top_km)
                   else "%.2f-%.2f" % (ev.rup_top_km, ev.rup_bot_km))
        out.append("| %d%s | %.4f | %s | %.1f | %.4f | %.3f | %.3f | %.4f "
                   "| %s |" % (
                       ev.k, "" if ev.finished else " (unfinished)",
                       ev.t_start_yr, interval, ev.duration_s, ev.peak_V,
                       ev.hypo_km, ev.z_peak_km, ev.surf_slip_m, rupture))
    out += ["", "first event start: %.4f yr" % table.t_start_yr.iloc[0]]
    ts = table.t_start_yr.values
    if len(ts) > 1:
        intervals = np.diff(ts)
        k0 = regular_from if regular_from else 3
        # the intervals between consecutive events k0, k0 + 1, ..., last
        sel = intervals[k0 - 1:]
        out.append("recurrence intervals [yr]: "
                   + ", ".join("%.3f" % x for x in intervals))
        if len(sel):
            out.append("mean recurrence over the intervals between events "
                       "%d..%d: %.4f yr (std %.4f yr, n=%d)"
                       % (k0, len(ts), sel.mean(), sel.std(), len(sel)))
        finished = table[table.finished]
        late = finished[finished.k >= k0]
        if len(late):
            out.append("mean over events %d..%d: peak V %.4f m/s, surface "
                       "slip %.4f m, hypocentre %.3f km, duration %.1f s"
                       % (k0, late.k.max(), late.peak_V.mean(),
                          late.surf_slip_m.mean(), late.hypo_km.mean(),
                          late.duration_s.mean()))
    return out


def write_series(path, t, vmax, sslip, ot, starts, ends, max_rows):
    nsteps = len(t)
    stride = int(np.ceil(2 * nsteps / max_rows))
    keep = np.zeros(nsteps, bool)
    keep[::stride] = True
    grid = np.linspace(t[0], t[-1], max_rows // 2)
    keep[np.clip(np.searchsorted(t, grid), 0, nsteps - 1)] = True
    keep[starts] = True
    keep[ends] = True
    keep[-1] = True
    columns = {"t_yr": t / YEAR, "max_slip_rate": vmax,
               "surface_slip": sslip}
    for zt, d in ot.items():
        tag = ("%g" % zt).replace(".", "p")
        columns["V_%skm" % tag] = d["v"].values[:nsteps]
        columns["tau_MPa_%skm" % tag] = d["tau"].values[:nsteps] / 1e6
    df = pd.DataFrame(columns)[keep]
    df.to_csv(path, index=False, float_format="%.10g")
    print("wrote %s (%d rows, stride %d)" % (path, len(df), stride))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("rundir")
    parser.add_argument("--csv", default=None)
    parser.add_argument("--md", default=None)
    parser.add_argument("--regular_from_event", type=int, default=None,
                        help="1-based event from which the sequence is "
                        "taken as regular (default: 3, i.e. the first two "
                        "events are left out)")
    parser.add_argument("--max_rows", type=int, default=50000)
    args = parser.parse_args()

    n, length, vm, ot = read_run(args.rundir)
    dz = length / n
    surface = ot[0.0]
    nsteps = min(len(surface), len(vm))
    t = vm["t"].values[:nsteps]
    if not np.allclose(surface["t"].values[:nsteps], t, rtol=1e-12,
                       atol=1e-6):
        raise SystemExit("time columns of output_vmax and output_ot_0 "
                         "differ")
    vmax = vm["v"].values[:nsteps]
    ivmax = vm["ivmax"].values.astype(int)[:nsteps]
    sslip = surface["slip"].values[:nsteps]

    table, starts, ends = find_events(args.rundir, n, dz, t, vmax, ivmax,
                                      sslip)
    text = "\n".join(report(args.rundir, n, length, nsteps, t[-1], table,
                            args.regular_from_event))
    print(text)
    if args.md:
        with open(args.md, "w") as f:
            f.write(text + "\n")
        table.to_csv(os.path.splitext(args.md)[0] + "_events.csv",
                     index=False)
    if args.csv:
        write_series(args.csv, t, vmax, sslip, ot, starts, ends,
                     args.max_rows)


if __name__ == "__main__":
    main()
