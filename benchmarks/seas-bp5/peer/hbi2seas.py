#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Convert native HBI output (patched with hbi-bp5.patch) to SEAS BP5-QD files.

usage: hbi2seas.py NATIVE_DIR OUT_DIR --commit SHA [--surface row|extrap]

NATIVE_DIR is the directory HBI ran in (bp5.in, bp5_param.dat, stations.json, output/).
Native files used (filenumber 0):
  output/local0-<cell>.dat  every step: k t log10|V| slip tau sigma mu psi vflow veln slipn
  output/monitor0.dat       every step: k t log10(Vmax) ... wall sum(V*ds) [m/s*km^2, patch]
  output/time0.dat          k t of each field frame (1 yr apart between events, 1 s during them)
  output/{slip,vel,tau}0.dat  stream binary, NCELLg doubles per frame
  output/event0.dat         per event: n step t_onset Mw hypocentre_cell (written at the event's end)
Written to OUT_DIR:
  fltst_strk<x2>dp<x3>.dat  t slip_2 slip_3 slip_rate_2 slip_rate_3 shear_stress_2 shear_stress_3 state
  global.dat                t max_slip_rate moment_rate
  slip_2_depth.dat, shear_stress_2_depth.dat    profiles along x3 at x2 = 0 (BP3 layout)
  slip_2_strike.dat, shear_stress_2_strike.dat  profiles along x2 at x3 = 10 km
  events.dat                HBI's event list with the hypocentre cell centre (x2, x3)

Stations sit on cell edges or corners at 1 km (cell centres are at half-integer km). Station values are
bilinear in the cell-centre values: at a corner, the mean of the 4 cells. Slip, slip rate and shear stress
are averaged linearly, and log10(state) is averaged. For x3 = 0, above the top row of centres (0.5 km), the
default (--surface row) uses the top row, i.e. the value at x3 = 0.5 km. --surface extrap extrapolates
linearly from the 0.5 and 1.5 km rows, in log10 for the slip rate.
HBI solves for one slip component at a fixed rake of 0 (pure strike slip). slip_3 and shear_stress_3 are
therefore written as 0, and slip_rate_3 as log10(1e-20) = -20, a placeholder for exactly zero.
"""
import argparse, datetime, json, math, os
import numpy as np

MU, V0, VP, F0, B = 32.04e9, 1e-6, 1e-9, 0.6, 0.03


def header(f, a, cell, eps, dtmax, extra):
    f.write("# This is the file header:\n")
    f.write("# problem=SEAS Benchmark BP5-QD\n")
    f.write("# code=HBI (github.com/sozawa94/hbi) commit %s + rsfcycle patch hbi-bp5.patch "
            "(output only, plus HACApK out-of-bounds fix); problem 3dph = Okada rectangles in a half space\n" % a.commit)
    f.write("# modeler=rsfcycle peer run (independent public code)\n")
    f.write("# date=%s\n" % datetime.date.today().isoformat())
    f.write("# element_size=%gm (uniform 1 km squares over the 100 km x 40 km RSF region; creep at V_p outside by back slip)\n" % (cell * 1e3))
    f.write("# time_integration=RK45 Cash-Karp, eps_r=%s (relative, per component), dtmax=%s s; time in s, 1 yr = 365 d\n" % (eps, dtmax))
    f.write("# single slip component (fixed rake 0): slip_3 = shear_stress_3 = 0, slip_rate_3 = -20 placeholder\n")
    for line in extra:
        f.write("# " + line + "\n")


def read_inp(path):
    d = {}
    for line in open(path):
        w = line.split()
        if len(w) >= 2:
            d.setdefault(w[0], []).append(w[1])
    return d


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("native")
    ap.add_argument("out")
    ap.add_argument("--commit", required=True)
    ap.add_argument("--surface", choices=["row", "extrap"], default="row")
    a = ap.parse_args()
    nat, out = a.native, a.out
    inp = read_inp(os.path.join(nat, "bp5.in"))
    eps, dtmax = inp["eps_r"][0], inp["dtmax"][0]
    meta = json.load(open(os.path.join(nat, "stations.json")))
    ds, imax, jmax = meta["cell_km"], meta["imax"], meta["jmax"]
    n = imax * jmax
    par = np.loadtxt(os.path.join(nat, "bp5_param.dat"), skiprows=1)   # a dc tau vel, HBI order
    dcg = par[:, 1]
    os.makedirs(out, exist_ok=True)

    # ---- stations
    for st in meta["stations"]:
        cells = st["cells"]
        x2s = sorted({c["x2"] for c in cells})
        x3s = sorted({c["x3"] for c in cells})
        t2 = (st["x2"] - x2s[0]) / (x2s[1] - x2s[0])
        t3 = (st["x3"] - x3s[0]) / (x3s[1] - x3s[0])
        if a.surface == "row":
            t3 = min(max(t3, 0.0), 1.0)
        assert 0.0 <= t2 <= 1.0
        data, w = [], []
        for c in cells:
            d = np.loadtxt(os.path.join(nat, "output", "local0-%d.dat" % c["id"]))
            data.append((c, d))
            w.append(((1 - t2) if c["x2"] == x2s[0] else t2) * ((1 - t3) if c["x3"] == x3s[0] else t3))
        w = np.array(w)
        assert abs(w.sum() - 1) < 1e-12
        t = data[0][1][:, 1]
        for c, d in data:
            assert d.shape == data[0][1].shape and np.array_equal(d[:, 1], t)
        slip = sum(wi * d[:, 3] for wi, (c, d) in zip(w, data))
        tau = sum(wi * d[:, 4] for wi, (c, d) in zip(w, data))
        if np.all(w >= 0):
            lv = np.log10(sum(wi * 10.0 ** d[:, 2] for wi, (c, d) in zip(w, data)))
        else:
            lv = sum(wi * d[:, 2] for wi, (c, d) in zip(w, data))
        lth = sum(wi * (np.log10(dcg[c["id"] - 1] / V0) + (d[:, 7] - F0) / (B * math.log(10.0)))
                  for wi, (c, d) in zip(w, data))
        # HBI's local output starts at step 1: prepend the t = 0 initial condition
        ids = [c["id"] - 1 for c, d in data]
        v0 = np.dot(w, par[ids, 3]) if np.all(w >= 0) else 10 ** np.dot(w, np.log10(par[ids, 3]))
        row0 = [0.0, 0.0, 0.0, math.log10(v0), -20.0, float(np.dot(w, par[ids, 2])), 0.0,
                float(np.dot(w, np.log10(dcg[ids] / VP)))]
        z = np.zeros_like(t)
        cols = np.column_stack([t, slip, z, lv, z - 20.0, tau, z, lth])
        with open(os.path.join(out, st["name"] + ".dat"), "w") as f:
            header(f, a, ds, eps, dtmax, [
                "location= on fault, x2 = %g km, x3 = %g km (down); cells %s, weights %s (surface mode %s)" % (
                    st["x2"], st["x3"],
                    " ".join("%d(%.1f,%.1f)" % (c["id"], c["x2"], c["x3"]) for c, d in data),
                    " ".join("%.3f" % x for x in w), a.surface),
                "Column #1 = Time (s)", "Column #2 = Slip_2 (m)", "Column #3 = Slip_3 (m)",
                "Column #4 = Slip_rate_2 (log10 m/s)", "Column #5 = Slip_rate_3 (log10 m/s)",
                "Column #6 = Shear_stress_2 (MPa)", "Column #7 = Shear_stress_3 (MPa)",
                "Column #8 = State (log10 s)",
                "The line below lists the names of the data fields"])
            f.write("t slip_2 slip_3 slip_rate_2 slip_rate_3 shear_stress_2 shear_stress_3 state\n")
            f.write("# Here is the time-series data.\n")
            np.savetxt(f, np.vstack([row0, cols]), fmt=["%22.14e"] + ["%15.7e"] * 7)

    # ---- global
    rows = []
    for line in open(os.path.join(nat, "output", "monitor0.dat")):
        w_ = line.split()
        if len(w_) >= 4:
            rows.append((float(w_[1]), float(w_[2]), float(w_[-1])))
    m = np.array(rows)
    mr = MU * m[:, 2] * 1e6       # Pa * (m/s * km^2 -> m^3/s) = N m/s
    with open(os.path.join(out, "global.dat"), "w") as f:
        header(f, a, ds, eps, dtmax, [
            "Column #1 = Time (s)", "Column #2 = Max slip rate (log10 m/s)",
            "Column #3 = Moment rate (N-m/s) = mu * sum_i V_i A_i over the whole 100 km x 40 km RSF region",
            "The line below lists the names of the data fields"])
        f.write("t max_slip_rate moment_rate\n")
        f.write("# Here is the time-series data.\n")
        np.savetxt(f, np.column_stack([m[:, 0], m[:, 1], mr]),
                   fmt=["%22.14e", "%15.7e", "%15.7e"])

    # ---- profiles from the field frames
    tf = np.loadtxt(os.path.join(nat, "output", "time0.dat"), ndmin=2)[:, 1]

    def frames(name):
        r = np.fromfile(os.path.join(nat, "output", name), dtype="<f8")
        nf = r.size // n
        return r[: nf * n].reshape(nf, imax, jmax)     # [frame, strike column, depth row]
    slipf, velf, tauf = frames("slip0.dat"), frames("vel0.dat"), frames("tau0.dat")
    nf = min(len(tf), slipf.shape[0], velf.shape[0], tauf.shape[0])
    lvmax = np.log10(np.abs(velf[:nf]).reshape(nf, -1).max(axis=1))
    xc = (np.arange(1, imax + 1) - imax / 2 - 0.5) * ds
    zc = (np.arange(1, jmax + 1) - 0.5) * ds
    i0 = imax // 2 - 1                                  # columns x2 = -ds/2, +ds/2
    j10 = int(round(10.0 / ds)) - 1                     # rows x3 = 10 -+ ds/2
    for nm, arr, col in (("slip_2", slipf, "Slip_2 (m)"), ("shear_stress_2", tauf, "Shear_stress_2 (MPa)")):
        dep = 0.5 * (arr[:nf, i0, :] + arr[:nf, i0 + 1, :])
        stk = 0.5 * (arr[:nf, :, j10] + arr[:nf, :, j10 + 1])
        for suffix, prof, nodes, desc in (
                ("depth", dep, zc, "along x3 (depth, km) at x2 = 0: mean of the two cell columns at x2 = -+%g km" % (ds / 2)),
                ("strike", stk, xc, "along x2 (km) at x3 = 10 km: mean of the two cell rows at x3 = 10 -+ %g km" % (ds / 2))):
            with open(os.path.join(out, "%s_%s.dat" % (nm, suffix)), "w") as f:
                header(f, a, ds, eps, dtmax, [
                    "Profile " + desc + ", nodes at cell centres",
                    "Frames every 1 yr between events and every ~1 s while max V > 1e-3 m/s (HBI dtout/dtout_co)",
                    "Row 1: 0 0 x(m)...; then rows: t(s) log10(max slip rate) values: " + col])
                f.write("# Here are the data.\n")
                np.savetxt(f, np.concatenate([[0.0, 0.0], nodes * 1e3])[None, :], fmt="%22.14e")
                np.savetxt(f, np.column_stack([tf[:nf], lvmax, prof]), fmt="%22.14e")

    # ---- HBI's event list with hypocentres
    ev = os.path.join(nat, "output", "event0.dat")
    with open(os.path.join(out, "events.dat"), "w") as f:
        header(f, a, ds, eps, dtmax, [
            "HBI event list: an event starts when max V > 1e-3 m/s and ends when max V < 5e-4 m/s",
            "hypocentre = cell of max V at the first step with max V > 1e-3 m/s (cell centre, km; x3 down)",
            "Mw from HBI: mean slip over the RSF region * mu * area (events still running at t_f are not listed)",
            "The line below lists the names of the data fields"])
        f.write("n step t_onset Mw cell x2_hypo x3_hypo\n")
        if os.path.exists(ev):
            for line in open(ev):
                w_ = line.split()
                if len(w_) < 5:
                    continue
                c = int(w_[4]) - 1
                f.write("%s %s %s %s %d %.3f %.3f\n" % (w_[0], w_[1], w_[2], w_[3], c + 1,
                                                        xc[c // jmax], zc[c % jmax]))
    print("wrote SEAS files to", out, "(%d steps, %d field frames)" % (len(m), nf))


if __name__ == "__main__":
    main()
