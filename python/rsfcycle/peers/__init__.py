# SPDX-License-Identifier: LGPL-2.1-or-later
"""Other codes run beside rsfcycle on the same benchmark (its peers): one
module per peer that writes the peer's input for a benchmark, reads its
output and converts it to what rsfcycle.catalog and rsfcycle.seas read.

- rsfcycle.peers.qdyn: QDYN (spectral boundary elements, quasi-dynamic),
  SEAS BP1-QD and BP2-QD;
- rsfcycle.peers.scycle: SCycle (SBP-SAT finite differences, switching
  between quasi-dynamic and fully dynamic phases), SEAS BP1-FD;
- the other modules of this package: the peers of the later benchmarks.

A peer's code is never copied here: its clone is located by an argument or
an environment variable (source()), and a missing one is one clear line.
"""

import os
import re


class PeerNotFound(Exception):
    """A peer's clone that is not given or is not where it is said to
    be; the message is one line for the user."""


def source(variable, given=None, marker=None, url=""):
    """The absolute path of a peer's clone: `given` (an argument) or else
    the environment variable `variable`. Raises PeerNotFound when neither
    is set, or when the file `marker` (relative to the clone) is
    missing."""
    path = given or os.environ.get(variable)
    if not path:
        raise PeerNotFound(f"set {variable} to a clone of the peer"
                           + (f" ({url})" if url else ""))
    path = os.path.abspath(path)
    if marker and not os.path.isfile(os.path.join(path, marker)):
        raise PeerNotFound(f"{path} is not the peer's clone (no {marker})")
    return path


def _seconds(text):
    """'1:28:03', '22:16.41' or '59.2' as seconds."""
    value = 0.0
    for part in text.strip().split(":"):
        value = 60 * value + float(part)
    return value


def time_v(path):
    """The wall time, CPU time (user + system) [s] and maximum resident
    memory [kB] of a run timed with `/usr/bin/time -v` (its output file,
    e.g. the peers' time.txt): {'wall_s', 'cpu_s', 'max_rss_kb'}, the
    entries found."""
    with open(path, encoding="utf-8", errors="replace") as f:
        text = f.read()
    out = {}
    m = re.search(r"Elapsed \(wall clock\) time.*?\):\s*([0-9:.]+)", text)
    if m:
        out["wall_s"] = _seconds(m.group(1))
    user = re.search(r"User time \(seconds\):\s*([0-9.]+)", text)
    system = re.search(r"System time \(seconds\):\s*([0-9.]+)", text)
    if user and system:
        out["cpu_s"] = float(user.group(1)) + float(system.group(1))
    m = re.search(r"Maximum resident set size \(kbytes\):\s*(\d+)", text)
    if m:
        out["max_rss_kb"] = int(m.group(1))
    return out
