// SPDX-License-Identifier: LGPL-2.1-or-later
// The set-up that the Green's-function operator tools of the benchmarks
// share: the fault of a parameter file, built as a run builds it, on one
// rank. The tools are benchmarks/green-function/okada/operator_response.cc
// (CMake target okada_operator_response) and
// benchmarks/seas-bp3/operator_loading.cc (bp3_operator_loading), built on
// demand (EXCLUDE_FROM_ALL) by the drivers that use them.
#ifndef rsfcycle_benchmarks_green_operator_tool_h
#define rsfcycle_benchmarks_green_operator_tool_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <iostream>
#include <memory>
#include <rsfcycle/app/simulation.h>
#include <rsfcycle/models/green_fault.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/scenes/scenes.h>
#include <sstream>
#include <stdexcept>
#include <string>

namespace rsfcycle
{
  /**
   * The Green's-function fault of the parameter file `file`, whose entries
   * `prm` holds (read by scenes::parse_parameter_file, with the tool's
   * overrides set): refuses a file whose Solver/Bulk is not green-function
   * or whose Dimension is not dim, and more than one rank; builds the scene
   * and the operator (GreenFault::setup) and writes the set-up's log to
   * stderr.
   */
  template <int dim>
  struct GreenOperatorTool
  {
    GreenOperatorTool(dealii::ParameterHandler &prm, const std::string &file)
    {
      if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) != 1)
        throw std::invalid_argument("runs on one rank");
      if (prm.get_integer("Dimension") != dim)
        throw std::invalid_argument(file + ": Dimension must be " +
                                    std::to_string(dim));
      parameters.parse_parameters(prm);
      if (parameters.solver.bulk != SolverParameters::Bulk::green_function)
        throw std::invalid_argument(file +
                                    ": Solver/Bulk must be green-function");
      scene = scenes::make_scene<dim>(prm.get("Scene"), prm);
      fault =
        std::make_unique<models::GreenFault<dim>>(parameters, *scene, log);
      fault->setup();
      std::cerr << log.str();
    }

    Parameters                               parameters;
    std::unique_ptr<physics::Scene<dim>>     scene;
    std::ostringstream                       log;
    std::unique_ptr<models::GreenFault<dim>> fault;
  };
} // namespace rsfcycle

#endif
