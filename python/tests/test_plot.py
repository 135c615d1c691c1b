# SPDX-License-Identifier: LGPL-2.1-or-later
"""rsfcycle.plot and rsfcycle.wedge_plots on the tiny run folder of
fixtures/run (a 2D wedge with three events) and on 3D and spring-slider
folders the tests write themselves."""

import math
import os
import shutil

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from rsfcycle import drawing, plot, wedge_plots  # noqa: E402

RUN = os.path.join(os.path.dirname(os.path.abspath(__file__)), "fixtures",
                   "run")
PNG = b"\x89PNG"


def is_png(path):
    with open(path, "rb") as f:
        return f.read(4) == PNG


def copy_run(tmp_path, name="run"):
    target = tmp_path / name
    shutil.copytree(RUN, target)
    return str(target)


def test_profile_of_the_fixture():
    rates = drawing.profile(RUN)
    assert rates.positions.tolist()[:3] == [0, 0.1, 0.17]
    assert rates.z is None
    assert rates.rates.shape == (len(rates.times), 8)
    assert np.all(np.diff(rates.times) > 0)
    assert rates.times[0] == 0


def test_profile_3d_leaves_out_a_row_cut_short(tmp_path):
    (tmp_path / "base-profile.csv").write_text(
        "# slip rate\ntime_s,0,0,1,1\nz_m,0,1,0,1\n0,1,2,3,4\n"
        "0.5,5,6,7,8\n1,9,10")
    rates = drawing.profile(str(tmp_path))
    assert rates.z.tolist() == [0, 1, 0, 1]
    assert rates.times.tolist() == [0, 0.5]
    assert rates.rates[1].tolist() == [5, 6, 7, 8]


def test_profile_missing_file(tmp_path):
    with pytest.raises(FileNotFoundError):
        drawing.profile(str(tmp_path))


def test_series_leaves_out_a_row_cut_short(tmp_path):
    folder = copy_run(tmp_path)
    full = drawing.series(RUN)
    with open(os.path.join(folder, "time-series.csv"), "a") as f:
        f.write("41,1,2")
    cut = drawing.series(folder)
    assert len(cut["time_s"]) == len(full["time_s"])


def test_kind_and_plate_rate():
    assert plot.kind({"Scene": "wedge", "Dimension": "2"}) == "wedge-2d"
    assert plot.kind({"Scene": "wedge", "Dimension": "3"}) == "wedge-3d"
    assert plot.kind({"Scene": "spring-slider"}) == "cycles"
    assert plot.kind({"Scene": "mesh-file", "Dimension": "2"}) == "cycles"
    assert plot.plate_rate({"Scene": "wedge",
                            "Wedge/Convergence rate": "5e-5"}) == 5e-5
    assert plot.plate_rate({"Scene": "mesh-file",
                            "Mesh file/Load velocity": "3, 4"}) == 5
    assert plot.plate_rate({"Scene": "spring-slider",
                            "Spring slider/Load point velocity": "1e-6"}) \
        == 1e-6


def test_event_window():
    from rsfcycle.events import Event
    found = [Event(k + 1, 10.0 * (k + 1), 10.0 * (k + 1) + 0.2,
                   recurrence=10.0 if k else math.nan) for k in range(3)]
    window, shown = drawing.event_window(found, 35.0, 2)
    assert [e.number for e in shown] == [2, 3]
    assert window == (15.0, 35.0)
    assert drawing.event_window(found, 5.0, 2) == (None, [])


def test_backstop_and_patch():
    parameters = {"Wedge/Convergence rate": "5e-5", "Wedge/Ramp time": "100",
                  "Wedge/Length": "1", "Wedge/Depth": "0.27"}
    lift = wedge_plots.backstop_uplift([0, 100, 200], parameters)
    along = np.array([0, 0.5 * 5e-5 * 100, 0.5 * 5e-5 * 100 + 5e-5 * 100])
    assert np.allclose(lift, along * 0.27 / math.hypot(1, 0.27))
    start, end = wedge_plots.patch_extent({})
    assert math.isclose(end - start, 0.2)
    assert len(wedge_plots.patch_outline({})) == 5


def test_figures_of_the_2d_wedge(tmp_path):
    written = plot.figures(RUN, str(tmp_path))
    names = sorted(os.path.basename(p) for p in written)
    assert names == ["fig3-surface-displacement.png", "fig4-slip-rate.png",
                     "fig5-event-statistics.png", "fig6-solver.png"]
    assert all(is_png(p) for p in written)


def test_figures_without_events_csv(tmp_path, capsys):
    folder = copy_run(tmp_path)
    os.remove(os.path.join(folder, "events.csv"))
    written = plot.figures(folder)
    assert len(written) == 4
    assert os.path.dirname(written[0]) == os.path.join(folder, "figures")
    assert "events found from" in capsys.readouterr().err


def test_fig7_of_two_tolerances(tmp_path):
    runs = []
    for eps in ("1e-3", "1e-4"):
        folder = copy_run(tmp_path, "eps" + eps)
        path = os.path.join(folder, "parameters.prm")
        with open(path) as f:
            text = f.read().replace("Fixed-point tolerance = 1e-4",
                                    f"Fixed-point tolerance = {eps}")
        with open(path, "w") as f:
            f.write(text)
        runs.append(folder)
    assert plot.main(["--fig7"] + runs + ["--out", str(tmp_path)]) == 0
    assert is_png(tmp_path / "fig7-effort-vs-tolerance.png")


def test_main_needs_one_run_without_fig7(tmp_path):
    with pytest.raises(SystemExit):
        plot.main([RUN, RUN])
    assert plot.main([RUN, "--out", str(tmp_path), "--events", "2"]) == 0
    assert is_png(tmp_path / "fig6-solver.png")


def write_3d_run(folder):
    """A 3D wedge folder: 4 x 3 nodes on the base, one event at 10 s."""
    os.makedirs(folder)
    with open(os.path.join(folder, "parameters.prm"), "w") as f:
        f.write("set Dimension = 3\nset Scene = wedge\nsubsection Wedge\n"
                "  set Convergence rate = 5e-5\n  set Width = 0.6\nend\n")
    s = [0.1, 0.2, 0.3, 0.4] * 3
    z = [0.0] * 4 + [0.3] * 4 + [0.6] * 4
    times = [0, 5] + [10 + 0.02 * k for k in range(9)] + [15]
    with open(os.path.join(folder, "base-profile.csv"), "w") as f:
        f.write("# slip rate\ntime_s," + ",".join(map(str, s)) + "\n")
        f.write("z_m," + ",".join(map(str, z)) + "\n")
        for t in times:
            peak = 30 * math.exp(-((t - 10.08) / 0.05) ** 2)
            f.write(f"{t}," + ",".join(
                f"{5e-5 * (1 + peak * math.exp(-((x - 0.25) / 0.1) ** 2)):.4g}"
                for x in s) + "\n")
    with open(os.path.join(folder, "time-series.csv"), "w") as f:
        f.write("time_s,step_size_s,fixed_point_iterations,tnnmg_iterations,"
                "linear_iterations,spatial_problems,max_slip_rate_m_per_s,"
                "all_tnnmg_iterations,all_linear_iterations\n")
        for t, dt in zip(times[1:], np.diff(times)):
            f.write(f"{t},{dt:.3g},2,3,3,3,1e-4,6,6\n")
    with open(os.path.join(folder, "events.csv"), "w") as f:
        f.write("event,start_s,end_s,duration_s,nucleation_position_m,"
                "peak_slip_rate_m_per_s,rupture_width_m,slip_um,"
                "recurrence_s\n1,10.02,10.16,0.14,0.25,1.5e-3,0.2,150,\n")


def test_figures_of_the_3d_wedge(tmp_path):
    folder = str(tmp_path / "wedge-3d")
    write_3d_run(folder)
    written = plot.figures(folder, str(tmp_path))
    assert sorted(os.path.basename(p) for p in written) == [
        "fig10-solver.png", "fig9-fault-slip-rate.png"]
    assert all(is_png(p) for p in written)


def write_slider_run(folder):
    """A spring-slider folder: one node, two events."""
    os.makedirs(folder)
    with open(os.path.join(folder, "parameters.prm"), "w") as f:
        f.write("set Scene = spring-slider\nsubsection Spring slider\n"
                "  set Load point velocity = 1e-6\nend\n")
    times = np.linspace(0, 100, 41)
    rates = 1e-6 * (1 + 1e3 * (np.exp(-((times - 30) / 2) ** 2)
                               + np.exp(-((times - 70) / 2) ** 2)))
    with open(os.path.join(folder, "base-profile.csv"), "w") as f:
        f.write("# slip rate\ntime_s,0\n")
        f.writelines(f"{t:g},{v:.4g}\n" for t, v in zip(times, rates))
    with open(os.path.join(folder, "time-series.csv"), "w") as f:
        f.write("time_s,step_size_s,fixed_point_iterations,tnnmg_iterations,"
                "linear_iterations,spatial_problems,max_slip_rate_m_per_s,"
                "slip_m,slip_rate_m_per_s,state_alpha,friction_coefficient,"
                "all_tnnmg_iterations,all_linear_iterations\n")
        slip = np.cumsum(rates) * 2.5
        for t, v, u in zip(times[1:], rates[1:], slip[1:]):
            f.write(f"{t:g},2.5,2,0,0,3,{v:.4g},{u:.4g},{v:.4g},0.1,0.6,0,0\n")
    with open(os.path.join(folder, "events.csv"), "w") as f:
        f.write("event,start_s,end_s,duration_s,nucleation_position_m,"
                "peak_slip_rate_m_per_s,rupture_width_m,slip_um,"
                "recurrence_s\n1,27.5,32.5,5,0,1e-3,0,100,\n"
                "2,67.5,72.5,5,0,1e-3,0,100,40\n")


def test_figures_of_the_spring_slider(tmp_path):
    folder = str(tmp_path / "slider")
    write_slider_run(folder)
    written = plot.figures(folder, str(tmp_path), time_unit="yr")
    assert sorted(os.path.basename(p) for p in written) == [
        "cycles-observations.png", "cycles-slip-rate.png"]
    assert all(is_png(p) for p in written)


def test_cycles_figures_of_a_contact_with_depth(tmp_path):
    folder = copy_run(tmp_path)
    path = os.path.join(folder, "parameters.prm")
    with open(path) as f:
        text = f.read().replace("set Scene            = wedge",
                                "set Scene            = mesh-file")
    with open(path, "w") as f:
        f.write(text)
    written = plot.figures(folder, str(tmp_path), dip=15, length_unit="km")
    assert [os.path.basename(p) for p in written] == [
        "cycles-slip-rate.png", "cycles-observations.png"]
