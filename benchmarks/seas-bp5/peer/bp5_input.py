#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Write the HBI input for SEAS BP5-QD (problem 3dph: rectangular elements, Okada half-space).

usage: bp5_input.py OUTDIR --cell KM --eps E --dtmax S --tmax YR [--stiffen F]

--stiffen F (a sensitivity study, not the benchmark): the kernel's shear modulus and the
shear-wave speed times F, so the elastic response is F times stiffer and the radiation damping
mu / (2 c_s) and the prestress stay the benchmark's.

Writes OUTDIR/bp5.in, OUTDIR/bp5_param.dat (columns a dc tau vel, HBI's cell order) and
OUTDIR/stations.json (the cells around each SEAS station, read by hbi2seas.py).

This replaces HBI's examples/bp5r_param.py. That script writes
tau = sigma*(a*asinh(...) + eta*V). It multiplies eta*V by sigma (25x too large: +3.47 MPa in
the nucleation patch). It also puts the damping term into HBI's tau, which is the frictional
strength (the elastic prestress minus eta*V). HBI then derives the state from (tau, V), so the
patch would start far above the steady state at V_p. Here tau = sigma*a*asinh(V/(2V0) exp(psi_ss(V_p)/a))
exactly. The state then comes out as steady state at V_p, and the elastic prestress HBI implies
is tau + eta*V, i.e. the spec's tau0 = sigma a asinh[...] + eta V, with V = V_i in the patch.
"""
import argparse, json, math, os

SIG, A0, AMAX, B, L, LNUC, F0, V0, VP, VI = 25.0, 0.004, 0.04, 0.03, 0.14, 0.13, 0.6, 1e-6, 1e-9, 0.03
HS, HT, H, LVW = 2.0, 2.0, 12.0, 60.0          # km
LF, WF = 100.0, 40.0                            # RSF rectangle, km
STATIONS = [(-36, 0), (-16, 0), (0, 0), (16, 0), (36, 0), (-24, 10), (-16, 10), (0, 10), (16, 10), (0, 22)]


def a_of(x2, x3):
    """spec (MF eq. 14)"""
    if HS + HT <= x3 <= HS + HT + H and abs(x2) <= LVW / 2:
        return A0
    if x3 <= HS or x3 >= HS + 2 * HT + H or abs(x2) >= LVW / 2 + HT:
        return AMAX
    r = max(abs(x3 - HS - HT - H / 2) - H / 2, abs(x2) - LVW / 2) / HT
    return A0 + r * (AMAX - A0)


def in_patch(x2, x3):
    return -30.0 <= x2 <= -18.0 and 4.0 <= x3 <= 16.0


def bracket(v, centres):
    """two neighbouring centres around v (the first two if v is above the first)."""
    for k in range(len(centres) - 1):
        if centres[k] <= v <= centres[k + 1]:
            return k, k + 1
    return (0, 1) if v < centres[0] else (len(centres) - 2, len(centres) - 1)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--cell", type=float, default=1.0, help="km")
    ap.add_argument("--eps", default="1e-6")
    ap.add_argument("--dtmax", default="3.1536e6")
    ap.add_argument("--tmax", default="1800")
    ap.add_argument("--stiffen", type=float, default=1.0)
    ap.add_argument("--dtout", default="1.0", help="field frames between events (yr)")
    ap.add_argument("--dtout-co", default="1.0", help="field frames during events (s)")
    a = ap.parse_args()
    ds = a.cell
    imax, jmax = int(round(LF / ds)), int(round(WF / ds))
    assert abs(imax * ds - LF) < 1e-9 and abs(jmax * ds - WF) < 1e-9
    xc = [(i - imax / 2 - 0.5) * ds for i in range(1, imax + 1)]   # HBI coordinate3ddip
    dc_ = [(j - 0.5) * ds for j in range(1, jmax + 1)]              # depth of row j
    eta = 32.04 / (2 * 3.464)                                       # MPa s/m
    psi_ss = F0 + B * math.log(V0 / VP)
    os.makedirs(a.out, exist_ok=True)
    with open(os.path.join(a.out, "bp5_param.dat"), "w") as f:
        f.write("a\tdc\ttau\tvel\n")
        for i in range(imax):
            for j in range(jmax):
                x2, x3 = xc[i], dc_[j]
                aa = a_of(x2, x3)
                v = VI if in_patch(x2, x3) else VP
                L_ = LNUC if in_patch(x2, x3) else L
                tau = SIG * aa * math.asinh(v / (2 * V0) * math.exp(psi_ss / aa))
                f.write("%.17g\t%.17g\t%.17g\t%.17g\n" % (aa, L_, tau, v))
    st = []
    for (s2, s3) in STATIONS:
        i0, i1 = bracket(s2, xc)
        j0, j1 = bracket(s3, dc_)
        cells = []
        for i in (i0, i1):
            for j in (j0, j1):
                cells.append(dict(id=i * jmax + j + 1, x2=xc[i], x3=dc_[j]))
        st.append(dict(name="fltst_strk%+03ddp%+03d" % (s2, s3), x2=s2, x3=s3, cells=cells))
    json.dump(dict(cell_km=ds, imax=imax, jmax=jmax, eta=eta, stations=st),
              open(os.path.join(a.out, "stations.json"), "w"), indent=1)
    ids = []
    for s in st:
        for c in s["cells"]:
            if c["id"] not in ids:
                ids.append(c["id"])
    assert len(ids) <= 64, "the patched HBI records at most 64 cells"
    lines = [
        "problem 3dph",            # planar fault in a half space, rectangular elements, Okada kernel
        "imax %d" % imax, "jmax %d" % jmax, "ds %g" % ds,
        "dipangle 90.0", "crake 0.0",   # vertical, pure strike slip (fixed rake)
        "rigid %.17g" % (32.04 * a.stiffen), "vs %.17g" % (3.464 * a.stiffen), "pois 0.25",
        "filenumber 0", "nstep 2000000000", "interval 2000000000",
        "tmax %s" % a.tmax,        # yr of 365 d
        "dtout %s" % a.dtout, "dtout_co %s" % a.dtout_co,
        "velth 1e-3",              # event list: start at max V > 1e-3, end at < 5e-4; hypocentre = argmax V at the start
        "eps_r %s" % a.eps, "dtmax %s" % a.dtmax, "dtinit 1e-3",
        "backslip T", "vpl 1d-9",  # loading: K (V - V_p) = creep at V_p on the infinite plane outside the RSF rectangle
        "parameterfromfile T", 'parameter_file "bp5_param.dat"', "parameter_file_ncol 4",
        "sigmaconst T", "sigmainit 25.0", "b 0.03", "f0 0.6", "vref 1e-6",
        "evlaw aging", "restart F",
        # HBI 29b8f905 never initialises pressurediffusion: without this line
        # its value is whatever the stack holds, and at 0.8, 1.25 and 2 km
        # cells it was true (a pore-pressure solve, "Maximum iteration", and
        # the Runge-Kutta failing in its first step)
        "pressurediffusion F",
    ] + ["outloc %d" % k for k in ids]
    open(os.path.join(a.out, "bp5.in"), "w").write("\n".join(lines) + "\n")
    print("HBI input in %s: %d x %d cells of %g km, %d station cells" % (a.out, imax, jmax, ds, len(ids)))


if __name__ == "__main__":
    main()
