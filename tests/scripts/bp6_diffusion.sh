#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# SEAS BP6-QD-A (prm/seas-bp6-qd-a.prm) on 200 m cells over its two years,
# twice: the pore pressure of the closed form (Pore pressure and Darcy
# velocity as expressions) and the pressure diffusing along the fault
# from an injection at one node (Pore fluid/Source = point, the 1D
# physics::FaultDiffusion on 25 m cells of |x3| <= 20 km, no flux at the
# ends, steps of 3600 s). Checked against the closed form and the physics:
#  - the diffused pore pressure at the station nodes x3 = 0, 1 and 5 km
#    equals BP6's closed form p = q0 / (beta phi sqrt(alpha)) [G(x, t) -
#    G(x, t - t_off)] (written again here) after the first 10 days to
#    0.01 MPa at the injection node (the point source's discretisation
#    error) and 1 kPa at 1 and 5 km; its Darcy velocity at 1 km equals the
#    closed form's to 1 % of its peak;
#  - the slip and the shear stress of every station stay within the
#    discretisation error of the closed-form run: the slip to 0.5 % of the
#    station's largest, the shear stress to 0.03 MPa (0.1 % of tau_init),
#    and the slip at the injection point after two years to 0.05 %.
# (Measured: the injection node's pressure within 8 kPa of 6.55 MPa after
# 10 days, the slip at x3 = 0 after two years 208.626 mm against 208.631
# mm, the stations' slip within 0.15 % of their largest, their shear
# stress within 0.012 MPa.)
# Usage: bp6_diffusion.sh RSFCYCLE SOURCE_DIR WORK_DIR PYTHON
set -u
exe=$1; src=$2; work=$3; python=$4
rm -rf "$work"; mkdir -p "$work"; cd "$work" || exit 1

for case in function point; do
  {
    echo "include $src/prm/seas-bp6-qd-a.prm"
    echo "set Output directory = $case"
    echo "subsection Mesh"
    echo "  set Local refinements = 3"
    echo "end"
    echo "subsection Output"
    echo "  set Writers = seas"
    echo "  set Progress interval = 1e9"
    echo "end"
    if [ $case = point ]; then
      printf '%s\n' "subsection Mesh file" "subsection Friction" \
        "set Pore pressure =" "set Darcy velocity =" \
        "subsection Pore fluid" "set Source = point" \
        "set Injection rate = 1.25e-6" "set Shut-in time = 8640000" \
        "set Permeability = 1e-13" "set Half width = 20000" \
        "set Cell size = 25" "set Time step = 3600" \
        "set Plane coordinates = -y" "end" "end" "end"
    fi
  } > $case.prm
  "$exe" $case.prm > $case.log 2>&1 || { tail -3 $case.log; exit 1; }
done

"$python" - <<'PY'
import glob, math, os, sys
import numpy as np

q0, beta, phi, alpha, t_off = 1.25e-6, 1e-8, 0.1, 0.1, 8640000.0


def G(x, t):
    if t <= 0:
        return 0.0
    u = abs(x) / math.sqrt(4 * alpha * t)
    return math.sqrt(t) * (math.exp(-u * u) / math.sqrt(math.pi)
                           - u * math.erfc(u))


def pressure(x, t):  # MPa
    return q0 / (beta * phi * math.sqrt(alpha)) * (G(x, t)
                                                   - G(x, t - t_off)) / 1e6


def darcy(x, t):
    e = lambda s: math.erfc(abs(x) / math.sqrt(4 * alpha * s)) if s > 0 else 0
    return math.copysign(1, x) * q0 / 2 * (e(t) - e(t - t_off))


def load(path):
    rows = [line.split() for line in open(path)
            if line.strip() and line[0] not in "#t"]
    return np.array(rows, dtype=float)


ok = True


def say(what, holds):
    global ok
    ok = ok and holds
    print(("yes " if holds else "NO  ") + what)


for name, x, tol in (("+00", 0.0, 0.01), ("+10", 1e3, 1e-3),
                     ("+50", 5e3, 1e-3)):
    d = load("point/fltst_strk" + name)
    late = d[:, 0] > 10 * 86400
    err = max(abs(p - pressure(x, t)) for t, p in zip(d[late, 0], d[late, 4]))
    say(f"p at x3 = {x / 1e3:g} km against the closed form to {tol} MPa",
        err <= tol)
d = load("point/fltst_strk+10")
peak = max(abs(darcy(1e3, t)) for t in d[:, 0])
err = max(abs(q - darcy(1e3, t)) for t, q in zip(d[:, 0], d[:, 5]))
say("Darcy velocity at 1 km against the closed form to 1 % of its peak",
    err <= 0.01 * peak)
for path in sorted(glob.glob("function/fltst_*")):
    a, b = load(path), load("point/" + os.path.basename(path))
    slip = np.interp(a[:, 0], b[:, 0], b[:, 1])
    tau = np.interp(a[:, 0], b[:, 0], b[:, 3])
    name = os.path.basename(path)
    say(f"{name}: slip within 0.5 % of its largest, shear stress within "
        "0.03 MPa of the closed-form run",
        np.max(abs(slip - a[:, 1])) <= 5e-3 * np.max(abs(a[:, 1]))
        and np.max(abs(tau - a[:, 3])) <= 0.03)
a, b = load("function/fltst_strk+00"), load("point/fltst_strk+00")
say("slip at the injection point after two years within 0.05 %",
    abs(b[-1, 1] / a[-1, 1] - 1) <= 5e-4 and a[-1, 0] == b[-1, 0])
sys.exit(0 if ok else 1)
PY
