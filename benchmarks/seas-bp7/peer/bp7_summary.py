#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Event catalogue for a SEAS-format BP7-QD output directory (works on any code's global.dat).

usage: bp7_summary.py DIR [DIR ...] [--vth 1e-3] [--merge SECONDS] [--yr 365.25]

The events are those of ../../seas-bp5/peer/bp5_summary.py (imported): maximal runs of max slip rate
>= vth in global.dat, runs closer than --merge s joined; M0 = integral of the moment rate over the run
(with the bracketing samples), Mw = (log10 M0 - 9.1)/1.5. This script only prints them in BP7's units:
start and end (first and last sample >= vth) in s, the peak max slip rate and its time after the start,
and the hypocentre in m (from DIR/events.dat, written by hbi2seas_bp7.py). Then the recurrence intervals.
"""
import argparse, os, sys
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "seas-bp5", "peer"))
from bp5_summary import catalogue   # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dirs", nargs="+")
    ap.add_argument("--vth", type=float, default=1e-3)
    ap.add_argument("--merge", type=float, default=0.0)
    ap.add_argument("--yr", type=float, default=365.25)
    a = ap.parse_args()
    yr = a.yr * 86400.0
    for d in a.dirs:
        tend, evs = catalogue(d, a.vth, a.merge, yr)
        print("== %s: t_end = %.6g s = %.3f yr (%g d), %d events (max V >= %g m/s)"
              % (d, tend, tend / yr, a.yr, len(evs), a.vth))
        print("%3s %16s %10s %16s %9s %9s %10s %10s %6s %14s" % (
            "#", "t0 (s)", "t0 (yr)", "t_end (s)", "dur (s)", "Vpeak", "t_pk-t0 s", "M0 (N m)", "Mw", "hypo x2,x3 m"))
        for n, e in enumerate(evs, 1):
            hy = "%+.0f,%+.0f" % e["hyp"] if e["hyp"] else "-"
            print("%3d %16.9e %10.5f %16.9e %9.3f %9.3e %10.3f %10.3e %6.3f %14s%s" % (
                n, e["t0"], e["t0"] / yr, e["t1"], e["t1"] - e["t0"], e["vmax"], e["tpk"], e["m0"], e["mw"], hy,
                "  (still running at t_end)" if e["final"] else ""))
        if len(evs) > 1:
            ti = np.diff([e["t0"] for e in evs]) / yr
            print("recurrence (yr): " + " ".join("%.4f" % x for x in ti))
            if len(ti) > 1:
                print("recurrence excluding the first interval: mean %.4f, min %.4f, max %.4f yr"
                      % (ti[1:].mean(), ti[1:].min(), ti[1:].max()))


if __name__ == "__main__":
    main()
