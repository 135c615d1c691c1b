#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Convert native HBI output for BP3-QD (see bp3_input.py, ../../seas-bp5/peer/hbi-bp5.patch) to SEAS-like files.

usage: hbi2seas_bp3.py NATIVE_DIR OUT_DIR --commit SHA

Native files used (filenumber 0):
  output/local0-<cell>.dat  every step: k t log10|V| slip tau sigma mu psi vflow veln slipn
  output/monitor0.dat       every step: k t log10(Vmax) meanslip meanmu max_sigma min_sigma err dt nrjct wall sum(V ds)
Writes:
  fltst_dpXXX.dat  (XXX = down-dip distance in 100 m): t slip slip_rate shear_stress normal_stress
                   slip (m, thrust positive), slip_rate = log10 |V| (m/s), stresses in MPa,
                   shear stress thrust positive (normal-faulting run, SENSE=normal: slip and
                   shear stress come out negative, as BP3 asks; HBI's variables are already signed so),
                   normal stress = 50 MPa + dsigma_n, compression positive.
  global.dat       t max_slip_rate(log10) min/max normal stress on the fault
  events.txt       catalogue: event start (max V first > 1e-3 m/s), end (max V < 1e-3), peak max V,
                   slip at 0 and 10 km at the event end, normal stress at 0 km before/after.
"""
import argparse, datetime, json, os
import numpy as np

YR = 365 * 86400.0
VTH = 1e-3


def header(f, commit, meta, extra):
    f.write("# This is the file header:\n")
    f.write("# problem=SEAS Benchmark BP3-QD (dip %g deg, %s)\n" % (meta.get('dip', 60), meta['sense']))
    f.write("# code=HBI (github.com/sozawa94/hbi) commit %s + rsfcycle patch hbi-bp5.patch "
            "(problem 2dph: half-space edge-dislocation kernels for shear and normal traction)\n" % commit)
    f.write("# modeler=rsfcycle peer run (independent public code)\n")
    f.write("# date=%s\n" % datetime.date.today().isoformat())
    f.write("# element_size=%gm (uniform, %d cells, 0-40 km down dip)\n" % (meta['cell'], meta['ncell']))
    f.write("# time_integration=RK45 Cash-Karp (HBI), eps_r=%s, dtmax=%s s\n" % (meta['eps'], meta['dtmax']))
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
    a = ap.parse_args()
    js = json.load(open(os.path.join(a.native, "stations.json")))
    inp = read_inp(os.path.join(a.native, "bp3.in"))
    meta = dict(cell=js['cell'], ncell=js['ncell'], eps=inp['eps_r'][0], dtmax=inp['dtmax'][0],
                sense=js.get('sense', 'thrust'), dip=js.get('dip', 60))
    tau_init = float(inp['tauinit'][0]); sig_init = float(inp['sigmainit'][0]); v_init = float(inp['velinit'][0])
    os.makedirs(a.out, exist_ok=True)

    # monitor (global): parse by tokens
    rows = []
    for line in open(os.path.join(a.native, "output", "monitor0.dat")):
        w = line.split()
        if len(w) >= 7:
            rows.append((int(w[0]), float(w[1]), float(w[2]), float(w[5]), float(w[6])))
    m = np.array(rows)
    m = m[m[:, 0] > 0]  # steps 1..; the k=0 line is the initial state
    km, tm, lvm = m[:, 0].astype(int), m[:, 1], m[:, 2]

    st = {}
    for s, cells in js['stations'].items():
        ds = [np.loadtxt(os.path.join(a.native, "output", "local0-%d.dat" % c)) for c in cells]
        n = min(len(d) for d in ds)
        ds = [d[:n] for d in ds]
        k = ds[0][:, 0].astype(int); t = ds[0][:, 1]
        for d in ds[1:]:
            assert np.array_equal(d[:, 0].astype(int), k)
        V = np.mean([10 ** d[:, 2] for d in ds], axis=0)
        slip = np.mean([d[:, 3] for d in ds], axis=0)
        tau = np.mean([d[:, 4] for d in ds], axis=0)
        sig = np.mean([d[:, 5] for d in ds], axis=0)
        t = np.concatenate([[0.0], t]); slip = np.concatenate([[0.0], slip])
        lv = np.concatenate([[np.log10(abs(v_init))], np.log10(V)])
        tau = np.concatenate([[tau_init], tau]); sig = np.concatenate([[sig_init], sig])
        st[float(s)] = dict(k=np.concatenate([[0], k]), t=t, slip=slip, lv=lv, tau=tau, sig=sig)
        where = ("cell 1 (centre %g m down dip)" % (js['cell'] / 2) if len(cells) == 1 else
                 "mean of cells %d and %d (centres %g and %g m down dip; V averaged linearly)"
                 % (cells[0], cells[1], (cells[0] - 0.5) * js['cell'], (cells[1] - 0.5) * js['cell']))
        name = "fltst_dp%03d.dat" % int(round(float(s) * 10))
        with open(os.path.join(a.out, name), "w") as f:
            header(f, a.commit, meta, [
                "location= on fault, %g km down dip: %s" % (float(s), where),
                "Column #1 = Time (s)", "Column #2 = Slip (m, thrust positive: negative for normal faulting)",
                "Column #3 = Slip rate (log10 |V|, m/s)",
                "Column #4 = Shear stress (MPa, thrust positive) [HBI's tau = tau0 + dtau_qs - eta V]",
                "Column #5 = Normal stress (MPa, compression positive) = 50 + dsigma_n",
                "The line below lists the names of the data fields"])
            f.write("t slip slip_rate shear_stress normal_stress\n")
            f.write("# Here is the time-series data.\n")
            np.savetxt(f, np.column_stack([t, slip, lv, tau, sig]), fmt=["%24.16e"] + ["%22.14e"] * 4)

    with open(os.path.join(a.out, "global.dat"), "w") as f:
        header(f, a.commit, meta, ["Column #1 = Time (s)", "Column #2 = Max slip rate (log10 m/s)",
                                   "Column #3/#4 = max/min normal stress on the fault (MPa)",
                                   "The line below lists the names of the data fields"])
        f.write("t max_slip_rate max_normal_stress min_normal_stress\n")
        f.write("# Here is the time-series data.\n")
        np.savetxt(f, np.column_stack([tm, lvm, m[:, 3], m[:, 4]]), fmt=["%24.16e"] + ["%22.14e"] * 3)

    # ---- catalogue
    above = lvm > np.log10(VTH)
    ev = []
    i = 0
    while i < len(above):
        if above[i]:
            j = i
            while j + 1 < len(above) and above[j + 1]:
                j += 1
            ip = i + np.argmax(lvm[i:j + 1])
            ev.append((i, j, ip))
            i = j + 1
        else:
            i += 1
    s0, s10 = st[0.0], st[10.0]

    def at(s, key, kk):
        idx = np.searchsorted(s['k'], kk)
        return s[key][min(idx, len(s['k']) - 1)]

    with open(os.path.join(a.out, "events.txt"), "w") as f:
        f.write("# BP3-QD (%s) HBI %s: events = intervals with max slip rate > 1e-3 m/s (1 yr = 3.1536e7 s)\n" % (meta['sense'], a.commit))
        f.write("# t_start = first step with max V > 1e-3; t_end = first step after with max V <= 1e-3 (after the last step above if the run ended)\n")
        f.write("# slip_0km/slip_10km at t_end (m, thrust positive, cumulative from t = 0); sn0 = normal stress at 0 km (MPa, compression +) at the step before t_start and at t_end\n")
        f.write("# n t_start_s t_start_yr t_end_s peak_log10Vmax peak_Vmax t_peak_s slip_0km slip_10km sn0_before sn0_after\n")
        for n, (i, j, ip) in enumerate(ev, 1):
            je = min(j + 1, len(km) - 1)
            kb, ke = km[i] - 1, km[je]
            f.write("%d %.10e %.6f %.10e %.6f %.6e %.10e %.6f %.6f %.6f %.6f\n" % (
                n, tm[i], tm[i] / YR, tm[je], lvm[ip], 10 ** lvm[ip], tm[ip],
                at(s0, 'slip', ke), at(s10, 'slip', ke), at(s0, 'sig', kb), at(s0, 'sig', ke)))
    print(open(os.path.join(a.out, "events.txt")).read())
    print("wrote SEAS-like files to", a.out, "; last time %.4f yr" % (tm[-1] / YR))


if __name__ == "__main__":
    main()
