// SPDX-License-Identifier: LGPL-2.1-or-later
// A continuum model run from a test's ParameterHandler with the method its
// Solver/Bulk names (the volume path's ProblemBase or the Green's-function
// method's GreenFault), as main.cc would run it.
#ifndef rsfcycle_tests_run_model_h
#define rsfcycle_tests_run_model_h

#include <deal.II/base/parameter_handler.h>
#include <rsfcycle/app/simulation.h>
#include <rsfcycle/models/green_fault.h>
#include <rsfcycle/models/problem_base.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/scenes/scenes.h>
#include <sstream>

template <int dim>
inline void
run_model(dealii::ParameterHandler &prm)
{
  using namespace rsfcycle;
  Parameters parameters;
  parameters.parse_parameters(prm);
  const auto         scene = scenes::make_scene<dim>("mesh-file", prm);
  std::ostringstream log;
  if (parameters.solver.bulk == SolverParameters::Bulk::green_function)
    {
      models::GreenFault<dim> fault(parameters, *scene, log);
      fault.run(prm);
    }
  else
    {
      ProblemBase<dim> problem(parameters, *scene, log);
      problem.run(prm);
    }
}

#endif
