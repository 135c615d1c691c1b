// SPDX-License-Identifier: LGPL-2.1-or-later
// The Green's-function method in 3D (two tangential dofs per contact node,
// the slip rate along the traction: free rake) against the volume path on
// the same mesh: tests/meshes/box-fault-3d.prm and .msh (a 24 x 12 x 12 km box
// of 2 km hexahedra, the fault plane y = 0 with 91 contact nodes, loaded at
// 1e-9 m/s along strike on the far side y = 12 km), a 12 x 6 km
// velocity-weakening patch (a = 0.01, b = 0.015, L = 8 mm) in a
// velocity-strengthening fault (a = 0.025), the BP1-like steady start at
// the plate rate and 3 MPa more shear prestress on a 6 x 3 km nucleation
// spot, quasi-dynamic, to the end of the first event (about 21 years).
// Both methods discretise the same semi-discrete problem (the same
// stiffness, lumped weights, radiation damping and law), the volume path
// with the trapezoidal step (delta = epsilon = 1e-4, TNNMG with the direct
// correction), the Green's-function method with the explicit
// Dormand-Prince 5(4) at 1e-7, so they differ by time-integration errors
// only (measured 7e-5 in the start time). Checked (yes/no lines):
//  - one event each; the first event within 0.05 % in time, its peak slip
//    rate within 2 %, its slip within 1 %, the same nucleation node;
//  - with Mesh file/Contact normal = free (the fault plane of an
//    antisymmetric problem: its normal displacement free, the normal
//    traction on the body zero) both methods again: one event each, the
//    first within 0.05 % of each other, and not the held contact's (the
//    body is softer: more than 0.1 % apart);
//  - the operator compressed as an H-matrix (a node's two dofs as two
//    points at its position): the same first event within 1e-6 relative;
//  - the uplift at the surface point (6, 2, 0) km at the end (the
//    operator's observation row against the volume's displacement; a
//    strike-slip patch lifts the surface only through its ends, so both
//    slip components enter) within 1 %.
// Figures are printed to digits that rounding cannot move.
#include "run_model.h"
#include "tests.h"

#include <cmath>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <iomanip>
#include <rsfcycle/app/simulation.h>
#include <rsfcycle/scenes/scenes.h>
#include <sstream>

using namespace rsfcycle;

namespace
{
  struct Result
  {
    std::vector<std::vector<double>> events;
    /** The last row of time-series.csv: the uplift at (6, 2, 0) km [m]. */
    double uplift = 0;
  };


  Result
  run(const std::string &settings, const std::string &dir)
  {
    const std::string        source = SOURCE_DIR;
    dealii::ParameterHandler prm;
    app::declare_parameters(prm);
    prm.parse_input(source + "/meshes/box-fault-3d.prm");
    prm.parse_input_from_string(
      "set Output directory = " + dir +
      "\nsubsection Mesh file\n  set File = " + source +
      "/meshes/box-fault-3d.msh\nend\n" + settings);
    run_model<3>(prm);
    Result result;
    result.events = read_csv(dir + "/events.csv");
    // the observation column follows the 7 fixed ones
    result.uplift = read_csv(dir + "/time-series.csv").back()[7];
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(6);
  const double year  = 3.15576e7;
  const auto   fixed = [](const double x, const int digits) {
    std::ostringstream out;
    out << std::fixed << std::setprecision(digits) << x;
    return out.str();
  };
  const auto yes = [](const bool b) { return b ? "yes" : "no"; };

  const std::string volume_settings = "subsection Time stepping\n"
                                      "  set Integrator = implicit\n"
                                      "  set Tolerance = 1e-4\n"
                                      "  set Initial step = 1e5\n"
                                      "  set Maximum step = 3.15576e7\n"
                                      "end\n"
                                      "subsection Solver\n"
                                      "  set Bulk = volume\n"
                                      "  set Linear correction = direct\n"
                                      "  set Fixed-point tolerance = 1e-4\n"
                                      "  set TNNMG tolerance = 1e-8\n"
                                      "  set Inner tolerance factor = 0\n"
                                      "end\n";
  const Result      volume          = run(volume_settings, "output-volume");
  const std::string green_settings  = "subsection Time stepping\n"
                                      "  set Integrator = runge-kutta\n"
                                      "  set Tolerance = 1e-7\n"
                                      "  set Initial step = 1e5\n"
                                      "  set Maximum step = 3.15576e7\n"
                                      "end\n"
                                      "subsection Solver\n"
                                      "  set Bulk = green-function\n";
  const Result      green =
    run(green_settings + "  set Green operator storage = dense\nend\n",
        "output-green");
  const Result compressed =
    run(green_settings + "  set Green operator storage = h-matrix\nend\n",
        "output-h-matrix");

  const std::string free_normal =
    "subsection Mesh file\n  set Contact normal = free\nend\n";
  const Result volume_free =
    run(volume_settings + free_normal, "output-volume-free");
  const Result green_free =
    run(green_settings + "end\n" + free_normal, "output-green-free");

  dealii::deallog << "events: volume " << volume.events.size() << ", green "
                  << green.events.size() << ", h-matrix "
                  << compressed.events.size() << " (one each: "
                  << yes(volume.events.size() == 1 &&
                         green.events.size() == 1 &&
                         compressed.events.size() == 1)
                  << ")" << std::endl;
  if (volume.events.empty() || green.events.empty() ||
      compressed.events.empty())
    return 0;
  const auto &v = volume.events[0], &g = green.events[0],
             &h = compressed.events[0];
  dealii::deallog << "first event [yr]: volume " << fixed(v[1] / year, 2)
                  << ", green " << fixed(g[1] / year, 2) << "; within 0.05 %: "
                  << yes(std::abs(g[1] / v[1] - 1) < 5e-4) << std::endl;
  dealii::deallog << "peak log10 V [m/s]: volume " << fixed(std::log10(v[5]), 2)
                  << ", green " << fixed(std::log10(g[5]), 2)
                  << "; within 2 %: " << yes(std::abs(g[5] / v[5] - 1) < 0.02)
                  << std::endl;
  dealii::deallog << "largest slip [mm]: volume " << fixed(v[7] / 1e3, 0)
                  << ", green " << fixed(g[7] / 1e3, 0)
                  << "; within 1 %: " << yes(std::abs(g[7] / v[7] - 1) < 0.01)
                  << std::endl;
  dealii::deallog << "nucleation [m along the base]: volume " << v[4]
                  << ", green " << g[4] << "; the same: " << yes(v[4] == g[4])
                  << std::endl;
  dealii::deallog << "uplift at (6, 2, 0) km at the end: within 1 %: "
                  << yes(std::abs(green.uplift / volume.uplift - 1) < 0.01)
                  << " (nonzero: " << yes(std::abs(volume.uplift) > 1e-6) << ")"
                  << std::endl;
  dealii::deallog << "h-matrix: first event within 1e-6 of the dense one: "
                  << yes(std::abs(h[1] / g[1] - 1) < 1e-6)
                  << ", peak within 1e-4: "
                  << yes(std::abs(h[5] / g[5] - 1) < 1e-4) << std::endl;
  dealii::deallog << "free normal: events volume " << volume_free.events.size()
                  << ", green " << green_free.events.size() << " (one each: "
                  << yes(volume_free.events.size() == 1 &&
                         green_free.events.size() == 1)
                  << ")" << std::endl;
  if (volume_free.events.empty() || green_free.events.empty())
    return 0;
  const auto &vf = volume_free.events[0], &gf = green_free.events[0];
  dealii::deallog << "free normal: first event [yr]: volume "
                  << fixed(vf[1] / year, 2) << ", green "
                  << fixed(gf[1] / year, 2) << "; within 0.05 %: "
                  << yes(std::abs(gf[1] / vf[1] - 1) < 5e-4)
                  << "; peak within 2 %: "
                  << yes(std::abs(gf[5] / vf[5] - 1) < 0.02)
                  << "; apart from the held contact's by more than 0.1 %: "
                  << yes(std::abs(vf[1] / v[1] - 1) > 1e-3) << std::endl;
  return 0;
}
