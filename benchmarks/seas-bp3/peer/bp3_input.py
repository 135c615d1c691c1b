#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Write HBI's input for SEAS BP3-QD (60 deg thrust or normal, half-space, normal-stress coupling).

usage: bp3_input.py NATIVE_DIR --cell METRES --eps E --dtmax S --tmax YR [--dip DEG] [--sense thrust|normal]
                    [--stiffen F]

--sense normal (BP3's normal-faulting variant): V_p = -1e-9 m/s, V_init = -1e-9 m/s and the
prestress -tau0 (tau0 from |V_init|, same formula), i.e. every signed quantity of the thrust
input flips; the state psi (theta0) is unchanged. HBI's slip, V and tau are signed in the
thrust-positive sense (V = 2 V0 exp(-psi/a) sinh(tau/(sigma a)), aging law with |V|, stress
rate K (V - V_p)), so no source change is needed.

--stiffen F (a sensitivity study, not the benchmark): the kernels' shear modulus times F and
the shear-wave speed times F, so the elastic response is F times stiffer and the radiation
damping mu / (2 c_s) and the prestress stay the benchmark's.

Writes NATIVE_DIR/bp3.in (HBI problem '2dph': planar fault of NCELL = 40 km / cell
elements from the free surface, dip DEG, half-space edge-dislocation kernel for shear
AND normal traction), NATIVE_DIR/bp3_param.dat (per-cell a) and
NATIVE_DIR/stations.json (which HBI cells make up each station).
"""
import argparse, json, math, os

P = dict(mu=32.04e9, cs=3464.0, nu=0.25, b=0.015, a0=0.010, amax=0.025, L=0.008,
         f0=0.6, V0=1e-6, sigma=50.0, Vp=1e-9, Vinit=1e-9, H=15e3, h=3e3, Wf=40e3)
STATIONS_KM = [0, 2.5, 5, 7.5, 10, 12.5, 15, 17.5, 20, 25, 30, 35]


def a_of(xd):
    """BP3 a(x_d), x_d = down-dip distance (m)."""
    if xd < P['H']:
        return P['a0']
    return min(P['amax'], P['a0'] + (P['amax'] - P['a0']) * (xd - P['H']) / P['h'])


def tau0_mpa():
    eta = P['mu'] / (2 * P['cs']) / 1e6  # MPa s/m
    amax = P['amax']
    f = amax * math.asinh(P['Vinit'] / (2 * P['V0']) *
                          math.exp((P['f0'] + P['b'] * math.log(P['V0'] / P['Vinit'])) / amax))
    return P['sigma'] * f + eta * P['Vinit'], eta


def stations(cell):
    """station -> list of 1-based cell ids whose values are averaged (cells straddling
    the station; at 0 km the surface cell only, centre cell/2 down dip)."""
    out = {}
    for s in STATIONS_KM:
        xm = s * 1e3
        k = int(round(xm / cell))  # number of cells above the station
        assert abs(k * cell - xm) < 1e-6, "cell must divide the station spacing"
        out["%g" % s] = [1] if k == 0 else [k, k + 1]
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("native")
    ap.add_argument("--cell", type=float, default=25.0)
    ap.add_argument("--eps", default="1e-6")
    ap.add_argument("--dtmax", default="3153600")
    ap.add_argument("--tmax", default="1500")
    ap.add_argument("--dip", type=float, default=60.0)
    ap.add_argument("--dtout_co", default="1.0")
    ap.add_argument("--sense", choices=["thrust", "normal"], default="thrust")
    ap.add_argument("--stiffen", type=float, default=1.0)
    a = ap.parse_args()
    sg = 1.0 if a.sense == "thrust" else -1.0  # sign of V_p, V_init and the prestress
    n = int(round(P['Wf'] / a.cell))
    assert abs(n * a.cell - P['Wf']) < 1e-6
    tau0, eta = tau0_mpa()
    st = stations(a.cell)
    cells = sorted({c for v in st.values() for c in v})
    assert len(cells) <= 64
    os.makedirs(a.native, exist_ok=True)
    with open(os.path.join(a.native, "bp3_param.dat"), "w") as f:
        f.write("a\n")
        for i in range(n):
            f.write("%.17g\n" % a_of((i + 0.5) * a.cell))
    L = ["problem 2dph",              # planar dipping fault from the free surface, half-space kernels
         "ncellg %d" % n, "ds %.17g" % (a.cell / 1e3), "dipangle %g" % a.dip, "ztop 0.0",
         "rigid %.17g" % (32.04 * a.stiffen), "vs %.17g" % (3.464 * a.stiffen),
         "pois 0.25",   # GPa, km/s; eta = rigid/(2 vs)
         "filenumber 0", "nstep 100000000", "interval 100000000",
         "tmax %s" % a.tmax, "dtout 1.0", "dtout_co %s" % a.dtout_co,
         "eps_r %s" % a.eps, "dtmax %s" % a.dtmax, "velth 1e-3",
         "backslip T", "vpl %g" % (sg * P['Vp']),       # stress rate K (V - Vp): exact for creep at Vp below W_f
         "parameterfromfile T", "parameter_file bp3_param.dat", "parameter_file_ncol 1",
         "b %g" % P['b'], "dc %g" % P['L'], "f0 %g" % P['f0'], "vref %g" % P['V0'], "a %g" % P['amax'],
         "evlaw aging",
         "pressurediffusion F",   # HBI leaves it uninitialised (../../seas-bp5/peer/bp5_input.py)
         # HBI's tau is the frictional strength tau0 + dtau - eta V: start it at tau0 - eta Vinit
         # (normal faulting: tau_el0 = -tau0 and V = -Vinit, so tauinit = -(tau0 - eta Vinit))
         "tauinit %.17g" % (sg * (tau0 - eta * P['Vinit'])), "sigmainit %g" % P['sigma'],
         "velinit %g" % (sg * P['Vinit'])]
    L += ["outloc %d" % c for c in cells]
    with open(os.path.join(a.native, "bp3.in"), "w") as f:
        f.write("\n".join(L) + "\n")
    with open(os.path.join(a.native, "stations.json"), "w") as f:
        json.dump(dict(cell=a.cell, ncell=n, tau0=sg * tau0, eta=eta, sense=a.sense, dip=a.dip, stations=st), f, indent=1)
    print("bp3.in (%s): %d cells of %g m, tau0 = %.15g MPa (HBI tauinit = tau0 - eta Vinit), %d station cells"
          % (a.sense, n, a.cell, sg * tau0, len(cells)))


if __name__ == "__main__":
    main()
