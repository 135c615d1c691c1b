# SPDX-License-Identifier: LGPL-2.1-or-later
"""rsfcycle.peers.tandem: tandem's BP3 input and its output as BP3's files,
on the small files of fixtures/tandem (tandem's CSV layout)."""

import math
import os
import shutil

import numpy as np
import pytest

from rsfcycle import seas
from rsfcycle.peers import tandem

FIXTURES = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                        "fixtures", "tandem")


def fixture(name):
    return os.path.join(FIXTURES, name)


def test_scenario():
    assert tandem.scenario(60, "thrust") == "bp3_d60_reverse"
    assert tandem.scenario(30, "normal") == "bp3_d30_normal"
    assert tandem.scenario(90, "normal") == "bp3_d90"
    with pytest.raises(ValueError):
        tandem.scenario(60, "strike-slip")


def test_fault_probes_lie_down_dip():
    probes = tandem.fault_probes(60)
    assert [p[0] for p in probes][:3] == ["dp000", "dp025", "dp050"]
    assert len(probes) == 12
    name, x, y = probes[-1]  # 35 km down dip
    assert name == "dp350"
    assert math.isclose(math.hypot(x, y), 35.0)
    assert math.isclose(x, 17.5) and y < 0


def test_input_toml(tmp_path):
    path = tandem.write_input(str(tmp_path), "bp3-d30.msh", dip=30,
                              sense="normal", final_time=3.1536e7)
    text = open(path).read()
    assert 'scenario = "bp3_d30_normal"' in text
    assert 'mesh_file = "bp3-d30.msh"' in text
    assert "final_time = 31536000\n" in text
    assert text.count("{ name = ") == 12 + 2
    assert '{ name = "fn-08", x = [-8.0, 0.0] }' in text
    assert "load_directory" not in text
    assert "load_directory" in tandem.input_toml("m.msh", resume=True)


def test_read_csv_keeps_the_continued_run_and_drops_a_cut_row():
    names, rows = tandem.read_csv(fixture("fltst_dp000.csv"))
    assert names == ["Time", "state", "slip0", "traction0", "slip-rate0",
                     "normal-stress"]
    # 2e8 was written past the checkpoint at 1.5e8; 3e8 is cut short
    assert list(rows[:, 0]) == [0.0, 1e8, 1.5e8, 2.5e8]


def test_fault_station_in_bp3_conventions():
    rows = tandem.fault_station(fixture("fltst_dp000.csv"))
    assert rows.shape == (4, 6)
    t, slip, log10_v, shear, normal, log10_theta = rows.T
    assert slip[3] == 2.5
    assert np.allclose(log10_v, [-9, -9, -6, 0])  # |V| for the sign
    assert math.isclose(shear[0], 26.54612236508921)  # thrust positive
    assert normal[1] == 50.1
    # psi = f0: theta = L / V0 = 8000 s; +0.01 in psi: 0.01 / (b ln 10)
    assert math.isclose(log10_theta[0], math.log10(8000))
    assert math.isclose(log10_theta[1] - log10_theta[0],
                        0.01 / (0.015 * math.log(10)))


def test_surface_station_down_positive_with_velocities():
    t, u1, u2, v1, v2 = tandem.surface_station(fixture("srfst_fn+08.csv")).T
    assert list(u2) == [0.0, 0.2, 0.6]  # tandem's y is up
    assert np.allclose(v1, 0.1) and np.allclose(v2, 0.2)


def test_write_seas_files_read_as_rsfcycle_reads_its_own(tmp_path):
    run = tmp_path / "run"
    shutil.copytree(FIXTURES, run)
    written = tandem.write_seas(str(run), version="b75f666",
                                element_size="250 m, degree 4")
    assert sorted(os.path.basename(p) for p in written) == [
        "fltst_dp000", "global.dat", "srfst_fn+08"]
    station = seas.SeasFile(str(run / "fltst_dp000"))
    assert station.keys["code"] == "tandem"
    assert station.keys["element_size"] == "250 m, degree 4"
    assert station.field_lines == [["t", "slip", "slip_rate",
                                    "shear_stress", "normal_stress",
                                    "state"]]
    names, rows = seas.table(str(run / "global.dat"))
    assert names == ["t", "max_slip_rate"]
    assert np.allclose(rows[:, 1], [-9, -2, 0])
    names, rows = seas.table(str(run / "srfst_fn+08"))
    assert rows.shape == (3, 5) and rows[2, 2] == 0.6


def test_write_seas_refuses_a_folder_without_output(tmp_path):
    with pytest.raises(ValueError):
        tandem.write_seas(str(tmp_path))


def test_cli(tmp_path, capsys):
    run = tmp_path / "run"
    shutil.copytree(FIXTURES, run)
    assert tandem.main(["convert", str(run)]) == 0
    assert "3 files" in capsys.readouterr().out
    assert tandem.main(["input", str(tmp_path), "--mesh", "m.msh"]) == 0
    assert capsys.readouterr().out.strip() == "bp3_d60_reverse"
