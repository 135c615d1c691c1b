#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Writes tandem's BP3-QD parameter file (TOML) for one dip and sense.

    tandem_input.py OUTDIR --dip 60 --sense thrust --mesh bp3.msh [--rtol-output R]

The scenario is tandem's own example (examples/tandem/2d/bp3.lua, copied
next to the mesh by run.sh): bp3_d{dip}_{reverse|normal}. Outputs: the
12 on-fault stations of the benchmark (fltst_dpXXX, at the down-dip
distances 0 ... 35 km), the maximum slip rate (global_, tandem's
fault_scalar_output) and the surface stations at x = +8 and -8 km
(srfst_fn+08, srfst_fn-08; tandem's y is up, the surface is y = 0).
Green's functions (mode QDGreen) are kept in OUTDIR/gf, so a second run on
the same mesh reuses them; the time loop is checkpointed to
OUTDIR/checkpoint every 10 CPU minutes (tandem's default is 30), and
--resume makes the run start from the last one (run.sh's RESUME=1).
"""
import argparse
import math

p = argparse.ArgumentParser()
p.add_argument("outdir")
p.add_argument("--dip", type=int, default=60)
p.add_argument("--sense", choices=("thrust", "normal"), default="thrust")
p.add_argument("--mesh", required=True)
p.add_argument("--final-time", type=float, default=47304000000.0,
               help="s (default 1500 years of 365 days)")
p.add_argument("--resume", action="store_true",
               help="continue from OUTDIR/checkpoint/last_checkpoint.txt")
a = p.parse_args()

dip = math.radians(a.dip)
scenario = (f"bp3_d{a.dip}" if a.dip == 90 else
            f"bp3_d{a.dip}_{'reverse' if a.sense == 'thrust' else 'normal'}")
probes = ",\n".join(
    f'    {{ name = "dp{dp:03d}", x = [{dp / 10 * math.cos(dip):.15g}, '
    f'{-dp / 10 * math.sin(dip):.15g}] }}'
    for dp in (0, 25, 50, 75, 100, 125, 150, 175, 200, 250, 300, 350))
resume = ('load_directory = "checkpoint/last_checkpoint.txt"\n'
          if a.resume else "")
# t_max: at most 0.3 years between samples between events (tandem's
# adaptive output samples densely when the slip rate changes)
toml = f"""final_time = {a.final_time:.0f}
mesh_file = "{a.mesh}"
lib = "bp3.lua"
scenario = "{scenario}"
mode = "QDGreen"
type = "elasticity"
ref_normal = [1, 0]
boundary_linear = true

[gf_checkpoint]
prefix = "gf"

[ts_checkpoint]
freq_cputime = 10
{resume}
[fault_probe_output]
prefix = "fltst_"
t_max = 9460800
probes = [
{probes}
]

[fault_scalar_output]
prefix = "global_"
t_max = 9460800

[domain_probe_output]
prefix = "srfst_"
t_max = 9460800
probes = [
    {{ name = "fn+08", x = [8.0, 0.0] }},
    {{ name = "fn-08", x = [-8.0, 0.0] }}
]
"""
with open(f"{a.outdir}/bp3.toml", "w") as f:
    f.write(toml)
print(scenario)
