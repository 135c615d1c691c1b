# SPDX-License-Identifier: LGPL-2.1-or-later
"""rsfcycle.peers.hbi on coarse grids: the input files, the conversion of
a small made-up HBI output into SEAS files, the event catalogue and the
figures. No HBI is needed."""

import json
import math
import os

import numpy as np
import pytest

from rsfcycle import seas, seas_rules
from rsfcycle.peers import hbi


def outlocs(native, benchmark):
    """The cell ids HBI records (the outloc lines of the input)."""
    inp = hbi.read_input(os.path.join(native, hbi.INPUT_NAME[benchmark]))
    return [int(v) for v in inp["outloc"]]


def fake_output(native, benchmark, shape, steps=40, events=((10, 14),)):
    """Write a made-up HBI output into NATIVE/output: every recorded cell
    slips 1 mm per step, log10 V = -9 but in the events (first and last
    step + 1, log10 V = -1); `shape` is the frames' shape per frame."""
    out = os.path.join(native, "output")
    os.makedirs(out, exist_ok=True)
    k = np.arange(1, steps + 1)
    t = 1e6 * k
    lv = np.full(steps, -9.0)
    for first, end in events:
        lv[(k >= first) & (k < end)] = -1.0
    for cell in outlocs(native, benchmark):
        cols = [k, t, lv, 1e-3 * k + 1e-6 * cell, 20.0 + 0 * k, 50.0 - 0.01 * k,
                0.6 + 0 * k, 0.7 + 0 * k, 0 * k, 0 * k, 0 * k]
        np.savetxt(os.path.join(out, f"local0-{cell}.dat"), np.column_stack(cols))
    with open(os.path.join(out, "monitor0.dat"), "w") as f:
        f.write("0 0.0 -9.0 0 0 50.0 50.0 0 0 ****** 0.1 1.0\n")
        for i in range(steps):
            f.write(f"{k[i]} {t[i]} {lv[i]} 0 0 51.0 49.0 1e-7 1e3 0 0.1 2.5\n")
    size = int(np.prod(shape))
    frames = np.arange(5)
    with open(os.path.join(out, "time0.dat"), "w") as f:
        for i in frames:
            f.write(f"{i} {i * 8e6}\n")
    for name, value in (("slip", 1.0), ("vel", 1e-9), ("tau", 20.0)):
        data = np.concatenate([value * (i + 1) * np.ones(size) for i in frames])
        data.astype("<f8").tofile(os.path.join(out, name + "0.dat"))
    with open(os.path.join(out, "event0.dat"), "w") as f:
        for n, (first, _) in enumerate(events, 1):
            f.write(f"{n} {first} {1e6 * first} 7.0 1\n")


def test_source_needs_a_folder(monkeypatch):
    monkeypatch.delenv("HBI_SRC", raising=False)
    with pytest.raises(hbi.HbiError, match="HBI_SRC"):
        hbi.source()
    assert hbi.source("x") == os.path.abspath("x")
    assert hbi.main(["build", "bp5"]) == 2


def test_patches_exist_and_name_builds(tmp_path):
    for benchmark in hbi.BENCHMARKS:
        for path in hbi.patch_files(benchmark):
            assert os.path.exists(path), path
    assert hbi.build_name(hbi.patch_files("bp7")) == "hbi-bp5-hbi-bp7"
    p = tmp_path / "a.patch"
    p.write_text("x")
    assert hbi._stamp([str(p)]).startswith(hbi.COMMIT)


def test_weights():
    centres = [-1.5, -0.5, 0.5, 1.5]
    assert hbi._weights(0.0, centres) == [(1, 0.5), (2, 0.5)]
    assert hbi._weights(-0.5, centres) == [(1, 1.0)]
    assert hbi._weights(-3.0, centres) == [(0, 1.0)]
    assert hbi._weights(9.0, centres) == [(3, 1.0)]


@pytest.mark.parametrize("benchmark,cell,names", [
    ("bp3", 2500.0, seas_rules.BP3_STATIONS),
    ("bp4", 10e3, seas_rules.BP4_STATIONS),
    ("bp5", 10e3, seas_rules.BP5_STATIONS),
    ("bp6", 100.0, seas_rules.BP6_STATIONS),
    ("bp7", 100.0, seas_rules.BP7_STATIONS)])
def test_input(tmp_path, benchmark, cell, names):
    path = hbi.write_input(benchmark, str(tmp_path), cell=cell)
    inp = hbi.read_input(path)
    meta = json.load(open(tmp_path / "stations.json"))
    assert [s["name"] for s in meta["stations"]] == names
    for s in meta["stations"]:
        assert abs(sum(c["w"] for c in s["cells"]) - 1) < 1e-12
    assert len(inp["outloc"]) <= hbi.MAX_STATION_CELLS
    assert float(inp["eps_r"][0]) == 1e-6
    assert abs(float(inp["tmax"][0]) * hbi.HBI_YEAR - hbi.DEFAULTS[benchmark]["tend"]) < 1


def test_input_values(tmp_path):
    hbi.write_input("bp3", str(tmp_path / "n"), cell=2500.0, sense="normal", dip=30)
    inp = hbi.read_input(str(tmp_path / "n" / "bp3.in"))
    assert float(inp["vpl"][0]) == -1e-9 and float(inp["dipangle"][0]) == 30
    assert abs(float(inp["tauinit"][0]) + hbi.bp3_tau0() - hbi.ETA * 1e-9) < 1e-9
    hbi.write_input("bp4", str(tmp_path / "4"), cell=1000.0)
    par = np.loadtxt(tmp_path / "4" / "bp4_param.dat", skiprows=1)
    v = par[:, 3]
    assert (v == 0.03).sum() == 121 and ((v > 1e-9) & (v < 0.03)).sum() == 48
    assert abs(hbi.bp4_tau0() - 25.855347) < 1e-6
    hbi.write_input("bp7", str(tmp_path / "7"), cell=10.0)
    par = np.loadtxt(tmp_path / "7" / "bp7_param.dat", skiprows=1)
    assert (par[:, 0] == 0.004).sum() == 1264
    with pytest.raises(hbi.HbiError):
        hbi.write_input("bp4", str(tmp_path / "x"), cell=3000.0)


def test_convert_plane_and_catalogue(tmp_path):
    native, out = str(tmp_path / "native"), str(tmp_path / "out")
    hbi.write_input("bp5", native, cell=10e3)
    fake_output(native, "bp5", (10, 4))
    hbi.convert("bp5", native, out)
    for name in seas_rules.BP5_STATIONS:
        names, rows = seas.table(os.path.join(out, name + ".dat"))
        assert names[:3] == ["t", "slip_2", "slip_3"]
        assert rows[0, 0] == 0 and len(rows) == 41
        if name == "fltst_strk+00dp+00":
            assert rows[0, 3] == pytest.approx(-9.0) and rows[1, 3] == -9.0
    f = seas.SeasFile(os.path.join(out, "global.dat"))
    assert f.keys["problem"] == "SEAS Benchmark BP5-QD"
    _, g = seas.table(os.path.join(out, "global.dat"))
    assert g[1, 2] == pytest.approx(32.04e9 * 2.5 * 1e6)
    x, t, lv, values = seas.profile(os.path.join(out, "slip_2_depth.dat"))
    assert len(x) == 4 and values.shape == (5, 4) and values[2, 0] == 3.0
    x, t, lv, values = seas.profile(os.path.join(out, "stress_2_strike.dat"))
    assert len(x) == 10 and values[0, 0] == 20.0
    events = hbi.catalogue(out, "fltst_strk+00dp+00")
    assert len(events) == 1
    e = events[0]
    assert e["start"] == 10e6 and e["end"] == 14e6 and e["peak"] == pytest.approx(0.1)
    assert e["slip"] == pytest.approx(4e-3)
    assert e["hypo"] == pytest.approx((-45e3, 5e3))
    assert e["moment"] == pytest.approx(32.04e15 * 2.5 * 4e6)
    s = hbi.sequence(events + [dict(e, start=e["start"] + d) for d in (5e6, 9e6, 12e6)])
    assert s["interval"] == pytest.approx(3.5e6) and s["settled"] == pytest.approx(4e6)


@pytest.mark.parametrize("benchmark,cell,shape", [
    ("bp4", 10e3, (10, 8)), ("bp7", 100.0, (8, 8))])
def test_convert_3dp(tmp_path, benchmark, cell, shape):
    native, out = str(tmp_path / "native"), str(tmp_path / "out")
    hbi.write_input(benchmark, native, cell=cell)
    fake_output(native, benchmark, shape)
    hbi.convert(benchmark, native, out)
    assert len(hbi.catalogue(out, "fltst_strk+000dp+000")) == 1
    x, t, lv, values = seas.profile(os.path.join(out, "slip_2_strike.dat"))
    assert x[0] == (-48e3 if benchmark == "bp4" else -390.0)


def test_convert_bp3(tmp_path):
    native, out = str(tmp_path / "native"), str(tmp_path / "out")
    hbi.write_input("bp3", native, cell=2500.0)
    fake_output(native, "bp3", (16,))
    hbi.convert("bp3", native, out)
    names, rows = seas.table(os.path.join(out, "fltst_dp100.dat"))
    assert names == ["t", "slip", "slip_rate", "shear_stress", "normal_stress"]
    assert rows[0, 4] == 50.0 and len(rows) == 41
    lines = [l for l in open(os.path.join(out, "events.txt")) if not l.startswith("#")]
    assert len(lines) == 1 and lines[0].split()[1] == "1.0000000000e+07"
    names, rows = seas.table(os.path.join(out, "srfst_x+08.dat"))
    assert names == ["t", "disp_x", "disp_z"] and rows.shape == (5, 3)
    assert rows[0, 1] == pytest.approx(0.0, abs=1e-12) or rows[0, 0] == 0


def test_bp3_surface_green():
    dip = math.radians(60)
    # a finite segment moves nothing far away
    for x in (-1e4, 1e4):
        u = np.subtract(hbi.bp3_surface_green(x, 1.0, dip), hbi.bp3_surface_green(x, 2.0, dip))
        assert abs(u[0]) < 1e-3 and abs(u[1]) < 1e-3


def test_convert_bp6(tmp_path):
    native, out = str(tmp_path / "native"), str(tmp_path / "out")
    hbi.write_input("bp6", native, cell=100.0, law="S")
    assert "evlaw slip" in open(os.path.join(native, "bp6.in")).read()
    fake_output(native, "bp6", (400,))
    hbi.convert("bp6", native, out)
    names, rows = seas.table(os.path.join(out, "fltst_strk+00.dat"))
    assert names[4:6] == ["pore_pressure", "darcy_vel"]
    assert rows[1, 4] == pytest.approx(0.01)
    x, t, lv, values = seas.profile(os.path.join(out, "slip.dat"))
    assert len(x) == 201 and x[0] == -10e3


def test_darcy():
    assert hbi.bp6_darcy(0.0, 0.0) == 0
    q = hbi.bp6_darcy(np.array([-1.0, 0.0, 1.0]), 86400.0)
    assert q[0] == -q[2] and q[1] == pytest.approx(0.5 * 1.25e-6, rel=1e-6)


def test_figures(tmp_path):
    native, out = str(tmp_path / "native"), str(tmp_path / "hbi")
    hbi.write_input("bp5", native, cell=10e3)
    fake_output(native, "bp5", (10, 4))
    hbi.convert("bp5", native, out)
    with open(os.path.join(out, "rupture.dat"), "w") as f:
        f.write("x2 x3 t\n")
        for i in range(5):
            for j in range(5):
                f.write(f"{i * 1e3} {j * 1e3} {1e7 + i + j}\n")
    hbi.plane_figures([("HBI", out)], str(tmp_path / "fig"), contour=1.0)
    for name in ("max-slip-rate", "slip-depth", "slip-strike", "rupture-HBI"):
        assert os.path.getsize(tmp_path / "fig" / (name + ".png")) > 1000
    assert hbi.catalogue(out, "fltst_strk+00dp+00")[0]["hypo"] == pytest.approx((-45e3, 5e3))


def test_compare_rows_and_formats():
    ours = [dict(start=0.0, peak=1.0, slip=1.0, mw=7.0),
            dict(start=2 * hbi.YEAR, peak=1.1, slip=2.0, mw=7.1)]
    peer = [dict(start=0.0, peak=1.0, slip=1.0, mw=7.0),
            dict(start=1 * hbi.YEAR, peak=1.0, slip=2.0, mw=7.0)]
    rows = hbi.compare_rows(ours, peer, "k.second second the second event\nk.mw mw Mw")
    assert rows[0][:3] == ("k.second", "+100.0", "%")
    assert rows[0][3] == "the second event: 2 against 1 yr"
    assert rows[1][1:3] == ("+0.100", "")
    assert hbi.compare_rows(ours, peer, {"k.p": ("peak", "p")})[0][1] == "+10.0"
    assert hbi.label(1000.0) == "1km" and hbi.label(500.0) == "500m"
    assert hbi.duration(489) == "8 min 9 s" and hbi.duration(11760) == "3 h 16 min"


def test_driver_help(capsys):
    def runs(args):
        """rsfcycle's runs."""
    with pytest.raises(SystemExit) as stop:
        hbi.driver("Title.\n\nMore.", os.path.join("x", "seas-bp5"), "bp5",
                   dict(runs=runs, peer=None), argv=["--help"])
    assert stop.value.code == 0
    assert "HBI into --work" in capsys.readouterr().out
