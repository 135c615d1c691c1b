# SPDX-License-Identifier: LGPL-2.1-or-later
"""HBI, the boundary-element peer of the SEAS benchmarks BP3 to BP7: its
build at the pinned commit with our patches, its input files, its run, its
output as SEAS files, and the event catalogues and figures that set a run
folder against it.

HBI (So Ozawa, github.com/sozawa94/hbi; Fortran and MPI, lattice
H-matrices, RK45 Cash-Karp) shares no code with rsfcycle. It is not kept
in this repository: HBI_SRC (or an argument) names a clone of it, cloned
there if the folder does not exist. Each set of patches is built in a
folder of its own, SRC/rsfcycle-builds/<patches> unless told otherwise,
from `git archive` of the pinned commit, so the clone itself is never
changed.

    HBI_SRC=HBI python3 -m rsfcycle.peers.hbi build bp5
    HBI_SRC=HBI python3 -m rsfcycle.peers.hbi run bp5 OUT [--cell 500]
    python3 -m rsfcycle.peers.hbi input bp5 NATIVE [--cell 500]
    python3 -m rsfcycle.peers.hbi convert bp5 OUT/native OUT

`run` writes HBI's input into OUT/native, runs HBI there on one core
(one MPI rank, OMP_NUM_THREADS=1, under `nice`), converts its output into
SEAS files in OUT and writes OUT/timing.txt. Lengths on the command line
are in metres, times in seconds (HBI's own `tmax` counts years of 365
days; the input writers convert).

The benchmarks and what HBI runs for them:

- bp3: problem 2dph, a planar dipping fault from the free surface in a
  half-space, shear and normal traction (BP3-QD: dip, thrust or normal);
- bp4: problem 3dp, rectangles in a whole space, one slip component;
- bp5: problem 3dph, Okada's half-space, one slip component;
- bp6: problem 2dp with pois 0 (the antiplane kernel) and the closed-form
  pore pressure with shut-in (patch hbi-bp6-closedform.patch), law A or S;
- bp7: problem 3dp with BP7's prescribed nucleation (patch hbi-bp7.patch).
"""

import argparse
import datetime
import hashlib
import io
import json
import math
import os
import resource
import shutil
import subprocess
import sys
import tarfile
import time

from rsfcycle import catalog, equal, results, run as run_folder, seas, seas_rules

COMMIT = "29b8f905ec5cc4fd83e180da792660ae9825543a"
GIT_URL = "https://github.com/sozawa94/hbi.git"
HBI_YEAR = 365 * 86400.0  # HBI's tmax and dtout count years of 365 days
YEAR = catalog.YEAR  # the SEAS descriptions' year of 365.25 days
BENCHMARKS = ("bp3", "bp4", "bp5", "bp6", "bp7")
MAX_STATION_CELLS = 64  # the cells the output patch records at most

# The patches, relative to the repository's root: hbi-bp5.patch fixes an
# out-of-bounds write of HACApK, records up to 64 cells and writes the
# station and monitor lines in full precision with the moment-rate
# integrand (no physics); BP6 and BP7 add their physics on top.
_P5 = "benchmarks/seas-bp5/peer/hbi-bp5.patch"
PATCHES = {
    "bp3": [_P5],
    "bp4": [_P5],
    "bp5": [_P5],
    "bp6": ["benchmarks/seas-bp6/peer/hbi-bp6-closedform.patch"],
    "bp7": [_P5, "benchmarks/seas-bp7/peer/hbi-bp7.patch"],
}

# What the benchmarks' README runs, per benchmark: cell [m], eps_r, dtmax
# [s], end time [s], field frames between events [HBI yr] and in them [s].
DEFAULTS = {
    "bp3": dict(cell=25.0, eps="1e-6", dtmax="3153600", tend=1500 * HBI_YEAR,
                dtout="1.0", dtout_co="1.0"),
    "bp4": dict(cell=1000.0, eps="1e-6", dtmax="3155760", tend=1000 * YEAR,
                dtout="5.0", dtout_co="1.0"),
    "bp5": dict(cell=1000.0, eps="1e-6", dtmax="3153600", tend=1800 * HBI_YEAR,
                dtout="1.0", dtout_co="1.0"),
    "bp6": dict(cell=10.0, eps="1e-6", dtmax="3600", tend=2 * HBI_YEAR,
                dtout="0.00273972602739726", dtout_co="1.0"),
    "bp7": dict(cell=10.0, eps="1e-6", dtmax="1e6", tend=10 * YEAR,
                dtout="0.01", dtout_co="0.02"),
}
INPUT_NAME = {b: b + ".in" for b in BENCHMARKS}

# the elastic medium of every benchmark: mu [GPa], c_s [km/s], eta [MPa s/m]
MU_GPA, CS_KM_S = 32.04, 3.464
ETA = MU_GPA / (2 * CS_KM_S)


class HbiError(Exception):
    """A problem with HBI's source, build, run or output, in one line."""


# ---------------------------------------------------------------- build

def source(src=None):
    """HBI's clone: `src`, else $HBI_SRC; HbiError when neither is set."""
    src = src or os.environ.get("HBI_SRC")
    if not src:
        raise HbiError("no HBI source: set HBI_SRC to a clone of "
                       "github.com/sozawa94/hbi (cloned there if absent) "
                       "or pass --hbi-src")
    return os.path.abspath(src)


def patch_files(benchmark, root=None):
    """The patch files (absolute paths) a benchmark builds HBI with."""
    root = root or results.repository_root()
    return [os.path.join(root, p) for p in PATCHES[benchmark]]


def build_name(patches):
    """The build folder's name for a list of patch files."""
    stems = [os.path.splitext(os.path.basename(p))[0] for p in patches]
    return "-".join(stems) if stems else "hbi"


def _stamp(patches):
    """The commit and the patches' SHA-256, which a build must match."""
    lines = [COMMIT]
    for p in patches:
        with open(p, "rb") as f:
            lines.append(hashlib.sha256(f.read()).hexdigest() + " " +
                         os.path.basename(p))
    return "\n".join(lines) + "\n"


def build(src, patches, prefix=None, nice=10, log=print):
    """Build HBI at COMMIT with `patches` (applied in order) in
    PREFIX/<patches> (PREFIX: SRC/rsfcycle-builds) and return the path of
    its binary lhbiem. `src` is cloned from $HBI_GIT (default GitHub) if
    absent. A build whose commit and patches match is reused."""
    if not os.path.isdir(src):
        url = os.environ.get("HBI_GIT", GIT_URL)
        log(f"cloning {url} into {src}")
        subprocess.run(["git", "clone", "-q", url, src], check=True)
    if subprocess.run(["git", "-C", src, "cat-file", "-e", COMMIT + "^{commit}"],
                      capture_output=True).returncode != 0:
        raise HbiError(f"{src}: not a clone of HBI with commit {COMMIT[:8]} "
                       f"(git -C {src} fetch)")
    prefix = os.path.abspath(prefix or os.path.join(src, "rsfcycle-builds"))
    dest = os.path.join(prefix, build_name(patches))
    binary = os.path.join(dest, "lhbiem")
    stamp = _stamp(patches)
    stamp_file = os.path.join(dest, ".rsfcycle-build")
    if os.path.exists(binary) and os.path.exists(stamp_file):
        with open(stamp_file) as f:
            if f.read() == stamp:
                return binary
    if shutil.which("mpifort") is None:
        raise HbiError("mpifort not found: HBI needs gfortran and MPI "
                       "(Debian: gfortran libopenmpi-dev)")
    shutil.rmtree(dest, ignore_errors=True)
    os.makedirs(dest)
    tree = subprocess.run(["git", "-C", src, "archive", "--format=tar", COMMIT],
                          check=True, capture_output=True).stdout
    with tarfile.open(fileobj=io.BytesIO(tree)) as archive:
        archive.extractall(dest)
    # a repository of its own, so that git apply works inside any tree
    subprocess.run(["git", "init", "-q", dest], check=True)
    for p in patches:
        subprocess.run(["git", "-C", dest, "apply", p], check=True)
    log(f"building HBI {COMMIT[:8]} + {', '.join(map(os.path.basename, patches))}"
        f" in {dest}")
    flags = ("mpifort -fallow-argument-mismatch -ffree-form "
             "-ffree-line-length-none -O3 -march=native -fopenmp")
    with open(os.path.join(dest, "build.log"), "w") as out:
        done = subprocess.run(["nice", "-n", str(nice), "make", "F90=" + flags],
                              cwd=dest, stdout=out, stderr=subprocess.STDOUT)
    if done.returncode != 0 or not os.path.exists(binary):
        raise HbiError(f"HBI's build failed: {os.path.join(dest, 'build.log')}")
    with open(stamp_file, "w") as f:
        f.write(stamp)
    return binary


# ---------------------------------------------------------------- input

def _weights(v, centres):
    """[(index, weight)] of linear interpolation at v in the sorted cell
    centres (weights > 0); beyond the first or last centre, that cell."""
    if v <= centres[0]:
        return [(0, 1.0)]
    if v >= centres[-1]:
        return [(len(centres) - 1, 1.0)]
    for k in range(len(centres) - 1):
        if centres[k] <= v <= centres[k + 1]:
            t = (v - centres[k]) / (centres[k + 1] - centres[k])
            return [(i, w) for i, w in ((k, 1.0 - t), (k + 1, t)) if w > 1e-12]
    raise ValueError(f"{v}: not between the cell centres")


def _count(length, cell, what):
    """The number of cells of size `cell` in `length` (they must fit)."""
    n = int(round(length / cell))
    if n < 1 or abs(n * cell - length) > 1e-6 * cell:
        raise HbiError(f"a cell of {cell:g} does not divide {what} "
                       f"({length:g})")
    return n


def _write_lines(path, lines):
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def _station_ids(stations, extra=()):
    """The distinct cell ids of the stations (and extra cells), in order."""
    ids = []
    for cells in [s["cells"] for s in stations] + [list(extra)]:
        for c in cells:
            if c["id"] not in ids:
                ids.append(c["id"])
    if len(ids) > MAX_STATION_CELLS:
        raise HbiError(f"{len(ids)} station cells: the patched HBI records "
                       f"at most {MAX_STATION_CELLS}")
    return ids


def _common_lines(o, tmax_s):
    """The input lines every benchmark shares: output, end, tolerance."""
    return ["filenumber 0", "nstep 2000000000", "interval 2000000000",
            "tmax %.17g" % (tmax_s / HBI_YEAR),  # years of 365 d
            "dtout %s" % o["dtout"], "dtout_co %s" % o["dtout_co"],
            "velth 1e-3",  # event list: start at max V > 1e-3
            "eps_r %s" % o["eps"], "dtmax %s" % o["dtmax"]]


# BP3-QD
BP3 = dict(b=0.015, a0=0.010, amax=0.025, L=0.008, f0=0.6, V0=1e-6, sigma=50.0,
           Vp=1e-9, Vinit=1e-9, H=15e3, h=3e3, Wf=40e3)
BP3_STATIONS_KM = [0, 2.5, 5, 7.5, 10, 12.5, 15, 17.5, 20, 25, 30, 35]


def bp3_a(xd):
    """BP3's a at the down-dip distance xd [m]."""
    if xd < BP3["H"]:
        return BP3["a0"]
    return min(BP3["amax"], BP3["a0"] + (BP3["amax"] - BP3["a0"]) *
               (xd - BP3["H"]) / BP3["h"])


def bp3_tau0():
    """BP3's prestress tau0 [MPa] (steady sliding at V_init with a_max)."""
    p = BP3
    f = p["amax"] * math.asinh(p["Vinit"] / (2 * p["V0"]) * math.exp(
        (p["f0"] + p["b"] * math.log(p["V0"] / p["Vinit"])) / p["amax"]))
    return p["sigma"] * f + ETA * p["Vinit"]


def _input_bp3(native, o):
    """bp3.in, bp3_param.dat (a per cell) and stations.json for BP3-QD.
    sense normal flips V_p, V_init and the prestress (HBI's variables are
    signed in the thrust sense); stiffen F multiplies the kernels' mu and
    c_s by F (the damping and prestress stay); sigmaconst holds sigma."""
    cell = o["cell"]
    sg = 1.0 if o["sense"] == "thrust" else -1.0
    n = _count(BP3["Wf"], cell, "40 km down dip")
    tau0 = bp3_tau0()
    stations = []
    for name, km in zip(seas_rules.BP3_STATIONS, BP3_STATIONS_KM):
        k = _count(km * 1e3, cell, "the stations' spacing") if km else 0
        cells = [1] if k == 0 else [k, k + 1]
        stations.append(dict(name=name, x=km * 1e3, cells=[
            dict(id=c, w=1.0 / len(cells), x=(c - 0.5) * cell) for c in cells]))
    ids = sorted(_station_ids(stations))
    _write_lines(os.path.join(native, "bp3_param.dat"),
                 ["a"] + ["%.17g" % bp3_a((i + 0.5) * cell) for i in range(n)])
    lines = ["problem 2dph", "ncellg %d" % n, "ds %.17g" % (cell / 1e3),
             "dipangle %g" % o["dip"], "ztop 0.0",
             "rigid %.17g" % (MU_GPA * o["stiffen"]),
             "vs %.17g" % (CS_KM_S * o["stiffen"]), "pois 0.25",
             ] + _common_lines(o, o["tend"]) + [
             "backslip T", "vpl %g" % (sg * BP3["Vp"]),
             "parameterfromfile T", "parameter_file bp3_param.dat",
             "parameter_file_ncol 1",
             "b %g" % BP3["b"], "dc %g" % BP3["L"], "f0 %g" % BP3["f0"],
             "vref %g" % BP3["V0"], "a %g" % BP3["amax"], "evlaw aging",
             "pressurediffusion F",
             # HBI's tau is the strength tau0 + dtau - eta V
             "tauinit %.17g" % (sg * (tau0 - ETA * BP3["Vinit"])),
             "sigmainit %g" % BP3["sigma"], "velinit %g" % (sg * BP3["Vinit"])]
    if o.get("sigmaconst"):
        lines.append("sigmaconst T")
    lines += ["outloc %d" % c for c in ids]
    return lines, dict(
        problem=f"SEAS Benchmark BP3-QD (dip {o['dip']:g}, {o['sense']})",
        cell_m=cell, ncell=n, dip=o["dip"], sense=o["sense"], tau0=sg * tau0,
        stations=stations, notes=[
            "problem 2dph: half-space edge-dislocation kernels for the shear "
            "and the normal traction"])


# the plane benchmarks BP4, BP5, BP7: HBI's cell k = i jmax + j + 1 (0-based
# i along strike, j down), x2 = (i + 1 - imax/2 - 0.5) ds
def _plane_stations(names, points, xc, x3c, jmax):
    """The stations' cells and bilinear weights at (x2, x3) [km]."""
    out = []
    for name, (s2, s3) in zip(names, points):
        cells = [dict(id=i * jmax + j + 1, x2=xc[i], x3=x3c[j], w=wi * wj)
                 for i, wi in _weights(s2, xc) for j, wj in _weights(s3, x3c)]
        out.append(dict(name=name, x2=s2, x3=s3, cells=cells))
    return out


def _plane_lines(problem, imax, jmax, ds_text, o, extra):
    return ([f"problem {problem}", "imax %d" % imax, "jmax %d" % jmax,
             "ds " + ds_text] + extra + _common_lines(o, o["tend"]))


BP4 = dict(sigma=50.0, a0=0.0065, amax=0.025, b=0.013, L=0.04, f0=0.6, V0=1e-6,
           Vp=1e-9, Vi=0.03)
BP4_POINTS = [(-36, 0), (-22.5, -7.5), (-16.5, -12), (-16.5, 0), (-16.5, 12),
              (0, -21), (0, -12), (0, 0), (0, 12), (0, 21), (16.5, -12),
              (16.5, 0), (16.5, 12), (36, 0)]


def bp4_a(x2, x3):
    """BP4's a at (x2, x3) [km]."""
    r = max(abs(x3) - 15.0, abs(x2) - 30.0) / 3.0
    return min(BP4["a0"] + max(0.0, r) * (BP4["amax"] - BP4["a0"]), BP4["amax"])


def bp4_tau0():
    """BP4's prestress [MPa] (steady sliding at V_p with a_max) + eta V_p."""
    p = BP4
    return p["sigma"] * p["amax"] * math.asinh(p["Vp"] / (2 * p["V0"]) * math.exp(
        (p["f0"] + p["b"] * math.log(p["V0"] / p["Vp"])) / p["amax"])) + ETA * p["Vp"]


def _overlap(c, ds, lo, hi):
    return max(0.0, min(c + ds / 2, hi) - max(c - ds / 2, lo)) / ds


def _solve_v(tau_el, a, psi, sigma, v0):
    """V with tau_el - eta V = sigma a asinh(V/(2 V0) exp(psi/a))."""
    lo, hi = -30.0, 2.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        v = 10.0 ** mid
        if tau_el - ETA * v > sigma * a * math.asinh(v / (2 * v0) * math.exp(psi / a)):
            lo = mid
        else:
            hi = mid
    return 10.0 ** (0.5 * (lo + hi))


def _input_bp4(native, o):
    """bp4.in, bp4_param.dat (a, L, tau, V per cell) and stations.json for
    BP4-QD (problem 3dp). The nucleation square starts at V_i with the
    state unchanged; a cell cut by its edge gets the cell average of the
    elastic prestress, so the perturbation keeps its integral."""
    p, ds = BP4, o["cell"] / 1e3
    imax, jmax = _count(100.0, ds, "100 km"), _count(80.0, ds, "80 km")
    if imax % 2 or jmax % 2:
        raise HbiError("BP4 needs an even number of cells along both sides")
    xc = [(i - imax / 2 - 0.5) * ds for i in range(1, imax + 1)]
    x3c = [(j - jmax / 2 - 0.5) * ds for j in range(1, jmax + 1)]  # -zcol
    t0 = bp4_tau0()
    rows = ["a\tdc\ttau\tvel"]
    for i in range(imax):
        for j in range(jmax):
            a = bp4_a(xc[i], x3c[j])
            psi0 = a * math.log(2 * p["V0"] / p["Vp"] * math.sinh(
                (t0 - ETA * p["Vp"]) / (a * p["sigma"])))
            fr = (_overlap(xc[i], ds, -28.5, -16.5) *
                  _overlap(x3c[j], ds, -13.5, -1.5))
            if fr >= 1 - 1e-12:
                v = p["Vi"]
            elif fr > 0:
                tp = p["sigma"] * a * math.asinh(p["Vi"] / (2 * p["V0"]) *
                                                 math.exp(psi0 / a)) + ETA * p["Vi"]
                v = _solve_v(fr * tp + (1 - fr) * t0, a, psi0, p["sigma"], p["V0"])
            else:
                v = p["Vp"]
            tau = p["sigma"] * a * math.asinh(v / (2 * p["V0"]) * math.exp(psi0 / a))
            rows.append("%.17g\t%.17g\t%.17g\t%.17g" % (a, p["L"], tau, v))
    _write_lines(os.path.join(native, "bp4_param.dat"), rows)
    stations = _plane_stations(seas_rules.BP4_STATIONS, BP4_POINTS, xc, x3c, jmax)
    lines = _plane_lines("3dp", imax, jmax, "%g" % ds, o, [
        "rigid 32.04", "vs 3.464", "pois 0.25"]) + [
        "dtinit 1e-3", "backslip T", "vpl 1d-9", "parameterfromfile T",
        'parameter_file "bp4_param.dat"', "parameter_file_ncol 4",
        "sigmaconst T", "sigmainit 50.0", "b 0.013", "f0 0.6", "vref 1e-6",
        "evlaw aging", "restart F", "pressurediffusion F"]
    lines += ["outloc %d" % k for k in _station_ids(stations)]
    return lines, dict(
        problem="SEAS Benchmark BP4-QD", cell_m=o["cell"], imax=imax, jmax=jmax,
        xc=xc, x3c=x3c, b=p["b"], sigma=p["sigma"], stations=stations,
        region="the 100 km x 80 km rate-and-state rectangle",
        profiles=dict(strike=dict(at=0.0, nodes=[float(x) for x in range(-48, 49)]),
                      depth=dict(at=0.0, nodes=[float(x) for x in range(-36, 37)])),
        notes=["problem 3dp: rectangles in a whole space, closed-form "
               "kernel; creep at V_p outside by back slip",
               "one slip component (along strike): slip_3 = stress_3 = 0, "
               "slip_rate_3 = -20 a placeholder"])


BP5 = dict(sigma=25.0, a0=0.004, amax=0.04, b=0.03, L=0.14, Lnuc=0.13, f0=0.6,
           V0=1e-6, Vp=1e-9, Vi=0.03)
BP5_POINTS = [(-36, 0), (-16, 0), (0, 0), (16, 0), (36, 0), (-24, 10), (-16, 10),
              (0, 10), (16, 10), (0, 22)]


def bp5_a(x2, x3):
    """BP5's a at (x2, x3) [km] (x3 depth)."""
    hs, ht, h, lvw = 2.0, 2.0, 12.0, 60.0
    if hs + ht <= x3 <= hs + ht + h and abs(x2) <= lvw / 2:
        return BP5["a0"]
    if x3 <= hs or x3 >= hs + 2 * ht + h or abs(x2) >= lvw / 2 + ht:
        return BP5["amax"]
    r = max(abs(x3 - hs - ht - h / 2) - h / 2, abs(x2) - lvw / 2) / ht
    return BP5["a0"] + r * (BP5["amax"] - BP5["a0"])


def _input_bp5(native, o):
    """bp5.in, bp5_param.dat (a, L, tau, V per cell) and stations.json for
    BP5-QD (problem 3dph). tau is HBI's strength for the steady state at
    V_p (V_i in the nucleation patch), so that tau + eta V is the
    benchmark's prestress (HBI's examples/bp5r_param.py multiplies eta V
    by sigma). param_file replaces the generated parameters."""
    p, ds = BP5, o["cell"] / 1e3
    imax, jmax = _count(100.0, ds, "100 km"), _count(40.0, ds, "40 km")
    xc = [(i - imax / 2 - 0.5) * ds for i in range(1, imax + 1)]
    zc = [(j - 0.5) * ds for j in range(1, jmax + 1)]
    psi_ss = p["f0"] + p["b"] * math.log(p["V0"] / p["Vp"])
    rows = ["a\tdc\ttau\tvel"]
    for i in range(imax):
        for j in range(jmax):
            a = bp5_a(xc[i], zc[j])
            patch = -30.0 <= xc[i] <= -18.0 and 4.0 <= zc[j] <= 16.0
            v = p["Vi"] if patch else p["Vp"]
            tau = p["sigma"] * a * math.asinh(v / (2 * p["V0"]) * math.exp(psi_ss / a))
            rows.append("%.17g\t%.17g\t%.17g\t%.17g" %
                        (a, p["Lnuc"] if patch else p["L"], tau, v))
    path = os.path.join(native, "bp5_param.dat")
    _write_lines(path, rows)
    if o.get("param_file"):
        with open(o["param_file"]) as f:
            given = f.read().splitlines()
        if len(given) != len(rows):
            raise HbiError(f"{o['param_file']}: {len(given)} lines, "
                           f"{len(rows)} expected")
        shutil.copy(o["param_file"], path)
    stations = _plane_stations(seas_rules.BP5_STATIONS, BP5_POINTS, xc, zc, jmax)
    st = o["stiffen"]
    lines = _plane_lines("3dph", imax, jmax, "%g" % ds, o, [
        "dipangle 90.0", "crake 0.0", "rigid %.17g" % (MU_GPA * st),
        "vs %.17g" % (CS_KM_S * st), "pois 0.25"]) + [
        "dtinit 1e-3", "backslip T", "vpl 1d-9", "parameterfromfile T",
        'parameter_file "bp5_param.dat"', "parameter_file_ncol 4",
        "sigmaconst T", "sigmainit 25.0", "b 0.03", "f0 0.6", "vref 1e-6",
        "evlaw aging", "restart F",
        # HBI leaves it unset: at some cell sizes the stack made it true
        "pressurediffusion F"]
    lines += ["outloc %d" % k for k in _station_ids(stations)]
    return lines, dict(
        problem="SEAS Benchmark BP5-QD", cell_m=o["cell"], imax=imax, jmax=jmax,
        xc=xc, x3c=zc, b=p["b"], sigma=p["sigma"], stations=stations,
        region="the 100 km x 40 km rate-and-state rectangle",
        profiles=dict(strike=dict(at=10.0, nodes=xc), depth=dict(at=0.0, nodes=zc)),
        notes=["problem 3dph: Okada's rectangles in a half-space; creep at "
               "V_p outside by back slip; stations at x3 = 0 take the top "
               "row of cells (centres ds/2 deep)",
               "one slip component (rake 0): slip_3 = stress_3 = 0, "
               "slip_rate_3 = -20 a placeholder"])


# BP6-QD-A/S: 2dp, the injection cell ncellg/2, stations x3 [m]
BP6 = dict(a=0.007, b=0.005, dc=0.004, f0=0.6, V0=1e-6, tauinit=29.2, sigma0=50.0,
           Vinit=1e-12, q0=1.25e-6, toff=100 * 86400.0, alpha=0.1)
BP6_POINTS_M = [-1500, 0, 500, 1000, 1500, 2500, 3500, 5000, 7500]


def _input_bp6(native, o):
    """bp6.in for BP6-QD-A (law A, ageing) or -S (law S, slip): problem
    2dp with pois 0 (the antiplane kernel), the closed-form pore pressure
    with shut-in after 100 days (hbi-bp6-closedform.patch), no loading."""
    cell, law = o["cell"], o["law"]
    n = _count(40e3, cell, "the 40 km fault")
    ic = n // 2  # HBI injects at cell ncellg/2 (1-based)
    stations = []
    for name, x in zip(seas_rules.BP6_STATIONS, BP6_POINTS_M):
        cid = ic + _count(abs(x), cell, "the stations' spacing") * (1 if x > 0 else -1) \
            if x else ic
        stations.append(dict(name=name, x3=x, cells=[dict(id=cid, w=1.0)]))
    lines = ["problem 2dp", "pois 0.0", "rigid 32.04", "vs 3.464",
             "analyticalinjection T", "pressurediffusion F", "injection flowrate",
             "qinj 1.25e-6", "tinj 0.273972602739726",  # 100 d in yr of 365 d
             "kp 1e-13", "eta 1e-3", "beta 1e-8", "phi 0.1",  # alpha = 0.1 m2/s
             "ncellg %d" % n, "ds %r" % (cell / 1000.0),
             "filenumber 0", "nstep 100000000", "interval 100000000",
             "dtout %s" % o["dtout"], "tmax %.17g" % (o["tend"] / HBI_YEAR),
             "eps_r %s" % o["eps"], "dtmax %s" % o["dtmax"],
             "a 0.007", "b 0.005", "dc 0.004", "f0 0.60", "vref 1e-6",
             "evlaw %s" % {"A": "aging", "S": "slip"}[law],
             "tauinit 29.2", "sigmainit 50.0", "velinit 1d-12",
             "sr 0", "vpl 0", "backslip F"]
    lines += ["outloc %d" % s["cells"][0]["id"] for s in stations]
    return lines, dict(problem=f"SEAS Benchmark BP6-{law}", law=law, cell_m=cell,
                       ncell=n, stations=stations, notes=[
                           "problem 2dp with pois 0: the antiplane kernel; "
                           "closed-form pore pressure with shut-in"])


BP7 = dict(sigma=25.0, a0=0.004, amax=0.016, b=0.01, L=0.53e-3, f0=0.6, V0=1e-6,
           Vp=1e-9)
BP7_POINTS_M = [(0, 0), (-100, 0), (0, 100), (100, 0), (0, -100), (-100, -100),
                (-100, 100), (100, -100), (100, 100), (-300, 0), (0, 300), (300, 0),
                (0, -300)]


def bp7_strength0(a):
    """BP7's steady-state strength at V_init [MPa] (tau0 - eta V_init)."""
    p = BP7
    return p["sigma"] * a * math.asinh(p["Vp"] / (2 * p["V0"]) * math.exp(
        (p["f0"] + p["b"] * math.log(p["V0"] / p["Vp"])) / a))


def _input_bp7(native, o):
    """bp7.in, bp7_param.dat and stations.json for BP7-QD (problem 3dp):
    a = 0.004 on the disc r <= 200 m (cell centres), 0.016 outside, steady
    state at V_init; the nucleation of hbi-bp7.patch (keyword
    bp7nucleation). Without it (nucleation False) tau gets + eta V_init, as
    HBI's examples/bp7ar_param.py, since an exact steady state never
    leaves t = 0 (HBI rejects a step with a zero error estimate)."""
    p, ds = BP7, o["cell"] / 1e3
    imax = jmax = _count(0.8, ds, "800 m")
    if imax % 2:
        raise HbiError("BP7 needs an even number of cells along a side")
    xc = [(i - imax / 2 - 0.5) * ds for i in range(1, imax + 1)]
    x3c = list(xc)
    nuc = o.get("nucleation", True)
    rows = ["a\tdc\ttau\tvel"]
    for i in range(imax):
        for j in range(jmax):
            a = p["a0"] if xc[i] ** 2 + x3c[j] ** 2 <= 0.2 * 0.2 else p["amax"]
            tau = bp7_strength0(a) + (0.0 if nuc else ETA * p["Vp"])
            rows.append("%.17g\t%.17g\t%.17g\t%.17g" % (a, p["L"], tau, p["Vp"]))
    _write_lines(os.path.join(native, "bp7_param.dat"), rows)
    points = [(x / 1e3, z / 1e3) for x, z in BP7_POINTS_M]
    stations = _plane_stations(seas_rules.BP7_STATIONS, points, xc, x3c, jmax)
    centre = [dict(id=i * jmax + j + 1, x2=xc[i], x3=x3c[j], w=wi * wj)
              for i, wi in _weights(-0.05, xc) for j, wj in _weights(-0.05, x3c)]
    lines = _plane_lines("3dp", imax, jmax, "%r" % ds, o, [
        "rigid 32.04", "vs 3.464", "pois 0.25"]) + [
        "dtinit 1", "backslip T", "vpl 1d-9", "parameterfromfile T",
        'parameter_file "bp7_param.dat"', "parameter_file_ncol 4",
        "sigmaconst T", "sigmainit 25.0", "b 0.01", "f0 0.6", "vref 1e-6",
        "evlaw aging", "restart F", "pressurediffusion F"]
    lines += ["bp7nucleation T"] if nuc else []
    lines += ["outloc %d" % k for k in _station_ids(stations, centre)]
    nodes = [x / 1e3 for x in range(-390, 391, 10)]
    return lines, dict(
        problem="SEAS Benchmark BP7-QD-A", cell_m=o["cell"], imax=imax, jmax=jmax,
        xc=xc, x3c=x3c, b=p["b"], sigma=p["sigma"], stations=stations,
        nucleation=nuc, nucleation_cells=centre,
        region="the 800 m x 800 m rate-and-state square",
        profiles=dict(strike=dict(at=0.0, nodes=nodes), depth=dict(at=0.0, nodes=nodes)),
        notes=["problem 3dp: square cells in a whole space; BP7's nucleation "
               + ("on" if nuc else "OFF"),
               "one slip component (along strike): slip_3 = stress_3 = 0, "
               "slip_rate_3 = -20 a placeholder"])


_INPUT = {"bp3": _input_bp3, "bp4": _input_bp4, "bp5": _input_bp5,
          "bp6": _input_bp6, "bp7": _input_bp7}


def options(benchmark, **given):
    """The benchmark's defaults (DEFAULTS, and dip 60, sense thrust,
    stiffen 1, law A, nucleation on) updated by the given options that
    are not None."""
    o = dict(DEFAULTS[benchmark], dip=60.0, sense="thrust", stiffen=1.0,
             law="A", nucleation=True, sigmaconst=False, param_file=None)
    o.update({k: v for k, v in given.items() if v is not None})
    if o["sense"] not in ("thrust", "normal"):
        raise HbiError(f"sense {o['sense']}: thrust or normal")
    if o["law"] not in ("A", "S"):
        raise HbiError(f"law {o['law']}: A (ageing) or S (slip)")
    return o


def write_input(benchmark, native, **given):
    """Write HBI's input for the benchmark into the folder `native`: the
    input file (returned), the per-cell parameters and stations.json (the
    stations' cells and weights, and what convert() needs). Options:
    cell [m], eps, dtmax [s], tend [s], dtout, dtout_co; bp3: dip, sense,
    stiffen, sigmaconst; bp5: stiffen, param_file; bp6: law; bp7:
    nucleation."""
    o = options(benchmark, **given)
    os.makedirs(native, exist_ok=True)
    lines, meta = _INPUT[benchmark](native, o)
    meta.update(benchmark=benchmark, eps=o["eps"], dtmax=o["dtmax"], tend=o["tend"])
    with open(os.path.join(native, "stations.json"), "w") as f:
        json.dump(meta, f, indent=1)
    path = os.path.join(native, INPUT_NAME[benchmark])
    _write_lines(path, lines)
    return path


# ---------------------------------------------------------------- run

def run(benchmark, out, binary, nice=10, **given):
    """Write the input into OUT/native, run HBI there (one rank, one
    thread, under nice), convert its output into OUT and write
    OUT/timing.txt; returns the timing as a dict (wall, user, system [s],
    steps, load)."""
    native = os.path.join(out, "native")
    shutil.rmtree(native, ignore_errors=True)
    os.makedirs(os.path.join(native, "output"))
    path = write_input(benchmark, native, **given)
    env = dict(os.environ, OMP_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    context = results.run_context()  # rsfcycle's commit, the date, the load
    load = context["load"]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.time()
    with open(os.path.join(native, "log.txt"), "w") as log:
        subprocess.run(["nice", "-n", str(nice), binary, os.path.basename(path)],
                       cwd=native, stdout=log, stderr=subprocess.STDOUT, env=env)
    wall = time.time() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(os.path.join(native, "log.txt")) as log:
        if "Time exceeds tmax" not in log.read():
            raise HbiError(f"HBI did not reach its end time: "
                           f"{os.path.join(native, 'log.txt')}")
    convert(benchmark, native, out)
    monitor = _monitor(native)
    timing = dict(wall=wall, user=after.ru_utime - before.ru_utime,
                  system=after.ru_stime - before.ru_stime,
                  steps=int(monitor[-1][0]) if monitor else 0, load=load)
    o = options(benchmark, **given)
    with open(os.path.join(out, "timing.txt"), "w") as f:
        f.write(f"code=HBI {COMMIT} + "
                f"{' + '.join(map(os.path.basename, PATCHES[benchmark]))}\n")
        f.write("case=" + " ".join(f"{k}={o[k]}" for k in sorted(o)) + "\n")
        f.write("cores=1 (one MPI rank, OMP_NUM_THREADS=1)\n")
        for key in ("wall", "user", "system"):
            f.write(f"{key}_s={timing[key]:.1f}\n")
        f.write(f"steps={timing['steps']}\nload_at_start={load}\n")
        f.write(f"rsfcycle_commit={context['commit']}\ndate={context['date']}\n")
    return timing


def read_timing(out):
    """OUT/timing.txt of run() as a dict (values as text)."""
    values = {}
    with open(os.path.join(out, "timing.txt")) as f:
        for line in f:
            key, _, value = line.strip().partition("=")
            values[key] = value
    return values


# ---------------------------------------------------------------- convert

def read_input(path):
    """HBI's input file as a dict keyword -> [values]."""
    values = {}
    with open(path) as f:
        for line in f:
            w = line.split()
            if len(w) >= 2:
                values.setdefault(w[0], []).append(w[1])
    return values


def _monitor(native):
    """output/monitor0.dat as lists of floats (the lines that parse)."""
    rows = []
    with open(os.path.join(native, "output", "monitor0.dat")) as f:
        for line in f:
            values = []
            for w in line.split():
                try:
                    values.append(float(w))
                except ValueError:
                    values.append(math.nan)  # an overflowed field (****)
            if len(values) >= 4:
                rows.append(values)
    return rows


def _local(native, cell):
    """output/local0-<cell>.dat: k t log10|V| slip tau sigma mu psi ..."""
    import numpy as np
    return np.loadtxt(os.path.join(native, "output", f"local0-{cell}.dat"), ndmin=2)


def _station(native, cells):
    """The weighted mean of the cells' local output: dict of k, t, slip,
    tau, sigma, lv (log10 of the mean |V|), psi (per cell, with weights)."""
    import numpy as np
    data = [_local(native, c["id"]) for c in cells]
    n = min(len(d) for d in data)
    data = [d[:n] for d in data]
    for d in data[1:]:
        if not np.array_equal(d[:, 1], data[0][:, 1]):
            raise HbiError("the station cells' times differ")
    w = [c["w"] for c in cells]
    return dict(k=data[0][:, 0], t=data[0][:, 1],
                slip=sum(wi * d[:, 3] for wi, d in zip(w, data)),
                tau=sum(wi * d[:, 4] for wi, d in zip(w, data)),
                sigma=sum(wi * d[:, 5] for wi, d in zip(w, data)),
                lv=np.log10(sum(wi * 10.0 ** d[:, 2] for wi, d in zip(w, data))),
                psi=[d[:, 7] for d in data])


def _log10_state(psi, dc, b, f0=0.6, v0=1e-6):
    """log10 theta of HBI's state psi = f0 + b ln(V0 theta / L)."""
    return math.log10(dc / v0) + (psi - f0) / (b * math.log(10.0))


def _header(f, meta, extra):
    f.write("# This is the file header:\n")
    f.write(f"# problem={meta['problem']}\n")
    f.write("# code=HBI (github.com/sozawa94/hbi)\n")
    f.write(f"# version={meta['commit']} + "
            f"{' + '.join(meta['patches'])}\n")
    f.write("# modeler=rsfcycle's peer run\n")
    f.write(f"# date={datetime.date.today():%Y/%m/%d}\n")
    f.write(f"# element_size={meta['cell_m']:g} m\n")
    f.write(f"# time_integration=RK45 Cash-Karp, eps_r={meta['eps']}, "
            f"dtmax={meta['dtmax']} s; times in s\n")
    for line in meta.get("notes", []) + list(extra):
        f.write("# " + line + "\n")


def _series(path, meta, extra, fields, columns, fmt="%22.14e"):
    """Write a time series: header, field line, columns."""
    import numpy as np
    with open(path, "w") as f:
        _header(f, meta, extra)
        f.write(" ".join(fields) + "\n")
        np.savetxt(f, np.column_stack(columns), fmt=fmt)


def _profile(path, meta, extra, fields, positions, t, lvmax, values):
    """Write a profile: header, field lines, row 1 (0 0 positions), rows
    t log10(max V) values."""
    import numpy as np
    with open(path, "w") as f:
        _header(f, meta, extra)
        f.write("".join(line + "\n" for line in fields))
        np.savetxt(f, np.concatenate([[0.0, 0.0], positions])[None, :], fmt="%22.14e")
        np.savetxt(f, np.column_stack([t, lvmax, values]), fmt="%22.14e")


def _frames(native, name, shape):
    """The field frames output/<name>0.dat (doubles) as [frame, *shape]."""
    import numpy as np
    r = np.memmap(os.path.join(native, "output", name + "0.dat"), dtype="<f8", mode="r")
    size = int(np.prod(shape))
    count = r.size // size
    return r[:count * size].reshape((count,) + tuple(shape))


def _frame_times(native):
    import numpy as np
    return np.loadtxt(os.path.join(native, "output", "time0.dat"), ndmin=2)[:, 1]


def convert(benchmark, native, out, commit=COMMIT):
    """HBI's output in the folder `native` (written by run()) as SEAS
    files in `out` (station files with the suffix .dat):
    bp3: fltst_dpXXX.dat (t slip slip_rate shear_stress normal_stress),
    global.dat, events.txt, srfst_x+08.dat and srfst_x-08.dat;
    bp4, bp5, bp7: fltst_strk*.dat, global.dat, slip_2_/stress_2_
    {strike,depth}.dat and events.dat (HBI's event list with hypocentres
    in m); bp6: fltst_strk*.dat, global.dat, slip.dat, shear_stress.dat,
    slip_rate.dat."""
    with open(os.path.join(native, "stations.json")) as f:
        meta = json.load(f)
    meta.update(commit=commit, patches=[os.path.basename(p) for p in PATCHES[benchmark]])
    os.makedirs(out, exist_ok=True)
    if benchmark == "bp3":
        _convert_bp3(native, out, meta)
        surface_bp3(native, out, meta)
    elif benchmark == "bp6":
        _convert_bp6(native, out, meta)
    else:
        _convert_plane(native, out, meta)


def _convert_bp3(native, out, meta):
    import numpy as np
    inp = read_input(os.path.join(native, "bp3.in"))
    tau0, sig0, v0 = (float(inp[k][0]) for k in ("tauinit", "sigmainit", "velinit"))
    m = np.array([r[:7] for r in _monitor(native) if len(r) >= 7])
    m = m[m[:, 0] > 0]  # the k = 0 line is the initial state
    km, tm, lvm = m[:, 0], m[:, 1], m[:, 2]
    series = {}
    for st in meta["stations"]:
        s = _station(native, st["cells"])
        cols = [np.concatenate([[first], s[key]]) for first, key in (
            (0.0, "t"), (0.0, "slip"), (math.log10(abs(v0)), "lv"), (tau0, "tau"),
            (sig0, "sigma"))]
        series[st["x"]] = dict(zip(("t", "slip", "lv", "tau", "sigma"), cols),
                               k=np.concatenate([[0], s["k"]]))
        cells = st["cells"]
        where = (f"cell 1 (centre {meta['cell_m'] / 2:g} m down dip)" if len(cells) == 1
                 else "mean of cells %d and %d (V averaged linearly)" %
                 (cells[0]["id"], cells[1]["id"]))
        _series(os.path.join(out, st["name"] + ".dat"), meta,
                [f"location= on fault, {st['x'] / 1e3:g} km down dip: {where}",
                 "slip thrust positive; slip_rate log10 |V|; stresses in MPa, "
                 "normal stress compression positive (50 + dsigma_n)"],
                ["t", "slip", "slip_rate", "shear_stress", "normal_stress"], cols)
    _series(os.path.join(out, "global.dat"), meta,
            ["max and min normal stress on the fault (MPa)"],
            ["t", "max_slip_rate", "max_normal_stress", "min_normal_stress"],
            [tm, lvm, m[:, 5], m[:, 6]])
    # the catalogue: runs of max V > 1e-3 m/s in the monitor
    s0, s10 = series[0.0], series[10e3]

    def at(s, key, k):
        return s[key][min(np.searchsorted(s["k"], k), len(s["k"]) - 1)]

    above = lvm > -3.0
    lines = ["# BP3-QD events: runs of max slip rate > 1e-3 m/s (HBI %s; 1 yr = "
             "3.1536e7 s); slips at the end (m); sn0: normal stress at 0 km "
             "before and after (MPa)" % meta["commit"][:8],
             "# n t_start_s t_start_yr t_end_s peak_log10Vmax peak_Vmax t_peak_s "
             "slip_0km slip_10km sn0_before sn0_after"]
    i, number = 0, 0
    while i < len(above):
        if not above[i]:
            i += 1
            continue
        j = i
        while j + 1 < len(above) and above[j + 1]:
            j += 1
        ip = i + int(np.argmax(lvm[i:j + 1]))
        je = min(j + 1, len(km) - 1)
        kb, ke = km[i] - 1, km[je]
        number += 1
        lines.append("%d %.10e %.6f %.10e %.6f %.6e %.10e %.6f %.6f %.6f %.6f" % (
            number, tm[i], tm[i] / HBI_YEAR, tm[je], lvm[ip], 10 ** lvm[ip], tm[ip],
            at(s0, "slip", ke), at(s10, "slip", ke), at(s0, "sigma", kb),
            at(s0, "sigma", ke)))
        i = j + 1
    _write_lines(os.path.join(out, "events.txt"), lines)


def bp3_surface_green(x, d, dip):
    """(u_x, u_z) at the surface point x [km] of unit thrust slip on the
    plane from down-dip distance d [km] to infinity, dip in radians
    (plane strain; x > 0 the hanging wall, u_z up)."""
    import numpy as np
    xi, depth = d * np.cos(dip), d * np.sin(dip)
    if depth == 0:
        at, r1, r2 = np.pi / 2 * np.sign(x), 0.0, 0.0
    else:
        z = (x - xi) / depth
        at = np.arctan(z)
        r1 = (np.sin(dip) - z * np.cos(dip)) / (1 + z * z)
        r2 = (np.cos(dip) + z * np.sin(dip)) / (1 + z * z)
    return (-(np.cos(dip) * (at - np.pi / 2) + r1) / np.pi,
            (np.sin(dip) * (at - np.pi / 2) + r2) / np.pi)


def surface_bp3(native, out, meta, points=(-8.0, 8.0), wf=40.0):
    """srfst_x-08.dat and srfst_x+08.dat: the surface displacement at x =
    -8, +8 km from HBI's slip frames (HBI does not compute it): the sum
    over cells of slip times the 2D half-space solution, plus V_p t on the
    plane below wf [km]; the frame in which the hanging wall moves V_p t/2
    up dip and the footwall V_p t/2 down dip far away; u = 0 at t = 0."""
    import numpy as np
    inp = read_input(os.path.join(native, "bp3.in"))
    n, ds, vp = int(inp["ncellg"][0]), float(inp["ds"][0]), float(inp["vpl"][0])
    dip = math.radians(meta["dip"])
    t = _frame_times(native)
    slip = _frames(native, "slip", (n,))
    count = min(len(t), len(slip))
    t, slip = t[:count], np.asarray(slip[:count])
    for x in points:
        g = np.array([np.subtract(bp3_surface_green(x, i * ds, dip),
                                  bp3_surface_green(x, (i + 1) * ds, dip))
                      for i in range(n)])
        cx, cz = bp3_surface_green(x, wf, dip)
        cx, cz = cx - 0.5 * math.cos(dip), cz + 0.5 * math.sin(dip)
        _series(os.path.join(out, "srfst_x%+03d.dat" % int(x)), meta,
                [f"surface displacement at x = {x:+g} km (x > 0 the hanging wall), "
                 "from HBI's slip frames and V_p t below 40 km",
                 "disp_x + in the dip direction, disp_z + up (m); u = 0 at t = 0"],
                ["t", "disp_x", "disp_z"],
                [t, slip @ g[:, 0] + vp * t * cx, slip @ g[:, 1] + vp * t * cz])


def _convert_plane(native, out, meta):
    import numpy as np
    imax, jmax, b = meta["imax"], meta["jmax"], meta["b"]
    par = np.loadtxt(os.path.join(native, f"{meta['benchmark']}_param.dat"),
                     skiprows=1, ndmin=2)  # a dc tau vel
    a, dc = par[:, 0], par[:, 1]
    psi0 = a * np.log(2 * 1e-6 / par[:, 3] * np.sinh(par[:, 2] / (meta["sigma"] * a)))
    lth0 = np.log10(dc / 1e-6) + (psi0 - 0.6) / (b * math.log(10.0))
    fields = ["t", "slip_2", "slip_3", "slip_rate_2", "slip_rate_3",
              "shear_stress_2", "shear_stress_3", "state"]
    for st in meta["stations"]:
        cells = st["cells"]
        s = _station(native, cells)
        ids = [c["id"] - 1 for c in cells]
        w = np.array([c["w"] for c in cells])
        lth = sum(wi * _log10_state(psi, dc[i], b) for wi, i, psi in zip(w, ids, s["psi"]))
        first = [0.0, 0.0, 0.0, math.log10(np.dot(w, par[ids, 3])), -20.0,
                 float(np.dot(w, par[ids, 2])), 0.0, float(np.dot(w, lth0[ids]))]
        z = np.zeros_like(s["t"])
        rows = np.vstack([first, np.column_stack(
            [s["t"], s["slip"], z, s["lv"], z - 20.0, s["tau"], z, lth])])
        _series(os.path.join(out, st["name"] + ".dat"), meta,
                ["location= on fault, x2 = %g m, x3 = %g m; cells %s, weights %s" % (
                    st["x2"] * 1e3, st["x3"] * 1e3,
                    " ".join(str(c["id"]) for c in cells),
                    " ".join("%.3f" % c["w"] for c in cells))],
                fields, rows.T, fmt=["%22.14e"] + ["%15.7e"] * 7)
    mon = np.array([(r[1], r[2], r[-1]) for r in _monitor(native)])
    _series(os.path.join(out, "global.dat"), meta,
            ["moment_rate = mu sum V A over " + meta["region"]],
            ["t", "max_slip_rate", "moment_rate"],
            [mon[:, 0], mon[:, 1], MU_GPA * 1e9 * mon[:, 2] * 1e6],
            fmt=["%22.14e", "%15.7e", "%15.7e"])
    tf = _frame_times(native)
    frames = {q: _frames(native, q, (imax, jmax)) for q in ("slip", "vel", "tau")}
    count = min([len(tf)] + [len(f) for f in frames.values()])
    lvmax = np.array([np.log10(np.abs(frames["vel"][k]).max()) for k in range(count)])
    xc, x3c = np.array(meta["xc"]), np.array(meta["x3c"])
    for quantity, name in (("slip", "slip_2"), ("tau", "stress_2")):
        arr = frames[quantity]
        for line, spec in meta["profiles"].items():
            nodes = np.array(spec["nodes"])
            if line == "strike":  # along x2 at x3 = at
                across = _weights(spec["at"], list(x3c))
                prof = np.array([np.interp(nodes, xc, sum(w * arr[k, :, j] for j, w in across))
                                 for k in range(count)])
                label = "x2"
            else:  # along x3 at x2 = at
                across = _weights(spec["at"], list(xc))
                prof = np.array([np.interp(nodes, x3c, sum(w * arr[k, i, :] for i, w in across))
                                 for k in range(count)])
                label = "x3"
            _profile(os.path.join(out, f"{name}_{line}.dat"), meta,
                     [f"profile along {label} at {'x3' if line == 'strike' else 'x2'}"
                      f" = {spec['at'] * 1e3:g} m, linear between cell centres; "
                      "frames of HBI's dtout and dtout_co"],
                     [label, "t", "max_slip_rate", name], nodes * 1e3, tf[:count],
                     lvmax, prof)
    rows = []
    path = os.path.join(native, "output", "event0.dat")
    if os.path.exists(path):
        with open(path) as f:
            for line in f:
                w = line.split()
                if len(w) >= 5:
                    c = int(w[4]) - 1
                    rows.append([float(w[0]), float(w[1]), float(w[2]), float(w[3]),
                                 c + 1, xc[c // jmax] * 1e3, x3c[c % jmax] * 1e3])
    _series(os.path.join(out, "events.dat"), meta,
            ["HBI's event list: onset at max V > 1e-3 m/s, end below 5e-4 m/s; "
             "the hypocentre is the cell of max V at the onset (centre, m)"],
            ["n", "step", "t_onset", "Mw", "cell", "x2_hypo", "x3_hypo"],
            np.array(rows).reshape(-1, 7).T, fmt="%.10g")


def bp6_darcy(x, t):
    """BP6's closed-form Darcy velocity [m/s] at x [m], t [s] (arrays):
    (q0/2) sgn(x) [erfc(|x|/sqrt(4 alpha t)) - H(t - t_off) erfc(...)],
    at x = 0 its limit x -> 0+."""
    import numpy as np
    erfc = np.vectorize(math.erfc, otypes=[float])
    x, t = np.broadcast_arrays(np.asarray(x, float), np.asarray(t, float))
    out = np.zeros(x.shape)
    on = t > 0
    out[on] = erfc(np.abs(x[on]) / np.sqrt(4 * BP6["alpha"] * t[on]))
    off = t > BP6["toff"]
    out[off] -= erfc(np.abs(x[off]) / np.sqrt(4 * BP6["alpha"] * (t[off] - BP6["toff"])))
    return 0.5 * BP6["q0"] * np.where(x < 0, -1.0, 1.0) * out


def _convert_bp6(native, out, meta):
    import numpy as np
    p, n, cell = BP6, meta["ncell"], meta["cell_m"]
    ic = n // 2 - 1  # 0-based injection cell
    psi0 = p["a"] * math.log(2 * p["V0"] / p["Vinit"] *
                             math.sinh(p["tauinit"] / (p["a"] * p["sigma0"])))
    lth0 = _log10_state(psi0, p["dc"], p["b"])
    for st in meta["stations"]:
        s = _station(native, st["cells"])
        t = s["t"]
        rows = np.vstack([[0.0, 0.0, math.log10(p["Vinit"]), p["tauinit"], 0.0, 0.0, lth0],
                          np.column_stack([t, s["slip"], s["lv"], s["tau"],
                                           p["sigma0"] - s["sigma"], bp6_darcy(st["x3"], t),
                                           _log10_state(s["psi"][0], p["dc"], p["b"])])])
        _series(os.path.join(out, st["name"] + ".dat"), meta,
                [f"location= on fault, x3 = {st['x3']:g} m (cell {st['cells'][0]['id']})",
                 "pore_pressure = sigma0 - HBI's effective normal stress; darcy_vel "
                 "the closed form (HBI does not compute it)"],
                ["t", "slip", "slip_rate", "shear_stress", "pore_pressure", "darcy_vel",
                 "state"], rows.T, fmt=["%22.14e"] + ["%15.7e"] * 6)
    mon = np.array([(r[1], r[2], r[-1]) for r in _monitor(native)])
    _series(os.path.join(out, "global.dat"), meta,
            ["moment_rate = mu sum V dx over |x3| <= 20 km (N/s per m)"],
            ["t", "max_slip_rate", "moment_rate"],
            [mon[:, 0], mon[:, 1], MU_GPA * 1e9 * mon[:, 2] * 1e3],
            fmt=["%22.14e", "%15.7e", "%15.7e"])
    tf = _frame_times(native)
    frames = {q: _frames(native, q, (n,)) for q in ("slip", "vel", "tau")}
    count = min([len(tf)] + [len(f) for f in frames.values()])
    x = np.arange(-10000.0, 10000.0 + 1, 100.0)
    idx = np.array([ic + int(round(v / cell)) for v in x])
    if np.any(np.abs(idx * cell - ic * cell - x) > 1e-3 * cell):
        raise HbiError(f"a cell of {cell:g} m does not divide the profiles' 100 m")
    vel = np.abs(np.asarray(frames["vel"][:count]))
    lvmax = np.log10(vel.max(axis=1))
    for name, values in (("slip", np.asarray(frames["slip"][:count])[:, idx]),
                         ("shear_stress", np.asarray(frames["tau"][:count])[:, idx]),
                         ("slip_rate", np.log10(np.maximum(vel[:, idx], 1e-300)))):
        _profile(os.path.join(out, name + ".dat"), meta,
                 ["profile along x3 from -10 to 10 km every 100 m (cell centres), "
                  "frames of HBI's dtout"],
                 ["z", "t", "max_slip_rate", name], x, tf[:count], lvmax, values)


# ---------------------------------------------------------------- comparisons

def seas_path(folder, name):
    """FOLDER/NAME, or FOLDER/NAME.dat (HBI's station files), or None."""
    for candidate in (name, name + ".dat"):
        path = os.path.join(folder, candidate)
        if os.path.exists(path):
            return path
    return None


def column(folder, name, field):
    """(t, values) of one field of a SEAS time series (rsfcycle's or
    HBI's); FileNotFoundError if the file is absent."""
    path = seas_path(folder, name)
    if path is None:
        raise FileNotFoundError(f"{folder}: no {name}")
    names, rows = seas.table(path)
    return rows[:, 0], rows[:, names.index(field)]


def catalogue(folder, station, field="slip_2", merge=0.0, threshold=1e-3):
    """The events of a SEAS folder (any code's): runs of global.dat's max
    slip rate >= threshold (rsfcycle.catalog.detect, `merge` s). Per event
    a dict: start, end [s], peak [m/s], moment [N m] (the moment rate
    integrated over the event), mw, slip (the station's `field` from start
    to end) and hypo ((x2, x3) [m]: HBI's events.dat, or the first node of
    rsfcycle's rupture.dat for the first event; else None)."""
    import numpy as np
    names, g = seas.table(seas_path(folder, "global.dat"))
    t, logv = g[:, 0], g[:, 1]
    rate = g[:, names.index("moment_rate")] if "moment_rate" in names else None
    ts, slip = column(folder, station, field)
    hypo = []
    path = seas_path(folder, "events.dat")
    if path:
        _, rows = seas.table(path)
        hypo = [(r[2], (r[5], r[6])) for r in rows.reshape(-1, 7)]
    first = None
    path = seas_path(folder, "rupture.dat")
    if path:
        _, rup = seas.table(path)
        if len(rup):
            k = int(np.argmin(rup[:, 2]))
            if rup[k, 2] < 1e9:
                first = (rup[k, 0], rup[k, 1])
    events = []
    for n, e in enumerate(catalog.detect(t, 10.0 ** logv, threshold, merge)):
        i, j = np.searchsorted(t, e.start), np.searchsorted(t, e.end)
        moment = float(np.trapz(rate[i:j + 1], t[i:j + 1])) if rate is not None else math.nan
        near = [h for s, h in hypo if abs(s - e.start) <= 1.0 + 1e-6 * e.start]
        events.append(dict(
            start=e.start, end=e.end, peak=e.peak, moment=moment,
            mw=2 / 3 * (math.log10(moment) - 9.1) if moment > 0 else math.nan,
            slip=float(np.interp(e.end, ts, slip) - np.interp(e.start, ts, slip)),
            hypo=near[0] if near else (first if n == 0 else None)))
    return events


def sequence(events):
    """Figures of a catalogue: first and second start, the mean interval
    after the first event, the mean of the last three intervals, and the
    medians over the events after the first of peak, slip and Mw."""
    import numpy as np
    starts = np.array([e["start"] for e in events])
    later = events[1:]

    def median(key):
        return float(np.median([e[key] for e in later])) if later else math.nan
    steps = np.diff(starts)
    return dict(events=len(events),
                first=starts[0] if len(starts) else math.nan,
                second=starts[1] if len(starts) > 1 else math.nan,
                interval=float(steps[1:].mean()) if len(steps) > 1 else math.nan,
                settled=float(steps[-3:].mean()) if len(steps) >= 3 else math.nan,
                intervals=list(steps),
                peak=median("peak"), slip=median("slip"), mw=median("mw"))


def print_catalogue(label, events, unit=1e3, year=YEAR):
    """Print a catalogue, hypocentres in km (unit 1e3) or m (unit 1)."""
    name = "km" if unit == 1e3 else "m"
    print(f"== {label}: {len(events)} events")
    print(f"   #  start [yr]  peak [m/s]  duration [s]     Mw   slip [m]  "
          f"hypocentre x2, x3 [{name}]")
    for k, e in enumerate(events, 1):
        h = "%.2f, %.2f" % (e["hypo"][0] / unit, e["hypo"][1] / unit) if e["hypo"] else "-"
        print(f"  {k:2d} {e['start'] / year:11.4f} {e['peak']:11.4f} "
              f"{e['end'] - e['start']:13.1f} {e['mw']:6.3f} {e['slip']:10.4f}  {h}")


def plane_figures(runs, out, unit=1e3, gaps=(10 * YEAR, 5.0), contour=2.0):
    """The figures of a 3D comparison into `out`: max-slip-rate.png (every
    run), slip-depth.png and slip-strike.png (slip_2 every gaps[0] s
    between events and every gaps[1] s in them, a panel per run) and
    rupture-LABEL.png (rupture-time contours every `contour` s of the
    first event, for runs with a rupture.dat). runs: [(label, folder)];
    positions in km (unit 1e3) or m (unit 1)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    name = "km" if unit == 1e3 else "m"
    os.makedirs(out, exist_ok=True)
    fig, ax = plt.subplots(figsize=(9, 3.5))
    for label, folder in runs:
        _, g = seas.table(seas_path(folder, "global.dat"))
        ax.plot(g[:, 0] / YEAR, g[:, 1], label=label, lw=0.8)
    ax.set(xlabel="t [yr]", ylabel="log10 max slip rate [m/s]")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "max-slip-rate.png"), dpi=120)
    plt.close(fig)
    for line in ("depth", "strike"):
        fig, axes = plt.subplots(1, len(runs), figsize=(5 * len(runs), 4), squeeze=False)
        for ax, (label, folder) in zip(axes[0], runs):
            path = seas_path(folder, f"slip_2_{line}.dat")
            if path is None:
                continue
            x, t, lv, values = seas.profile(path)
            x = x / unit
            last = -math.inf
            for k in range(len(t)):
                seismic = lv[k] >= -3.0
                if t[k] - last >= gaps[1 if seismic else 0]:
                    colour = "r" if seismic else "b"
                    if line == "depth":
                        ax.plot(values[k], x, color=colour, lw=0.4)
                    else:
                        ax.plot(x, values[k], color=colour, lw=0.4)
                    last = t[k]
            ax.set_title(label)
            if line == "depth":
                ax.invert_yaxis()
                ax.set(xlabel="slip_2 [m]", ylabel=f"x3 [{name}]")
            else:
                ax.set(xlabel=f"x2 [{name}]", ylabel="slip_2 [m]")
        fig.tight_layout()
        fig.savefig(os.path.join(out, f"slip-{line}.png"), dpi=120)
        plt.close(fig)
    for label, folder in runs:
        path = seas_path(folder, "rupture.dat")
        if path is None:
            continue
        _, rup = seas.table(path)
        rup = rup[rup[:, 2] < 1e9]
        if len(rup) < 3:
            continue
        tt = rup[:, 2] - rup[:, 2].min()
        fig, ax = plt.subplots(figsize=(7, 4))
        c = ax.tricontour(rup[:, 0] / unit, rup[:, 1] / unit, tt,
                          levels=np.arange(0, tt.max() + contour, contour), cmap="viridis")
        fig.colorbar(c, ax=ax, label="rupture time [s]")
        ax.invert_yaxis()
        ax.set(xlabel=f"x2 [{name}]", ylabel=f"x3 [{name}]", aspect="equal",
               title=f"{label}: the first event, from {rup[:, 2].min():.3g} s")
        fig.tight_layout()
        fig.savefig(os.path.join(out, f"rupture-{label}.png"), dpi=120)
        plt.close(fig)


# ---------------------------------------------------------------- drivers

def label(cell_m):
    """A cell size as a folder label: 1000 -> '1km', 500 -> '500m'."""
    return f"{cell_m / 1e3:g}km" if cell_m >= 1e3 and cell_m % 1e3 == 0 else f"{cell_m:g}m"


def run_rsfcycle(base, folder, entries=None, ranks=2, binary=None):
    """Run the shipped parameter file `base` (a path from the repository's
    root) with `entries` into FOLDER on RANKS ranks of BINARY (default
    build/rsfcycle): rsfcycle.bench.run_variant."""
    from rsfcycle import bench
    root = results.repository_root()
    binary = os.path.abspath(binary or os.path.join(root, "build", "rsfcycle"))
    if not os.path.isfile(binary):
        raise HbiError(f"{binary}: not built (bash quickstart.sh builds it), "
                       "or give --binary")
    bench.run_variant(binary, os.path.join(root, base), folder, entries, ranks)
    return folder


def context_of(folder):
    """(context, cores) of a run folder for rsfcycle.results.record:
    timing.txt's for HBI's run (the rsfcycle commit of the driver, one
    core), else rsfcycle.bench.context_of."""
    from rsfcycle import bench
    if os.path.exists(os.path.join(folder, "timing.txt")):
        date = datetime.date.fromtimestamp(os.path.getmtime(folder)).isoformat()
        timing = read_timing(folder)
        return dict(commit=timing.get("rsfcycle_commit", "unknown"),
                    date=timing.get("date", date),
                    load=timing.get("load_at_start", "")), 1
    return bench.context_of(folder)


def rsfcycle_times(folder):
    """(the whole run, the time loop, the operator's build) [s] of an
    rsfcycle run folder's log.txt; None for what it does not have."""
    if not os.path.exists(os.path.join(folder, "log.txt")):
        return None, None, None
    return (run_folder.wall_time(folder), run_folder.section_time(folder, "Time stepping"),
            run_folder.section_time(folder, "Green's function operator"))


def hbi_time(folder):
    """(wall, CPU) [s] of an HBI run folder's timing.txt, or (None, None)."""
    if not os.path.exists(os.path.join(folder, "timing.txt")):
        return None, None
    timing = read_timing(folder)
    return float(timing["wall_s"]), float(timing["user_s"]) + float(timing["system_s"])


def duration(seconds):
    """A wall time as the READMEs give it: '396 s', '8 min 9 s', '3 h 16 min'."""
    s = int(round(seconds))
    if s < 100:
        return f"{seconds:.3g} s"
    if s < 3600:
        return f"{s // 60} min {s % 60} s"
    return f"{s // 3600} h {s % 3600 // 60} min"


def signed(x, digits=2):
    """A number with its sign: '+3.40', '-0.09'."""
    return f"{x:+.{digits}f}"


def differences(ours, peer):
    """Relative differences ours/peer - 1 of two catalogues (catalogue()):
    second (the second event's start), interval (mean after the first
    event), settled (mean of the last three intervals), peak and slip
    (medians after the first), first_peak, first_slip, first_start; and
    the differences of Mw: mw (median after the first), first_mw."""
    a, b = sequence(ours), sequence(peer)
    out = {k: a[k] / b[k] - 1 for k in ("second", "interval", "settled", "peak", "slip")}
    out["mw"] = a["mw"] - b["mw"]
    if ours and peer:
        for key in ("peak", "slip", "start"):
            out["first_" + key] = ours[0][key] / peer[0][key] - 1 if peer[0][key] else math.nan
        out["first_mw"] = ours[0]["mw"] - peer[0]["mw"]
    return out


# figure -> (from the sequence or the first event, its key, scale, unit)
FIGURES = {"second": ("seq", "second", 1 / YEAR, "yr"),
           "interval": ("seq", "interval", 1 / YEAR, "yr"),
           "settled": ("seq", "settled", 1 / YEAR, "yr"),
           "peak": ("seq", "peak", 1, "m/s"), "slip": ("seq", "slip", 1, "m"),
           "mw": ("seq", "mw", 1, ""), "first_peak": ("first", "peak", 1, "m/s"),
           "first_slip": ("first", "slip", 1, "m"), "first_mw": ("first", "mw", 1, ""),
           "first_start": ("first", "start", 1, "s")}


def compare_rows(ours, peer, spec, digits=1, places=4):
    """Rows (key, value, unit, description) of results.csv for spec
    [(key, figure, text)], {key: (figure, text)} or lines "key figure
    text" (figure a key of FIGURES): the value is ours against peer in %
    (Mw: the difference), the description the text followed by ': OURS
    against PEER UNIT'."""
    a, b = sequence(ours), sequence(peer)
    if isinstance(spec, str):
        spec = [line.split(None, 2) for line in spec.strip().splitlines()]
    if isinstance(spec, dict):
        spec = [(key, figure, text) for key, (figure, text) in spec.items()]
    rows = []
    for key, figure, text in spec:
        where, name, scale, unit = FIGURES[figure]
        x, y = ((a[name], b[name]) if where == "seq" else
                (ours[0][name] if ours else math.nan, peer[0][name] if peer else math.nan))
        if name == "mw":
            value, value_unit = f"{x - y:+.3f}", ""
        else:
            value, value_unit = signed(100 * (x / y - 1) if y else math.nan, digits), "%"
        rows.append((key, value, value_unit, f"{text}: {x * scale:.{places}g} against "
                     f"{y * scale:.{places}g} {unit}".rstrip()))
    return rows


def record(folder, rows, context, cores):
    """Write rows (key, value, unit, description) into FOLDER/results.csv
    with the run's context, and print them."""
    for key, value, unit, description in rows:
        results.record(folder, key, value, unit, description, cores, context)
        print(f"{key}: {value} {unit}  ({description})")


EQUAL_HELP = """
  equal    the cost at equal accuracy: rsfcycle at its shipped step
           tolerance and 3 and 10 times looser (one rank), HBI at eps_r
           1e-6, 1e-5, 1e-4 (one core), side by side with --run into
           WORK/equal; each code's cheapest run whose catalogue is
           unchanged (rsfcycle.equal), the ratio of the costs into
           results.csv"""


def driver(doc, here, benchmark, commands, extra=None, argv=None, equal=None):
    """The command line of a benchmark's driver: `commands` maps a name to
    its handler (its docstring's first line is the help; `peer` None:
    peer(benchmark, args)), `extra` a name to a function that adds that
    command's own arguments. Every command gets --work (default
    HERE/runs); `runs` gets --binary and --ranks, `peer` HBI's options
    (--hbi-src, --prefix, --nice, --name, the benchmark's run options).
    `equal` (base .prm, shipped tolerance, station, merge [s]) adds the
    command `equal` (equal_command on catalogue()). A missing HBI, build or
    run folder ends with one line and exit status 2."""
    name = os.path.basename(here)
    description, epilog = doc.split("\n\n")[0], doc.split("\n\n", 1)[1]
    if equal:
        def equal_handler(args):
            """The cost at equal accuracy against HBI (each code's cheapest run with unchanged results)."""
            base, shipped, station, merge = equal
            return equal_command(args, here, benchmark, base, shipped,
                                 lambda folder: catalogue(folder, station, merge=merge))
        commands = dict(commands, equal=equal_handler)
        # after the list of commands, before the paragraph on WORK
        head, found, tail = epilog.partition("\n\nWORK is")
        epilog = head + EQUAL_HELP + found + tail
    parser = argparse.ArgumentParser(
        prog=f"PYTHONPATH=python /usr/bin/python3 benchmarks/{name}/run.py",
        description=description, epilog=epilog,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    for command, handler in commands.items():
        if handler is None:
            def handler(args):
                """HBI into --work (HBI_SRC or --hbi-src), on one core."""
                peer(benchmark, args)
        text = handler.__doc__.strip().split("\n")[0]
        p = sub.add_parser(command, help=text, description=text)
        p.add_argument("--work", default=os.path.join(here, "runs"),
                       help=f"the run folders (default benchmarks/{name}/runs)")
        if command == "runs":
            p.add_argument("--binary", help="rsfcycle (default build/rsfcycle)")
            p.add_argument("--ranks", type=int, default=2)
        if command == "peer":
            p.add_argument("--hbi-src", help="HBI's clone (default $HBI_SRC)")
            p.add_argument("--prefix", help="where HBI is built (SRC/rsfcycle-builds)")
            p.add_argument("--nice", type=int, default=10)
            p.add_argument("--name", help="the run folder in --work "
                           "(default hbi-<cells>)")
            add_run_options(p, benchmark)
        if command == "equal":
            equal_arguments(p)
        if extra and command in extra:
            extra[command](p)
        p.set_defaults(handler=handler)
    args = parser.parse_args(argv)
    try:
        return args.handler(args) or 0
    except (HbiError, FileNotFoundError) as e:
        print(f"{name}: {e}", file=sys.stderr)
        return 2


def peer(benchmark, args):
    """The `peer` command of a driver: build HBI, run it with the options
    of `args` into WORK/<--name or hbi-<cells>>; returns the folder."""
    binary = build(source(args.hbi_src), patch_files(benchmark), args.prefix, args.nice)
    o = options(benchmark, **run_options(args))
    out = os.path.join(args.work, args.name or "hbi-" + label(o["cell"]))
    timing = run(benchmark, out, binary, args.nice, **run_options(args))
    print(f"{out}: {timing['steps']} steps, {duration(timing['wall'])} wall, "
          f"{timing['user']:.0f} s CPU")
    return out


# ---------------------------------------------------------------- equal

def equal_arguments(p):
    """The options of a driver's `equal` command (argparse parser `p`)."""
    p.add_argument("--run", action="store_true", help="run the sweeps' missing "
                   "runs first (both codes side by side, one core each)")
    p.add_argument("--binary", help="rsfcycle (default build/rsfcycle)")
    p.add_argument("--hbi-src", help="HBI's clone (default $HBI_SRC)")
    p.add_argument("--prefix", help="where HBI is built (SRC/rsfcycle-builds)")
    p.add_argument("--nice", type=int, default=0)


def rsfcycle_cost(folder, reference):
    """rsfcycle's cost of a run whose time loop ended [s]: the time loop
    plus the operator's build as the sweep's reference run measured it
    (the looser runs read the operator from the reference's file)."""
    return rsfcycle_times(folder)[1] + (rsfcycle_times(reference)[2] or 0.0)


def equal_command(args, here, benchmark, base, shipped, results_of, label="",
                  hbi_options=None, compare=None, within=1e-4, text=None):
    """A driver's `equal` command for a benchmark with HBI as its peer:
    with --run, rsfcycle's sweep (`base` at `shipped` and looser
    tolerances, one rank, the operator built once) and HBI's (equal.HBI_EPS)
    run side by side into WORK/equal, one core each; then each code's
    cheapest unchanged run (`results_of(folder)` gives what `compare`
    compares) and the ratio of the two costs go to results.csv
    (equal.<label>.*, `text` naming the label). The rsfcycle cost is its
    time loop plus the operator's build; HBI's is its whole run."""
    from concurrent.futures import ThreadPoolExecutor
    work = os.path.join(args.work, "equal")
    tag = label + "." if label else ""  # in the keys
    folder_tag = label + "-" if label else ""
    ours = [(f"rsfcycle-{folder_tag}{t}", t) for t in equal.tolerances(shipped)]
    peers = [(f"hbi-{folder_tag}{e}", e) for e in equal.HBI_EPS]
    reference = os.path.join(work, ours[0][0])
    if args.run:
        def sweep_ours():
            for name, t in ours:
                folder = os.path.join(work, name)
                if rsfcycle_times(folder)[1] is not None:
                    continue
                entries = {"Time stepping/Tolerance": t}
                if name != ours[0][0]:
                    entries["Solver/Green operator file"] = os.path.join(
                        reference, "green-operator.bin")
                run_rsfcycle(base, folder, entries, 1, args.binary)

        def sweep_peer():
            binary = build(source(args.hbi_src), patch_files(benchmark),
                           args.prefix, args.nice)
            for name, e in peers:
                folder = os.path.join(work, name)
                if not os.path.exists(os.path.join(folder, "timing.txt")):
                    run(benchmark, folder, binary, args.nice, eps=e,
                        **(hbi_options or {}))

        os.makedirs(work, exist_ok=True)
        with ThreadPoolExecutor(2) as pool:
            for job in [pool.submit(sweep_ours), pool.submit(sweep_peer)]:
                job.result()
    found = {"rsfcycle": [], "HBI": []}
    for name, t in ours:
        folder = os.path.join(work, name)
        if rsfcycle_times(folder)[1] is not None:  # its time loop ended
            found["rsfcycle"].append((name, t, results_of(folder),
                                      rsfcycle_cost(folder, reference), folder))
    for name, e in peers:
        folder = os.path.join(work, name)
        if os.path.exists(os.path.join(folder, "timing.txt")):
            found["HBI"].append((name, e, results_of(folder), hbi_time(folder)[0],
                                 folder))
    for code, runs in found.items():
        if not runs:
            raise FileNotFoundError(f"{work}: no {code} run of the sweep "
                                    "(run.py equal --run)")
    chosen = {}
    for code, runs in found.items():
        chosen[code], states = equal.cheapest_unchanged(runs, compare or equal.unchanged,
                                                        within)
        print(equal.table(code, states))
    a, b = chosen["rsfcycle"], chosen["HBI"]
    x = equal.ratio(a, b)
    print(f"equal accuracy: {a[0]} over {b[0]}: {x:.2f}x")
    what = f" ({text or label})" if label else ""
    rows = [(f"equal.{tag}rsfcycle", a[1], "", "rsfcycle's step tolerance of its cheapest "
             f"run with its results unchanged{what}, of "
             + ", ".join(r[1] for r in found["rsfcycle"])),
            (f"equal.{tag}rsfcycle_cost", duration(a[3]), "",
             f"rsfcycle's time loop at {a[1]} and the operator's build, one rank{what}"),
            (f"equal.{tag}ratio", f"{x:.2f}", "x", "rsfcycle's cost over HBI's at equal "
             f"accuracy, side by side, one core each{what}")]
    record(here, rows, *context_of(a[4]))
    record(here, [(f"equal.{tag}hbi", b[1], "", "HBI's eps_r of its cheapest run with "
                   f"results unchanged{what}, of " + ", ".join(r[1] for r in found["HBI"])),
                  (f"equal.{tag}hbi_cost", duration(b[3]), "",
                   f"HBI's whole run at eps_r {b[1]}, one core{what}")],
           *context_of(b[4]))
    return 0


# ---------------------------------------------------------------- CLI

RUN_OPTIONS = {"bp3": ("dip", "sense", "stiffen", "sigmaconst"),
               "bp4": (), "bp5": ("stiffen", "param_file"), "bp6": ("law",),
               "bp7": ("nucleation",)}


def add_run_options(parser, benchmark=None):
    """The options of `run` and `input` (also the drivers' `peer`): every
    one defaults to the benchmark's (DEFAULTS); with a benchmark, only its
    own."""
    def wanted(name):
        return benchmark is None or name in RUN_OPTIONS[benchmark]
    parser.add_argument("--cell", type=float, help="cell size [m]")
    parser.add_argument("--eps", help="HBI's eps_r (relative RK45 tolerance)")
    parser.add_argument("--dtmax", help="largest time step [s]")
    parser.add_argument("--tend", type=float, help="end time [s]")
    if wanted("dip"):
        parser.add_argument("--dip", type=float, help="bp3: the dip [degrees] (60)")
    if wanted("sense"):
        parser.add_argument("--sense", choices=["thrust", "normal"], help="bp3")
    if wanted("stiffen"):
        parser.add_argument("--stiffen", type=float,
                            help="bp3, bp5: the kernels this many times stiffer, "
                            "the damping unchanged (a sensitivity study)")
    if wanted("sigmaconst"):
        parser.add_argument("--sigmaconst", action="store_true", default=None,
                            help="bp3: hold the normal stress (a diagnostic)")
    if wanted("param_file"):
        parser.add_argument("--param-file", help="bp5: per-cell parameters to "
                            "use instead of the generated ones")
    if wanted("law"):
        parser.add_argument("--law", choices=["A", "S"], help="bp6: ageing or slip law")
    if wanted("nucleation"):
        parser.add_argument("--no-nucleation", dest="nucleation", action="store_false",
                            default=None, help="bp7: without the prescribed nucleation")


def run_options(args):
    """The run options of parsed arguments (add_run_options) as a dict."""
    return {k: getattr(args, k, None) for k in (
        "cell", "eps", "dtmax", "tend", "dip", "sense", "stiffen", "sigmaconst",
        "param_file", "law", "nucleation")}


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="python3 -m rsfcycle.peers.hbi",
        description="HBI, the SEAS benchmarks' peer: build it at the pinned "
        "commit with our patches, write its input, run it, convert its "
        "output to SEAS files. HBI's clone comes from --hbi-src or HBI_SRC.")
    sub = parser.add_subparsers(dest="command", required=True)
    b = sub.add_parser("build", help="build HBI for a benchmark; prints the binary")
    r = sub.add_parser("run", help="input, run (one core) and conversion into OUT")
    i = sub.add_parser("input", help="write HBI's input into NATIVE only")
    c = sub.add_parser("convert", help="convert NATIVE's output into SEAS files in OUT")
    for p in (b, r, i, c):
        p.add_argument("benchmark", choices=BENCHMARKS)
    for p in (b, r):
        p.add_argument("--hbi-src", help="HBI's clone (default: $HBI_SRC)")
        p.add_argument("--prefix", help="where builds go (SRC/rsfcycle-builds)")
        p.add_argument("--nice", type=int, default=10)
    r.add_argument("out")
    i.add_argument("native")
    c.add_argument("native")
    c.add_argument("out")
    for p in (r, i):
        add_run_options(p)
    args = parser.parse_args(argv)
    try:
        if args.command in ("build", "run"):
            binary = build(source(args.hbi_src), patch_files(args.benchmark),
                           args.prefix, args.nice)
            if args.command == "build":
                print(binary)
                return 0
            timing = run(args.benchmark, args.out, binary, args.nice, **run_options(args))
            print(f"{args.out}: {timing['steps']} steps, {timing['wall']:.0f} s wall, "
                  f"{timing['user']:.0f} s CPU")
        elif args.command == "input":
            print(write_input(args.benchmark, args.native, **run_options(args)))
        else:
            convert(args.benchmark, args.native, args.out)
    except HbiError as e:
        print(f"hbi: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
