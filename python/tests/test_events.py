# SPDX-License-Identifier: LGPL-2.1-or-later
"""rsfcycle.events on the tiny 2D wedge run of fixtures/run: three events
at 10, 20 and 30 s, each 0.15 s long; the surface at 15 cm rises by 50 µm
in each (plus the 1 µm/s of the loading)."""

import math
import os
import shutil

import pytest

from rsfcycle import drawing, events, run

RUN = os.path.join(os.path.dirname(os.path.abspath(__file__)), "fixtures",
                   "run")


def test_read_the_catalogue():
    found = events.read(RUN)
    assert [e.number for e in found] == [1, 2, 3]
    assert [e.start for e in found] == [10, 20, 30]
    assert math.isnan(found[0].recurrence)
    assert found[1].recurrence == 10
    assert found[2].slip_um == 186
    assert math.isclose(found[0].duration, 0.15)


def test_read_without_events_csv(tmp_path):
    assert events.read(str(tmp_path)) is None


def test_detect_from_the_series_and_the_profile():
    ts = drawing.series(RUN)
    found = events.detect(ts["time_s"], ts["max_slip_rate_m_per_s"], 5e-5,
                          10, drawing.profile(RUN))
    assert [e.start for e in found] == [10, 20, 30]
    assert [round(e.end, 2) for e in found] == [10.15, 20.15, 30.15]
    first = found[0]
    assert first.nucleation == 0.27
    # nodes above 10 v0 at the peak: 0.22, 0.27, 0.32
    assert math.isclose(first.width, 0.1)
    assert first.slip_um > 0
    assert found[1].recurrence == 10
    assert all(math.isnan(e.width) for e in events.detect(
        ts["time_s"], ts["max_slip_rate_m_per_s"], 5e-5, 10))


def test_transition_rule():
    parameters = run.parameters(RUN)
    assert events.transition(parameters) == (1, 0.0)
    assert events.transition({}) == (2, 0.0)
    assert events.transition(parameters, time=15.0) == (0, 15.0)
    assert events.transition(parameters, events=3) == (3, 0.0)
    found = events.read(RUN)
    assert [events.in_transition(i, e, (1, 0.0))
            for i, e in enumerate(found)] == [True, False, False]
    assert [events.in_transition(i, e, (0, 25.0))
            for i, e in enumerate(found)] == [True, True, False]


def test_jumps_of_the_uplift():
    ts = drawing.series(RUN)
    jump = events.jumps(ts["time_s"], ts["uplift_15cm_m"], [10, 20],
                        [10.15, 20.15])
    assert jump == pytest.approx([50.15e-6, 50.15e-6], rel=1e-3)


def test_means_after_the_transition():
    row = events.means(RUN, skip=0)
    assert row["events"] == 3
    assert row["recurrence_s"] == 10
    assert row["slip_um"] == pytest.approx(183)
    assert row["uplift_15cm_um"] == pytest.approx(50.15, rel=1e-3)
    assert row["uplift_45cm_um"] == pytest.approx(-5.955, rel=1e-3)
    with pytest.raises(SystemExit):
        events.means(RUN, skip=1)


def test_differences_between_catalogues():
    found = events.read(RUN)
    same = events.differences(found, found)
    assert same == {"events": 3, "reference_events": 3, "start": 0,
                    "peak": 0, "slip": 0}
    moved = [events.Event(e.number, e.start + 1e-3, e.end, peak=e.peak,
                          slip_um=1.1 * e.slip_um) for e in found[:2]]
    other = events.differences(moved, found)
    assert other["events"] == 2
    assert other["start"] == pytest.approx(1e-3)
    assert other["slip"] == pytest.approx(0.1)


def test_progress_and_cycles():
    points = events.progress(RUN)
    assert points == [(8.0, 2), (20.1, 6), (32.0, 10)]
    assert events.wall_at(points, 14.05) == pytest.approx(4)
    assert events.wall_at(points, 40) is None
    stats = events.cycles(RUN)
    assert stats["cycles"] == 2
    assert stats["recurrence"] == 10
    assert stats["unknowns"] == 290
    assert stats["fixed_point_iterations"] == (2, 2.0)
    assert stats["wall_per_cycle"] == pytest.approx(
        (events.wall_at(points, 30) - events.wall_at(points, 10)) / 2)
    assert events.cycles(RUN, 1)["first"] == 20


def test_cycles_need_two_events(tmp_path):
    folder = tmp_path / "run"
    shutil.copytree(RUN, folder)
    lines = (folder / "events.csv").read_text().splitlines()
    (folder / "events.csv").write_text("\n".join(lines[:2]) + "\n")
    with pytest.raises(SystemExit):
        events.cycles(str(folder))


def test_catalogue_lines_mark_the_transition():
    lines = events.catalogue_lines(events.read(RUN), (1, 0.0))
    assert len(lines) == 4
    assert lines[1].endswith("(transition)")
    assert not lines[2].endswith("(transition)")
    km = events.catalogue_lines(events.read(RUN), length_unit="km", dip=30)
    assert "depth [km]" in km[0]


def test_main_prints_catalogue_and_cycles(capsys):
    assert events.main([RUN, "--cycles", "2"]) == 0
    out = capsys.readouterr().out
    assert "cycles measured: 2" in out
    assert "mean recurrence time: 10 s" in out
    assert "(transition)" in out


def test_main_in_years_and_km(capsys):
    assert events.main([RUN, "--unit", "yr", "--length-unit", "km",
                        "--dip", "15"]) == 0
    assert "nucleation depth [km]" in capsys.readouterr().out


def test_main_without_a_catalogue(tmp_path):
    with pytest.raises(SystemExit):
        events.main([str(tmp_path)])
