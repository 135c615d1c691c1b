# SPDX-License-Identifier: LGPL-2.1-or-later
"""rsfcycle.peers.scycle: the input for BP1-FD on a coarse grid, and a
small SCycle run (log and profiles) made up by the tests."""

import os

import numpy as np

from rsfcycle import seas
from rsfcycle.peers import scycle

YEAR = scycle.YEAR


def coarse():
    """Input options of a small grid (2 km to 10 km, 5 stretched cells)."""
    return dict(h=2.0, hz=10.0, hy=4.0, lz=100.0, ly=50.0, nz2=5, ny2=5)


def test_grid():
    x, r = scycle.grid(0.05, 45.0, 500.0, 150)
    assert len(x) == 901 + 150 and x[-1] == 500.0
    assert np.allclose(np.diff(x[:901]), 0.05)
    assert abs(r - 1.040) < 1e-3  # the 50 m grid of the peer run
    steps = np.diff(x[900:])
    assert np.allclose(steps[1:-1] / steps[:-2], r)
    try:
        scycle.grid(0.03, 10.0, 20.0, 5)
    except ValueError as e:
        assert "multiple" in str(e)
    else:
        raise AssertionError("10 km in steps of 30 m accepted")


def test_petsc_round_trip(tmp_path):
    path = str(tmp_path / "vec")
    scycle.petsc_write(path, [1.5, -2.0, 3e-9])
    assert os.path.getsize(path) == 8 + 3 * 8
    assert list(scycle.petsc_read(path)) == [1.5, -2.0, 3e-9]


def test_initial_conditions():
    z = np.array([0.0, 15.0, 16.5, 18.0, 40.0])
    ic = scycle.initial_conditions(z)
    assert np.allclose(ic["a"], [0.01, 0.01, 0.0175, 0.025, 0.025])
    assert abs(ic["tau0"] - 26.546122) < 1e-5
    # steady sliding at V_init: sigma F(V_init, psi) = tau_0 - eta V_init
    f = ic["a"] * np.arcsinh(scycle.VINIT / (2 * scycle.V0) *
                             np.exp(ic["psi"] / ic["a"]))
    assert np.allclose(scycle.SIGMA * f, ic["tau0"] - scycle.ETA * 1e-9)


def test_write_input(tmp_path):
    line = scycle.write_input(str(tmp_path / "run"), trigger_qd2fd=1e-4,
                              **coarse())
    assert "Ny = 8, Nz = 11" in line
    text = (tmp_path / "run" / "bp1fd.in").read_text()
    assert "Ny = 8\nNz = 11\n" in text
    assert "trigger_qd2fd = 0.0001\n" in text
    assert "trigger_fd2qd = 0.001\n" in text
    assert "momentumBalanceType = quasidynamic_and_dynamic\n" in text
    assert "lockedDepths = [0 40.002000 40.002000 100.0]" in text
    assert "inputDir = %s/\n" % (tmp_path / "run" / "ICs") in text
    assert (tmp_path / "run" / "output").is_dir()
    z = scycle.petsc_read(str(tmp_path / "run" / "ICs" / "z"))
    y = scycle.petsc_read(str(tmp_path / "run" / "ICs" / "y"))
    assert len(z) == len(y) == 8 * 11
    assert list(z[:3]) == [0.0, 2.0, 4.0] and y[10] == 0 and y[11] == 2.0
    tau = scycle.petsc_read(str(tmp_path / "run" / "ICs" / "tau"))
    assert len(tau) == 11 and abs(tau[0] - (26.546122 - 4.62444e-9)) < 1e-5


def test_input_command(tmp_path, capsys):
    assert scycle.main(["input", str(tmp_path / "run"), "--h", "2",
                        "--hz", "10", "--hy", "4", "--nz2", "5", "--ny2",
                        "5", "--lz", "100", "--ly", "50",
                        "--max-num-cycles", "2"]) == 0
    assert "maxNumCycles = 2\n" in (tmp_path / "run" / "bp1fd.in").read_text()
    assert "bp1fd.in: Ny = " in capsys.readouterr().out


def fake_log(path):
    """A log with two spells above 1 mm/s an hour apart (one event) and
    a second event a year later."""
    t = [0.0, 1e7, 2e7, 2e7 + 1, 2e7 + 2, 2e7 + 3, 2e7 + 3603, 2e7 + 3604,
         2e7 + 3605, 2e7 + YEAR, 2e7 + YEAR + 1, 2e7 + YEAR + 2]
    v = [1e-9, 1e-6, 2e-3, 5.0, 1e-4, 1e-4, 2e-3, 1e-4, 1e-5, 0.1, 1e-5,
         1e-9]
    with open(path, "w") as f:
        f.write("some other line\n")
        for k, (tk, vk) in enumerate(zip(t, v)):
            regime = "fully dynamic" if vk > 1e-3 else "quasidynamic"
            f.write(f"{k}: t = {tk!r} s, dt = 1 {regime} | allowed = 1, "
                    f"maxVel = {vk:e}, other = 3\n")
    return t, v


def fake_profiles(t):
    """Profiles at the log's times: 21 nodes every 2 km, the slip of the
    first event 2 m at the surface (decreasing with depth)."""
    z = np.arange(21) * 2.0
    t = np.array(t)
    jump = np.where(t >= 2e7 + 2, 2.0, 0.0) + np.where(t > 2e7 + YEAR, 1.0,
                                                       0.0)
    slip = np.outer(jump, 1 - z / 80.0) + 1e-12 * t[:, None]
    v = np.full((len(t), 21), 1e-9)
    v[3, 6] = 5.0  # the peak at 12 km
    v[4, 6] = 2e-3
    v[2, 5] = 2e-3  # the first node above the threshold at 10 km
    return {"z": z, "t": t, "dynamic": np.zeros(len(t), bool), "slip": slip,
            "V": v, "tau": np.full((len(t), 21), 26.5),
            "psi": np.full((len(t), 21), 0.6)}


def test_log_events_table(tmp_path):
    t, v = fake_log(str(tmp_path / "log.txt"))
    log = scycle.read_log(str(tmp_path / "log.txt"))
    assert list(log["t"]) == t and list(log["vmax"]) == v
    assert log["dynamic"].sum() == 4 and log["step"][-1] == 11
    found = scycle.events(log)
    assert len(found) == 2
    assert found[0].start == 2e7 and found[0].end == 2e7 + 3604
    assert found[0].peak == 5.0 and found[1].peak == 0.1
    apart = scycle.events(log, merge=0)
    assert len(apart) == 3
    text = scycle.event_table(log, found, fake_profiles(t))
    assert "| 1 | %.4f |  | 3604.0 | 3 | 5.0000 | 12.00 | 2.0000 | 10.00 |" \
        % (2e7 / YEAR) in text
    assert "| 2 | %.4f | 1.000 |" % ((2e7 + YEAR) / YEAR) in text


def test_series_round_trip(tmp_path):
    t, v = fake_log(str(tmp_path / "log.txt"))
    log = scycle.read_log(str(tmp_path / "log.txt"))
    scycle.write_series(str(tmp_path / "series.csv"), log, fake_profiles(t))
    ts, vs, slip = scycle.read_series(str(tmp_path / "series.csv"))
    assert np.allclose(ts, t) and np.allclose(vs, v)
    assert abs(slip[-1] - 3.0 - 1e-12 * t[-1]) < 1e-6  # 8 digits


def test_write_seas(tmp_path):
    t, _ = fake_log(str(tmp_path / "log.txt"))
    files = scycle.write_seas(str(tmp_path / "seas"), fake_profiles(t))
    names = sorted(os.path.basename(f) for f in files)
    assert names[0] == "devol.dat" and "fltst_dp075" in names
    assert len(names) == 13
    f = seas.SeasFile(str(tmp_path / "seas" / "fltst_dp075"))
    assert f.keys["problem"] == "SEAS Benchmark BP1-FD"
    assert f.keys["element_size"] == "2000 m"
    names, rows = seas.table(str(tmp_path / "seas" / "fltst_dp075"))
    assert names == ["t", "slip", "slip_rate", "shear_stress", "state"]
    assert len(rows) == len(t)
    assert abs(rows[-1, 1] - 3.0 * (1 - 7.5 / 80) - 1e-12 * t[-1]) < 1e-9
    assert abs(rows[0, 2] + 9.0) < 1e-9 and rows[0, 3] == 26.5
    assert abs(rows[0, 4] - np.log10(0.008 / 1e-6)) < 1e-9
    positions, times, logv, slip = seas.profile(
        str(tmp_path / "seas" / "devol.dat"))
    assert len(positions) == 81 and positions[-1] == 40e3
    # every 5 years, every second while above 1 mm/s: t = 0 and the three
    # records above; the record a year after the event is not due
    assert list(times) == [0.0, 2e7, 2e7 + 1, 2e7 + 2]
    assert abs(logv[2] - np.log10(5.0)) < 1e-6
    assert abs(slip[-1, 0] - 2.0 - 1e-12 * times[-1]) < 1e-9
    assert abs(slip[-1, 80] - 2.0 * 0.5 - 1e-12 * times[-1]) < 1e-9


def test_read_profiles(tmp_path):
    import pytest
    h5py = pytest.importorskip("h5py")
    t, _ = fake_log(str(tmp_path / "log.txt"))
    p = fake_profiles(t)
    os.makedirs(str(tmp_path / "output"))
    with h5py.File(str(tmp_path / "output" / "data_context.h5"), "w") as c:
        c["/fault/z"] = p["z"][:, None]
    with h5py.File(str(tmp_path / "output" / "data_1D.h5"), "w") as f:
        f["/time/time1D"] = p["t"][:, None]
        f["/time/regime1D"] = np.zeros((len(t), 1))
        for name, key in (("slip", "slip"), ("slipVel", "V"), ("tau", "tau"),
                          ("psi", "psi")):
            f["/fault/" + name] = p[key][:, :, None]
    read = scycle.read_profiles(str(tmp_path))
    assert np.allclose(read["z"], p["z"]) and np.allclose(read["V"], p["V"])
    assert not read["dynamic"].any()
