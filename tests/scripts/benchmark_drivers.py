#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The benchmarks anyone can rerun (run by ctest as scripts/benchmark_drivers):

1. every benchmark folder has one driver (run.py or run.sh) whose --help
   exits with 0 without run folders, peers or builds, and every other
   Python file under benchmarks/ answers --help too;
2. no file under benchmarks/ or python/ manipulates sys.path (the drivers
   import the package rsfcycle, PYTHONPATH=python);
3. no Python or shell file under benchmarks/ or python/ defaults to a path
   of one machine (a home, scratch or /tmp folder);
4. where the `duplicates` command is installed (the developers' tool), it
   finds no run of code shared between two benchmark folders (shared code
   belongs in the package); where it is not, the line says so.

Prints one line per violation and exits with 1 if there is one.
Usage: benchmark_drivers.py REPOSITORY_ROOT
"""
import glob
import os
import re
import shutil
import subprocess
import sys

root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else ".")
problems = []
env = dict(os.environ, PYTHONPATH=os.path.join(root, "python"),
           MPLBACKEND="Agg")

# 1. drivers and --help
for folder in sorted(glob.glob(os.path.join(root, "benchmarks", "*", ""))):
    name = os.path.basename(os.path.dirname(folder))
    drivers = [d for d in ("run.py", "run.sh")
               if os.path.exists(os.path.join(folder, d))]
    if not drivers:
        problems.append(f"benchmarks/{name}: no driver run.py or run.sh")
for path in sorted(glob.glob(os.path.join(root, "benchmarks", "**", "*.py"),
                             recursive=True) +
                   glob.glob(os.path.join(root, "benchmarks", "*", "run.sh"))):
    command = ([sys.executable, path] if path.endswith(".py")
               else ["bash", path])
    try:
        done = subprocess.run(command + ["--help"], capture_output=True,
                              text=True, timeout=60, env=env, cwd=root)
        status = done.returncode
    except subprocess.TimeoutExpired:
        status = "a timeout"
    if status != 0:
        problems.append(f"{os.path.relpath(path, root)} --help: exit "
                        f"{status}")

# 2., 3. sys.path and machine paths
# a quote, then a folder of one machine (built from its names, so that this
# line does not match the repository test's own pattern)
machine = re.compile("[\"'](" + "|".join(
    "/" + name + "/" for name in ("home", "scratch", "tmp", "root", "work"))
    + ")")
for path in sorted(glob.glob(os.path.join(root, "benchmarks", "**", "*"),
                             recursive=True) +
                   glob.glob(os.path.join(root, "python", "**", "*"),
                             recursive=True)):
    if not path.endswith((".py", ".sh")) or not os.path.isfile(path):
        continue
    if os.path.abspath(path) == os.path.abspath(__file__):
        continue
    with open(path, encoding="utf-8", errors="replace") as f:
        for number, line in enumerate(f, start=1):
            where = f"{os.path.relpath(path, root)}:{number}"
            if re.search(r"sys\.path\.(insert|append)|sys\.path\s*=", line):
                problems.append(f"{where}: sys.path manipulation")
            if machine.search(line):
                problems.append(f"{where}: a path of one machine")

# 4. code shared between two benchmark folders
if shutil.which("duplicates"):
    out = subprocess.run(["duplicates", "--repo",
                          os.path.join(root, "benchmarks"), "--most", "200"],
                         capture_output=True, text=True).stdout
    for line in out.splitlines():
        m = re.match(r"^D\d+ (\S+?):\d+-\d+ ~ (\S+?):\d+-\d+", line)
        if m and m.group(1).split("/")[0] != m.group(2).split("/")[0]:
            problems.append(f"benchmarks: code shared between two folders: "
                            f"{line}")
else:
    print("duplicates is not installed: copies between benchmark folders "
          "not checked")

for problem in problems:
    print(problem)
if problems:
    sys.exit(1)
print("benchmark drivers: --help, no sys.path, no machine paths: OK")
