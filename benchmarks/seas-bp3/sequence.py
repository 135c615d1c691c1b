#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""SEAS BP3-QD: the event sequences of several runs side by side.

    sequence.py NAME=RUN [NAME=RUN ...] [--until YEARS]

RUN is a folder with global.dat (t, log10 max slip rate) and fltst_dp000
or fltst_dp000.dat (t, slip, ...): rsfcycle's SEAS output, HBI's
(peer/run.sh) or tandem's (tandem/run.sh). Events are found as compare.py
finds them (max V >= 1 mm/s; re-crossings within 60 s belong to the
event; an event the run ended in is left out). Per event and run: the
start [yr of 365 d], the interval since the previous event [yr], the peak
slip rate [m/s] and the slip at the surface station over the event [m]
(0 for a partial rupture that does not reach it). Events are listed in
order, run by run in columns; they are not paired (the point is to see
where the sequences part).
"""
import os
import sys

from compare import YEAR, events, pop_until, rows, value_at


def station(run):
    for name in ("fltst_dp000", "fltst_dp000.dat"):
        if os.path.exists(f"{run}/{name}"):
            return rows(f"{run}/{name}")
    sys.exit(f"{run}: no fltst_dp000 or fltst_dp000.dat")


def main():
    args = sys.argv[1:]
    if not args or any(a in ("-h", "--help") for a in args):
        print(__doc__)
        return
    until = pop_until(args)
    table = []
    for arg in args:
        name, _, run = arg.partition("=")
        g = rows(f"{run}/global.dat")
        s = station(run)
        found = [e for e in events(g[:, 0], g[:, 1])
                 if e[0] < until and e[1] < g[-1, 0]]
        lines = []
        for i, (a, b, p) in enumerate(found):
            interval = (f"{(a - found[i - 1][0]) / YEAR:7.2f}" if i else
                        f"{'-':>7}")
            slip = value_at(s, b, 1) - value_at(s, a - 1, 1)
            lines.append(f"{a / YEAR:8.2f} {interval} {10 ** p:6.3f} "
                         f"{slip:6.3f}")
        table.append((f"{name} (to {g[-1, 0] / YEAR:.0f} yr)", lines))
    width = 30
    print("  #  " + "".join(f"{n:<{width + 3}}" for n, _ in table))
    print("     " + "".join(f"{'start  interval  peak  slip0':<{width + 3}}"
                            for _ in table))
    for i in range(max(len(l) for _, l in table)):
        print(f"{i + 1:3d}  " + "".join(
            f"{(l[i] if i < len(l) else ''):<{width + 3}}" for _, l in table))


if __name__ == "__main__":
    main()
