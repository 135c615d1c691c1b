#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Write the HBI input for SEAS BP4-QD (problem 3dp: planar fault of rectangles in a whole space).

usage: bp4_input.py OUTDIR --cell KM --eps E --dtmax S --tend S

Writes OUTDIR/bp4.in, OUTDIR/bp4_param.dat (columns a dc tau vel, HBI's cell order) and
OUTDIR/stations.json (the cells around each SEAS station, read by hbi2seas_bp4.py).

The set-up is the one of rsfcycle's prm/seas-bp4-qd.prm:
- RSF rectangle |x2| <= 50 km, |x3| <= 40 km (x3 down); creep at V_p outside (HBI back slip);
- a = min(a0 + max(0, r)(amax - a0), amax), r = max(|x3| - 15, |x2| - 30)/3 (km), b = 0.013,
  L = 0.04 m, f0 = 0.6, V0 = 1e-6 m/s, sigma = 50 MPa (constant), V_p = 1e-9 m/s;
- uniform prestress tau0 = sigma amax asinh(V_p/(2V0) exp((f0 + b ln(V0/V_p))/amax)) + eta V_p;
  the state is the one at which tau0 gives V = V_p with the local a;
- on the nucleation square x2 in [-28.5, -16.5], x3 in [-13.5, -1.5] km the slip rate starts at
  V_i = 0.03 m/s with the state unchanged (the prestress there is raised accordingly:
  tau_p = sigma a0 asinh[(V_i/V_p) sinh((tau0 - eta V_p)/(a0 sigma))] + eta V_i = 31.5895 MPa).
The square's edges are cell centres at 1 km (and cut cells at 2 km). A cell cut by an edge gets the cell
average of the elastic prestress, f tau_p + (1 - f) tau0 (f = the fraction of its area in the square),
with the state unchanged, and the V that satisfies the friction law there. So the imposed stress
perturbation has the spec's integral (144 km^2 x (tau_p - tau0)) at any cell size.
HBI's QD variable tau is the frictional strength (elastic prestress minus eta V), and HBI derives the
state from (tau, V): psi = a ln[(2V0/V) sinh(tau/(a sigma))]. So we write
  tau = sigma a asinh[V/(2V0) exp(psi0/a)],  psi0 = a ln[(2V0/V_p) sinh((tau0 - eta V_p)/(a sigma))],
with V = V_p outside the square and V_i inside. The elastic prestress HBI implies is tau + eta V, i.e.
tau0 outside and rsfcycle's raised prestress (+ eta V_i) inside.
"""
import argparse, json, math, os

SIG, A0, AMAX, B, L, F0, V0, VP, VI = 50.0, 0.0065, 0.025, 0.013, 0.04, 0.6, 1e-6, 1e-9, 0.03
MU, CS = 32.04, 3.464                           # GPa, km/s
H, LVW, HT = 15.0, 60.0, 3.0                    # km
LF, WF = 100.0, 80.0                            # RSF rectangle (|x2| <= 50, |x3| <= 40), km
ETA = MU / (2 * CS)                             # MPa s/m (4.62471)
# (x2, x3) in km, x3 down; names in 100 m units as rsfcycle's "Plane station names = 100 m"
STATIONS = [(-36, 0), (-22.5, -7.5), (-16.5, -12), (-16.5, 0), (-16.5, 12), (0, -21), (0, -12), (0, 0),
            (0, 12), (0, 21), (16.5, -12), (16.5, 0), (16.5, 12), (36, 0)]


def a_of(x2, x3):
    r = max(abs(x3) - H, abs(x2) - LVW / 2) / HT
    return min(A0 + max(0.0, r) * (AMAX - A0), AMAX)


PATCH2, PATCH3 = (-28.5, -16.5), (-13.5, -1.5)   # nucleation square, km


def overlap(c, ds, lo, hi):
    return max(0.0, min(c + ds / 2, hi) - max(c - ds / 2, lo)) / ds


def patch_fraction(x2, x3, ds):
    """fraction of the cell centred at (x2, x3) that lies in the nucleation square"""
    return overlap(x2, ds, *PATCH2) * overlap(x3, ds, *PATCH3)


def solve_v(tau_el, a, psi):
    """V with tau_el - eta V = sigma a asinh(V/(2V0) exp(psi/a)) (bisection in log V)"""
    lo, hi = -30.0, 2.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        v = 10.0 ** mid
        if tau_el - ETA * v > SIG * a * math.asinh(v / (2 * V0) * math.exp(psi / a)):
            lo = mid
        else:
            hi = mid
    return 10.0 ** (0.5 * (lo + hi))


def tau0():
    return SIG * AMAX * math.asinh(VP / (2 * V0) * math.exp((F0 + B * math.log(V0 / VP)) / AMAX)) + ETA * VP


def name(x2, x3):
    return "fltst_strk%+04ddp%+04d" % (int(round(x2 * 10)), int(round(x3 * 10)))


def weights(v, centres):
    """[(index, weight)] of the linear interpolation in the cell centres (weights > 0 only)."""
    for k in range(len(centres) - 1):
        if centres[k] <= v <= centres[k + 1]:
            t = (v - centres[k]) / (centres[k + 1] - centres[k])
            return [(i, w) for i, w in ((k, 1.0 - t), (k + 1, t)) if w > 1e-12]
    raise ValueError("station outside the grid")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--cell", type=float, default=1.0, help="km")
    ap.add_argument("--eps", default="1e-6")
    ap.add_argument("--dtmax", default="3155760", help="s (0.1 yr of 365.25 d)")
    ap.add_argument("--tend", type=float, default=3.15576e10, help="s (1000 yr of 365.25 d)")
    ap.add_argument("--dtout", default="5.0", help="field frames between events (HBI yr of 365 d)")
    ap.add_argument("--dtout-co", default="1.0", help="field frames during events (s)")
    a = ap.parse_args()
    ds = a.cell
    imax, jmax = int(round(LF / ds)), int(round(WF / ds))
    assert abs(imax * ds - LF) < 1e-9 and abs(jmax * ds - WF) < 1e-9 and imax % 2 == 0 and jmax % 2 == 0
    # HBI coordinate3dp: cell k = (i-1)*jmax + j, xcol = (i - imax/2 - 0.5) ds, zcol = -(j - jmax/2 - 0.5) ds (up)
    xc = [(i - imax // 2 - 0.5) * ds for i in range(1, imax + 1)]
    x3c = [(j - jmax // 2 - 0.5) * ds for j in range(1, jmax + 1)]   # x3 = -zcol (down)
    t0 = tau0()
    os.makedirs(a.out, exist_ok=True)
    npatch, nedge, area = 0, 0, 0.0
    with open(os.path.join(a.out, "bp4_param.dat"), "w") as f:
        f.write("a\tdc\ttau\tvel\n")
        for i in range(imax):
            for j in range(jmax):
                x2, x3 = xc[i], x3c[j]
                aa = a_of(x2, x3)
                psi0 = aa * math.log(2 * V0 / VP * math.sinh((t0 - ETA * VP) / (aa * SIG)))
                fr = patch_fraction(x2, x3, ds)
                if fr >= 1.0 - 1e-12:        # inside the square: V_i, state unchanged
                    v = VI
                    npatch += 1
                elif fr > 0.0:               # cut by the square's edge: the cell average of the elastic prestress
                    tp = SIG * aa * math.asinh(VI / (2 * V0) * math.exp(psi0 / aa)) + ETA * VI
                    v = solve_v(fr * tp + (1 - fr) * t0, aa, psi0)
                    nedge += 1
                else:
                    v = VP
                area += fr * ds * ds
                tau = SIG * aa * math.asinh(v / (2 * V0) * math.exp(psi0 / aa))
                f.write("%.17g\t%.17g\t%.17g\t%.17g\n" % (aa, L, tau, v))
    st = []
    for (s2, s3) in STATIONS:
        cells = []
        for i, wi in weights(s2, xc):
            for j, wj in weights(s3, x3c):
                cells.append(dict(id=i * jmax + j + 1, x2=xc[i], x3=x3c[j], w=wi * wj))
        st.append(dict(name=name(s2, s3), x2=s2, x3=s3, cells=cells))
    json.dump(dict(cell_km=ds, imax=imax, jmax=jmax, eta=ETA, tau0=t0, tend=a.tend, stations=st),
              open(os.path.join(a.out, "stations.json"), "w"), indent=1)
    ids = []
    for s in st:
        for c in s["cells"]:
            if c["id"] not in ids:
                ids.append(c["id"])
    assert len(ids) <= 64, "the patched HBI records at most 64 cells"
    lines = [
        "problem 3dp",             # planar fault in a whole space, rectangles, closed-form full-space kernel (ret3dp)
        "imax %d" % imax, "jmax %d" % jmax, "ds %g" % ds,
        "rigid 32.04", "vs 3.464", "pois 0.25",
        "filenumber 0", "nstep 2000000000", "interval 2000000000",
        "tmax %.17g" % (a.tend / (365 * 24 * 3600)),   # HBI's yr are 365 d
        "dtout %s" % a.dtout, "dtout_co %s" % a.dtout_co,
        "velth 1e-3",              # event list: start at max V > 1e-3, end at < 5e-4; hypocentre = argmax V at the start
        "eps_r %s" % a.eps, "dtmax %s" % a.dtmax, "dtinit 1e-3",
        "backslip T", "vpl 1d-9",  # loading: K (V - V_p) = creep at V_p on the infinite plane outside the RSF rectangle
        "parameterfromfile T", 'parameter_file "bp4_param.dat"', "parameter_file_ncol 4",
        "sigmaconst T", "sigmainit 50.0", "b 0.013", "f0 0.6", "vref 1e-6",
        "evlaw aging", "restart F",
        "pressurediffusion F",     # HBI leaves it uninitialised (../../seas-bp5/peer/bp5_input.py)
    ] + ["outloc %d" % k for k in ids]
    open(os.path.join(a.out, "bp4.in"), "w").write("\n".join(lines) + "\n")
    print("HBI input in %s: %d x %d cells of %g km; nucleation square: %d cells inside, %d cut by its edge "
          "(area %.1f km^2); %d station cells; tau0 = %.6f MPa" % (a.out, imax, jmax, ds, npatch, nedge, area, len(ids), t0))


if __name__ == "__main__":
    main()
