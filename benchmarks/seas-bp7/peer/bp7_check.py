#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Check HBI's BP7 nucleation (hbi-bp7.patch) in a native run directory written by run.sh.

usage: bp7_check.py NATIVE_DIR [--times 0.1,0.2,...]

At the 4 cells around the nucleation centre (x2, x3) = (-50, -50) m (recorded by bp7_input.py), it compares
ln(V/V_init) with the imposed stress over a sigma, dtau0 G1(r) G2(t)/(a sigma), at the given times of the
0 < t < T = 1 s ramp. Before slip and state evolution matter, V/V_init = sinh((tau0' + dtau)/(a sigma)) /
sinh(tau0'/(a sigma)) = exp(dtau/(a sigma)) to within e^(-2 tau0'/(a sigma)), so the two must agree early
in the ramp and ln(V/V_init) falls behind once the cell slips. It also prints the first step with max V
>= 1e-3 m/s (time and the cell of max V, from HBI's monitor and event list).
"""
import argparse, json, math, os
import numpy as np

DTAU0, RNUC, TNUC, XN, ZN = 1.75, 0.15, 1.0, -0.05, -0.05   # MPa, km, s, km, km (x3 = -zcol)


def g2(t):
    t = np.asarray(t, float)
    out = np.where(t >= TNUC, 1.0, 0.0)
    m = (t > 0) & (t < TNUC)
    out[m] = np.exp((t[m] - TNUC) ** 2 / (t[m] * (t[m] - 2 * TNUC)))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("native")
    ap.add_argument("--times", default="0.1,0.2,0.3,0.4,0.5,0.6,0.7,0.8,0.9,1.0")
    a = ap.parse_args()
    meta = json.load(open(os.path.join(a.native, "stations.json")))
    par = np.loadtxt(os.path.join(a.native, "bp7_param.dat"), skiprows=1)
    sig, vi = meta["sigma"], 1e-9
    times = [float(x) for x in a.times.split(",")]
    print("== %s: nucleation %s" % (a.native, "on" if meta["nucleation"] else
                                    "OFF (the dtau columns are what the keyword would impose)"))
    cols = []
    for c in meta["nucleation_cells"]:
        d = np.loadtxt(os.path.join(a.native, "output", "local0-%d.dat" % c["id"]), ndmin=2)
        r2 = (c["x2"] - XN) ** 2 + (c["x3"] - ZN) ** 2
        g1 = math.exp(r2 / (r2 - RNUC ** 2)) if r2 < RNUC ** 2 else 0.0
        cols.append((c, d, g1, par[c["id"] - 1, 0]))
    print("cells: " + "; ".join("%d (%+.1f, %+.1f) m, G1 = %.5f, a = %g" % (c["id"], c["x2"] * 1e3, c["x3"] * 1e3, g1, aa)
                                for c, d, g1, aa in cols))
    print("%8s %8s %9s %12s  %-47s %s" % ("t (s)", "G2(t)", "dtau MPa", "dtau/(a sig)", "ln(V/V_init) in the 4 cells",
                                           "slip (m), cell 1"))
    for tt in times:
        c, d, g1, aa = cols[0]
        k = int(np.argmin(np.abs(d[:, 1] - tt)))
        t = d[k, 1]
        dt = DTAU0 * g1 * float(g2(t))
        lvs = [dd[int(np.argmin(np.abs(dd[:, 1] - t))), 2] * math.log(10) - math.log(vi) for _, dd, _, _ in cols]
        print("%8.4f %8.5f %9.5f %12.4f  %-47s %.2e" % (t, float(g2(t)), dt, dt / (aa * sig),
                                                       " ".join("%11.4f" % x for x in lvs), d[k, 3]))
    mon = np.loadtxt(os.path.join(a.native, "output", "monitor0.dat"), usecols=(1, 2))
    k = int(np.argmax(mon[:, 1] >= -3))
    if mon[k, 1] >= -3:
        print("first step with max V >= 1e-3 m/s: t = %.6f s (log10 Vmax = %.3f)" % (mon[k, 0], mon[k, 1]))
    ev = os.path.join(a.native, "output", "event0.dat")
    if os.path.exists(ev) and os.path.getsize(ev):
        w = open(ev).readline().split()
        c = int(w[4]) - 1
        ds, jmax = meta["cell_km"] * 1e3, meta["jmax"]
        i, j = c // jmax + 1, c % jmax + 1
        print("HBI event 1: onset %s s, hypocentre cell %d at (x2, x3) = (%.1f, %.1f) m" % (
            w[2], c + 1, (i - meta["imax"] // 2 - 0.5) * ds, (j - jmax // 2 - 0.5) * ds))


if __name__ == "__main__":
    main()
