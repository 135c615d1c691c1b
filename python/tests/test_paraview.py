# SPDX-License-Identifier: LGPL-2.1-or-later
"""rsfcycle.paraview: the pvbatch scripts it runs and its command lines
(ParaView itself is not needed)."""

import os
import py_compile

from rsfcycle import paraview

RUN = os.path.join(os.path.dirname(os.path.abspath(__file__)), "fixtures",
                   "run")


def test_scripts_are_there_and_compile(tmp_path):
    for name in ("check", "screenshot"):
        path = paraview.script(name)
        assert os.path.isfile(path)
        py_compile.compile(path, cfile=str(tmp_path / (name + ".pyc")),
                           doraise=True)


def test_command_and_pvd_file():
    command = paraview.command("check", ["RUN/solution.pvd"])
    assert command[:3] == ["xvfb-run", "-a", "pvbatch"]
    assert command[3].endswith("check_pvd.py")
    assert command[4:] == ["RUN/solution.pvd"]
    assert paraview.pvd_file(RUN) == os.path.join(RUN, "solution.pvd")
    assert paraview.pvd_file("fault.pvd") == "fault.pvd"


def test_a_missing_record_is_one_line(capsys):
    assert paraview.main(["check", RUN]) == 2
    assert "solution.pvd: not found" in capsys.readouterr().err


def test_missing_tools_are_one_line(monkeypatch, capsys):
    monkeypatch.setattr(paraview.shutil, "which", lambda tool: None)
    assert paraview.missing_tools() == ["xvfb-run", "pvbatch"]
    assert paraview.main(["screenshot", RUN, "mesh.png"]) == 2
    assert "install the Debian packages" in capsys.readouterr().err


def test_runs_the_script(monkeypatch):
    calls = []

    class Done:
        returncode = 0

    monkeypatch.setattr(paraview, "missing_tools", lambda: [])
    monkeypatch.setattr(paraview.subprocess, "run",
                        lambda command: calls.append(command) or Done())
    assert paraview.main(["screenshot", RUN, "mesh.png", "state"]) == 0
    assert calls[0][4:] == [RUN, "mesh.png", "state"]
