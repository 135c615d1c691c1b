// SPDX-License-Identifier: LGPL-2.1-or-later
// The two mirror models of SEAS BP1-QD (prm/seas-bp1-qd.prm) that
// tests/green_function_split.cc and tests/volume_split.cc compare: the
// one-sided body x >= 0 of prm/meshes/seas-bp1.msh with G/2 and rho/2
// against a rigid mirror (the benchmark's reduction), and the two-sided
// tests/meshes/split-fault-2d.msh, the same body and its mirror image
// x <= 0 with the full G and rho, the fault meshed once per side, the
// remote sides at +Vp/2 (load) and -Vp/2 (load-opposite), the fault below
// 40 km creeping at the plates' difference Vp; gravity off. Plane strain
// ("vector": dip slip on the vertical fault): the one-sided contact's
// normal free and its extension creeping. Observation points at 2 and 8
// km, the two-sided model's also at -2 km (time-series.csv columns 7, 8,
// and 9).
#ifndef rsfcycle_tests_bp1_mirror_models_h
#define rsfcycle_tests_bp1_mirror_models_h

#include <string>

/** Settings over prm/seas-bp1-qd.prm: the one-sided mirror model. */
inline std::string
bp1_one_sided(const std::string &displacement)
{
  const std::string source = SOURCE_DIR;
  const bool        vector = displacement == "vector";
  return "set Displacement = " + displacement +
         "\n"
         "subsection Mesh file\n"
         "  set File = " +
         source +
         "/../prm/meshes/seas-bp1.msh\n"
         "  set Gravity = 0, 0\n"
         "  set Observation points = fn+02: 2e3, 0; fn+08: 8e3, 0\n" +
         (vector ? "  set Load velocity = 0, 1e-9\n"
                   "  set Contact normal = free\n"
                   "  set Boundary roles = 1: contact, 2: creep, 3: free, 4: "
                   "free, 5: load\n" :
                   "") +
         "end\n";
}

/** Settings over prm/seas-bp1-qd.prm: the two-sided split fault. */
inline std::string
bp1_two_sided(const std::string &displacement)
{
  const std::string source = SOURCE_DIR;
  const bool        vector = displacement == "vector";
  const std::string material =
    "density 2670, bulk modulus 53.39686e9, Poisson ratio 0.25, shear "
    "viscosity 0, bulk viscosity 0";
  return "set Displacement = " + displacement +
         "\n"
         "subsection Mesh file\n"
         "  set File = " +
         source +
         "/meshes/split-fault-2d.msh\n"
         "  set Boundary roles = 1: contact, 2: creep, 3: free, 4: free, 5: "
         "load, 11: fault-opposite, 12: fault-opposite, 13: free, 14: free, "
         "15: load-opposite\n"
         "  set Materials = 10: " +
         material + "; 20: " + material +
         "\n"
         "  set Gravity = 0, 0\n"
         "  set Load velocity = " +
         (vector ? "0, 5e-10" : "5e-10") +
         "\n"
         "  set Observation points = fn+02: 2e3, 0; fn+08: 8e3, 0; fn-02: "
         "-2e3, 0\n"
         "end\n";
}

#endif
