# SPDX-License-Identifier: LGPL-2.1-or-later
"""Helpers shared by the benchmark scripts of rsfcycle."""
import re
import subprocess
import time


def run(exe, args, log):
    """Run rsfcycle with args, its screen output to log; wall time [s]."""
    start = time.time()
    with open(log, "w") as f:
        subprocess.run([exe] + args, stdout=f, stderr=subprocess.STDOUT,
                       check=True)
    return time.time() - start


def set_entry(prm_file, name, value):
    """Set `name` (in whatever subsection) of a parameters.prm file."""
    lines = open(prm_file).read().split("\n")
    for i, line in enumerate(lines):
        words = line.split("=")[0].split()
        if words[:1] == ["set"] and " ".join(words[1:]) == name:
            lines[i] = f"  set {name} = {value}"
    open(prm_file, "w").write("\n".join(lines))


def wedge_prm(root, depth, out, end, extra=""):
    """prm/wedge-2d.prm with the grading, tolerances and correction of the
    benchmarks' measurements (tests/wedge-2d-pinned.prm: distance 1.5,
    delta = epsilon = 1e-5, direct), 2 global and `depth` local
    refinements, no VTU, no progress lines, no timed checkpoints."""
    return f"""include {root}/prm/wedge-2d.prm
include {root}/tests/wedge-2d-pinned.prm
set End time = {end}
set Output directory = {out}
set Overwrite output = true
subsection Mesh
  set Global refinements = 2
  set Local refinements = {depth}
end
subsection Output
  set Write VTU = false
  set Progress interval = 1e9
  set Checkpoint minutes = 1e6
end
{extra}"""


def stepping_time(log):
    """The time loop alone: TimerOutput section "Time stepping" [s]."""
    return float(re.search(r"\| Time stepping\s+\|\s+\d+\s+\|\s+"
                           r"([0-9.e+-]+)s", log).group(1))
