#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Per-event slip and peak slip rate at the SEAS on-fault stations of a BP4 (or BP5) output directory.

usage: bp4_stations.py DIR [--vth 1e-3] [--merge 86400] [--window 86400] [--yr 365.25]

Works on any code's SEAS files (global.dat and fltst_*.dat). The events are those of
../../seas-bp5/peer/bp5_summary.py (runs of max V >= vth in global.dat, runs closer than --merge s joined).
For each event and station: the slip over --window s from the event's start (interpolated in the
station's time series) and the station's peak slip rate in that window. The last line per station is the
total slip at the end of the run.
"""
import argparse, glob, os, sys
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "seas-bp5", "peer"))
from bp5_summary import catalogue, read_seas   # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dir")
    ap.add_argument("--vth", type=float, default=1e-3)
    ap.add_argument("--merge", type=float, default=86400.0)
    ap.add_argument("--window", type=float, default=86400.0)
    ap.add_argument("--yr", type=float, default=365.25)
    a = ap.parse_args()
    tend, evs = catalogue(a.dir, a.vth, a.merge, a.yr * 86400.0)
    print("== %s: %d events; per station: slip (m) over %g s from each onset / peak slip rate (m/s)"
          % (a.dir, len(evs), a.window))
    print("%-22s " % "station" + " ".join("%17s" % ("ev%d %.1fyr" % (n + 1, e["t0"] / (a.yr * 86400)))
                                         for n, e in enumerate(evs)) + "   total slip (m)")
    for f in sorted(glob.glob(os.path.join(a.dir, "fltst_*.dat"))):
        d = read_seas(f)
        t, s, lv = d[:, 0], d[:, 1], d[:, 3]
        cells = []
        for e in evs:
            t0, t1 = e["t0"], e["t0"] + a.window
            ds = np.interp(t1, t, s) - np.interp(t0, t, s)
            m = (t >= t0) & (t <= t1)
            cells.append("%8.3f/%8.2e" % (ds, 10 ** lv[m].max() if m.any() else float("nan")))
        print("%-22s " % os.path.basename(f)[:-4] + " ".join(cells) + "   %8.3f" % s[-1])


if __name__ == "__main__":
    main()
