#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The normal stress on the base of the loaded wedge, from VTU snapshots.

rsfcycle holds the normal stress on the base fixed at its value in the
static gravity equilibrium (frictionless base, backstop fixed;
doc/model.md §5). This script computes the normal stress that the wedge's own
stress field exerts on the base at later times, when the backstop has
compressed it, from the displacement and velocity of the solution
snapshots (built-in wedge: rotated frame, base on y = 0):
sigma_n = -sigma_yy at the midpoint of every base face, with the elastic
(K = 50 kPa, nu = 0.3) and Kelvin-Voigt (eta_b = eta_s = 1 / 10 kPa s)
stress of the bilinear displacement and velocity of the cell above it.

Usage: benchmarks/paper-events/normal_stress.py RUNDIR [--times t1,t2,...]
  prints sigma_n(s) along the base at the snapshots nearest to the times,
  its ratio to the snapshot at t = 0, and fits of that ratio on the patch.
The snapshots come from a run with Output/Write VTU = true (run.py's
`default-vtu`, every 20 s to 720 s).
"""
import base64
import os
import re
import struct
import sys
import zlib

import numpy as np

K, NU = 5e4, 0.3
G = 3 * K * (1 - 2 * NU) / (2 * (1 + NU))
LAM = K - 2 * G / 3
ETA = {0: 1e3, 1: 1e4}  # material id -> eta_s = eta_b [Pa s]
DTYPES = {"Float32": "<f4", "Float64": "<f8", "Int32": "<i4", "UInt8": "u1",
          "Int64": "<i8", "UInt32": "<u4"}


def read_vtu(path):
    """The DataArrays of a deal.II VTU file (binary, zlib-compressed)."""
    text = open(path).read()
    arrays = {}
    pattern = (r'<DataArray type="(\w+)"(?: Name="([^"]*)")?'
               r'(?: NumberOfComponents="(\d+)")? format="binary">\s*(\S+)'
               r'\s*</DataArray>')
    for m in re.finditer(pattern, text):
        typ, name, components, data = m.groups()
        n_blocks = struct.unpack("<I", base64.b64decode(data[:8])[:4])[0]
        header_bytes = 4 * (3 + n_blocks)
        header_b64 = 4 * ((header_bytes + 2) // 3)
        header = struct.unpack(f"<{3 + n_blocks}I",
                               base64.b64decode(data[:header_b64]))
        body = base64.b64decode(data[header_b64:])
        raw, offset = b"", 0
        for size in header[3:]:
            raw += zlib.decompress(body[offset:offset + size])
            offset += size
        a = np.frombuffer(raw, dtype=DTYPES[typ])
        if components:
            a = a.reshape(-1, int(components))
        arrays[name or "Points"] = a
    time = re.search(r'Name="TIME"[^>]*>\s*([0-9.eE+-]+)', text)
    arrays["TIME"] = float(time.group(1)) if time else float("nan")
    return arrays


def base_stress(path):
    """(s, sigma_n, tau) at the midpoints of the base faces, sorted by s."""
    d = read_vtu(path)
    points = d["Points"][:, :2].astype(float)
    u = d["displacement"][:, :2].astype(float)
    v = d["velocity"][:, :2].astype(float)
    cells = d["connectivity"].reshape(-1, 4)
    material = d["material_id"]
    corners = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], float)
    rows = []
    for c, cell in enumerate(cells):
        x = points[cell]
        on_base = np.abs(x[:, 1]) < 1e-9
        if on_base.sum() != 2:
            continue
        xi = corners[on_base].mean(axis=0)  # midpoint of the base face
        dn = np.array([[-(1 - xi[1]), -(1 - xi[0])], [1 - xi[1], -xi[0]],
                       [xi[1], xi[0]], [-xi[1], 1 - xi[0]]])
        dndx = dn @ np.linalg.inv(x.T @ dn)
        gu, gv = u[cell].T @ dndx, v[cell].T @ dndx
        e, ed = 0.5 * (gu + gu.T), 0.5 * (gv + gv.T)
        mid = material[cell[0]] if len(material) == len(points) \
            else material[c]
        eta = ETA[int(round(float(mid)))]
        syy = (LAM * np.trace(e) + 2 * G * e[1, 1]
               + eta / 3 * np.trace(ed) + 2 * eta * ed[1, 1])
        sxy = 2 * G * e[0, 1] + 2 * eta * ed[0, 1]
        rows.append((x[on_base, 0].mean(), -syy, sxy))
    rows.sort()
    return np.array(rows), d["TIME"]


def snapshots(rundir):
    folder = os.path.join(rundir, "solution")
    files = sorted(f for f in os.listdir(folder) if f.endswith(".vtu"))
    return [os.path.join(folder, f) for f in files]


def main():
    if len(sys.argv) < 2 or sys.argv[1].startswith("-"):
        if "-h" in sys.argv or "--help" in sys.argv:
            print(__doc__)
            return
        sys.exit("normal_stress.py: usage: normal_stress.py RUNDIR "
                 "[--times t1,t2,...] (RUNDIR: a run with VTU snapshots)")
    rundir = sys.argv[1]
    files = snapshots(rundir)
    times = [float(t) for t in (sys.argv[sys.argv.index("--times") + 1]
                                .split(",") if "--times" in sys.argv
                                else "0,200,400,500,600,700".split(","))]
    data = {}
    for f in files:
        t = float(re.search(r'Name="TIME"[^>]*>\s*([0-9.eE+-]+)',
                            open(f).read(2000)).group(1))
        data[t] = f
    ref, _ = base_stress(data[min(data)])
    patch = (ref[:, 0] >= 0.163) & (ref[:, 0] <= 0.363)
    print("s [m] along the base | sigma_n at t = 0 [Pa] | ratio to t = 0 "
          "at t = " + ", ".join(f"{t:g}" for t in times))
    cols = []
    for t in times:
        tt = min(data, key=lambda k: abs(k - t))
        a, time = base_stress(data[tt])
        cols.append((time, a[:, 1] / ref[:, 1]))
    for i in range(0, len(ref), max(1, len(ref) // 40)):
        print(f"{ref[i, 0]:.3f} {ref[i, 1]:8.1f} "
              + " ".join(f"{c[1][i]:6.3f}" for c in cols))
    for time, ratio in cols:
        print(f"t = {time:g} s: ratio on the patch mean "
              f"{ratio[patch].mean():.4f}, range {ratio[patch].min():.4f} "
              f"- {ratio[patch].max():.4f}; s < 0.45 m mean "
              f"{ratio[ref[:, 0] < 0.45].mean():.4f}")


if __name__ == "__main__":
    main()
