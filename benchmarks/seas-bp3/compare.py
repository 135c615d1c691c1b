#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""SEAS BP3-QD: rsfcycle's run against HBI's (benchmarks/seas-bp3/peer).

    compare.py RSFCYCLE_RUN HBI_RUN [--until YEARS]

RSFCYCLE_RUN: a run folder of prm/seas-bp3-qd.prm (global.dat, fltst_dpXXX,
srfst_fn+08, srfst_fn-08); HBI_RUN: a folder of peer/run.sh (global.dat,
fltst_dpXXX.dat, srfst_x+08.dat, srfst_x-08.dat). Events of both are found
the same way: an event starts at the first row with max slip rate >= 1e-3
m/s and ends at the first row below it (re-crossings within 60 s belong to
the event). Per event: start (years of 365 days), peak slip rate, slip at
0 and 10 km down dip at the end, the jump of the surface displacement
at x = +8 km and -8 km (horizontal +x, vertical up) over the event, and
the normal stress at 0 and 10 km before and after it, with rsfcycle's
relative differences from HBI (HBI's 0 km station is its surface cell's
centre, half a cell down dip; rsfcycle's the surface node). Events are paired in order, as
far as both runs go (--until: only events that start before).
"""
import sys

import numpy as np

YEAR = 3.1536e7  # 365 days, the benchmark's year


def rows(path):
    """The numeric rows of a SEAS file."""
    data = []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts or line.startswith("#"):
                continue
            try:
                data.append([float(p) for p in parts])
            except ValueError:
                continue
    return np.array(data)


def events(t, log10_v, merge=60.0):
    """(start, end, peak log10 V) of the intervals above 1e-3 m/s; an
    interval that starts within `merge` seconds of the last one's end
    belongs to it. The end is the first row below again."""
    found = []
    above = log10_v >= -3
    i = 0
    while i < len(t):
        if not above[i]:
            i += 1
            continue
        j = i
        while j + 1 < len(t) and above[j + 1]:
            j += 1
        end = min(j + 1, len(t) - 1)
        peak = log10_v[i:end + 1].max()
        if found and t[i] - found[-1][1] < merge:
            found[-1] = (found[-1][0], t[end], max(found[-1][2], peak))
        else:
            found.append((t[i], t[end], peak))
        i = end + 1
    return found


def value_at(table, t, column):
    """Linear interpolation of a column at time t."""
    return float(np.interp(t, table[:, 0], table[:, column]))


def pop_until(args):
    """Removes `--until YEARS` from args; the time in s (inf without it)."""
    if "--until" not in args:
        return float("inf")
    k = args.index("--until")
    until = float(args[k + 1]) * YEAR
    del args[k:k + 2]
    return until


def main():
    args = sys.argv[1:]
    if any(a in ("-h", "--help") for a in args):
        print(__doc__)
        return
    until = pop_until(args)
    if len(args) != 2:
        sys.exit("usage: compare.py RSFCYCLE_RUN HBI_RUN [--until YEARS]")
    ours, peer = args
    g1, g2 = rows(ours + "/global.dat"), rows(peer + "/global.dat")
    e1 = [e for e in events(g1[:, 0], g1[:, 1]) if e[0] < until]
    e2 = [e for e in events(g2[:, 0], g2[:, 1]) if e[0] < until]
    # the last event of a run that ended during it is cut
    e1 = [e for e in e1 if e[1] < g1[-1, 0]]
    n = min(len(e1), len(e2))
    s1 = {d: rows(f"{ours}/fltst_dp{d}") for d in ("000", "100")}
    s2 = {d: rows(f"{peer}/fltst_dp{d}.dat") for d in ("000", "100")}
    # surface: ours (t, u_x, u_down, ...), HBI's (t, u_x, u_up)
    u1 = {x: rows(f"{ours}/srfst_fn{x}08") for x in ("+", "-")}
    u2 = {x: rows(f"{peer}/srfst_x{x}08.dat") for x in ("+", "-")}

    def rel(a, b):
        return 100 * (a / b - 1)

    print(f"events: rsfcycle {len(e1)}, HBI {len(e2)}; compared {n}")
    print("  #  start [yr] rsf / HBI (%)   interval [yr] rsf / HBI (%)   "
          "peak V [m/s] rsf / HBI (%)   slip 0 km [m] (%)   slip 10 km [m] (%)")
    worst = {"start": 0, "interval": 0, "peak": 0, "slip0": 0, "jump": 0,
             "normal": 0}
    for i in range(n):
        (a1, b1, p1), (a2, b2, p2) = e1[i], e2[i]
        line = (f"{i + 1:3d}  {a1 / YEAR:8.2f} / {a2 / YEAR:8.2f} "
                f"({rel(a1, a2):+.2f})")
        worst["start"] = max(worst["start"], abs(rel(a1, a2)))
        if i > 0:
            i1, i2 = a1 - e1[i - 1][0], a2 - e2[i - 1][0]
            line += (f"   {i1 / YEAR:7.2f} / {i2 / YEAR:7.2f} "
                     f"({rel(i1, i2):+.2f})")
            worst["interval"] = max(worst["interval"], abs(rel(i1, i2)))
        else:
            line += " " * 32
        line += (f"   {10 ** p1:6.3f} / {10 ** p2:6.3f} "
                 f"({rel(10 ** p1, 10 ** p2):+.1f})")
        worst["peak"] = max(worst["peak"], abs(rel(10 ** p1, 10 ** p2)))
        for d, key in (("000", "slip0"), ("100", None)):
            x1 = value_at(s1[d], b1, 1) - value_at(s1[d], a1 - 1, 1)
            x2 = value_at(s2[d], b2, 1) - value_at(s2[d], a2 - 1, 1)
            line += f"   {x1:6.3f} / {x2:6.3f}"
            if abs(x2) > 0.1:
                line += f" ({rel(x1, x2):+.2f})"
                if key:
                    worst[key] = max(worst[key], abs(rel(x1, x2)))
        print(line)
        jumps = []
        for x in ("+", "-"):
            for c1, c2, sign in ((1, 1, 1), (2, 2, -1)):
                j1 = sign * (value_at(u1[x], b1, c1) -
                             value_at(u1[x], a1 - 1, c1))
                j2 = value_at(u2[x], b2, c2) - value_at(u2[x], a2 - 1, c2)
                jumps.append(f"{x}8 km {'xz'[c1 - 1]}: {j1:+.3f} / "
                             f"{j2:+.3f} m")
                if abs(j2) > 0.1:
                    jumps[-1] += f" ({rel(j1, j2):+.2f} %)"
                    worst["jump"] = max(worst["jump"], abs(rel(j1, j2)))
        print("       surface jumps rsf / HBI: " + "; ".join(jumps))
        normal = []
        for d in ("000", "100"):
            n1 = [value_at(s1[d], t, 4) for t in (a1 - 1, b1)]
            n2 = [value_at(s2[d], t, 4) for t in (a2 - 1, b2)]
            normal.append(f"{int(d) / 10:g} km {n1[0]:.2f} -> {n1[1]:.2f} / "
                          f"{n2[0]:.2f} -> {n2[1]:.2f}")
            worst["normal"] = max(worst["normal"],
                                  abs(n1[1] - n1[0] - (n2[1] - n2[0])))
        print("       normal stress [MPa] before -> after, rsf / HBI: " +
              "; ".join(normal))
    print("largest differences [%; normal: of the change over an event, "
          "MPa]: " + ", ".join(f"{k} {v:.2f}" for k, v in worst.items()))


if __name__ == "__main__":
    main()
