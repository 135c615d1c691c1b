// SPDX-License-Identifier: LGPL-2.1-or-later
// A fault between two deformable sides in the volume method
// (Discretisation::tie_fault_sides, physics/split_fault.h) against the
// one-sided mirror model of the same antisymmetric problem: SEAS BP1-QD
// (prm/seas-bp1-qd.prm with Solver/Bulk = volume, the direct linear
// correction, implicit steps at tolerance 1e-6, TNNMG 1e-11) on 400 m fault
// cells, gravity off, over the first 1e9 s (interseismic creep into the
// locked patch; about 1,700 steps; the largest slip rate 9.5e-10 m/s at the
// end).
//  (the two models of tests/bp1_mirror_models.h)
//  - one-sided: the body x >= 0 of prm/meshes/seas-bp1.msh with G/2 and
//    rho/2 against a rigid mirror (the benchmark's reduction);
//  - two-sided: tests/meshes/split-fault-2d.msh, the same body and its
//    mirror image x <= 0 with the full G and rho, the fault x = 0 meshed
//    once per side, the remote sides at +Vp/2 and -Vp/2, the fault below
//    40 km creeping at Vp, the radiation damping of a fault between two
//    sides (tests/green_function_split.cc, the same set-up in the
//    Green's-function method).
// The two-sided solution is antisymmetric and its + half is the one-sided
// solution with the displacement halved: the tied system of the two sides
// has the energy, the mass, the damping and the friction of the one-sided
// system in the same slip, so the two runs solve the same discrete problem
// and agree to the solver's tolerance. Checked, antiplane and plane strain
// (dip slip on the vertical fault; the one-sided contact's normal free, the
// two-sided normal displacement tied, and by antisymmetry the slip changes
// no normal stress):
//  - after the first step (the same step in both): the surface
//    displacement at 2 and 8 km from the fault, 2 x two-sided against
//    one-sided, within 1e-8, and at -2 km the negative of +2 km's within
//    1e-9 (the - side, from the mean and the slip);
//  - at the end: the same number of steps, the largest slip rate within
//    1e-6 relative and the surface displacement at 2 km within 1e-6.
// On 2 ranks (volume_split.mpirun=2.output; the two sides' nodes of a pair
// on different ranks): algebraic multigrid instead of the direct correction
// (one rank only), to 5e7 s, antiplane only (the plane-strain tie across
// ranks, with its normal displacement, is volume_split_normal.mpirun=2's),
// the same checks but the steps' count (the iterative solves' rounding
// moves the step sizes).
// Printed: the first step's displacement in um to 1e-6, the end's in mm
// to 0.01, log10 V [m/s] to 0.001.
#include "bp1_mirror_models.h"
#include "run_model.h"
#include "tests.h"

#include <cmath>
#include <deal.II/base/mpi.h>
#include <iomanip>
#include <sstream>

using namespace rsfcycle;

namespace
{
  struct Result
  {
    std::vector<std::vector<double>> series;
  };

  Result
  run(const std::string &settings, const std::string &dir)
  {
    const std::string        source = SOURCE_DIR;
    dealii::ParameterHandler prm;
    app::declare_parameters(prm);
    prm.parse_input(source + "/../prm/seas-bp1-qd.prm");
    prm.parse_input_from_string(
      "set Output directory = " + dir +
      "\n"
      "set Overwrite output = true\n"
      "set End time = " +
      std::string(on_ranks() ? "5e7" : "1e9") +
      "\n"
      "subsection Mesh\n"
      "  set Local refinements = 2\n"
      "end\n"
      "subsection Time stepping\n"
      "  set Integrator = implicit\n"
      "  set Tolerance = 1e-6\n"
      "end\n"
      "subsection Solver\n"
      "  set Bulk = volume\n" +
      (on_ranks() ? "  set Linear correction = amg\n"
                    "  set Linear correction cycles = 20\n" :
                    "  set Linear correction = direct\n") +
      "  set TNNMG tolerance = 1e-11\n"
      "end\n"
      "subsection Output\n"
      "  set Writers = time series, base profile, events\n"
      "  set Progress interval = 1e9\n"
      "  subsection SEAS\n"
      "    set Benchmark = none\n"
      "  end\n"
      "end\n" +
      settings);
    run_model<2>(prm);
    return {read_csv(dir + "/time-series.csv")};
  }

  const char *
  yes(const bool condition)
  {
    return condition ? "yes" : "no";
  }

  void
  compare(const std::string &displacement)
  {
    const std::string one_sided = bp1_one_sided(displacement);
    const std::string two_sided = bp1_two_sided(displacement);
    const Result      one =
      run(one_sided, "output-volume-one-sided-" + displacement);
    const Result two =
      run(two_sided, "output-volume-two-sided-" + displacement);

    dealii::deallog << displacement << std::endl;
    // time-series.csv: 7 fixed columns (the 7th the largest slip rate),
    // then the observations
    const auto &a = one.series.front(), &b = two.series.front();
    double      error = 0;
    for (const unsigned int c : {7u, 8u})
      error = std::max(error, std::abs(2 * b[c] / a[c] - 1));
    dealii::deallog << "first step: the same in both: " << yes(a[0] == b[0])
                    << "; surface displacement at 2 km [um]: one-sided "
                    << to_fixed(1e6 * a[7], 6) << ", 2 x two-sided "
                    << to_fixed(2e6 * b[7], 6)
                    << "; at 2 and 8 km within 1e-8: " << yes(error < 1e-8)
                    << "; at -2 km the negative within 1e-9: "
                    << yes(std::abs(b[9] + b[7]) < 1e-9 * std::abs(b[7]))
                    << std::endl;
    const auto &ea = one.series.back(), &eb = two.series.back();
    dealii::deallog << "at the end: ";
    if (!on_ranks())
      dealii::deallog << "steps " << one.series.size() << " and "
                      << two.series.size() << ", the same: "
                      << yes(one.series.size() == two.series.size()) << "; ";
    dealii::deallog << "log10 max V [m/s]: one-sided "
                    << to_fixed(std::log10(ea[6]), 3) << ", two-sided "
                    << to_fixed(std::log10(eb[6]), 3) << "; within 1e-6: "
                    << yes(std::abs(eb[6] / ea[6] - 1) < 1e-6) << std::endl;
    dealii::deallog << "surface displacement at 2 km at the end [mm]: "
                       "one-sided "
                    << to_fixed(1e3 * ea[7], 2) << ", 2 x two-sided "
                    << to_fixed(2e3 * eb[7], 2) << "; within 1e-6: "
                    << yes(std::abs(2 * eb[7] / ea[7] - 1) < 1e-6) << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(6);
  compare("antiplane");
  if (!on_ranks())
    compare("vector");
  return 0;
}
