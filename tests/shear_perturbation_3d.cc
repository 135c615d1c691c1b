// SPDX-License-Identifier: LGPL-2.1-or-later
// The shear stress perturbation Delta tau(x) g(t) of the Green's-function
// method (SEAS BP7's prescribed nucleation), in 3D with two-component slip,
// on the problem of tests/meshes/box-creep-3d.prm (a velocity-weakening
// patch in steady sliding at V = 1e-9 m/s, a = 0.01 and sigma_n = 50 MPa
// there; its 3 MPa nucleation spot is the shear prestress of that file).
// Checked (yes/no lines):
//  - the direct effect in closed form: a perturbation of 1 MPa on the spot,
//    ramped in by BP7's G2 (g(t) = exp((t - 1)^2 / (t (t - 2))) for
//    0 < t < 1 s, 1 after), raises the spot's slip rate to
//    log(V / 1e-9) = Delta tau g(t) / (a sigma_n) - (b / a) log(1 + t /
//    theta_0): the patch starts at V = 1e-9 m/s far below its steady
//    state (theta_0 = L / V* = 4000 s, so theta = theta_0 + t while
//    V theta / L < 0.01); the largest slip rate is the spot's or the
//    steady 1e-9 m/s of the velocity-strengthening nodes, to 1e-4 in
//    log V at every row up to t = 3 s (neglected: V theta / L in the
//    state's rate, 1e-5 in log V; the slip's stress, < 1 Pa; the
//    radiation damping, eta V < 0.1 Pa, against a sigma_n = 0.5 MPa);
//  - the perturbation acts as a prestress along the load: the spot's 3 MPa
//    given as a perturbation with g = 1 gives the first event of the
//    spot as prestress to 1e-6 (the two take different paths: the
//    prestress through the finite elements' load and the operator's g0,
//    the perturbation as lumped nodal forces added to the fault's force);
//  - its sign: -3 MPa on the spot delays the first event past the end of
//    the +3 MPa run's.
#include "run_model.h"
#include "tests.h"

#include <cmath>
#include <deal.II/base/mpi.h>

using namespace rsfcycle;

namespace
{
  const std::string spot = "if(abs(x) < 3e3 && z > -5e3 && z < -3e3, 1, 0)";
  const std::string steady_prestress =
    "50e6 * 0.025 * asinh(1e-9 / 2e-6 * exp((0.6 + 0.015 * ln(1e-6 / "
    "1e-9)) / 0.025))";

  /** events.csv and time-series.csv of a Green's-function run. */
  std::pair<std::vector<std::vector<double>>, std::vector<std::vector<double>>>
  run(const std::string &settings, const std::string &dir)
  {
    const std::string        source = SOURCE_DIR;
    dealii::ParameterHandler prm;
    app::declare_parameters(prm);
    prm.parse_input(source + "/meshes/box-creep-3d.prm");
    prm.parse_input_from_string(
      "set Output directory = " + dir +
      "\nsubsection Mesh file\n  set File = " + source +
      "/meshes/box-creep-3d.msh\nend\n"
      "subsection Time stepping\n"
      "  set Integrator = runge-kutta\n"
      "  set Tolerance = 1e-7\n"
      "  set Initial step = 1e-3\n"
      "  set Maximum step = 3.15576e7\n"
      "end\n"
      "subsection Solver\n  set Bulk = green-function\nend\n" +
      settings);
    run_model<3>(prm);
    return {read_csv(dir + "/events.csv"), read_csv(dir + "/time-series.csv")};
  }

  /** The friction settings: the prestress and the perturbation. */
  std::string
  friction_settings(const std::string &prestress,
                    const std::string &perturbation,
                    const std::string &history)
  {
    return "subsection Mesh file\n subsection Friction\n"
           "  set Shear prestress = " +
           prestress + "\n  set Shear stress perturbation = " + perturbation +
           "\n  set Shear stress perturbation history = " + history +
           "\n end\nend\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(6);
  const auto yes = [](const bool b) { return b ? "yes" : "no"; };

  // the direct effect: 1 MPa ramped in over 1 s, 3 s of steps <= 0.05 s
  const std::string g = "if(t <= 0, 0, if(t < 1, exp((t - 1)^2 / (t * (t - "
                        "2))), 1))";
  const auto        ramp =
    run(friction_settings(steady_prestress, "1e6 * " + spot, g) +
          "set End time = 3\nsubsection Time stepping\n"
          "  set Maximum step = 0.05\nend\n",
        "perturbation-ramp");
  const auto g_of = [](const double t) {
    return t <= 0 ? 0. :
           t < 1  ? std::exp((t - 1) * (t - 1) / (t * (t - 2))) :
                    1.;
  };
  double       worst = 0;
  unsigned int rows  = 0;
  for (const auto &row : ramp.second)
    {
      const double t = row[0], V = row[6];
      const double spot_log_V =
        1e6 * g_of(t) / (0.01 * 50e6) - 1.5 * std::log(1 + t / 4000);
      worst = std::max(worst,
                       std::abs(std::log(V / 1e-9) - std::max(0., spot_log_V)));
      ++rows;
    }
  dealii::deallog << "ramp: rows to t = 3 s: at least 60: " << yes(rows >= 60)
                  << "; log(V / 1e-9) = Delta tau g(t) / (a sigma_n) - (b / "
                     "a) log(1 + t / theta_0) to 1e-4 at every row: "
                  << yes(worst < 1e-4) << std::endl;
  dealii::deallog << "ramp: log(V / 1e-9) at t = 3 s (2 - 1.5 log(1 + 3 / "
                     "4000) = 1.9989): "
                  << std::round(std::log(ramp.second.back()[6] / 1e-9) * 1e4) /
                       1e4
                  << std::endl;

  // the spot as prestress, as a perturbation (g = 1), and of opposite sign
  const auto as_prestress =
    run(friction_settings("3e6 * " + spot + " + " + steady_prestress, "", "1"),
        "spot-prestress");
  const auto as_perturbation =
    run(friction_settings(steady_prestress, "3e6 * " + spot, "1"),
        "spot-perturbation");
  const auto opposite =
    run(friction_settings(steady_prestress, "-3e6 * " + spot, "1") +
          "set End time = " + std::to_string(as_prestress.second.back()[0]) +
          "\n",
        "spot-opposite");
  if (as_prestress.first.empty() || as_perturbation.first.empty())
    {
      dealii::deallog << "no first event" << std::endl;
      return 0;
    }
  const double t1 = as_prestress.first[0][1], t2 = as_perturbation.first[0][1];
  dealii::deallog << "first event [yr]: prestress "
                  << std::round(t1 / 3.15576e7 * 100) / 100
                  << "; the perturbation with g = 1 the same to 1e-6: "
                  << yes(std::abs(t2 / t1 - 1) < 1e-6) << std::endl;
  dealii::deallog << "-3 MPa: no event before the end of the +3 MPa run: "
                  << yes(opposite.first.empty()) << std::endl;
  return 0;
}
