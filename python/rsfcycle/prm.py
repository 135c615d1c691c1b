# SPDX-License-Identifier: LGPL-2.1-or-later
"""Parameter files for variants of a shipped .prm: the one way the
benchmarks write them.

    from rsfcycle import prm
    prm.variant("runs/d3.prm", "prm/wedge-2d.prm", "runs/d3",
                {"Mesh/Refinement distance": 3, "End time": 200})
"""

import os


def variant(path, base, output_directory, entries=None, includes=()):
    """Write the parameter file `path`: `include base` (an absolute path, so
    the file runs from anywhere), then the `includes`, then `Output
    directory`, `Overwrite output = true` and each entry of `entries`
    ('Subsection/Subsection/Entry' -> value, in their order). Returns
    path."""
    lines = [f"include {os.path.abspath(base)}"]
    lines += [f"include {os.path.abspath(i)}" for i in includes]
    lines += [f"set Output directory = {os.path.abspath(output_directory)}",
              "set Overwrite output = true"]
    for name, value in (entries or {}).items():
        *sections, entry = name.split("/")
        for depth, section in enumerate(sections):
            lines.append("  " * depth + f"subsection {section}")
        lines.append("  " * len(sections) + f"set {entry} = {value}")
        for depth in reversed(range(len(sections))):
            lines.append("  " * depth + "end")
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    return path
