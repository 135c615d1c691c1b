# SPDX-License-Identifier: LGPL-2.1-or-later
"""rsfcycle.peers.qdyn (and the helpers of rsfcycle.peers) on a small
QDYN run folder written by the tests: 8 elements, two stations, one
event."""

import os

import numpy as np

from rsfcycle import catalog
from rsfcycle.peers import PeerNotFound, qdyn, source, time_v

N, L = 8, 40e3
DZ = L / N


def fake_run(folder):
    """A QDYN run folder: qdyn.in's first lines, output_vmax, the stations
    at 0 and 7.5 km, one event (steps 40 - 44 above 1 mm/s) with its
    output_dyn_max_0."""
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "qdyn.in"), "w") as f:
        f.write("1    meshdim\n%d    NN\n%.15g 50000    L, W\n3    finite\n"
                % (N, L))
    t = np.arange(100) * qdyn.YEAR  # one step a year
    v = np.full(100, 1e-9)
    v[40:45] = [2e-3, 0.5, 3.0, 0.2, 2e-3]
    ivmax = np.full(100, 3)
    ivmax[42] = 4
    slip = np.where(np.arange(100) >= 44, 2.5, 0.0) + 1e-9 * t
    with open(os.path.join(folder, "output_vmax"), "w") as f:
        f.write("# t ivmax v theta tau dtau_dt slip sigma\n")
        for k in range(100):
            f.write("%.10e %d %.6e 1 2.6e7 0 %.6e 5e7\n"
                    % (t[k], ivmax[k], v[k], slip[k]))
    with open(os.path.join(folder, "iot_depths.txt"), "w") as f:
        f.write("# target_depth_km element_index(0-based) "
                "element_centre_depth_m\n0 0 2500\n7.5 1 7500\n")
    for i, scale in ((0, 1.0), (1, 2.0)):
        with open(os.path.join(folder, "output_ot_%d" % i), "w") as f:
            f.write("# header\n")
            for k in range(100):
                f.write("%.10e 0 0 %.6e 1 %.6e 0 %.6e 5e7\n"
                        % (t[k], scale * v[k], 2.6e7 * scale,
                           scale * slip[k]))
    with open(os.path.join(folder, "output_dyn_max_0"), "w") as f:
        for i in range(1, N + 1):
            x = (i - N / 2 - 0.5) * DZ
            hit = 2 <= i <= 4
            f.write("%g 0 0 0 0 %.10e %g\n"
                    % (x, t[42] if hit else 0.0, 1.0 if hit else 1e-9))
    return t


def test_bp1_fault():
    fault = qdyn.bp1_fault(n=2048)
    z = fault["z"]
    assert abs(z[0] - 40e3 / 4096) < 1e-9
    assert fault["a"][0] == qdyn.A0 and fault["a"][-1] == qdyn.AMAX
    k = np.argmin(abs(z - 16.5e3))
    assert abs(fault["a"][k] - (0.010 + 0.015 * (z[k] - 15e3) / 3e3)) < 1e-12
    assert not fault["deep"].any()
    # tau_0 of BP1: 26.546 MPa (with eta V_init)
    assert abs(fault["tau0"] / 1e6 - 26.546122) < 1e-5
    # steady sliding at V_init: sigma F(V_init, theta_0) = tau_0 - eta V_init
    a, theta = fault["a"][100], fault["theta0"][100]
    f = a * np.arcsinh(qdyn.VINIT / (2 * qdyn.V0) * np.exp(
        (qdyn.F0 + qdyn.B * np.log(qdyn.V0 * theta / 8e-3)) / a))
    assert abs(qdyn.SIGMA * f - (fault["tau0"] - qdyn.ETA * qdyn.VINIT)) < 1
    assert [round(z[i] / 1e3, 1) for i in fault["iot"]][:4] == \
        [0.0, 2.5, 5.0, 7.5]
    deep = qdyn.bp1_fault(n=1024, length=51.2e3, lf=40e3, a_deep=10.0)
    assert deep["deep"].any() and (deep["a"][deep["deep"]] == 10.0).all()
    assert (deep["b"][deep["deep"]] == 0).all()


def test_bp1_fault_needs_a_power_of_2():
    try:
        qdyn.bp1_fault(n=1000)
    except ValueError as e:
        assert "power of 2" in str(e)
    else:
        raise AssertionError("N = 1000 accepted")


def test_bp1_settings():
    s = qdyn.bp1_settings(n=1024, tmax_yr=1200, dc=4e-3)
    assert s["N"] == 1024 and s["FINITE"] == 3 and s["MESHDIM"] == 1
    assert s["TMAX"] == 1200 * 365 * 86400
    assert s["SET_DICT_RSF"]["DC"] == 4e-3
    assert s["SET_DICT_RSF"]["RNS_LAW"] == 2
    assert abs(0.5 * s["MU"] / s["VS"] - qdyn.ETA) < 1e-6


def test_source_and_load_pyqdyn(tmp_path, monkeypatch):
    monkeypatch.delenv("QDYN_SRC", raising=False)
    try:
        qdyn.load_pyqdyn()
    except PeerNotFound as e:
        assert "QDYN_SRC" in str(e)
    else:
        raise AssertionError("no clone accepted")
    try:
        source("QDYN_SRC", str(tmp_path), "src/pyqdyn.py")
    except PeerNotFound as e:
        assert "src/pyqdyn.py" in str(e)
    else:
        raise AssertionError("a folder without pyqdyn.py accepted")
    # a stand-in for QDYN's wrapper: the calls write_input() makes
    (tmp_path / "src").mkdir()
    (tmp_path / "src" / "pyqdyn.py").write_text(
        "import numpy as np\n"
        "class qdyn:\n"
        "    def __init__(self):\n"
        "        self.set_dict = {}\n"
        "    def settings(self, s):\n"
        "        self.set_dict.update(s)\n"
        "    def render_mesh(self):\n"
        "        n = self.set_dict['N']\n"
        "        self.mesh_dict = {k: np.zeros(n) for k in\n"
        "            ('A', 'B', 'TH_0', 'MU_SS', 'IOT', 'X')}\n"
        "    def write_input(self):\n"
        "        with open('qdyn.in', 'w') as f:\n"
        "            f.write('%d %g\\n' % (self.set_dict['N'],\n"
        "                                  self.mesh_dict['A'][0]))\n")
    monkeypatch.setenv("QDYN_SRC", str(tmp_path))
    line = qdyn.write_input(str(tmp_path / "run"), n=256)
    assert "N = 256" in line
    assert (tmp_path / "run" / "qdyn.in").read_text() == "256 0.01\n"
    rows = (tmp_path / "run" / "iot_depths.txt").read_text().splitlines()
    assert len(rows) == 1 + len(qdyn.STATION_DEPTHS_KM)
    assert rows[4].split()[:2] == ["7.5", "47"]  # 40 km / 256: 7.5 km


def test_read_run_and_events(tmp_path):
    t = fake_run(str(tmp_path))
    run = qdyn.read_run(str(tmp_path))
    assert qdyn.read_mesh(str(tmp_path)) == (N, L)
    assert run["n"] == N and run["length"] == L
    assert sorted(run["stations"]) == [0.0, 7.5]
    found, table = qdyn.events(run)
    assert len(found) == 1 and len(table) == 1
    e, row = found[0], table.iloc[0]
    assert e.start == t[40] and e.end == t[45] and e.peak == 3.0
    assert abs(e.jump - (2.5 + 1e-9 * (t[45] - t[39]))) < 1e-9
    assert abs(row.t_start_yr - 40) < 1e-12
    assert row.hypo_km == (3 - 0.5) * DZ / 1e3
    assert row.z_peak_km == (4 - 0.5) * DZ / 1e3
    assert row.rup_top_km == 5.0 and row.rup_bot_km == 20.0
    text = qdyn.report(run, table, regular_from=1)
    assert "| 1 | 40.0000 |" in text and "first event's start: 40.0000" in text


def test_series_and_readers(tmp_path):
    t = fake_run(str(tmp_path / "run"))
    run = qdyn.read_run(str(tmp_path / "run"))
    found, table = qdyn.events(run)
    d = qdyn.series(run, found, max_rows=10)
    assert {"t_yr", "max_slip_rate", "surface_slip", "V_0km", "V_7p5km",
            "tau_MPa_7p5km"} <= set(d.columns)
    # the records around the event are kept, and the last one
    for k in (39, 40, 45, 99):
        assert (abs(d.t_yr - k) < 1e-12).any()
    assert len(d) < 100
    path = str(tmp_path / "series.csv")
    qdyn.series(run, found, max_rows=1000).to_csv(
        path, index=False, float_format="%.10g")
    ts, v, slip = qdyn.read_series(path)
    assert abs(ts[-1] - t[-1]) < 1e-3 and v.max() == 3.0
    # the peer's series gives the same event as its full output
    again = catalog.detect(ts, v, 1e-3, series=slip)
    assert len(again) == 1 and again[0].start == found[0].start
    ts, logv, tau = qdyn.read_station(path, 7.5)
    assert abs(logv.max() - np.log10(6.0)) < 1e-9 and tau[0] == 52.0
    table.to_csv(str(tmp_path / "events.csv"), index=False)
    (e,) = qdyn.read_events(str(tmp_path / "events.csv"))
    assert abs(e.start - found[0].start) < 1e-3 and e.peak == 3.0


def test_stats_command(tmp_path, capsys):
    fake_run(str(tmp_path / "run"))
    md, csv = str(tmp_path / "stats.md"), str(tmp_path / "series.csv")
    assert qdyn.main(["stats", str(tmp_path / "run"), "--md", md,
                      "--csv", csv]) == 0
    assert os.path.exists(str(tmp_path / "stats_events.csv"))
    assert "events (max V > 0.001 m/s): 1" in open(md).read()
    assert qdyn.main(["stats", str(tmp_path / "nothing")]) == 2


def test_time_v(tmp_path):
    path = tmp_path / "time.txt"
    path.write_text(
        "\tUser time (seconds): 1330.50\n\tSystem time (seconds): 2.25\n"
        "\tElapsed (wall clock) time (h:mm:ss or m:ss): 22:16.41\n"
        "\tMaximum resident set size (kbytes): 123456\n")
    out = time_v(str(path))
    assert abs(out["wall_s"] - 1336.41) < 1e-9
    assert abs(out["cpu_s"] - 1332.75) < 1e-9 and out["max_rss_kb"] == 123456
    path.write_text("Elapsed (wall clock) time (h:mm:ss or m:ss): 1:28:03\n")
    assert time_v(str(path)) == {"wall_s": 5283.0}
