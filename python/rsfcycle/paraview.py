# SPDX-License-Identifier: LGPL-2.1-or-later
"""A run folder's VTU snapshots in ParaView, without a display.

    python3 -m rsfcycle.paraview check RUN|FILE.pvd|FILE.xdmf
    python3 -m rsfcycle.paraview screenshot RUN OUT.png [FIELD]

`check` opens RUN/solution.pvd (or the .pvd given), updates it at the last
time step and prints the number of time steps, points and cells and the
range of every array; it exits with 1 if one of the fields rsfcycle writes
is missing. `screenshot` draws the mesh of RUN's first snapshot, coloured
by FIELD (default material_id), into OUT.png (the picture of
doc/mesh-file.md).

Both run a script of rsfcycle/pvbatch/ with ParaView's Python as
`xvfb-run -a pvbatch SCRIPT ...`; they need the Debian packages paraview,
python3-paraview and xvfb.
"""

import argparse
import os
import shutil
import subprocess
import sys

SCRIPTS = {"check": "check_pvd.py", "screenshot": "mesh_screenshot.py"}
TOOLS = ("xvfb-run", "pvbatch")


def script(name):
    """The path of the pvbatch script of a command ('check',
    'screenshot')."""
    return os.path.join(os.path.dirname(os.path.abspath(__file__)),
                        "pvbatch", SCRIPTS[name])


def pvd_file(target):
    """The PVD record to check: RUN/solution.pvd for a run folder, else
    the file given."""
    if os.path.isdir(target):
        return os.path.join(target, "solution.pvd")
    return target


def command(name, arguments):
    """The command line that runs a script: xvfb-run -a pvbatch SCRIPT
    ARGUMENTS."""
    return ["xvfb-run", "-a", "pvbatch", script(name)] + list(arguments)


def missing_tools():
    """The programs of TOOLS that are not on the PATH."""
    return [tool for tool in TOOLS if shutil.which(tool) is None]


def main(argv=None):
    """python3 -m rsfcycle.paraview check|screenshot ..."""
    parser = argparse.ArgumentParser(
        prog="python3 -m rsfcycle.paraview",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description=__doc__.split("\n\n", 1)[1])
    commands = parser.add_subparsers(dest="command", required=True)
    check = commands.add_parser("check", help="the arrays of a PVD record")
    check.add_argument("target", metavar="RUN|FILE.pvd")
    picture = commands.add_parser("screenshot",
                                  help="a picture of a 2D run's mesh")
    picture.add_argument("run", metavar="RUN")
    picture.add_argument("out", metavar="OUT.png")
    picture.add_argument("field", metavar="FIELD", nargs="?",
                         default="material_id")
    args = parser.parse_args(argv)
    if args.command == "check":
        arguments = [pvd_file(args.target)]
        if not os.path.exists(arguments[0]):
            print(f"{arguments[0]}: not found (a run with vtu in Output/Writers "
                  "writes it)", file=sys.stderr)
            return 2
    else:
        arguments = [args.run, args.out, args.field]
    missing = missing_tools()
    if missing:
        print(f"{', '.join(missing)} not found: install the Debian packages "
              "paraview, python3-paraview and xvfb", file=sys.stderr)
        return 2
    return subprocess.run(command(args.command, arguments)).returncode


if __name__ == "__main__":
    sys.exit(main())
