// SPDX-License-Identifier: LGPL-2.1-or-later
// The slip-induced normal stress of a split fault in the volume method
// (Discretisation::fault_normal_rows, ImplicitStep::couple_normal_forces)
// against the Green's-function method on the same mesh: SEAS BP3-QD at 60
// degrees, thrust (prm/seas-bp3-qd.prm) on 200 m fault cells (2 local
// refinements, 200 contact nodes, one rank), both with implicit steps at
// tolerance 1e-5 and TNNMG 1e-10, over the first 3e9 s (95 years of
// interseismic loading: the creep below the locked zone raises the normal
// stress at the surface by about 2.5 MPa). On one mesh the two methods solve
// the same discrete problem (the Green's functions are the Schur complement
// of the volume's stiffness, the normal rows the same rows of the + side),
// so they agree up to their time integration. Checked (measured: 6-7
// digits, benchmarks/seas-bp3/README.md):
//  - at 3e9 s, the normal stress change at the surface (dp000) and at
//    10 km (dp100) within 1e-4 of the surface's change;
//  - the slip rate at dp100 and dp200 within 1e-4 (log10 within 4e-5);
//  - the surface displacement at +-8 km (two components) within 1e-5
//    relative.
// On 2 ranks (volume_split_normal.mpirun=2.output; the pairs' two nodes
// on different ranks, the normal rows reading ghosts): the volume method
// with algebraic multigrid (the direct correction runs on one rank; on
// BP3's domain it needs 60-80 CG iterations a step), to 3e7 s (132 steps,
// normal stress changes of 0.03 MPa), the same checks but the surface
// displacements within 5e-5 (at 3e7 s the two methods' first steps still
// show: 1.1e-5 apart on one rank with the direct correction too; the
// 2-rank volume run is within 7e-7 of the 1-rank one).
// Printed: the normal stress changes [MPa] to 1e-3, log10 V to 1e-3, the
// displacements [m] to 1e-4.
#include "run_model.h"
#include "tests.h"

#include <cmath>
#include <deal.II/base/mpi.h>

using namespace rsfcycle;

namespace
{
  const char *
  yes(const bool ok)
  {
    return ok ? "yes" : "no";
  }

  void
  run(const std::string &bulk, const std::string &dir)
  {
    const std::string        source = SOURCE_DIR;
    dealii::ParameterHandler prm;
    app::declare_parameters(prm);
    prm.parse_input(source + "/../prm/seas-bp3-qd.prm");
    prm.parse_input_from_string("set Output directory = " + dir +
                                "\n"
                                "set Overwrite output = true\n"
                                "set End time = " +
                                std::string(on_ranks() ? "3e7" : "3e9") +
                                "\n"
                                "subsection Mesh file\n"
                                "  set File = " +
                                source +
                                "/../prm/meshes/seas-bp3-60.msh\n"
                                "end\n"
                                "subsection Mesh\n"
                                "  set Global refinements = 0\n"
                                "  set Local refinements = 2\n"
                                "end\n"
                                "subsection Time stepping\n"
                                "  set Integrator = implicit\n"
                                "end\n"
                                "subsection Solver\n"
                                "  set Bulk = " +
                                bulk +
                                "\n"
                                "  set Linear correction = " +
                                (bulk == "volume" && on_ranks() ?
                                   "amg\n  set Linear correction cycles = 20" :
                                   "direct") +
                                "\n"
                                "  set TNNMG tolerance = 1e-10\n"
                                "end\n"
                                "subsection Output\n"
                                "  set Progress interval = 1e9\n"
                                "end\n");
    run_model<2>(prm);
  }

  /** Column `column` of a SEAS file at time t (linear in between rows). */
  double
  at(const std::string &file, const double t, const unsigned int column)
  {
    const auto rows = read_seas(file);
    for (unsigned int k = 1; k < rows.size(); ++k)
      if (rows[k][0] >= t)
        {
          const double w = (t - rows[k - 1][0]) / (rows[k][0] - rows[k - 1][0]);
          return (1 - w) * rows[k - 1][column] + w * rows[k][column];
        }
    return rows.back()[column];
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(6);
  run("volume", "bp3-volume");
  run("green-function", "bp3-green");
  const double t = on_ranks() ? 3e7 : 3e9;
  // fltst: t slip slip_rate shear_stress normal_stress state
  const auto station = [&](const std::string &dir, const std::string &dp) {
    return dir + "/fltst_dp" + dp;
  };
  const double scale = at(station("bp3-green", "000"), t, 4) - 50;
  for (const std::string dp : {"000", "100"})
    {
      const double v = at(station("bp3-volume", dp), t, 4) - 50,
                   g = at(station("bp3-green", dp), t, 4) - 50;
      dealii::deallog << "dp" << dp << " normal stress change [MPa]: volume "
                      << to_fixed(v, 3) << ", Green's functions "
                      << to_fixed(g, 3) << "; within 1e-4 of the surface's: "
                      << yes(std::abs(v - g) < 1e-4 * std::abs(scale))
                      << std::endl;
    }
  for (const std::string dp : {"100", "200"})
    {
      const double v = at(station("bp3-volume", dp), t, 2),
                   g = at(station("bp3-green", dp), t, 2);
      dealii::deallog << "dp" << dp << " log10 V [m/s]: volume "
                      << to_fixed(v, 3) << ", Green's functions "
                      << to_fixed(g, 3)
                      << "; within 4e-5: " << yes(std::abs(v - g) < 4e-5)
                      << std::endl;
    }
  for (const std::string fn : {"+08", "-08"})
    for (const unsigned int c : {1u, 2u})
      {
        const double v = at("bp3-volume/srfst_fn" + fn, t, c),
                     g = at("bp3-green/srfst_fn" + fn, t, c);
        dealii::deallog << "fn" << fn << " displacement " << c
                        << " [m]: volume " << to_fixed(v, 4)
                        << ", Green's functions " << to_fixed(g, 4)
                        << "; within " << (on_ranks() ? "5e-5" : "1e-5") << ": "
                        << yes(std::abs(v - g) <
                               (on_ranks() ? 5e-5 : 1e-5) * std::abs(g))
                        << std::endl;
      }
  return 0;
}
