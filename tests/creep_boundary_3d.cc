// SPDX-License-Identifier: LGPL-2.1-or-later
// The creep role (a part of the fault plane that slides at the load
// velocity, its normal displacement as the contact's) and free slip on a
// face parallel to the contact, in 3D, on tests/meshes/box-creep-3d.prm
// and .msh: SEAS BP5's set-up in small (the frictional contact above 8 km
// depth with a free normal, the plane below it creeping at 1e-9 m/s, the
// only load; the far side y = 12 km free slip), quasi-dynamic, to the end
// of the first event. Checked (yes/no lines):
//  - the Green's-function method (explicit Dormand-Prince 5(4) at 1e-7)
//    and the volume path (trapezoidal step, TNNMG with the geometric
//    multigrid correction, whose Dirichlet masks of creep and free slip
//    are built apart from the fixed dofs the Green's functions use): one
//    event each, the first within 0.05 % of each other, peaks within 2 %;
//  - the boundary conditions at the end, in both methods, from the
//    observation points' three components: on the far side the normal
//    displacement is zero (|u_y| < 1e-12 m) while it moves along strike;
//    on the creeping plane u_x = 1e-9 m/s t to 1e-6 relative and u_z = 0,
//    while its normal displacement is free (|u_y| > 1 mm);
//  - with the contact's normal held, creep is a load boundary: the first
//    event of creep and of `load` on the same faces (far side free) the
//    same to 1e-9 relative;
//  - with the normal free, holding the creeping plane's normal too (a
//    load boundary there, as BP5 ran before the creep role) stiffens the
//    body: its first event more than 0.1 % earlier than with creep.
// Figures are printed to digits that rounding cannot move.
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
    std::vector<std::vector<double>> events;
    /** The last row of time-series.csv. */
    std::vector<double> last;
  };


  Result
  run(const std::string &settings, const std::string &dir)
  {
    const std::string        source = SOURCE_DIR;
    dealii::ParameterHandler prm;
    app::declare_parameters(prm);
    prm.parse_input(source + "/meshes/box-creep-3d.prm");
    prm.parse_input_from_string(
      "set Output directory = " + dir +
      "\nsubsection Mesh file\n  set File = " + source +
      "/meshes/box-creep-3d.msh\nend\n" + settings);
    run_model<3>(prm);
    return {read_csv(dir + "/events.csv"),
            read_csv(dir + "/time-series.csv").back()};
  }


  std::string
  roles(const std::string &far, const std::string &lower)
  {
    return "subsection Mesh file\n  set Boundary roles = 1: contact, 2: " +
           far + ", 3: free, 4: free, 5: " + lower + "\nend\n";
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
                                      "  set Linear correction = multigrid\n"
                                      "  set Fixed-point tolerance = 1e-4\n"
                                      "  set TNNMG tolerance = 1e-8\n"
                                      "  set Inner tolerance factor = 0\n"
                                      "end\n";
  const std::string green_settings  = "subsection Time stepping\n"
                                      "  set Integrator = runge-kutta\n"
                                      "  set Tolerance = 1e-7\n"
                                      "  set Initial step = 1e5\n"
                                      "  set Maximum step = 3.15576e7\n"
                                      "end\n"
                                      "subsection Solver\n"
                                      "  set Bulk = green-function\n"
                                      "end\n";
  const std::string held =
    "subsection Mesh file\n  set Contact normal = held\nend\n";

  const Result volume = run(volume_settings, "creep-volume");
  const Result green  = run(green_settings, "creep-green");
  const Result normal_held =
    run(green_settings + roles("free-slip", "load"), "creep-normal-held");
  const Result held_creep =
    run(green_settings + held + roles("free", "creep"), "held-creep");
  const Result held_load =
    run(green_settings + held + roles("free", "load"), "held-load");

  dealii::deallog << "events: volume " << volume.events.size() << ", green "
                  << green.events.size() << " (one each: "
                  << yes(volume.events.size() == 1 && green.events.size() == 1)
                  << ")" << std::endl;
  if (volume.events.empty() || green.events.empty() ||
      normal_held.events.empty() || held_creep.events.empty() ||
      held_load.events.empty())
    return 0;
  const auto &v = volume.events[0], &g = green.events[0];
  dealii::deallog << "first event [yr]: volume " << fixed(v[1] / year, 2)
                  << ", green " << fixed(g[1] / year, 2) << "; within 0.05 %: "
                  << yes(std::abs(g[1] / v[1] - 1) < 5e-4)
                  << "; peaks within 2 %: "
                  << yes(std::abs(g[5] / v[5] - 1) < 0.02) << std::endl;

  // the time-series columns: t and 6 fixed ones, then far (u_x, u_y, u_z),
  // creep (u_x, u_y, u_z)
  for (const auto &[name, r] :
       {std::make_pair("volume", &volume), std::make_pair("green", &green)})
    {
      const auto  &row = r->last;
      const double t = row[0], far_y = row[8], creep_x = row[10],
                   creep_y = row[11], creep_z = row[12];
      dealii::deallog << name
                      << ": far side u_y = 0: " << yes(std::abs(far_y) < 1e-12)
                      << " (u_x moves: " << yes(std::abs(row[7]) > 1e-3)
                      << "); creeping plane u_x = V t: "
                      << yes(std::abs(creep_x / (1e-9 * t) - 1) < 1e-6)
                      << ", u_z = 0: " << yes(std::abs(creep_z) < 1e-12)
                      << ", u_y free: " << yes(std::abs(creep_y) > 1e-3)
                      << std::endl;
    }

  const double same = held_creep.events[0][1] / held_load.events[0][1] - 1;
  dealii::deallog << "normal held: creep and load the same first event: "
                  << yes(std::abs(same) < 1e-9) << std::endl;
  const double earlier = 1 - normal_held.events[0][1] / g[1];
  dealii::deallog << "normal free: the creeping plane's normal held (load) "
                     "makes the first event more than 0.1 % earlier: "
                  << yes(earlier > 1e-3) << std::endl;
  return 0;
}
