#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Convert native HBI output (patched for BP6, see hbi-bp6-closedform.patch) to
SEAS BP6-QD files: fltst_strk*.dat, global.dat, slip.dat (+ shear_stress.dat, slip_rate.dat).

usage: hbi2seas.py NATIVE_DIR OUT_DIR --law A|S --cell METRES --commit SHA [--eps E]

NATIVE_DIR is the directory HBI ran in (it holds output/ and bp6.in).
Native files used (filenumber 0):
  output/local0-<cell>.dat  every step: k t log10|V| slip tau sigma mu psi vflow veln slipn
  output/monitor0.dat       every step: k t log10(Vmax) ... wall sum(V*ds) [m/s*km, patch]
  output/time0.dat          k t of each field frame
  output/{slip,vel,tau,sigma}0.dat  stream binary, NCELLg doubles per frame
Pore pressure = sigma0 - sigma_eff as output by HBI (closed form evaluated in the code).
Darcy velocity is NOT computed by HBI; it is written from the closed form
q = -(k/eta_f) dp/dx3 = (q0/2) sgn(x3) [erfc(|x3|/sqrt(4 a t)) - H(t-toff) erfc(|x3|/sqrt(4 a (t-toff)))],
using the x3 -> 0+ limit at x3 = 0.
"""
import argparse, datetime, math, os, sys
import numpy as np

P = dict(mu=32.04e9, sigma0=50.0, f0=0.6, V0=1e-6, dc=0.004, b=0.005,
         q0=1.25e-6, toff=100 * 86400.0, alpha=0.1)
STATIONS = [-1.5, 0.0, 0.5, 1.0, 1.5, 2.5, 3.5, 5.0, 7.5]  # km


def read_inp(path):
    d = {}
    for line in open(path):
        w = line.split()
        if len(w) >= 2:
            d.setdefault(w[0], []).append(w[1])
    return d


def darcy(x_m, t):
    """closed-form Darcy velocity (m/s), x in m, t in s (arrays ok)."""
    x_m = np.asarray(x_m, float)
    t = np.asarray(t, float)
    sgn = np.where(x_m < 0, -1.0, 1.0)  # x3=0 -> 0+ limit
    ax = np.abs(x_m)
    from math import erfc
    verfc = np.vectorize(lambda z: erfc(z))
    out = np.zeros(np.broadcast(x_m, t).shape)
    t1 = np.broadcast_to(t, out.shape)
    m = t1 > 0
    out[m] = verfc(np.broadcast_to(ax, out.shape)[m] / np.sqrt(4 * P['alpha'] * t1[m]))
    m2 = t1 > P['toff']
    out[m2] -= verfc(np.broadcast_to(ax, out.shape)[m2] / np.sqrt(4 * P['alpha'] * (t1[m2] - P['toff'])))
    return 0.5 * P['q0'] * np.broadcast_to(sgn, out.shape) * out


def header(f, law, commit, cell, eps, extra):
    f.write("# This is the file header:\n")
    f.write("# problem=SEAS Benchmark BP6-QD-%s\n" % law)
    f.write("# code=HBI (github.com/sozawa94/hbi) commit %s + rsfcycle patch hbi-bp6-closedform.patch "
            "(closed-form pore pressure with shut-in; 2dp kernel with pois=0 = antiplane)\n" % commit)
    f.write("# modeler=rsfcycle peer run (independent public code)\n")
    f.write("# date=%s\n" % datetime.date.today().isoformat())
    f.write("# element_size=%gm (uniform, fault |x3|<=20 km)\n" % cell)
    f.write("# time_integration=RK45 Cash-Karp, eps_r=%s (relative, per component), dtmax=%s s\n" % (eps[0], eps[1]))
    for line in extra:
        f.write("# " + line + "\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("native")
    ap.add_argument("out")
    ap.add_argument("--law", required=True)
    ap.add_argument("--cell", type=float, required=True)
    ap.add_argument("--commit", required=True)
    a = ap.parse_args()
    inp = read_inp(os.path.join(a.native, "bp6.in"))
    n = int(inp["ncellg"][0])
    ds_km = float(inp["ds"][0])
    eps = (inp.get("eps_r", ["1e-4"])[0], inp.get("dtmax", ["inf"])[0])
    ic = n // 2 - 1  # 0-based index of the injection cell (HBI uses xcol(ncellg/2))
    xyz = np.loadtxt(os.path.join(a.native, "output", "xyz0.dat"))
    x3 = (xyz[:, 0] - xyz[ic, 0]) * 1e3  # m
    os.makedirs(a.out, exist_ok=True)

    # ---- stations
    for s in STATIONS:
        cid = n // 2 + int(round(s * 1e3 / a.cell))  # 1-based cell id
        fn = os.path.join(a.native, "output", "local0-%d.dat" % cid)
        d = np.loadtxt(fn)
        t, lv, slip, tau, sig, psi = d[:, 1], d[:, 2], d[:, 3], d[:, 4], d[:, 5], d[:, 7]
        xs = x3[cid - 1]
        assert abs(xs - s * 1e3) < 1e-3 * a.cell, (xs, s)
        pp = P['sigma0'] - sig
        q = darcy(xs, t)
        lth = np.log10(P['dc'] / P['V0']) + (psi - P['f0']) / P['b'] / math.log(10.0)
        # HBI's local output starts at step 1; prepend the t=0 initial condition
        psi0 = 0.007 * math.log(2 * P['V0'] / 1e-12 * math.sinh(29.2 / (0.007 * P['sigma0'])))
        lth0 = math.log10(P['dc'] / P['V0']) + (psi0 - P['f0']) / P['b'] / math.log(10.0)
        row0 = np.array([[0.0, 0.0, -12.0, 29.2, 0.0, 0.0, lth0]])
        name = "fltst_strk%+03d.dat" % int(round(s * 10))
        with open(os.path.join(a.out, name), "w") as f:
            header(f, a.law, a.commit, a.cell, eps, [
                "location= on fault, x3 = %g km (cell centre %.3f m from the injection cell)" % (s, xs),
                "Column #1 = Time (s)", "Column #2 = Slip (m)", "Column #3 = Slip rate (log10 m/s)",
                "Column #4 = Shear stress (MPa)", "Column #5 = Pore pressure (MPa)",
                "Column #6 = Darcy velocity (m/s) [closed form, not computed by HBI; x3=0 uses the 0+ limit]",
                "Column #7 = State (log10 s)",
                "The line below lists the names of the data fields"])
            f.write("t slip slip_rate shear_stress pore_pressure darcy_vel state\n")
            f.write("# Here is the time-series data.\n")
            np.savetxt(f, np.vstack([row0, np.column_stack([t, slip, lv, tau, pp, q, lth])]),
                       fmt=["%22.14e"] + ["%15.7e"] * 6)

    # ---- global
    # parse by tokens: the k=0 line has an overflowed i4 field ("****") glued to its neighbour
    rows = []
    for line in open(os.path.join(a.native, "output", "monitor0.dat")):
        w = line.split()
        if len(w) >= 4:
            rows.append((float(w[1]), float(w[2]), float(w[-1])))
    m = np.array(rows)
    mr = P['mu'] * m[:, 2] * 1e3  # Pa * (m/s * km -> m^2/s) = N/s per unit length
    with open(os.path.join(a.out, "global.dat"), "w") as f:
        header(f, a.law, a.commit, a.cell, eps, [
            "Column #1 = Time (s)", "Column #2 = Max slip rate (log10 m/s)",
            "Column #3 = Moment rate per unit length (N/s) = mu * sum_i V_i dx_i over |x3|<=20 km",
            "The line below lists the names of the data fields"])
        f.write("t max_slip_rate moment_rate\n")
        f.write("# Here is the time-series data.\n")
        np.savetxt(f, np.column_stack([m[:, 0], m[:, 1], mr]), fmt=["%22.14e", "%15.7e", "%15.7e"])

    # ---- profiles (field frames, about daily)
    tf = np.loadtxt(os.path.join(a.native, "output", "time0.dat"))[:, 1]
    def frames(name):
        r = np.fromfile(os.path.join(a.native, "output", name), dtype="<f8")
        nf = r.size // n
        return r[: nf * n].reshape(nf, n)
    slipf, velf, tauf = frames("slip0.dat"), frames("vel0.dat"), frames("tau0.dat")
    nf = min(len(tf), slipf.shape[0], velf.shape[0], tauf.shape[0])
    xd = np.arange(-10000.0, 10000.0 + 1, 100.0)
    idx = np.array([ic + int(round(x / a.cell)) for x in xd])
    assert np.allclose(x3[idx], xd, atol=1e-3 * a.cell)
    lvf = np.log10(np.maximum(np.abs(velf), 1e-300))
    for nm, arr, col in (("slip.dat", slipf, "Slip (m)"), ("shear_stress.dat", tauf, "Shear stress (MPa)"),
                         ("slip_rate.dat", lvf, "Slip rate (log10 m/s)")):
        with open(os.path.join(a.out, nm), "w") as f:
            header(f, a.law, a.commit, a.cell, eps, [
                "Profile along x3 from -10 to 10 km every 100 m (cell centres), frames about every day",
                "Row 1: 0 0 x3(m)...; then rows: t(s) log10(max slip rate) values: " + col])
            f.write("# Here are the data.\n")
            np.savetxt(f, np.concatenate([[0.0, 0.0], xd])[None, :], fmt="%22.14e")
            rows = np.column_stack([tf[:nf], np.log10(np.abs(velf[:nf]).max(axis=1)), arr[:nf][:, idx]])
            np.savetxt(f, rows, fmt="%22.14e")
    print("wrote SEAS files to", a.out, "(%d frames)" % nf)


if __name__ == "__main__":
    main()
