#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Write QDYN's input file (qdyn.in) for SCEC SEAS benchmark BP1-QD (or
BP2-QD, which is BP1 with D_c = 4 mm) and the list of output elements
(iot_depths.txt).

Usage:
  make_input.py OUTDIR [--qdyn-src DIR] [--L 40e3] [--N 2048] [--Lf 40e3]
                [--a_deep 1] [--tmax_yr 3000] [--Dc 8e-3] [--solver 2]
                [--acc 1e-8] [--ntout_ot 1] [--ntout_ox 1000] [--nxout 16]
                [--nxout_dyn 1]

DIR is a checkout of QDYN (https://github.com/ydluo/qdyn, commit
e06edb1db4d402fbc4581e086a019d30e433cc56); default: the environment
variable QDYN_SRC. The file is written by QDYN's own Python wrapper,
DIR/src/pyqdyn.py (it needs numpy and pandas), which is imported from
there and not copied here. The set-up follows QDYN's BP1 example
(examples/scec_benchmarks/BP1/SCEC2018_benchmark.m; its Python version is
examples/scec_benchmarks/BP2/seas_bp2.py).

  --L      length of QDYN's frictional segment [m], i.e. the depth extent
           of the mesh
  --N      number of elements; a power of 2 (QDYN's FFT, fftsg.f90, stops
           otherwise), so L = 40 km gives 19.53125 m (N = 2048) or
           39.0625 m (N = 1024), never 25 m
  --Lf     BP1's depth of the rate-and-state zone W_f [m]; if L > Lf, the
           elements below Lf get a = A_DEEP, b = 0 and MU_SS = 40 A_DEEP,
           which makes them creep at about V_PL (an approximation of BP1's
           imposed creep; with L = Lf the creep below W_f is exact, see
           FINITE below)
  --a_deep a of those elements
  --tmax_yr simulated time in QDYN's years of 365 days
  --Dc     D_c [m]: 8e-3 for BP1, 4e-3 for BP2
  --solver, --acc   QDYN's SOLVER and ACC
  --ntout_ot, --ntout_ox, --nxout, --nxout_dyn   QDYN's output intervals

What the QDYN settings mean for BP1 (checked in QDYN's source at that
commit):
  MESHDIM = 1, FAULT_TYPE = 1: a 1D fault in a 2D antiplane medium, a
    vertical strike-slip fault (fault_stress.f90: kernel 0.5 MU |k|).
  FINITE = 3: "symmetric finite fault". compute_stress_2d mirrors the slip
    rate about the top edge of element 1 (an image fault: a free surface
    at z = 0); friction acts on the segment 0 < z < L only, and outside it
    the slip rate is exactly V_PL, since the kernel (Cochard and Rice 1997,
    eq. 40, kernel_I.tab) acts on V - V_PL (derivs_all.f90). Element i
    (1-based) has its centre at depth (i - 1/2) L/N. W is unused (it is
    read only for FINITE = 0), LAM is unused in 2D.
  MU = rho c_s^2 = 2670 * 3464^2 Pa, VS = c_s = 3464 m/s: VS > 0 turns on
    radiation damping eta = MU/(2 VS) (initialize.f90).
  RNS_LAW = 2 ("SCEC 2018 benchmark", friction.f90): friction coefficient
    a asinh(V/(2 V_SS) exp((MU_SS + b ln(theta/theta*))/a)) with
    theta* = DC/V_SS; so MU_SS = f_0 = 0.6 and V_SS = BP1's V_0 = 1e-6 m/s.
  THETA_LAW = 1: the ageing law, dtheta/dt = 1 - V theta/DC.
  SIGMA = 50 MPa, B = 0.015, DC = D_c, A(z) = 0.010 above 15 km, linear to
    0.025 at 18 km, 0.025 below, evaluated at the element centres.
  V_PL = V_p = 1e-9 m/s: the loading (creep) rate, read per element and
    independent of V_SS (input.f90), so no change of QDYN is needed.
  V_0 = V_init = 1e-9 m/s: QDYN's initial slip rate (not BP1's V_0).
  TH_0: the initial state from BP1's tau_0 = sigma a_max
    asinh(V_init/(2 V_0) exp((f_0 + b ln(V_0/V_init))/a_max)) + eta V_init,
    theta_0 = (D_c/V_0) exp((a/b) ln(2 V_0/V_init sinh((tau_0 - eta
    V_init)/(a sigma))) - f_0/b) (the formula of QDYN's BP1 example);
    QDYN then sets the initial stress to sigma F(V_init, theta_0) + CO =
    tau_0 - eta V_init (initialize.f90). CO (cohesion) = 0; V1 and V2 are
    not used by RNS_LAW = 2.
  TMAX = tmax_yr * 365 * 86400 s (QDYN's YEAR, constants.f90, has 365
    days), NSTOP = 0: stop at TMAX.
  SOLVER = 2: adaptive Runge-Kutta-Fehlberg 4(5) in double precision
    (ode_rk45.f90) with relative tolerance ACC (absolute tolerance 0);
    DTTRY and DTMAX are not used by it. The run ends with the message
    "RK45 error [8]: invalid input parameters" when it reaches TMAX.
  Output: NTOUT_OT = 1 writes output_vmax (the maximum slip rate on the
    fault and its element) and output_ot_<i> (i 0-based, IOT = 1) at
    every time step, at the elements whose centres are nearest to 0, 2.5,
    5, 7.5, 10, 12.5, 15, 17.5, 20, 25, 30 and 35 km (iot_depths.txt);
    NTOUT = 1000 and NXOUT = 16 write a snapshot (output_ox) every 1000
    steps at every 16th element; OX_DYN = 1 writes output_dyn_pre_<k>,
    output_dyn_post_<k> and output_dyn_max_<k> for every event k (from 0)
    with DYN_TH_ON = DYN_TH_OFF = 1e-3 m/s on the maximum slip rate, and
    DYN_SKIP = -1 so that event 0 is not skipped (QDYN skips the events
    with count <= DYN_SKIP). V_TH only selects output_iasp's entries
    (IASP = 0 everywhere, so it holds only its header).
  X: the element-centre depth, for reference; QDYN does not read the
    coordinate lines for MESHDIM = 1 on one process.
"""
import argparse
import os
import sys

import numpy as np

YEAR = 365.0 * 24 * 3600  # QDYN's YEAR (constants.f90)

# BP1 (Erickson et al. 2020)
RHO = 2670.0
VS = 3464.0
MU = RHO * VS ** 2  # 32.04 GPa
ETA = MU / (2 * VS)
SIGMA = 50e6
A0, AMAX, B = 0.010, 0.025, 0.015
F0 = 0.6
V0 = 1e-6  # BP1's reference slip rate -> QDYN's V_SS
VP = 1e-9  # plate rate -> QDYN's V_PL
VINIT = VP  # initial slip rate -> QDYN's V_0
H, HTRANS = 15e3, 3e3
STATION_DEPTHS_KM = np.array([0, 2.5, 5, 7.5, 10, 12.5, 15, 17.5, 20, 25,
                              30, 35])


def import_pyqdyn(qdyn_src):
    """QDYN's Python wrapper class from the checkout qdyn_src."""
    if not qdyn_src:
        sys.exit("give the QDYN checkout with --qdyn-src DIR or QDYN_SRC")
    path = os.path.join(os.path.abspath(qdyn_src), "src")
    if not os.path.isfile(os.path.join(path, "pyqdyn.py")):
        sys.exit("%s/pyqdyn.py not found: not a QDYN checkout" % path)
    sys.path.insert(0, path)
    from pyqdyn import qdyn

    return qdyn


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("outdir")
    parser.add_argument("--qdyn-src", default=os.environ.get("QDYN_SRC"),
                        help="QDYN checkout (default: $QDYN_SRC)")
    parser.add_argument("--L", type=float, default=40e3)
    parser.add_argument("--N", type=int, default=2048)
    parser.add_argument("--Lf", type=float, default=40e3)
    parser.add_argument("--a_deep", type=float, default=1.0)
    parser.add_argument("--tmax_yr", type=float, default=3000.0)
    parser.add_argument("--Dc", type=float, default=8e-3, help="BP2: 4e-3")
    parser.add_argument("--solver", type=int, default=2)
    parser.add_argument("--acc", type=float, default=1e-8)
    parser.add_argument("--ntout_ot", type=int, default=1)
    parser.add_argument("--ntout_ox", type=int, default=1000)
    parser.add_argument("--nxout", type=int, default=16)
    parser.add_argument("--nxout_dyn", type=int, default=1)
    args = parser.parse_args()
    qdyn = import_pyqdyn(args.qdyn_src)

    length, n = args.L, args.N
    if n < 1 or n & (n - 1):
        sys.exit("N must be a power of 2 (QDYN's FFT)")
    dz = length / n
    # element-centre depths; element 1 is next to the free surface
    z = (np.arange(n) + 0.5) * dz

    a = A0 + (AMAX - A0) * (z - H) / HTRANS
    a[z < H] = A0
    a[z >= H + HTRANS] = AMAX
    b = np.full(n, B)
    deep = z > args.Lf
    a[deep] = args.a_deep
    b[deep] = 0.0

    # BP1's initial conditions: tau_0 for steady sliding at V_init with
    # a_max, theta_0 such that sigma F(V_init, theta_0) = tau_0 - eta V_init
    tau0 = (SIGMA * AMAX * np.arcsinh(
        VINIT / (2 * V0) * np.exp((F0 + B * np.log(V0 / VINIT)) / AMAX))
        + ETA * VINIT)
    rsf = ~deep
    theta0 = np.empty(n)
    theta0[rsf] = (args.Dc / V0) * np.exp(
        (a[rsf] / B) * np.log(2 * V0 / VINIT * np.sinh(
            (tau0 - ETA * VINIT) / (a[rsf] * SIGMA))) - F0 / B)
    # b = 0 below Lf: the state does not enter the friction there
    theta0[deep] = args.Dc / VINIT

    iot = [int(np.argmin(np.abs(z - d * 1e3))) for d in STATION_DEPTHS_KM]

    p = qdyn()
    settings = {
        "MESHDIM": 1,
        "FINITE": 3,
        "N": n,
        "L": length,
        "W": 50e3,  # unused with FINITE = 3
        "MU": MU,
        "LAM": MU,  # unused in 2D
        "VS": VS,  # radiation damping eta = MU/(2 VS)
        "SIGMA": SIGMA,
        "V_PL": VP,
        "TMAX": args.tmax_yr * YEAR,
        "NSTOP": 0,
        "DTTRY": 1e-3,
        "DTMAX": 0,
        "ACC": args.acc,
        "SOLVER": args.solver,
        "FAULT_TYPE": 1,
        "IC": 0,
        "NTOUT_OT": args.ntout_ot,
        "NTOUT": args.ntout_ox,
        "NXOUT": args.nxout,
        "OX_SEQ": 0,
        "OX_DYN": 1,
        "NXOUT_DYN": args.nxout_dyn,
        "DYN_TH_ON": 1e-3,
        "DYN_TH_OFF": 1e-3,
        "DYN_SKIP": -1,  # QDYN skips the events with count <= DYN_SKIP
        "V_TH": 1e-3,
        "SET_DICT_RSF": {
            "RNS_LAW": 2,  # regularised rate and state (friction.f90)
            "THETA_LAW": 1,  # ageing law
            "A": A0, "B": B, "DC": args.Dc,
            "MU_SS": F0, "V_SS": V0,
            "V_0": VINIT, "TH_0": 1.0,
            "V1": 0.01, "V2": 1e-7, "CO": 0.0,
        },
    }
    p.settings(settings)
    p.render_mesh()
    p.mesh_dict["A"][:] = a
    p.mesh_dict["B"][:] = b
    p.mesh_dict["TH_0"][:] = theta0
    if deep.any():
        # the regularised law is in its logarithmic regime if
        # V/(2 V_SS) exp(MU_SS/a) >> 1; QDYN integrates dV/dt from stress
        # rates, so the friction level below Lf does not matter
        p.mesh_dict["MU_SS"][deep] = 40.0 * args.a_deep
    p.mesh_dict["IOT"][:] = 0
    p.mesh_dict["IOT"][iot] = 1
    p.mesh_dict["X"][:] = z  # not read by QDYN for MESHDIM = 1

    os.makedirs(args.outdir, exist_ok=True)
    cwd = os.getcwd()
    os.chdir(args.outdir)
    try:
        p.write_input()
    finally:
        os.chdir(cwd)
    with open(os.path.join(args.outdir, "iot_depths.txt"), "w") as f:
        f.write("# target_depth_km element_index(0-based) "
                "element_centre_depth_m\n")
        for d, i in zip(STATION_DEPTHS_KM, iot):
            f.write("%g %d %.4f\n" % (d, i, z[i]))
    print("dz = %.4f m, N = %d, L = %.1f m, tau0 = %.6f MPa, "
          "eta = %.6e Pa s/m" % (dz, n, length, tau0 / 1e6, ETA))
    lb = MU * args.Dc / (SIGMA * B)
    print("Lb = mu Dc/(sigma b) = %.1f m -> %.1f cells" % (lb, lb / dz))


if __name__ == "__main__":
    main()
