#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Surface displacement at x = +-8 km for the HBI BP3-QD run (not computed by HBI itself).

usage: hbi_surface_bp3.py NATIVE_DIR OUT_DIR [--dip 60]

From HBI's slip frames (output/slip0.dat, times in output/time0.dat: every 1 yr between events,
every dtout_co s while max V > 1e-3 m/s) we evaluate the 2D plane-strain half-space solution
(nu-independent at the surface) for thrust slip on each 25 m element, plus the creep
V_p t on the plane below W_f = 40 km:
  u(x,t) = sum_i slip_i(t) [G(x, d_i_top) - G(x, d_i_bot)] + V_p t G(x, W_f),
G(x,d) = surface displacement of unit thrust slip on the plane from down-dip distance d to
infinity (thrust-positive slip: for the normal-faulting run the signed HBI slip and V_p < 0 give
the hanging wall subsiding; checked against Okada's DC3D with a +-1e4 km long strike: |diff| < 1.4e-4 m per m).
x is horizontal, positive in the dip direction (x > 0: hanging wall), trace at x = 0;
u_x positive toward +x, u_z positive UP. Reference: u = 0 at t = 0 (zero slip, zero creep), and the
symmetric frame: far from the fault the hanging wall moves by +V_p t/2 up dip and the footwall by
V_p t/2 down dip (another frame adds a term linear in t: V_p t (cos dip, -sin dip) c).
"""
import argparse, os, sys
import numpy as np

WF = 40.0  # km; V_p (signed, -1e-9 m/s for normal faulting) is read from bp3.in


def G(x, d, th):
    xi, D = d * np.cos(th), d * np.sin(th)
    if D == 0:
        at, r1, r2 = np.pi / 2 * np.sign(x), 0.0, 0.0
    else:
        z = (x - xi) / D
        at = np.arctan(z)
        r1 = (np.sin(th) - z * np.cos(th)) / (1 + z * z)
        r2 = (np.cos(th) + z * np.sin(th)) / (1 + z * z)
    return -(np.cos(th) * (at - np.pi / 2) + r1) / np.pi, (np.sin(th) * (at - np.pi / 2) + r2) / np.pi


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("native"); ap.add_argument("out")
    ap.add_argument("--dip", type=float, default=60.0)
    a = ap.parse_args()
    th = np.radians(a.dip)
    inp = {l.split()[0]: l.split()[1] for l in open(os.path.join(a.native, "bp3.in")) if len(l.split()) >= 2}
    n, ds = int(inp['ncellg']), float(inp['ds'])
    VP = float(inp['vpl'])  # signed: -1e-9 for normal faulting
    sense = "thrust" if VP > 0 else "normal"
    t = np.array([float(l.split()[1]) for l in open(os.path.join(a.native, "output", "time0.dat")) if l.strip()])
    r = np.fromfile(os.path.join(a.native, "output", "slip0.dat"), dtype="<f8")
    nf = min(len(t), r.size // n)
    slip = r[: nf * n].reshape(nf, n); t = t[:nf]
    for x in (-8.0, 8.0):
        gx = np.zeros(n); gz = np.zeros(n)
        for i in range(n):
            ux1, uz1 = G(x, i * ds, th); ux2, uz2 = G(x, (i + 1) * ds, th)
            gx[i], gz[i] = ux1 - ux2, uz1 - uz2
        cx, cz = G(x, WF, th)
        # symmetric frame: G(x, d) -> +-1/2 of the slip vector far on either side (G itself holds the
        # hanging wall fixed far away); only the semi-infinite creep term carries this constant.
        cx, cz = cx - 0.5 * np.cos(th), cz + 0.5 * np.sin(th)
        ux = slip @ gx + VP * t * cx
        uz = slip @ gz + VP * t * cz
        name = os.path.join(a.out, "srfst_x%+03d.dat" % int(x))
        with open(name, "w") as f:
            f.write("# SEAS BP3-QD (dip %g %s), HBI peer run: surface displacement at x = %+g km "
                    "(x > 0 hanging wall), from HBI slip frames + creep Vp t below 40 km (post-processed, not HBI)\n" % (a.dip, sense, x))
            f.write("# frame: far field of hanging wall +Vp t/2 up dip, footwall Vp t/2 down dip (Vp = %g m/s, signed); u = 0 at t = 0\n" % VP)
            f.write("# frames: every 1 yr between events, every dtout_co s during events\n")
            f.write("# Column #1 = Time (s), #2 = u_x (m, + in the dip direction, i.e. toward the hanging wall), #3 = u_z (m, + up)\n")
            f.write("t disp_x disp_z\n")
            np.savetxt(f, np.column_stack([t, ux, uz]), fmt=["%24.16e", "%22.14e", "%22.14e"])
        print("wrote", name, "(%d frames)" % nf)


if __name__ == "__main__":
    main()
