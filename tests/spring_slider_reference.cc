// SPDX-License-Identifier: LGPL-2.1-or-later
// Our scheme against an independent reference: the quasi-dynamic
// stick-slip spring-slider of prm/spring-slider.prm (k = k_crit / 2, ageing
// law) over 1000 s (4 events), once with the wedge's scheme (Newmark,
// fixed-point coupling, step doubling) at delta = epsilon = 1e-7, once with
// SUNDIALS ARKODE (implicit additive Runge-Kutta, adaptive, in the
// variables (slip, log V, alpha)) at relative tolerance 1e-11.
// Measured: slip at 1000 s 1108.4656 um (ours) against 1108.4650 um
// (reference), a difference of 6e-10 m; mean recurrence time (events 2-4)
// 303.31243 s against 303.31237 s (7e-5 s, 2e-7 relative); event starts
// within 1e-4 s; peak slip rates (about 7700 v0) within 1e-4 relative. Stated
// tolerances, checked as yes/no: slip within 1e-8 m (1e-3 L), recurrence time
// within 1e-5 relative, every event start within 1e-3 s, the same number of
// events, peak slip rates within 1%.
#include "tests.h"

#include <cmath>
#include <rsfcycle/app/simulation.h>
#include <rsfcycle/models/spring_slider.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/scenes/scenes.h>
#include <sstream>

using namespace rsfcycle;

namespace
{
  models::SpringSlider::Summary
  run(const std::string &integrator,
      const double       tolerance,
      const std::string &dir)
  {
    std::ostringstream tol;
    tol << tolerance;
    ParameterHandler prm;
    app::declare_parameters(prm);
    prm.parse_input_from_string(
      "set Scene = spring-slider\n"
      "set End time = 1000\n"
      "set Output directory = " +
      dir +
      "\n"
      "subsection Time stepping\n"
      "  set Integrator = " +
      integrator +
      "\n"
      "  set Controller = step-doubling\n"
      "  set Tolerance = " +
      tol.str() +
      "\n"
      "  set Initial step = 1e-3\n"
      "  set Minimum step = 1e-14\n"
      "  set Maximum step = 10\n"
      "end\n"
      "subsection Solver\n"
      "  set Fixed-point tolerance = " +
      tol.str() +
      "\n"
      "end\n"
      "subsection Output\n"
      "  set Writers = time series, base profile, events\n"
      "  set Progress interval = 1e9\n"
      "end\n"
      "subsection Spring slider\n"
      "  set Reference output period = 1\n"
      "end\n");
    Parameters parameters;
    parameters.parse_parameters(prm);
    models::SpringSlider slider(parameters, prm);
    std::ostringstream   log;
    return slider.run(prm, log);
  }

  const char *
  yes_no(const bool b)
  {
    return b ? "yes" : "no";
  }
} // namespace

int
main()
{
  initlog(6);
  using dealii::deallog;
  const auto ours      = run("implicit", 1e-7, "output-ours");
  const auto reference = run("arkode", 1e-11, "output-reference");

  const double v0 = 1e-6;
  deallog << "events: ours " << ours.events.size() << ", reference "
          << reference.events.size() << std::endl;
  deallog << "reference: slip at 1000 s [um] = "
          << reference.final_state.slip * 1e6
          << ", recurrence time [s] = " << reference.mean_recurrence_time
          << std::endl;
  deallog << "slip within 1e-8 m: "
          << yes_no(std::abs(ours.final_state.slip -
                             reference.final_state.slip) < 1e-8)
          << std::endl;
  deallog << "recurrence time within 1e-5 relative: "
          << yes_no(std::abs(ours.mean_recurrence_time -
                             reference.mean_recurrence_time) <
                    1e-5 * reference.mean_recurrence_time)
          << std::endl;
  if (ours.events.size() == reference.events.size())
    for (std::size_t i = 0; i < ours.events.size(); ++i)
      deallog << "event " << i + 1 << ": start within 1e-3 s: "
              << yes_no(std::abs(ours.events[i].start -
                                 reference.events[i].start) < 1e-3)
              << ", peak log10(V/v0) = "
              << std::log10(reference.events[i].peak_slip_rate / v0)
              << ", peak within 1%: "
              << yes_no(std::abs(ours.events[i].peak_slip_rate /
                                   reference.events[i].peak_slip_rate -
                                 1) < 0.01)
              << std::endl;
}
