#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Write an SCycle input (.in file + PETSc binary initial-condition/grid files)
for SCEC SEAS BP1-FD, following SCycle's own SEAS_benchmarks/BP1 (BP1.in and
createICs.m), switched to momentumBalanceType = quasidynamic_and_dynamic.

usage: make_input.py OUTDIR [options]   (OUTDIR/bp1fd.in, OUTDIR/ICs/, OUTDIR/output/)
The defaults are the 50 m run of README.md: h = 50 m, uniform to 45 km depth
and 10 km across, 150 stretched cells each way to 500 km, three events.

Run with Debian's /usr/bin/python3 (needs numpy).  SCycle units: lengths km,
stresses MPa, mu GPa, rho g/cm^3, slip m, velocities m/s, time s.

Grid: SCycle's BP1 uses a constant spacing h near the fault (createICs.m:
25 m to z = 55 km and to y = 5 km) and a stretched grid out to 500 km.  The
helper constructCoord_constL1 that createICs.m calls is not in the repository,
so this script builds its own: constant spacing h on [0, H], then cells that
grow geometrically (constant ratio r, first stretched cell = h*r) out to L.
"""
import argparse, os, struct
import numpy as np

p = argparse.ArgumentParser()
p.add_argument("outdir", help="run folder (created)")
p.add_argument("--h", type=float, default=0.05, help="fault/near-field cell size [km]")
p.add_argument("--Hz", type=float, default=45.0, help="depth of the uniform-spacing zone [km]")
p.add_argument("--Hy", type=float, default=10.0, help="width of the uniform-spacing zone [km]")
p.add_argument("--Lz", type=float, default=500.0)
p.add_argument("--Ly", type=float, default=500.0)
p.add_argument("--nz2", type=int, default=150, help="number of stretched cells in z")
p.add_argument("--ny2", type=int, default=150, help="number of stretched cells in y")
p.add_argument("--maxTime", type=float, default=600 * 365.25 * 86400.0,
               help="[s]; SCycle spins at maxTime instead of stopping: end with maxNumCycles")
p.add_argument("--maxStepCount", type=float, default=1e8)
p.add_argument("--stride1D_qd", type=int, default=10)
p.add_argument("--stride1D_fd", type=int, default=20)
p.add_argument("--stride2D_qd", type=int, default=0)
p.add_argument("--stride2D_fd", type=int, default=0)
p.add_argument("--trigger_qd2fd", type=float, default=1e-3, help="max V [m/s] to switch QD->FD (current SCycle: max slip rate)")
p.add_argument("--trigger_fd2qd", type=float, default=1e-3, help="max V [m/s] to switch FD->QD")
p.add_argument("--limit_qd", type=float, default=1e-5, help="QD->FD only allowed once max V has been below this")
p.add_argument("--limit_fd", type=float, default=1e-1, help="FD->QD only allowed once max V has been above this")
p.add_argument("--timeStepTol", type=float, default=1e-7)
p.add_argument("--momentum", default="quasidynamic_and_dynamic")
p.add_argument("--maxNumCycles", type=int, default=3,
               help="stop after 2*N QD/FD phases (N=3: right after the FD phase of event 3)")
args = p.parse_args()

# ---------------- BP1 parameters (Erickson et al. 2020; BP1-FD same values) ----------
rho = 2.670          # g/cm^3  (2670 kg/m^3)
cs = 3.464           # km/s
mu = rho * cs**2     # GPa = 32.03812032
sigma = 50.0         # MPa
a0, amax, b0 = 0.010, 0.025, 0.015
H, hh = 15.0, 3.0    # km: a = a0 above H, linear to amax at H+hh
Dc = 0.008           # m
f0, V0 = 0.6, 1e-6
Vp = 1e-9
Vinit = Vp
Wf = 40.0            # km, RSF on 0..Wf, creep at Vp below
eta = 0.5 * np.sqrt(mu * rho)   # MPa s/m = mu/(2 cs) = 4.62444

# ---------------- grid ----------------
def coord(h, Hc, L, n2):
    n1 = int(round(Hc / h))
    assert abs(n1 * h - Hc) < 1e-9, "H must be a multiple of h"
    R = L - Hc
    # solve h*r*(r^n2-1)/(r-1) = R for r > 1 by bisection
    f = lambda r: h * r * (r**n2 - 1.0) / (r - 1.0) - R
    lo, hi = 1.0 + 1e-12, 2.0
    assert f(lo) < 0 < f(hi), "stretching not solvable: change n2"
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if f(mid) > 0: hi = mid
        else: lo = mid
    r = 0.5 * (lo + hi)
    x1 = h * np.arange(n1 + 1)
    d2 = h * r ** np.arange(1, n2 + 1)
    x2 = Hc + np.cumsum(d2)
    x = np.concatenate([x1, x2])
    x[-1] = L
    return x, r

z, rz = coord(args.h, args.Hz, args.Lz, args.nz2)
y, ry = coord(args.h, args.Hy, args.Ly, args.ny2)
Nz, Ny = len(z), len(y)

# ---------------- initial conditions (BP1) ----------------
a = np.interp(z, [0.0, H, H + hh, args.Lz], [a0, a0, amax, amax])
tau0 = sigma * amax * np.arcsinh(Vinit / (2 * V0) * np.exp((f0 + b0 * np.log(V0 / Vinit)) / amax)) + eta * Vinit
# theta0 = Dc/V0 exp[(a/b) ln(2V0/Vinit sinh((tau0-eta Vinit)/(a sigma))) - f0/b];  psi = f0 + b ln(V0 theta/Dc)
psi = a * np.log(2 * V0 / Vinit * np.sinh((tau0 - eta * Vinit) / (a * sigma)))
tau0v = np.full(Nz, tau0)

# ---------------- write PETSc binary Vecs ----------------
VEC_FILE_CLASSID = 1211214
def petsc_write(fname, v):
    v = np.asarray(v, dtype=">f8").ravel()
    with open(fname, "wb") as fh:
        fh.write(struct.pack(">ii", VEC_FILE_CLASSID, v.size))
        fh.write(v.tobytes())

base = os.path.abspath(args.outdir)
icdir = os.path.join(base, "ICs") + "/"
outdir = os.path.join(base, "output") + "/"
os.makedirs(icdir, exist_ok=True)
os.makedirs(outdir, exist_ok=True)
# body ordering in SCycle: index = iy*Nz + iz (z fastest), cf. Domain::setFields
Y = np.repeat(y, Nz)
Z = np.tile(z, Ny)
petsc_write(icdir + "y", Y)
petsc_write(icdir + "z", Z)
petsc_write(icdir + "psi", psi)
petsc_write(icdir + "prestress", tau0v)   # tau0 incl. eta*Vinit (as createICs.m)
petsc_write(icdir + "tauQS", tau0v)
petsc_write(icdir + "tau", tau0v - eta * Vinit)

eps = 1e-3 * args.h   # keep the 0/0 of setVec's zero-width interval off any grid node
infile = f"""# SCEC SEAS BP1-FD for SCycle (generated by make_input.py)
# based on SCycle SEAS_benchmarks/BP1/BP1.in (commit 74a132f); grid h = {args.h*1000:.1f} m
# Ny = {Ny} (uniform to {args.Hy} km, stretch ratio {ry:.5f}), Nz = {Nz} (uniform to {args.Hz} km, ratio {rz:.5f})

inputDir = {icdir}
outputDir = {outdir}

Ny = {Ny}
Nz = {Nz}
Ly = {args.Ly}
Lz = {args.Lz}
order = 4
gridSpacingType = variableGridSpacing

problemType = strikeSlip
bulkDeformationType = linearElastic
momentumBalanceType = {args.momentum}
vL = {Vp:g}

# rate-and-state friction: RSF on 0-{Wf:g} km, creep at vL below (locked = -1)
lockedVals = [0 0 -1 -1]
lockedDepths = [0 {Wf+eps:.6f} {Wf+eps:.6f} {args.Lz}]
stateLaw = agingLaw
f0 = {f0}
v0 = {V0:g}
DcVals = [{Dc} {Dc}]
DcDepths = [0 {args.Lz}]
aVals = [{a0} {a0} {amax} {amax}]
aDepths = [0 {H} {H+hh} {args.Lz}]
bVals = [{b0} {b0}]
bDepths = [0 {args.Lz}]
sNVals = [{sigma} {sigma}]
sNDepths = [0 {args.Lz}]
rootTol = 1e-12

# off-fault material
muVals = [{mu:.8f} {mu:.8f}]
muDepths = [0 {args.Lz}]
rhoVals = [{rho} {rho}]
rhoDepths = [0 {args.Lz}]
linSolverTrans = MUMPSCHOLESKY
momBal_computeSxz = 0

# boundary conditions: quasi-dynamic phases (as SCycle's BP1.in: free surface everywhere but the fault)
momBal_bcR_qd = freeSurface
momBal_bcT_qd = freeSurface
momBal_bcB_qd = freeSurface
momBal_bcL_qd = symmFault
# fully dynamic phases: free surface on top, absorbing far boundaries
momBal_bcR_fd = outGoingCharacteristics
momBal_bcT_fd = freeSurface
momBal_bcB_fd = outGoingCharacteristics
momBal_bcL_fd = symmFault

# QD <-> FD switching (this SCycle version compares max slip rate [m/s])
trigger_qd2fd = {args.trigger_qd2fd:g}
trigger_fd2qd = {args.trigger_fd2qd:g}
limit_qd = {args.limit_qd:g}
limit_fd = {args.limit_fd:g}

# time integration
timeIntegrator = RK43
timeControlType = PID
timeIntInds = [psi slip]
normType = L2_absolute
timeStepTol = {args.timeStepTol:g}
initDeltaT = 1e-3
minDeltaT = 1e-3
maxDeltaT = 3.15576e7
initTime = 0
maxTime = {args.maxTime:.6e}
maxStepCount = {args.maxStepCount:.0f}
stride1D_qd = {args.stride1D_qd}
stride2D_qd = {args.stride2D_qd}
stride1D_fd = {args.stride1D_fd}
stride2D_fd = {args.stride2D_fd}
saveChkpts = 1
strideChkpt = 100000
strideChkpt_fd = 100000
restartFromChkpt = 0
maxNumCycles = {args.maxNumCycles}
"""
with open(os.path.join(base, "bp1fd.in"), "w") as fh:
    fh.write(infile)
print(f"{base}/bp1fd.in: Ny={Ny} Nz={Nz} nodes={Ny*Nz} ry={ry:.5f} rz={rz:.5f} "
      f"tau0={tau0:.6f} MPa eta={eta:.6f} psi(0)={psi[0]:.6f} psi(Lz)={psi[-1]:.6f}")
print("min/max dz near 40 km:", np.diff(z)[(z[:-1] > 39) & (z[:-1] < 41)][:3], " z[-3:]", z[-3:])
