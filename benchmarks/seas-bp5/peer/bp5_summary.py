#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Event catalogue for a SEAS-format BP5-QD output directory (works on any code's global.dat).

usage: bp5_summary.py DIR [DIR ...] [--vth 1e-3] [--merge SECONDS] [--yr 365]

An event is a maximal run of samples of global.dat with max slip rate >= vth (default 1e-3 m/s).
Runs separated by less than --merge seconds (default 0: none) are joined.
For each event the script prints:
- the start time (first sample >= vth; in years of --yr days, default 365 as HBI and tandem use);
- the peak slip rate and the time of the peak after the start;
- the duration (last minus first sample >= vth);
- M0 = integral of the moment rate over the event, and Mw = (log10 M0 - 9.1)/1.5.
If DIR/events.dat exists (written by hbi2seas.py), the hypocentre is taken from it. That is the cell
where V first exceeds 1e-3 m/s, matched to the event by its onset time.
Then it prints the recurrence intervals (differences of the start times) and their statistics.
"""
import argparse, os
import numpy as np


def read_seas(path):
    rows = []
    for line in open(path):
        s = line.strip()
        if not s or s[0] == "#" or s[0].isalpha():
            continue
        rows.append([float(x) for x in s.split()])
    return np.array(rows)


def catalogue(d, vth, merge, yr):
    g = read_seas(os.path.join(d, "global.dat"))
    t, lv, mr = g[:, 0], g[:, 1], g[:, 2]
    on = lv >= np.log10(vth)
    idx = np.flatnonzero(on)
    runs = []
    if idx.size:
        start = prev = idx[0]
        for k in idx[1:]:
            if k != prev + 1 and t[k] - t[prev] > merge:
                runs.append((start, prev))
                start = k
            prev = k
        runs.append((start, prev))
    hyp = []
    ev = os.path.join(d, "events.dat")
    if os.path.exists(ev):
        for line in open(ev):
            w = line.split()
            if w and w[0].isdigit():
                hyp.append((float(w[2]), float(w[5]), float(w[6])))
    out = []
    for (a, b) in runs:
        sl = slice(max(a - 1, 0), min(b + 2, len(t)))     # include the bracketing samples below vth
        m0 = np.trapz(mr[sl], t[sl])
        kp = a + int(np.argmax(lv[a:b + 1]))
        h = [x for x in hyp if abs(x[0] - t[a]) < 1.0 + 1e-6 * t[a]]
        out.append(dict(t0=t[a], t1=t[b], vmax=10 ** lv[kp], tpk=t[kp] - t[a], m0=m0,
                        mw=(np.log10(m0) - 9.1) / 1.5 if m0 > 0 else float("nan"),
                        hyp=(h[0][1], h[0][2]) if h else None, final=(b == len(t) - 1)))
    return t[-1], out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dirs", nargs="+")
    ap.add_argument("--vth", type=float, default=1e-3)
    ap.add_argument("--merge", type=float, default=0.0)
    ap.add_argument("--yr", type=float, default=365.0)
    a = ap.parse_args()
    yr = a.yr * 86400.0
    for d in a.dirs:
        tend, evs = catalogue(d, a.vth, a.merge, yr)
        print("== %s: t_end = %.6g s = %.2f yr (%g d), %d events (max V >= %g m/s)"
              % (d, tend, tend / yr, a.yr, len(evs), a.vth))
        print("%3s %12s %16s %9s %10s %10s %10s %6s %16s" % ("#", "t0 (yr)", "t0 (s)", "Vpeak", "t_pk-t0 s",
                                                            "dur (s)", "M0 (N m)", "Mw", "hypo x2,x3 km"))
        for n, e in enumerate(evs, 1):
            hy = "%+.1f,%.1f" % e["hyp"] if e["hyp"] else "-"
            print("%3d %12.4f %16.6e %9.3e %10.2f %10.2f %10.3e %6.2f %16s%s" % (
                n, e["t0"] / yr, e["t0"], e["vmax"], e["tpk"], e["t1"] - e["t0"], e["m0"], e["mw"], hy,
                "  (still running at t_end)" if e["final"] else ""))
        if len(evs) > 1:
            ti = np.diff([e["t0"] for e in evs]) / yr
            print("recurrence (yr): " + " ".join("%.2f" % x for x in ti))
            if len(ti) > 1:
                print("recurrence excluding the first interval (spin-up): mean %.2f, min %.2f, max %.2f yr"
                      % (ti[1:].mean(), ti[1:].min(), ti[1:].max()))


if __name__ == "__main__":
    main()
