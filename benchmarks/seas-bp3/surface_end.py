#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""HBI's discretization of the slip-induced normal stress near the surface,
against the half-space closed form (README.md, "The surface end against the
closed form"; bp3_operator_loading gives rsfcycle's side).

  surface_end.py bem PROFILE W CELL
      the normal stress change [MPa] of a unit thrust slip `linear`
      (1 - x_d / W) or `cosine` (cos^2(pi x_d / (2 W))) above W [m] on
      HBI's cells of CELL m (slip constant on a cell, at its centre), at the
      first cells' centres, by HBI's kernel (D2dip2 of its
      m_HACApK_calc_entry_ij.f90, transcribed), and the closed form there
      (the edge dislocation of tests/edge_dislocation.h integrated over the
      profile's dislocation density);
  surface_end.py slip OUTPUT CELL EVENTS FILE.csv
      the coseismic slip of HBI's events EVENTS (comma-separated, from 0)
      in OUTPUT/EQslip0.dat (an HBI run of CELL m cells over the 40 km
      fault), its gradient at the surface, HBI's own normal stress change of
      that slip at the first centres, and FILE.csv, rows x_d,slip at the
      cells' centres (and x_d = 0 with the first centre's slip), for
      `bp3_operator_loading PRM 60 GLOBAL LOCAL file FILE.csv`.

BP3 at 60 degrees: mu = 32.04 GPa, nu = 0.25. Stresses compression
positive, the thrust slip positive.
"""
import sys

import numpy as np

MU, NU, DIP = 32.04e9, 0.25, np.pi / 3
FAULT = 40e3


def closed_form(t, z):
    """{T_s, T_n} at t of a unit thrust edge dislocation at z (Segall)."""
    c2, sd = np.cos(2 * DIP), np.sin(DIP)
    d = t * t + z * z - 2 * t * z * c2
    p1 = t**4 - 3 * t**3 * z + 7 * t * t * z * z - 3 * t * z**3 + z**4
    p2 = t**4 - 5 * t**3 * z + 4 * t * t * z * z - 5 * t * z**3 + z**4
    with np.errstate(divide="ignore", invalid="ignore"):
        shear = (2 * MU * z * (t + z) * sd * sd
                 * (p1 + p2 * c2 + t * t * z * z * np.cos(4 * DIP))
                 / (np.pi * (1 - NU) * (t - z) * d**3))
    normal = (-4 * MU * z * z * np.cos(DIP) * sd**3
              * (z**3 - 3 * t * t * z + 2 * t**3 * c2)
              / (np.pi * (1 - NU) * d**3))
    return shear, normal


def hbi_d2dip2(x, y, xs, ys):
    """HBI's D2dip2: sxx, syy, sxy at (x, y) (y depth) of a dislocation at
    (xs, ys) on a fault of dip DIP (transcribed from HBI)."""
    s1, s2 = np.cos(DIP), np.sin(DIP)
    dx, ym, yp = x - xs, y - ys, y + ys
    r1, r2 = np.hypot(dx, ym), np.hypot(dx, yp)
    k = MU / (2 * np.pi * (1 - NU))
    sxx = (s1 * k * (ym * (ym**2 + 3 * dx**2) / r1**4
                     - yp * (yp**2 + 3 * dx**2) / r2**4
                     + 2 * ys / r2**6 * (6 * y * yp * dx**2 - ym * yp**3
                                         - dx**4))
           + s2 * k * (dx * (ym**2 - dx**2) / r1**4
                       - dx * (yp**2 - dx**2) / r2**4
                       + 4 * ys * dx / r2**6 * ((2 * ys - y) * yp**2
                                                + (3 * y + 2 * ys) * dx**2)))
    syy = (s1 * k * (ym * (ym**2 - dx**2) / r1**4
                     - yp * (yp**2 - dx**2) / r2**4
                     - 2 * ys / r2**6 * (6 * y * yp * dx**2
                                         - (3 * y + ys) * yp**3 + dx**4))
           - s2 * k * (dx * (3 * ym**2 + dx**2) / r1**4
                       - dx * (3 * yp**2 + dx**2) / r2**4
                       - 4 * ys * dx * y / r2**6 * (3 * yp**2 - dx**2)))
    sxy = (s1 * k * (dx * (ym**2 - dx**2) / r1**4
                     - dx * (yp**2 - dx**2) / r2**4
                     + 4 * ys * dx * y / r2**6 * (3 * yp**2 - dx**2))
           + s2 * k * (ym * (ym**2 - dx**2) / r1**4
                       - yp * (yp**2 - dx**2) / r2**4
                       + 2 * ys / r2**6 * (6 * y * yp * dx**2 - dx**4
                                           + (ys - y) * yp**3)))
    return sxx, syy, sxy


def hbi_normal(t, edges, slip):
    """HBI's normal traction [Pa] at down-dip t of cells [edges] slipping
    `slip` (its matel2dph2_ij, 'n')."""
    c, s = np.cos(DIP), np.sin(DIP)
    left = hbi_d2dip2(t * c, t * s, edges[:-1] * c, edges[:-1] * s)
    right = hbi_d2dip2(t * c, t * s, edges[1:] * c, edges[1:] * s)
    sxx, syy, sxy = (np.sum(slip * (p - q)) for p, q in zip(left, right))
    return (-0.5 * (sxx + syy) + 0.5 * (sxx - syy) * np.cos(2 * DIP)
            + sxy * np.sin(2 * DIP))


def integrate(f, a, b, tol, depth=0):
    """Adaptive 12-point Gauss-Legendre of f over [a, b]."""
    x, w = np.polynomial.legendre.leggauss(12)

    def gauss(l, r):
        return 0.5 * (r - l) * np.sum(w * f(0.5 * (l + r) + 0.5 * (r - l) * x))
    m = 0.5 * (a + b)
    whole, halves = gauss(a, b), gauss(a, m) + gauss(m, b)
    if abs(whole - halves) < tol or depth > 40:
        return halves
    return (integrate(f, a, m, tol, depth + 1)
            + integrate(f, m, b, tol, depth + 1))


def profile(name, w):
    if name == "linear":
        return (lambda x: np.where(x < w, 1 - x / w, 0.0),
                lambda z: np.full_like(z, 1 / w))
    if name == "cosine":
        return (lambda x: np.where(x < w, np.cos(0.5 * np.pi * x / w)**2, 0.0),
                lambda z: 0.5 * np.pi / w * np.sin(np.pi * z / w))
    raise SystemExit("PROFILE: linear or cosine")


def bem(name, w, cell):
    slip, density = profile(name, w)
    edges = np.arange(int(round(FAULT / cell)) + 1) * cell
    centres = 0.5 * (edges[1:] + edges[:-1])
    s = slip(centres)
    print(f"# {name}, W = {w:g} m, HBI cells of {cell:g} m: x_d [m], HBI's "
          "normal stress change [MPa], the closed form there [MPa]")
    for t in centres[[0, 1, 2, 4, 8]]:
        def f(z):
            return density(z) * closed_form(t, z)[1]
        exact = (integrate(f, 0, t, 1e-4) + integrate(f, t, w, 1e-4)
                 if t < w else integrate(f, 0, w, 1e-4))
        print(f"{t:.3f} {hbi_normal(t, edges, s) / 1e6:.4f} {exact / 1e6:.4f}")


def hbi_slip(output, cell, events, file):
    n = int(round(FAULT / cell))
    slips = np.fromfile(f"{output}/EQslip0.dat").reshape(-1, n)
    s = sum(slips[int(e)] for e in events.split(","))
    edges = np.arange(n + 1) * cell
    centres = 0.5 * (edges[1:] + edges[:-1])
    ten = max(1, int(round(250 / cell)))
    print(f"# HBI events {events}, {cell:g} m cells: slip at the surface "
          f"{s[0]:.4f} m, gradient over the top {ten * cell:g} m "
          f"{(s[ten] - s[0]) / (ten * cell):.3e} /m")
    print("# x_d [m], HBI's normal stress change [MPa]")
    for j in [0, 1, 2, 4, 8]:
        print(f"{centres[j]:.3f} {hbi_normal(centres[j], edges, s) / 1e6:.4f}")
    with open(file, "w") as out:
        out.write(f"x_d,slip\n0,{s[0]:.12g}\n")
        for x, v in zip(centres, s):
            out.write(f"{x:.6f},{v:.12g}\n")


def main():
    args = sys.argv[1:]
    if len(args) == 4 and args[0] == "bem":
        bem(args[1], float(args[2]), float(args[3]))
    elif len(args) == 5 and args[0] == "slip":
        hbi_slip(args[1], float(args[2]), args[3], args[4])
    else:
        raise SystemExit(__doc__)


if __name__ == "__main__":
    main()
