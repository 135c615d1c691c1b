#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""What a user who clones the repository may rely on (run by ctest as
scripts/repository):

1. licence: LICENSE and CITATION.cff exist, and every tracked source,
   header, script, CMake, parameter, geometry and Markdown file carries
   the line "SPDX-License-Identifier: LGPL-2.1-or-later" in its first two
   lines;
2. self-contained: no tracked file names a path of one machine, speaks of
   sessions, or refers to design notes outside the repository (the
   pattern FORBIDDEN below);
3. one source for every figure: every figure that README.md, doc/ and the
   benchmark READMEs quote from a results file matches it, README.md's
   SEAS table is what the results files give (no cell over 120
   characters), and no duration or ratio in README.md or doc/ prose is
   left unquoted (python/rsfcycle/results.py).

Prints one line per violation and exits with 1 if there is one.
Usage: repository.py REPOSITORY_ROOT
"""
import os
import re
import subprocess
import sys

root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else ".")
sys.path.insert(0, os.path.join(root, "python"))
from rsfcycle import results  # noqa: E402

SPDX = "SPDX-License-Identifier: LGPL-2.1-or-later"
# Built from parts so that this file does not match itself.
FORBIDDEN = re.compile("/" + "work/|/" + "tmp/|[Ss]" + r"ession [0-9]|" +
                       "MODEL" + r"\.md|shared/" + "design")
# Files that carry no licence line: data, compared test outputs, images,
# meshes, the licence itself.
NO_LICENCE = re.compile(r"(^|/)LICENSE$|\.output$|\.csv$|\.png$|\.msh$")


def tracked_files():
    """The repository's files: git's list in a clone, else a walk that
    skips build folders and run folders."""
    try:
        out = subprocess.run(["git", "-C", root, "ls-files", "-z"],
                             capture_output=True, check=True).stdout
        return [f for f in out.decode().split("\0") if f]
    except (OSError, subprocess.CalledProcessError):
        found = []
        for folder, dirs, names in os.walk(root):
            dirs[:] = [d for d in dirs if not d.startswith(("build", ".",
                                                            "output"))]
            for name in names:
                found.append(os.path.relpath(os.path.join(folder, name),
                                             root))
        return found


problems = []
for required in ("LICENSE", "CITATION.cff"):
    if not os.path.exists(os.path.join(root, required)):
        problems.append(f"{required}: missing")

for path in tracked_files():
    full = os.path.join(root, path)
    if not os.path.isfile(full):
        continue
    try:
        with open(full, encoding="utf-8") as f:
            text = f.read()
    except UnicodeDecodeError:
        continue
    if not NO_LICENCE.search(path) and SPDX not in "".join(
            text.splitlines(True)[:2]):
        problems.append(f"{path}: no '{SPDX}' line at the top")
    for number, line in enumerate(text.splitlines(), start=1):
        match = FORBIDDEN.search(line)
        if match:
            problems.append(f"{path}:{number}: '{match.group(0)}' "
                            "(a machine path, a session or a note outside "
                            "the repository)")

problems += results.check(root)

for problem in problems:
    print(problem)
if problems:
    sys.exit(1)
print("licence lines, self-contained documents and quoted figures: OK")
