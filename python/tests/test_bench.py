# SPDX-License-Identifier: LGPL-2.1-or-later
"""rsfcycle.bench, the benchmark drivers' helpers, on the log of
fixtures/run and on small files and commands of the test's own."""

import os
import stat
import sys

import pytest

from rsfcycle import bench, run

RUN = os.path.join(os.path.dirname(os.path.abspath(__file__)), "fixtures",
                   "run")
STATISTICS = (
    "| Section                   | no. calls |   min time  rank |   avg time |"
    "   max time  rank |\n"
    "| TNNMG: line search        |    117016 |     17.17s     1 |     17.22s |"
    "     17.26s     0 |\n"
    "| Time stepping             |         1 |       321s     0 |       321s |"
    "       322s     1 |\n")

def log():
    return bench.text(os.path.join(RUN, "log.txt"))


def test_timer_table_and_mesh():
    sections = bench.timer_sections(log())
    assert sections["Time stepping"] == 12.1
    assert sections["Setup"] == 0.25
    assert sections["Total"] == 12.5
    assert bench.timer_spread(STATISTICS, "Time stepping") == (321, 322)
    assert bench.timer_spread(log(), "Time stepping") is None
    assert bench.mesh(log()) == {"cells": 120, "levels": 4, "unknowns": 290,
                                 "contact_nodes": 8, "cell_min": 0.05,
                                 "cell_max": 0.2}
    assert bench.loop_time("Wall time of the time loop: 0.0477 s\n") == 0.0477
    assert bench.loop_time(log()) is None


def test_step_counts():
    series = run.time_series(RUN)
    counts = bench.step_counts(series)
    assert counts["steps"] == len(series)
    assert counts["fixed_point_iterations"] == (2, 2.0)
    assert counts["tnnmg_iterations"][0] == 4
    window = bench.step_counts(series, after=30)
    assert window["steps"] == len(series[series["time_s"] > 30])


def test_wedge_variant(tmp_path):
    path = bench.wedge_variant(str(tmp_path / "k6.prm"), str(tmp_path / "k6"),
                               6, 1000, {"Solver/Linear correction": "amg"})
    text = open(path).read()
    assert text.splitlines()[0].endswith(os.path.join("prm", "wedge-2d.prm"))
    assert "wedge-2d-pinned.prm" in text.splitlines()[1]
    assert "  set Local refinements = 6" in text
    assert "set End time = 1000" in text
    assert "  set Linear correction = amg" in text
    plain = bench.wedge_variant(str(tmp_path / "p.prm"), "p", 5, 10,
                                pinned=False)
    assert "pinned" not in open(plain).read()


def test_tables(tmp_path):
    path = str(tmp_path / "runs.csv")
    bench.write_table(path, ["a", "b"], [{"a": 1, "b": "x", "c": 3}])
    assert bench.read_table(path) == [{"a": "1", "b": "x"}]
    assert bench.markdown(["a", "b"], [[1, 2]]) == \
        "| a | b |\n|---|---|\n| 1 | 2 |\n"


def test_missing_build_and_peer_exit_2(tmp_path, monkeypatch):
    with pytest.raises(SystemExit) as stop:
        bench.executable(str(tmp_path))
    assert stop.value.code == 2
    monkeypatch.delenv("SOME_PEER_SRC", raising=False)
    with pytest.raises(SystemExit) as stop:
        bench.environment("SOME_PEER_SRC", "a clone of the peer")
    assert stop.value.code == 2
    monkeypatch.setenv("SOME_PEER_SRC", "peer")
    assert bench.environment("SOME_PEER_SRC", "a clone") == "peer"


def test_run_with_log_and_timeout(tmp_path):
    log_file = str(tmp_path / "out.log")
    wall, status = bench.run([sys.executable, "-c", "print('hello')"],
                             log_file)
    assert status == 0 and wall > 0
    assert open(log_file).read() == "hello\n"
    _, status = bench.run([sys.executable, "-c", "import time; "
                           "time.sleep(5)"], log_file, timeout=0.2)
    assert status == 124
    assert bench.mpirun(2, ["x"]) == ["mpirun", "--oversubscribe", "-np", "2",
                                      "x"]


def fake_rsfcycle(tmp_path):
    """A stand-in binary that writes its arguments into args.txt and
    prints the time loop's line."""
    path = tmp_path / "rsfcycle"
    path.write_text(f"#!{sys.executable}\nimport sys\n"
                    f"open({str(tmp_path / 'args.txt')!r}, 'w').write("
                    "' '.join(sys.argv[1:]))\n"
                    "print('Wall time of the time loop: 0.25 s')\n")
    path.chmod(path.stat().st_mode | stat.S_IEXEC)
    return str(path)


def test_resume_a_copy_with_other_entries(tmp_path):
    exe = bench.executable(fake_rsfcycle(tmp_path))
    preload = tmp_path / "pre"
    preload.mkdir()
    (preload / "parameters.prm").write_text("set End time = 520\n")
    (preload / "checkpoint.bin").write_text("state")
    out = str(tmp_path / "window")
    bench.resume(exe, str(preload), out, {"End time": 540,
                                          "Solver/Coupling": "explicit"},
                 str(tmp_path / "window.log"))
    assert (tmp_path / "args.txt").read_text() == f"--resume {out}"
    text = open(os.path.join(out, "parameters.prm")).read()
    assert text.splitlines()[0] == \
        f"include {os.path.join(out, 'preload.prm')}"
    assert "set End time = 540" in text
    assert "  set Coupling = explicit" in text
    assert open(os.path.join(out, "checkpoint.bin")).read() == "state"
    assert (preload / "parameters.prm").read_text() == "set End time = 520\n"
    wall, output = bench.repeat_loop(exe, "x.prm", str(tmp_path / "r.log"),
                                     2)
    assert wall == 0.25 and "time loop" in output


def test_record_writes_results(tmp_path, monkeypatch):
    monkeypatch.setattr(bench, "folder", lambda name: str(tmp_path))
    context = {"commit": "abc1234", "date": "2026-01-02", "load": "idle"}
    bench.record("demo", [("steps", "31,114", "", "time steps")], cores=2,
                 context=context)
    text = open(tmp_path / "results.csv").read()
    assert "steps,\"31,114\",,abc1234,2026-01-02,2,idle,time steps" in text


def test_cli_from_stage_functions(tmp_path, capsys):
    def runs(*cases, build="", work="", depth=6, tol=1e-5, rerun=False,
             law: ("band", "centre") = "band"):
        """Run the cases.

        depth: local refinements
        """
        return cases, build, work, depth, tol, rerun, law

    def against(run: "?" = None, levels: int = 0):
        """A run folder."""
        return run

    def list_(count: int):
        """The cases."""
        return count

    def compare(first, *others, only_=""):
        """Runs against the first."""
        return first, others, only_

    stages = [runs, against, list_, compare]
    assert bench.cli("doc", "demo", stages, ["compare", "a", "b", "c",
                                             "--only", "x"]) == \
        ("a", ("b", "c"), "x")
    got = bench.cli("doc", "demo", stages, ["runs", "a", "b", "--depth",
                                             "7", "--rerun", "--law",
                                             "centre"])
    assert got[0] == ("a", "b") and got[3:] == (7, 1e-5, True, "centre")
    assert got[1].endswith("build")
    assert got[2].endswith(os.path.join("benchmarks", "demo", "runs"))
    assert bench.cli("doc", "demo", stages, ["against"]) is None
    assert bench.cli("doc", "demo", stages, ["against", "RUN"]) == "RUN"
    assert bench.cli("doc", "demo", stages, ["list", "3"]) == 3
    with pytest.raises(SystemExit):
        bench.cli("doc", "demo", stages, ["runs", "--law", "other"])
    with pytest.raises(SystemExit):
        bench.cli("doc", "demo", stages, ["runs", "--help"])
    assert "local refinements (default 6)" in capsys.readouterr().out
    with pytest.raises(SystemExit):
        bench.cli("doc", "demo", stages, [])


def test_resumed_wall_time(tmp_path):
    """A run resumed once: the first segment counts to its progress line at
    the checkpoint's step (12, not 14: those steps were taken again), the
    second to its TimerOutput total."""
    (tmp_path / "log.txt").write_text(
        "*** Step 1: t = 1 s / 9 s, dt = 1 s, wall 0h00m10s, ETA 0h01m00s\n"
        "*** Step 12: t = 5 s / 9 s, dt = 1 s, wall 0h01m40s, ETA 0h00m50s\n"
        "*** Step 14: t = 6 s / 9 s, dt = 1 s, wall 0h02m00s, ETA 0h00m40s\n"
        "Resumed from the checkpoint at t = 5 s, step 12\n"
        "*** Step 13: t = 6 s / 9 s, dt = 1 s, wall 0h00m05s, ETA 0h00m30s\n"
        "| Total wallclock time elapsed since start    |        30s |\n")
    assert run.resumed_wall_time(tmp_path) == 100 + 30
    (tmp_path / "log.txt").write_text("no progress\n")
    assert run.resumed_wall_time(tmp_path) is None
