#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Convert native HBI output (problem 3dp, hbi-bp5.patch + hbi-bp7.patch) to SEAS BP7-QD files.

usage: hbi2seas_bp7.py NATIVE_DIR OUT_DIR --commit SHA

NATIVE_DIR is the directory HBI ran in (bp7.in, bp7_param.dat, stations.json, output/), written by bp7_input.py.
Native files used (filenumber 0), as in the BP4/BP5 converters (../../seas-bp4/peer/hbi2seas_bp4.py):
  output/local0-<cell>.dat  every step: k t log10|V| slip tau sigma mu psi vflow veln slipn
  output/monitor0.dat       every step: k t log10(Vmax) ... wall sum(V*ds) [m/s*km^2, whole RSF square]
  output/time0.dat          k t of each field frame
  output/{slip,vel,tau}0.dat  stream binary, NCELLg doubles per frame
  output/event0.dat         per event: n step t_onset Mw hypocentre_cell (written at the event's end)
Written to OUT_DIR:
  fltst_strk<x2>dp<x3>.dat  (names in m) t slip_2 slip_3 slip_rate_2 slip_rate_3 shear_stress_2 shear_stress_3 state
  global.dat                t max_slip_rate moment_rate
  slip_2_strike.dat, shear_stress_2_strike.dat  profiles along x2 = -390..390 m (10 m) at x3 = 0
  slip_2_depth.dat, shear_stress_2_depth.dat    profiles along x3 = -390..390 m (10 m) at x2 = 0
  events.dat                HBI's event list with the hypocentre cell centre (x2, x3 in m; x3 = -zcol)
The station and profile treatment is that of the BP4 converter (bilinear in the cell centres; log10 state
averaged; slip_3 = shear_stress_3 = 0 and slip_rate_3 = -20 as the one-component placeholder). Its main()
hard-codes BP4's file names, b, sigma, profile lines and headers, so the steps are repeated here for BP7.
Shear stress is HBI's tau, the frictional strength tau0 + K(slip - V_p t) + dtau_nuc - eta V: it includes
the prescribed nucleation perturbation.
"""
import argparse, datetime, json, math, os, sys
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "seas-bp5", "peer"))
from hbi2seas import read_inp   # noqa: E402  (the BP5 converter's input reader)

MU, V0, F0 = 32.04e9, 1e-6, 0.6


def header(f, a, cell, eps, dtmax, nuc, extra):
    f.write("# This is the file header:\n")
    f.write("# problem=SEAS Benchmark BP7-QD (aging law)\n")
    f.write("# code=HBI (github.com/sozawa94/hbi) commit %s + rsfcycle patches hbi-bp5.patch (output, HACApK fix) "
            "and hbi-bp7.patch (prescribed nucleation, %s); problem 3dp = square cells in a whole space, "
            "closed-form full-space kernel\n" % (a.commit, "on" if nuc else "OFF"))
    f.write("# modeler=rsfcycle peer run (independent public code)\n")
    f.write("# date=%s\n" % datetime.date.today().isoformat())
    f.write("# element_size=%gm (uniform squares over the 800 m x 800 m RSF region; creep at V_p outside by back slip)\n"
            % (cell * 1e3))
    f.write("# time_integration=RK45 Cash-Karp, eps_r=%s (relative, per component), dtmax=%s s; time in s\n" % (eps, dtmax))
    f.write("# single slip component (along strike): slip_3 = shear_stress_3 = 0, slip_rate_3 = -20 placeholder\n")
    for line in extra:
        f.write("# " + line + "\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("native")
    ap.add_argument("out")
    ap.add_argument("--commit", required=True)
    a = ap.parse_args()
    nat, out = a.native, a.out
    inp = read_inp(os.path.join(nat, "bp7.in"))
    eps, dtmax = inp["eps_r"][0], inp["dtmax"][0]
    meta = json.load(open(os.path.join(nat, "stations.json")))
    ds, imax, jmax, B, SIG, nuc = (meta[k] for k in ("cell_km", "imax", "jmax", "b", "sigma", "nucleation"))
    n = imax * jmax
    par = np.loadtxt(os.path.join(nat, "bp7_param.dat"), skiprows=1)   # a dc tau vel, HBI order
    ag, dcg = par[:, 0], par[:, 1]
    psi0 = ag * np.log(2 * V0 / par[:, 3] * np.sinh(par[:, 2] / (SIG * ag)))   # HBI's initial state
    lth0 = np.log10(dcg / V0) + (psi0 - F0) / (B * math.log(10.0))
    os.makedirs(out, exist_ok=True)
    hdr = lambda f, extra: header(f, a, ds, eps, dtmax, nuc, extra)   # noqa: E731

    # ---- stations
    for st in meta["stations"]:
        cells = st["cells"]
        w = np.array([c["w"] for c in cells])
        assert abs(w.sum() - 1) < 1e-12 and np.all(w > 0)
        data = [np.loadtxt(os.path.join(nat, "output", "local0-%d.dat" % c["id"]), ndmin=2) for c in cells]
        t = data[0][:, 1]
        for d in data:
            assert d.shape == data[0].shape and np.array_equal(d[:, 1], t)
        ids = np.array([c["id"] - 1 for c in cells])
        slip = sum(wi * d[:, 3] for wi, d in zip(w, data))
        tau = sum(wi * d[:, 4] for wi, d in zip(w, data))
        lv = np.log10(sum(wi * 10.0 ** d[:, 2] for wi, d in zip(w, data)))
        lth = sum(wi * (np.log10(dcg[i] / V0) + (d[:, 7] - F0) / (B * math.log(10.0))) for wi, i, d in zip(w, ids, data))
        # HBI's local output starts at step 1: prepend the t = 0 initial condition
        row0 = [0.0, 0.0, 0.0, math.log10(np.dot(w, par[ids, 3])), -20.0, float(np.dot(w, par[ids, 2])), 0.0,
                float(np.dot(w, lth0[ids]))]
        z = np.zeros_like(t)
        cols = np.column_stack([t, slip, z, lv, z - 20.0, tau, z, lth])
        with open(os.path.join(out, st["name"] + ".dat"), "w") as f:
            hdr(f, [
                "location= on fault, x2 = %g m, x3 = %g m (x3 = -HBI zcol); cells %s, weights %s" % (
                    st["x2"] * 1e3, st["x3"] * 1e3,
                    " ".join("%d(%g,%g)" % (c["id"], c["x2"] * 1e3, c["x3"] * 1e3) for c in cells),
                    " ".join("%.3f" % x for x in w)),
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
        hdr(f, ["Column #1 = Time (s)", "Column #2 = Max slip rate (log10 m/s)",
                "Column #3 = Moment rate (N-m/s) = mu * sum_i V_i A_i over the whole 800 m x 800 m RSF region",
                "The line below lists the names of the data fields"])
        f.write("t max_slip_rate moment_rate\n")
        f.write("# Here is the time-series data.\n")
        np.savetxt(f, np.column_stack([m[:, 0], m[:, 1], mr]), fmt=["%22.14e", "%15.7e", "%15.7e"])

    # ---- profiles from the field frames
    tf = np.loadtxt(os.path.join(nat, "output", "time0.dat"), ndmin=2)[:, 1]

    def frames(name):
        r = np.memmap(os.path.join(nat, "output", name), dtype="<f8", mode="r")
        nf = r.size // n
        return r[: nf * n].reshape(nf, imax, jmax)     # [frame, strike column i, row j (x3 up the index)]
    slipf, velf, tauf = frames("slip0.dat"), frames("vel0.dat"), frames("tau0.dat")
    nf = min(len(tf), slipf.shape[0], velf.shape[0], tauf.shape[0])
    lvmax = np.array([np.log10(np.abs(velf[k]).max()) for k in range(nf)])
    xc = (np.arange(1, imax + 1) - imax // 2 - 0.5) * ds * 1e3     # m
    x3c = (np.arange(1, jmax + 1) - jmax // 2 - 0.5) * ds * 1e3    # m, x3 = -zcol
    i0, j0 = imax // 2 - 1, jmax // 2 - 1                          # columns x2 = -+ds/2, rows x3 = -+ds/2
    nodes = np.arange(-390.0, 390.0 + 1e-9, 10.0)   # as prm/seas-bp7-qd.prm
    for nm, arr, col in (("slip_2", slipf, "Slip_2 (m)"), ("shear_stress_2", tauf, "Shear_stress_2 (MPa)")):
        stk = np.array([np.interp(nodes, xc, 0.5 * (arr[k, :, j0] + arr[k, :, j0 + 1])) for k in range(nf)])
        dep = np.array([np.interp(nodes, x3c, 0.5 * (arr[k, i0, :] + arr[k, i0 + 1, :])) for k in range(nf)])
        for suffix, prof, desc in (
                ("strike", stk, "along x2 (m) at x3 = 0: mean of the two cell rows at x3 = -+%g m" % (ds * 500)),
                ("depth", dep, "along x3 (m, = -HBI zcol) at x2 = 0: mean of the two cell columns at x2 = -+%g m"
                 % (ds * 500))):
            with open(os.path.join(out, "%s_%s.dat" % (nm, suffix)), "w") as f:
                hdr(f, ["Profile " + desc + "; linear between cell centres",
                        "Frames every %s yr (365 d) between events and every ~%s s while max V > 1e-3 m/s"
                        % (inp["dtout"][0], inp["dtout_co"][0]),
                        "Row 1: 0 0 x(m)...; then rows: t(s) log10(max slip rate) values: " + col])
                f.write("# Here are the data.\n")
                np.savetxt(f, np.concatenate([[0.0, 0.0], nodes])[None, :], fmt="%22.14e")
                np.savetxt(f, np.column_stack([tf[:nf], lvmax, prof]), fmt="%22.14e")

    # ---- HBI's event list with hypocentres (m)
    ev = os.path.join(nat, "output", "event0.dat")
    with open(os.path.join(out, "events.dat"), "w") as f:
        hdr(f, ["HBI event list: an event starts when max V > 1e-3 m/s and ends when max V < 5e-4 m/s",
                "hypocentre = cell of max V at the first step with max V > 1e-3 m/s (cell centre, m; x3 = -zcol)",
                "Mw from HBI's own formula (events still running at t_end are not listed)",
                "The line below lists the names of the data fields"])
        f.write("n step t_onset Mw cell x2_hypo_m x3_hypo_m\n")
        if os.path.exists(ev):
            for line in open(ev):
                w_ = line.split()
                if len(w_) < 5:
                    continue
                c = int(w_[4]) - 1
                f.write("%s %s %s %s %d %.1f %.1f\n" % (w_[0], w_[1], w_[2], w_[3], c + 1, xc[c // jmax], x3c[c % jmax]))
    print("wrote SEAS files to", out, "(%d steps, %d field frames)" % (len(m), nf))


if __name__ == "__main__":
    main()
