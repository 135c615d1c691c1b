#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Event statistics from an SCycle BP1(-FD) run (run with /usr/bin/python3: numpy, h5py).

usage: stats.py RUNDIR [--vthr V] [--csv SERIES.csv] [--seas DIR]
  RUNDIR: a run folder of run.sh. Prints the event table (markdown).
  --csv: the series compare.py --qdyn reads (t_s, max_slip_rate [m/s] at
    every step from the log, surface_slip [m] interpolated in time between
    the profile records), so that compare.py reduces SCycle's run exactly
    as it reduces rsfcycle's.
  --seas: SEAS-style files that plot_bp1.py --run reads, from the profile
    records: global.dat (t, log10 max V), slip.dat (slip along depth 0 - 40 km,
    every 5 years between events and every second during them),
    fltst_dpXXX at the BP1 station depths (t, slip, log10 V, shear stress,
    log10 state with theta = D_c/V_0 exp((psi - f_0)/b)), linear in depth
    between the grid nodes.

Two sources are used:
  * RUNDIR/log.txt: with VERBOSE=1 SCycle prints one line per time step,
    "<step>: t = <time> s, dt = <dt> <regime> | allowed = ., maxVel = <max V on fault>, ...".
    This is every step, so it gives event start/end times and peak slip rate exactly
    at the resolution of the time stepping (VecMax of slipVel over the whole fault).
  * RUNDIR/output/data_1D.h5 (every stride1D_qd / stride1D_fd steps): fault profiles
    /fault/slip, /fault/slipVel, ... (n_out, Nz, 1), /time/time1D, /time/regime1D (1 = FD),
    /momBal/surfDisp (n_out, Ny, 1); depths from output/data_context.h5 /fault/z [km].
    Slip at z = 0 (first fault node) gives the surface slip of each event; the profile
    record nearest to the event start/end is used.
Event: max V > Vthr (default 1e-3 m/s), start = first step above, end = first step below;
spells above Vthr separated by less than MERGE_GAP (1 day) are merged into one event.
Years: 365.25 d (to compare with QDYN's 365-d years multiply by 365.25/365).
"""
import argparse
import os
import re

import h5py
import numpy as np

parser = argparse.ArgumentParser(description="SCycle BP1-FD event statistics")
parser.add_argument("rundir")
parser.add_argument("--vthr", type=float, default=1e-3, help="event threshold [m/s]")
parser.add_argument("--csv", help="write the series for compare.py --qdyn")
parser.add_argument("--seas", help="write SEAS-style files for plot_bp1.py here")
args = parser.parse_args()
run = args.rundir.rstrip("/")
vthr = args.vthr
YR = 365.25 * 86400.0
MERGE_GAP = 86400.0   # s; dips below Vthr around the QD<->FD switches belong to the same event

pat = re.compile(r"^(\d+): t = (\S+) s, dt = (\S+) (quasidynamic|fully dynamic) \| allowed = (\d), maxVel = ([^,\s]+)")
steps, tt, dts, reg, vmax = [], [], [], [], []
with open(run + "/log.txt") as fh:
    for line in fh:
        m = pat.match(line)
        if m:
            steps.append(int(m.group(1))); tt.append(float(m.group(2))); dts.append(float(m.group(3)))
            reg.append(m.group(4) == "fully dynamic"); vmax.append(float(m.group(6)))
tt, vmax, reg, dts = map(np.array, (tt, vmax, reg, dts))
print(f"log: {len(tt)} steps, t_end = {tt[-1]/YR:.4f} yr, FD steps = {reg.sum()}, QD steps = {(~reg).sum()}")

above = vmax > vthr
ev = []
i = 0
while i < len(tt):
    if above[i]:
        j = i
        while j < len(tt) and above[j]:
            j += 1
        # merge with the previous event if the gap below Vthr is shorter than MERGE_GAP
        if ev and tt[i] - tt[ev[-1][1]] < MERGE_GAP:
            ev[-1] = (ev[-1][0], min(j, len(tt) - 1), j >= len(tt))
        else:
            ev.append((i, min(j, len(tt) - 1), j >= len(tt)))
        i = j
    else:
        i += 1

with h5py.File(run + "/output/data_context.h5", "r") as c:
    zf = c["/fault/z"][:].ravel()
with h5py.File(run + "/output/data_1D.h5", "r") as f:
    t1 = f["/time/time1D"][:].ravel()
    slip = f["/fault/slip"][:, :, 0]
    V = f["/fault/slipVel"][:, :, 0]
    regime1 = f["/time/regime1D"][:].ravel()

print(f"h5: {len(t1)} records, z[0] = {zf[0]} km, dz(0) = {1000*(zf[1]-zf[0]):.1f} m")
print("| # | start [yr] | interval [yr] | duration above Vthr [s] | FD steps in event | peak V (log) [m/s] | peak V depth (h5) [km] | surface slip (h5) [m] | hypocentre (h5) [km] |")
print("|---|---|---|---|---|---|---|---|---|")
prev = None
for k, (i, j, open_) in enumerate(ev, 1):
    ts, te = tt[i], tt[j]
    pk = vmax[i:j + 1].max()
    ks = np.searchsorted(t1, ts); ke = min(np.searchsorted(t1, te), len(t1) - 1)
    # surface slip: slip at z=0 at the record after the end minus the record before the start
    kb = max(ks - 1, 0)
    ssurf = slip[ke, 0] - slip[kb, 0]
    seg = V[kb:ke + 1]
    if seg.size:
        kk, iz = np.unravel_index(np.argmax(seg), seg.shape)
        zpk = zf[iz]
    else:
        zpk = np.nan
    hyp = zf[np.argmax(V[ks])] if ks < len(t1) else np.nan
    nfd = int(reg[i:j + 1].sum())
    itv = "" if prev is None else f"{(ts - prev)/YR:.3f}"
    print(f"| {k} | {ts/YR:.4f} | {itv} | {te - ts:.1f}{' (open)' if open_ else ''} | {nfd} | {pk:.4f} | {zpk:.2f} | {ssurf:.4f} | {hyp:.2f} |")
    prev = ts


DEPTHS_KM = [0, 2.5, 5, 7.5, 10, 12.5, 15, 17.5, 20, 25, 30, 35]
F0, V0, B, DC = 0.6, 1e-6, 0.015, 0.008  # BP1 (make_input.py)
with h5py.File(run + "/output/data_1D.h5", "r") as f:
    tau = f["/fault/tau"][:, :, 0]
    psi = f["/fault/psi"][:, :, 0]

if args.csv:
    # every logged step; the surface slip between two profile records linear in time
    surface = np.interp(tt, t1, slip[:, 0])
    with open(args.csv, "w") as fh:
        fh.write("t_s,max_slip_rate,surface_slip\n")
        for row in zip(tt, vmax, surface):
            fh.write("%.10g,%.6e,%.8g\n" % row)
    print(f"wrote {args.csv}: {len(tt)} rows")

if args.seas:
    os.makedirs(args.seas, exist_ok=True)
    vmax1 = V.max(axis=1)

    def header(fh, location, names):
        fh.write("# problem=SEAS Benchmark BP1-FD\n# code=SCycle 74a132f + scycle.patch\n")
        fh.write("# element_size=%.0f m\n# location=%s\n" % (1000 * (zf[1] - zf[0]), location))
        fh.write(names + "\n")

    with open(os.path.join(args.seas, "global.dat"), "w") as fh:
        header(fh, "whole fault", "t max_slip_rate")
        for k in range(len(t1)):
            fh.write("%.10g %.10g\n" % (t1[k], np.log10(vmax1[k])))
    with open(os.path.join(args.seas, "slip.dat"), "w") as fh:
        header(fh, "on fault, slip profiles", "t max_slip_rate slip")
        # the rate-and-state part (0 - 40 km), as rsfcycle's slip.dat
        onf = zf <= 40.0 + 1e-6
        fh.write("0 0 " + " ".join("%.6g" % (1000 * z) for z in zf[onf]) + "\n")
        last = -1e300
        for k in range(len(t1)):
            if t1[k] - last >= (1.0 if vmax1[k] > 1e-3 else 5 * YR):
                fh.write("%.10g %.6g " % (t1[k], np.log10(vmax1[k])))
                fh.write(" ".join("%.6g" % x for x in slip[k][onf]) + "\n")
                last = t1[k]
    theta = DC / V0 * np.exp((psi - F0) / B)
    for d in DEPTHS_KM:
        with open(os.path.join(args.seas, "fltst_dp%03d" % round(10 * d)), "w") as fh:
            header(fh, "on fault, %.1f km depth" % d, "t slip slip_rate shear_stress state")
            for k in range(len(t1)):
                at = lambda field: np.interp(d, zf, field[k])
                fh.write("%.10g %.10g %.10g %.10g %.10g\n" % (
                    t1[k], at(slip), np.log10(at(V)), at(tau), np.log10(at(theta))))
    print(f"wrote SEAS-style files to {args.seas}")
