#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Summary table and physics sanity checks for SEAS BP6-QD output in SEAS format.

usage: bp6_summary.py DIR [DIR ...]     (each DIR holds fltst_strk*.dat, global.dat,
                                         slip.dat and optionally slip_rate.dat)
Works on any code's SEAS-format BP6 files (HBI peer here; rsfcycle output too).
Times are in days (1 yr = 365 d).
"""
import math, os, sys
import numpy as np

DAY = 86400.0
STATIONS = ["-15", "+00", "+05", "+10", "+15", "+25", "+35", "+50", "+75"]
Q0, BETA, PHI, ALPHA, TOFF = 1.25e-6, 1e-8, 0.1, 0.1, 100 * DAY


def load(fn):
    rows = []
    for line in open(fn):
        w = line.split()
        if not w or line.lstrip().startswith("#"):
            continue
        try:
            rows.append([float(v) for v in w])
        except ValueError:
            continue  # field-name line
    return np.array(rows)


def interp_t(t, y, tq):
    return np.interp(tq, t, y)


def profile_at(prof, tq):
    """linear-in-time interpolation of a profile file; returns x (m), values."""
    x = prof[0, 2:]
    t = prof[1:, 0]
    v = prof[1:, 2:]
    j = np.searchsorted(t, tq)
    j = min(max(j, 1), len(t) - 1)
    w = (tq - t[j - 1]) / (t[j] - t[j - 1])
    return x, (1 - w) * v[j - 1] + w * v[j]


def front(x, v, thr):
    """outermost crossing of v=thr on each side of x=0 (linear interpolation in x), km."""
    out = []
    for side in (-1, 1):
        m = (x * side) >= 0
        xs, vs = x[m] * side, v[m]
        o = np.argsort(xs); xs, vs = xs[o], vs[o]
        above = np.nonzero(vs > thr)[0]
        if len(above) == 0:
            out.append(float("nan")); continue
        i = above[-1]
        if i + 1 < len(xs):
            xf = xs[i] + (vs[i] - thr) / (vs[i] - vs[i + 1]) * (xs[i + 1] - xs[i])
        else:
            xf = xs[i]
        out.append(side * xf / 1e3)
    return out


def summarize(d):
    print("## %s" % d)
    st = {s: load(os.path.join(d, "fltst_strk%s.dat" % s)) for s in STATIONS}
    g = load(os.path.join(d, "global.dat"))
    slip = load(os.path.join(d, "slip.dat"))
    srf = os.path.join(d, "slip_rate.dat")
    sr = load(srf) if os.path.exists(srf) else None

    print("station | slip 100 d (m) | slip 1 yr (m) | slip 2 yr (m) | peak V (m/s) | t_peak (d)")
    for s in STATIONS:
        a = st[s]
        t = a[:, 0]
        sl = [interp_t(t, a[:, 1], T * DAY) for T in (100, 365, 730)]
        k = np.argmax(a[:, 2])
        print("%s | %.4e | %.4e | %.4e | %.3e | %.2f" % (s, *sl, 10 ** a[k, 2], t[k] / DAY))

    print("\nfront | t (d) | slip>1mm x3- (km) | slip>1mm x3+ (km) | x3+/sqrt(t/1d) | V>1e-9 x3- | V>1e-9 x3+ | V>1e-11 x3+ | max V (m/s) at t")
    for T in (10, 30, 60, 80, 100, 365, 730):
        x, v = profile_at(slip, T * DAY)
        f1 = front(x, v, 1e-3)
        if sr is not None:
            x2, lv = profile_at(sr, T * DAY)
            f2 = front(x2, lv, -9.0)
            f3 = front(x2, lv, -11.0)
        else:
            f2 = f3 = [float("nan")] * 2
        mv = 10 ** interp_t(g[:, 0], g[:, 1], T * DAY)
        print("front | %d | %.3f | %.3f | %.4f | %.3f | %.3f | %.3f | %.3e" % (T, f1[0], f1[1], f1[1] / math.sqrt(T), f2[0], f2[1], f3[1], mv))
    k = np.argmax(g[:, 1])
    print("\nmax slip rate overall: %.4e m/s at t = %.3f d" % (10 ** g[k, 1], g[k, 0] / DAY))
    for T in (1, 10, 30, 60, 99.9, 100.1, 110, 150, 200, 365, 500, 730):
        print("  max V at %6.1f d: %.4e m/s   moment rate %.4e N/s" %
              (T, 10 ** interp_t(g[:, 0], g[:, 1], T * DAY), interp_t(g[:, 0], g[:, 2], T * DAY)))

    # ---- sanity checks
    a0 = st["+00"]
    p_exact = Q0 / (BETA * PHI * math.sqrt(ALPHA)) * math.sqrt(TOFF / math.pi) / 1e6
    t0 = a0[:, 0]
    pe = Q0 / (BETA * PHI * math.sqrt(ALPHA)) / math.sqrt(math.pi) / 1e6 * (
        np.sqrt(t0) - np.sqrt(np.maximum(t0 - TOFF, 0.0)))  # closed form at x3 = 0
    j = np.searchsorted(t0, TOFF) - 1
    print("\ncheck p(0,t_off) closed form = %.5f MPa; code at last sample before t_off (t=%.1f s): %.5f MPa;"
          " max |p_code - p_exact| at x3=0 over all samples: %.2e MPa" % (p_exact, t0[j], a0[j, 4], np.max(np.abs(a0[:, 4] - pe))))
    pre = [10 ** st[s][0, 2] for s in STATIONS]
    print("check t=0 slip rate at stations: min %.3e max %.3e m/s" % (min(pre), max(pre)))
    m, p = st["-15"], st["+15"]
    tt = np.linspace(1 * DAY, 730 * DAY, 500)
    sm, sp = interp_t(m[:, 0], m[:, 1], tt), interp_t(p[:, 0], p[:, 1], tt)
    print("check symmetry slip(-1.5 km) vs slip(+1.5 km): max rel diff %.2e" % np.max(np.abs(sm - sp) / np.maximum(sp, 1e-12)))
    x, v = profile_at(slip, 365 * DAY)
    vr = v[::-1]
    print("check symmetry slip profile at 365 d (|x3|<=10 km): max |s(x)-s(-x)| = %.2e m (max slip %.3e m)" %
          (np.max(np.abs(v - vr)), v.max()))
    print()


for d in sys.argv[1:]:
    summarize(d)
