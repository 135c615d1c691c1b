// SPDX-License-Identifier: LGPL-2.1-or-later
// The checks across entries and subsections of the parameters, the first
// part of the run's one pass of checks (app::check_run()): each failure is
// one line naming the entries and what is allowed.
#include <rsfcycle/format.h>
#include <rsfcycle/parameters.h>
#include <stdexcept>

namespace rsfcycle
{
  void
  Parameters::validate() const
  {
    if (run.antiplane && (run.dimension != 2 || run.scene != "mesh-file"))
      throw std::invalid_argument(
        "Displacement = antiplane: needs Dimension = 2 and Scene = "
        "mesh-file (this run has Dimension = " +
        std::to_string(run.dimension) + ", Scene = " + run.scene + ")");
    const auto &ts   = time_stepping;
    using Integrator = TimeSteppingParameters::Integrator;
    if (!(ts.minimum_step <= ts.initial_step))
      throw std::invalid_argument(
        "Time stepping/Minimum step = " + format_number(ts.minimum_step) +
        ": must not exceed Initial step = " + format_number(ts.initial_step));
    if (!(ts.initial_step <= ts.maximum_step))
      throw std::invalid_argument(
        "Time stepping/Initial step = " + format_number(ts.initial_step) +
        ": must not exceed Maximum step = " + format_number(ts.maximum_step));
    if (mesh.global_refinements + mesh.local_refinements > 16)
      throw std::invalid_argument(
        "Mesh/Global refinements + Local refinements = " +
        std::to_string(mesh.global_refinements + mesh.local_refinements) +
        ": at most 16 levels are allowed");
    if (!(output.event_output_interval <= output.output_interval))
      throw std::invalid_argument("Output/Event output interval = " +
                                  format_number(output.event_output_interval) +
                                  ": must not exceed Output interval = " +
                                  format_number(output.output_interval));
    output.seas.validate(run.dimension);
    const bool green = solver.bulk == SolverParameters::Bulk::green_function;
    const std::string bulk = "Solver/Bulk = green-function: needs ";
    if (green && solver.dynamics != SolverParameters::Dynamics::quasi_dynamic)
      throw std::invalid_argument(
        bulk + "Solver/Dynamics = quasi-dynamic (this run has " +
        name_of(solver.dynamics) +
        ": inertia or no radiation damping is no Green's function ODE)");
    if (solver.green_single_precision &&
        solver.green_compression_tolerance < 1e-5)
      throw std::invalid_argument(
        "Solver/Green compression precision = single: needs Green "
        "compression tolerance >= 1e-5 (this run has " +
        format_number(solver.green_compression_tolerance) +
        "; a float holds about 7 digits)");
    if (!green && !solver.green_operator_file.empty())
      throw std::invalid_argument(
        "Solver/Green operator file = " + solver.green_operator_file +
        ": needs Solver/Bulk = green-function");
    if (green && run.dimension != 2 && ts.integrator == Integrator::implicit)
      throw std::invalid_argument(
        bulk + "Time stepping/Integrator = runge-kutta in 3D (the implicit "
               "step on the fault takes one slip component per node, 2D "
               "only)");
    if (green && ts.integrator == Integrator::arkode)
      throw std::invalid_argument(
        bulk + "Time stepping/Integrator = runge-kutta or implicit (arkode "
               "samples the run only every Maximum step)");
    if ((ts.integrator == Integrator::explicit_steps ||
         ts.integrator == Integrator::implicit_explicit) &&
        (green || solver.dynamics != SolverParameters::Dynamics::dynamic))
      throw std::invalid_argument(
        "Time stepping/Integrator = " + name_of(ts.integrator) +
        ": needs Solver/Dynamics = "
        "dynamic and Solver/Bulk = volume (the explicit step is the wave "
        "equation's; this run has " +
        name_of(solver.dynamics) + ", " + name_of(solver.bulk) + ")");
    if ((ts.integrator == Integrator::explicit_steps ||
         ts.integrator == Integrator::implicit_explicit) &&
        !solver.lumped_mass)
      throw std::invalid_argument(
        "Time stepping/Integrator = " + name_of(ts.integrator) +
        ": needs Solver/Mass matrix = lumped (the explicit step's mass; "
        "the implicit steps of the run take it too)");
    if (!green && ts.integrator == Integrator::runge_kutta &&
        run.scene != "spring-slider")
      throw std::invalid_argument(
        "Time stepping/Integrator = runge-kutta: needs Solver/Bulk = "
        "green-function for a continuum scene");
  }
} // namespace rsfcycle
