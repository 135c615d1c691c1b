#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Write the HBI input for SEAS BP7-QD (problem 3dp: planar fault of square cells in a whole space).

usage: bp7_input.py OUTDIR --cell M --eps E --dtmax S --tend S [--no-nucleation]

Writes OUTDIR/bp7.in, OUTDIR/bp7_param.dat (columns a dc tau vel, HBI's cell order) and
OUTDIR/stations.json (the cells around each SEAS station, read by hbi2seas_bp7.py).

Set-up (SEAS BP7-QD, aging law):
- RSF square |x2|, |x3| <= 400 m; creep at V_p = 1e-9 m/s outside (HBI back slip);
- VW disc r <= 200 m: a = a0 = 0.004 inside, a_max = 0.016 outside (sharp, at the cell centres);
  b = 0.01, D_RS = 0.53e-3 m (the value of HBI's examples/bp7ar.in and of the Julia set-up), f0 = 0.6,
  V0 = 1e-6 m/s, sigma = 25 MPa (constant), mu = 32.04 GPa, c_s = 3.464 km/s, eta = mu/(2 c_s);
- V_init = 1e-9 m/s, theta0 = D_RS/V_init, i.e. steady state at V_init with the local a:
  tau0 = sigma a asinh[V_init/(2V0) exp((f0 + b ln(V0/V_init))/a)] + eta V_init.
  HBI's QD variable tau is the frictional strength (tau0 - eta V), so we write tau0 - eta V_init;
- nucleation: the stress perturbation dtau0 G1(r) G2(t) of hbi-bp7.patch, switched on by the input
  keyword `bp7nucleation T` (omitted with --no-nucleation).
  --no-nucleation also writes tau = tau0 (+ eta V_init) as HBI's examples/bp7ar_param.py does: an exact
  steady state never leaves it, and HBI's stepper rejects steps whose error estimate is exactly zero
  (errmax <= 1e-20), so it stops at t = 0. The excess 4.6e-9 MPa seeds the instability as in bp7ar.
  For the same reason dtinit is HBI's default 1 s: the first step's stages then sample the ramp.
Coordinates as the BP4 peer run: HBI's coordinate3dp puts cell k = (i-1) jmax + j at
x2 = (i - imax/2 - 0.5) ds, zcol = -(j - jmax/2 - 0.5) ds, and x3 = -zcol ("dp" in the station names).
"""
import argparse, json, math, os, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "seas-bp4", "peer"))
from bp4_input import weights   # noqa: E402  (linear interpolation weights in the cell centres)

SIG, A0, AMAX, B, L, F0, V0, VP = 25.0, 0.004, 0.016, 0.01, 0.53e-3, 0.6, 1e-6, 1e-9
MU, CS = 32.04, 3.464                           # GPa, km/s
ETA = MU / (2 * CS)                             # MPa s/m (4.62471)
LF = 0.8                                        # RSF square side, km
RVW = 0.2                                       # VW disc radius, km
# (x2, x3) in m, x3 = -zcol; names in m
STATIONS = [(0, 0), (-100, 0), (0, 100), (100, 0), (0, -100), (-100, -100), (-100, 100), (100, -100),
            (100, 100), (-300, 0), (0, 300), (300, 0), (0, -300)]


def a_of(x2, x3):
    return A0 if x2 * x2 + x3 * x3 <= RVW * RVW else AMAX


def strength0(a):
    """steady-state frictional strength at V_init (= tau0 - eta V_init), MPa"""
    return SIG * a * math.asinh(VP / (2 * V0) * math.exp((F0 + B * math.log(V0 / VP)) / a))


def name(x2, x3):
    return "fltst_strk%+04ddp%+04d" % (int(round(x2)), int(round(x3)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--cell", type=float, default=10.0, help="m")
    ap.add_argument("--eps", default="1e-6")
    ap.add_argument("--dtmax", default="1e6", help="s")
    ap.add_argument("--tend", type=float, default=3.15576e8, help="s (10 yr of 365.25 d)")
    ap.add_argument("--dtout", default="0.01", help="field frames between events (HBI yr of 365 d)")
    ap.add_argument("--dtout-co", default="0.02", help="field frames during events (s)")
    ap.add_argument("--no-nucleation", action="store_true")
    a = ap.parse_args()
    ds = a.cell / 1e3                                       # km
    imax = jmax = int(round(LF / ds))
    assert abs(imax * ds - LF) < 1e-9 and imax % 2 == 0
    xc = [(i - imax // 2 - 0.5) * ds for i in range(1, imax + 1)]
    x3c = [(j - jmax // 2 - 0.5) * ds for j in range(1, jmax + 1)]   # x3 = -zcol
    os.makedirs(a.out, exist_ok=True)
    nvw = 0
    with open(os.path.join(a.out, "bp7_param.dat"), "w") as f:
        f.write("a\tdc\ttau\tvel\n")
        for i in range(imax):
            for j in range(jmax):
                aa = a_of(xc[i], x3c[j])
                nvw += aa == A0
                f.write("%.17g\t%.17g\t%.17g\t%.17g\n" % (aa, L, strength0(aa) + (ETA * VP if a.no_nucleation else 0.0), VP))
    st = []
    for (s2, s3) in STATIONS:
        cells = []
        for i, wi in weights(s2 / 1e3, xc):
            for j, wj in weights(s3 / 1e3, x3c):
                cells.append(dict(id=i * jmax + j + 1, x2=xc[i], x3=x3c[j], w=wi * wj))
        st.append(dict(name=name(s2, s3), x2=s2 / 1e3, x3=s3 / 1e3, cells=cells))
    # the cells around the nucleation centre (x2, x3) = (-50, -50) m, recorded for bp7_check.py
    nuc = [dict(id=i * jmax + j + 1, x2=xc[i], x3=x3c[j], w=wi * wj)
           for i, wi in weights(-0.05, xc) for j, wj in weights(-0.05, x3c)]
    ids = []
    for s in st + [dict(cells=nuc)]:
        for c in s["cells"]:
            if c["id"] not in ids:
                ids.append(c["id"])
    assert len(ids) <= 64, "the patched HBI records at most 64 cells"
    json.dump(dict(cell_km=ds, imax=imax, jmax=jmax, eta=ETA, b=B, sigma=SIG, tend=a.tend,
                   nucleation=not a.no_nucleation, nucleation_cells=nuc, stations=st),
              open(os.path.join(a.out, "stations.json"), "w"), indent=1)
    lines = [
        "problem 3dp",             # planar fault in a whole space, closed-form full-space kernel (ret3dp)
        "imax %d" % imax, "jmax %d" % jmax, "ds %r" % ds,
        "rigid 32.04", "vs 3.464", "pois 0.25",
        "filenumber 0", "nstep 2000000000", "interval 2000000000",
        "tmax %.17g" % (a.tend / (365 * 24 * 3600)),   # HBI's yr are 365 d
        "dtout %s" % a.dtout, "dtout_co %s" % a.dtout_co,
        "velth 1e-3",              # event list: start at max V > 1e-3, end at < 5e-4; hypocentre = argmax V at the start
        "eps_r %s" % a.eps, "dtmax %s" % a.dtmax, "dtinit 1",  # HBI's default; see the docstring
        "backslip T", "vpl 1d-9",  # loading: K (V - V_p) = creep at V_p on the plane outside the RSF square
        "parameterfromfile T", 'parameter_file "bp7_param.dat"', "parameter_file_ncol 4",
        "sigmaconst T", "sigmainit 25.0", "b 0.01", "f0 0.6", "vref 1e-6",
        "evlaw aging", "restart F",
        "pressurediffusion F",     # HBI leaves it uninitialised (../../seas-bp5/peer/bp5_input.py)
    ] + (["bp7nucleation T"] if not a.no_nucleation else []) + ["outloc %d" % k for k in ids]
    open(os.path.join(a.out, "bp7.in"), "w").write("\n".join(lines) + "\n")
    print("HBI input in %s: %d x %d cells of %g m; %d VW cells (%.4f km^2, disc %.4f); %d station cells; "
          "strength0 = %.9f (VW) / %.9f MPa; nucleation %s"
          % (a.out, imax, jmax, a.cell, nvw, nvw * ds * ds, math.pi * RVW ** 2, len(ids),
             strength0(A0), strength0(AMAX), "off" if a.no_nucleation else "on"))


if __name__ == "__main__":
    main()
