#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The Green's-function operator's response to a uniform strike-slip patch
(okada_operator_response's CSV) against Okada's (1992) half-space solution
(dc3d_points), README.md here.

    compare_okada.py --dc3d DC3D_POINTS --out DIR LABEL=response.csv ...

For each response: the patch is the set of contact nodes that slip 1 m
(the CSV's slip column; traction given for all), its edges in Okada's solution halfway between the
last slipping node and the next (the discrete slip ramps over one cell).
Okada's stress sigma_xy, sigma_zy on the plane (y = +1 mm, full mu; the
one-sided body with mu / 2 and slip s is the whole space's antisymmetric
half) against rsfcycle's traction -(S s)_i / w_k, and Okada's displacement
times 2 (the one-sided body's displacement is twice the whole problem's)
against O s at the stations. Errors are relative to Okada's stress drop at
the patch's centre. Printed: the tables of README.md; written:
DIR/okada-strike.png, DIR/okada-depth.png.
"""
import argparse
import csv
import os
import subprocess

import numpy as np

MU = 32.038e9  # BP5's shear modulus [Pa] (the .prm's halved one times 2)
NU = 0.25
LAMBDA = 2 * MU * NU / (1 - 2 * NU)
ALPHA = (LAMBDA + MU) / (LAMBDA + 2 * MU)


def read_response(path):
    nodes, stations = {}, {}
    with open(path) as f:
        for row in csv.DictReader(f):
            key = (row["kind"], int(row["index"]))
            where = nodes if row["kind"] == "node" else stations
            entry = where.setdefault(
                key[1],
                {"name": row["name"],
                 "p": np.array([float(row[c]) for c in "xyz"]),
                 "slip": float(row["slip"]),
                 "v": np.zeros(3)})
            entry["v"][int(row["component"])] = float(row["value"])
    return list(nodes.values()), list(stations.values())


def patch_edges(nodes):
    """Okada's rectangle: halfway between the last slipping node and the
    next one, on each side (the nodes lie on lines of x and z)."""
    xs = np.unique(np.round([n["p"][0] for n in nodes], 3))
    zs = np.unique(np.round([n["p"][2] for n in nodes], 3))
    patch = np.array([n["p"] for n in nodes if n["slip"] > 0.5])

    def edges(values, inside):
        lo, hi = inside.min() - 1e-3, inside.max() + 1e-3
        below = values[values < lo].max()
        above = values[values > hi].min()
        return 0.5 * (below + inside.min()), 0.5 * (inside.max() + above)

    return edges(xs, patch[:, 0]) + edges(zs, patch[:, 2])


def okada(dc3d, points, edges, slip=1.0):
    """Displacement and gradient at points (n x 3) for a vertical fault
    with strike slip `slip` (the side y > 0 moving +x relative to y < 0) on
    x in [xa, xb], z in [za, zb]."""
    xa, xb, za, zb = edges
    depth = -za  # the reference point: the bottom edge
    header = "%.9g %.9g 90 %.9g %.9g 0 %.9g %.9g 0 0\n" % (
        ALPHA, depth, xa, xb, zb - za, -slip)
    text = header + "".join("%.9g %.9g %.9g\n" % tuple(p) for p in points)
    out = subprocess.run([dc3d], input=text, capture_output=True, text=True,
                         check=True).stdout
    data = np.array([[float(v) for v in line.split()]
                     for line in out.splitlines()])
    if len(data) != len(points) or np.any(data[:, 15] != 0):
        raise RuntimeError("DC3D failed at some points")
    u = data[:, 3:6]
    # columns uxx uyx uzx uxy uyy uzy uxz uyz uzz: g[:, i, j] = d u_i / d x_j
    g = np.zeros((len(points), 3, 3))
    for j in range(3):
        for i in range(3):
            g[:, i, j] = data[:, 6 + 3 * j + i]
    return u, g


def stress(g):
    eps = 0.5 * (g + np.transpose(g, (0, 2, 1)))
    trace = np.trace(eps, axis1=1, axis2=2)
    return LAMBDA * trace[:, None, None] * np.eye(3) + 2 * MU * eps


def compare(label, path, args):
    nodes, stations = read_response(path)
    edges = patch_edges(nodes)
    xa, xb, za, zb = edges
    h = np.min(np.diff(np.unique(np.round([n["p"][0] for n in nodes], 3))))
    p = np.array([n["p"] for n in nodes])
    p_plane = p.copy()
    p_plane[:, 1] = 1e-3  # the plane's y > 0 side
    _, g = okada(args.dc3d, p_plane, edges)
    sigma = stress(g)
    exact = np.stack([sigma[:, 0, 1], sigma[:, 2, 1]], axis=1)  # s_xy, s_zy
    ours = np.array([[n["v"][0], n["v"][2]] for n in nodes])
    # distance from the patch's edge lines (inside or outside)
    dx = np.minimum(np.abs(p[:, 0] - xa), np.abs(p[:, 0] - xb))
    dz = np.minimum(np.abs(p[:, 2] - za), np.abs(p[:, 2] - zb))
    inside_x = (p[:, 0] > xa) & (p[:, 0] < xb)
    inside_z = (p[:, 2] > za) & (p[:, 2] < zb)
    distance = np.where(inside_x & inside_z, np.minimum(dx, dz),
                        np.where(inside_x, dz,
                                 np.where(inside_z, dx, np.hypot(dx, dz))))
    centre = np.argmin(np.hypot(p[:, 0] - 0.5 * (xa + xb),
                                p[:, 2] - 0.5 * (za + zb)))
    drop = abs(exact[centre, 0])
    result = {"label": label, "nodes": len(nodes), "h": h, "edges": edges,
              "centre": (ours[centre, 0], exact[centre, 0])}
    for d in args.distances:
        m = distance >= d
        err = np.abs(ours[m] - exact[m])
        worst = [p[m][np.argmax(err[:, j])] / 1e3 for j in (0, 1)]
        result[d] = (err[:, 0].max() / drop, err[:, 1].max() / drop,
                     np.sqrt(np.mean(err[:, 0] ** 2)) / drop, worst)
    # stations: twice Okada's displacement (the one-sided body)
    sp = np.array([s["p"] for s in stations])
    u, _ = okada(args.dc3d, sp, edges)
    result["stations"] = [(s["name"], s["v"], 2 * u[i])
                          for i, s in enumerate(stations)]
    result["curves"] = (p, ours, exact)
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--dc3d", required=True, help="dc3d_points binary")
    parser.add_argument("--out", required=True, help="folder for figures")
    parser.add_argument("--distances", type=float, nargs="+",
                        default=[2e3, 4e3],
                        help="compare at nodes at least this far from the "
                        "patch's edges [m]")
    parser.add_argument("runs", nargs="+", help="LABEL=response.csv")
    args = parser.parse_args()
    results = [compare(*r.split("=", 1), args) for r in args.runs]

    print("| mesh | contact nodes | patch (Okada's edges) [km] | "
          "centre: rsfcycle, Okada [MPa] | " +
          " | ".join("largest error (at x, z [km]), strike / dip; rms "
                     "(strike); nodes >= %g km from the edges" % (d / 1e3)
                     for d in args.distances) + " |")
    print("|---" * (4 + len(args.distances)) + "|")
    for r in results:
        xa, xb, za, zb = (e / 1e3 for e in r["edges"])
        cells = " | ".join(
            "%.2f %% (%g, %g) / %.2f %% (%g, %g), %.2f %%" % (
                100 * r[d][0], *(np.round(r[d][3][0][[0, 2]], 1) + 0.0),
                100 * r[d][1], *(np.round(r[d][3][1][[0, 2]], 1) + 0.0),
                100 * r[d][2]) for d in args.distances)
        print("| %s | %d | %g … %g × %g … %g | %.4f, %.4f | %s |" % (
            r["label"], r["nodes"], xa, xb, za, zb, r["centre"][0] / 1e6,
            r["centre"][1] / 1e6, cells))
    print()
    print("| station | " + " | ".join(
        "%s u_x, u_y, u_z [mm] (Okada × 2)" % r["label"] for r in results)
        + " |")
    print("|---" * (1 + len(results)) + "|")
    for i, (name, _, _) in enumerate(results[0]["stations"]):
        cells = []
        for r in results:
            _, ours, exact = r["stations"][i]
            cells.append(", ".join("%.2f (%.2f)" % (1e3 * a, 1e3 * b)
                                   for a, b in zip(ours, exact)))
        print("| %s | %s |" % (name, " | ".join(cells)))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    os.makedirs(args.out, exist_ok=True)
    for axis, fixed, name in ((0, 2, "strike"), (2, 0, "depth")):
        fig, ax = plt.subplots(figsize=(7, 4))
        for r in results:
            p, ours, exact = r["curves"]
            xa, xb, za, zb = r["edges"]
            at = 0.5 * (za + zb) if axis == 0 else 0.5 * (xa + xb)
            line = np.abs(p[:, fixed] - at) < 0.51 * r["h"]
            near = p[line, fixed]
            at = near[np.argmin(np.abs(near - at))]
            line = np.abs(p[:, fixed] - at) < 1e-3
            order = np.argsort(p[line, axis])
            (drawn,) = ax.plot(p[line, axis][order] / 1e3,
                               ours[line, 0][order] / 1e6, "o", ms=3,
                               label="rsfcycle %s" % r["label"])
            ax.plot(p[line, axis][order] / 1e3, exact[line, 0][order] / 1e6,
                    "--", lw=0.8, color=drawn.get_color(),
                    label="Okada at its nodes, edges of its patch")
        ax.set_xlabel("x (along strike) [km]" if axis == 0
                      else "z (up) [km]")
        ax.set_ylabel("shear stress change σ_xy [MPa]")
        ax.set_ylim(-4, 3)  # the edges' singular peaks cut
        ax.set_title("1 m strike slip on a patch, %s:\nthe Green's-function "
                     "operator against Okada (1992)" % (
                         "along strike through the patch's middle depth"
                         if axis == 0 else "along depth at x = 0"),
                     fontsize=8)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(args.out, "okada-%s.png" % name), dpi=120)


if __name__ == "__main__":
    main()
