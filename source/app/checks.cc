// SPDX-License-Identifier: LGPL-2.1-or-later
#include <rsfcycle/app/checks.h>
#include <rsfcycle/models/continuum.h>
#include <rsfcycle/models/green_fault.h>
#include <rsfcycle/output/writers.h>
#include <stdexcept>
#include <string>

namespace rsfcycle
{
  namespace app
  {
    namespace
    {
      /** What the volume method cannot represent in the scene. */
      template <int dim>
      void
      check_volume_method(const Parameters          &parameters,
                          const physics::Scene<dim> &scene)
      {
        if (scene.split_fault() &&
            parameters.solver.linear_correction ==
              SolverParameters::LinearCorrection::multigrid)
          throw std::invalid_argument(
            "Solver/Linear correction: a fault-opposite side (Mesh "
            "file/Boundary roles) in the volume method needs direct (one "
            "rank) or amg (the geometric multigrid's levels do not tie the "
            "two sides yet)");
        if (scene.split_fault() && scene.gravity().norm() != 0)
          throw std::invalid_argument(
            "Mesh file/Gravity: a fault-opposite side (Boundary roles) "
            "needs Gravity = 0 (the initial slip of a split fault under "
            "gravity is not implemented yet)");
        if (scene.pore_pressure())
          throw std::invalid_argument(
            "Mesh file/Friction/Pore pressure: needs Solver/Bulk = "
            "green-function (the volume method keeps the normal stress "
            "constant in time)");
        if (scene.shear_perturbation())
          throw std::invalid_argument(
            "Mesh file/Friction/Shear stress perturbation: needs "
            "Solver/Bulk = green-function (the volume method's shear "
            "prestress is constant in time)");
      }


      /**
       * The explicit step (Time stepping/Integrator = explicit) needs
       * inviscid materials: Kelvin-Voigt viscosity makes C a full matrix
       * and the stable step tiny.
       */
      template <int dim>
      void
      check_explicit_steps(const Parameters          &parameters,
                           const physics::Scene<dim> &scene)
      {
        if (parameters.time_stepping.integrator !=
            TimeSteppingParameters::Integrator::explicit_steps)
          return;
        if (const auto viscous = models::viscous_material(scene))
          throw std::invalid_argument(
            "Time stepping/Integrator = explicit: needs inviscid materials "
            "(material " +
            std::to_string(viscous->first) +
            " is Kelvin-Voigt viscous: its explicit step would be tiny; "
            "Integrator = implicit takes it)");
      }


      /** What the number of MPI ranks allows. */
      void
      check_ranks(const Parameters  &parameters,
                  const bool         spring_slider,
                  const unsigned int n_processes)
      {
        if (n_processes <= 1)
          return;
        const std::string n = std::to_string(n_processes);
        if (spring_slider)
          throw std::invalid_argument("Scene = " + parameters.run.scene +
                                      " runs on one MPI rank, not on " + n +
                                      ": start it without mpirun");
        if (parameters.solver.linear_correction ==
            SolverParameters::LinearCorrection::direct)
          throw std::invalid_argument(
            "Solver/Linear correction = direct runs on one MPI rank, not "
            "on " +
            n + ": choose multigrid or amg, or start it without mpirun");
        if (parameters.solver.direct_fallback)
          throw std::invalid_argument(
            "Solver/Direct fallback = true runs on one MPI rank, not on " + n +
            ": set it false, or start it without mpirun");
      }
    } // namespace


    template <int dim>
    void
    check_run(const Parameters          &parameters,
              const physics::Scene<dim> *scene,
              const unsigned int         n_processes)
    {
      parameters.validate();
      const bool green =
        parameters.solver.bulk == SolverParameters::Bulk::green_function;
      if (!scene)
        output::check_writers(parameters,
                              output::Offer{}.fields,
                              "the spring-slider");
      else
        output::check_writers(parameters,
                              models::continuum_fields(),
                              green ? "the Green's-function method" :
                                      "the volume method");
      if (scene && green)
        models::GreenFault<dim>::check(parameters, *scene);
      else if (scene)
        {
          check_volume_method(parameters, *scene);
          check_explicit_steps(parameters, *scene);
        }
      check_ranks(parameters, !scene, n_processes);
    }


    template void
    check_run<2>(const Parameters &, const physics::Scene<2> *, unsigned int);
    template void
    check_run<3>(const Parameters &, const physics::Scene<3> *, unsigned int);
  } // namespace app
} // namespace rsfcycle
