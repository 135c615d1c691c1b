// SPDX-License-Identifier: LGPL-2.1-or-later
#include <rsfcycle/app/checks.h>
#include <rsfcycle/app/simulation.h>
#include <rsfcycle/models/green_fault.h>
#include <rsfcycle/models/problem_base.h>
#include <rsfcycle/models/spring_slider.h>
#include <rsfcycle/output/writers.h>
#include <rsfcycle/parameter_file.h>
#include <rsfcycle/scenes/scenes.h>
#include <rsfcycle/time/integrators.h>
#include <rsfcycle/time/schemes.h>
#include <stdexcept>

namespace rsfcycle
{
  namespace app
  {
    using physics::Scene;


    void
    declare_parameters(ParameterHandler &prm)
    {
      Parameters::declare_parameters(prm,
                                     scenes::scene_names(),
                                     time::scheme_names(),
                                     output::writer_names());
      output::declare_parameters(prm);
      scenes::declare_parameters(prm);
      models::SpringSlider::declare_parameters(prm);
    }


    void
    parse_parameter_file(ParameterHandler &prm, const std::string &file)
    {
      // The entries that name an input file, as (subsection, entry); a
      // scene with a new file entry adds it here.
      rsfcycle::parse_parameter_file(
        prm, file, {{"Mesh file", "File"}, {"Solver", "Green operator file"}});
    }


    namespace
    {
      /**
       * A continuum scene solved by ProblemBase<dim>, or with `Solver/Bulk =
       * green-function` by models::GreenFault<dim>.
       */
      template <int dim>
      class ContinuumSimulation : public Simulation
      {
      public:
        ContinuumSimulation(const Parameters &parameters, ParameterHandler &prm)
          : parameters(parameters)
          , scene(scenes::make_scene<dim>(parameters.run.scene, prm))
        {
          check_run<dim>(parameters, scene.get(), launched_processes().first);
        }

        /** green-function: the model and its operator (it may refuse). */
        void
        prepare(const bool resume) override
        {
          if (green_function())
            {
              fault = std::make_unique<models::GreenFault<dim>>(parameters,
                                                                *scene,
                                                                fault_log);
              fault->setup(resume);
              // the outputs refuse what the mesh's contact cannot give
              // (the SEAS stations and profiles against its nodes) now,
              // before the run folder is made: their constructors write
              // nothing
              output::make_writers(parameters, fault->layout(), fault->offer());
            }
        }

        bool
        run(const ParameterHandler &prm,
            std::ostream           &log,
            const bool              resume) override
        {
          if (fault)
            {
              // the log exists only now: the model writes through fault_log
              fault_log.rdbuf(log.rdbuf());
              fault_log.exceptions(log.exceptions());
              return fault->run(prm, resume);
            }
          ProblemBase<dim> problem(parameters, *scene, log);
          return problem.run(prm, resume);
        }

      private:
        /** `Solver/Bulk = green-function`: models::GreenFault. */
        bool
        green_function() const
        {
          return parameters.solver.bulk ==
                 SolverParameters::Bulk::green_function;
        }

        const Parameters           &parameters;
        std::unique_ptr<Scene<dim>> scene;
        /** The log of the green-function model, set by run(). */
        std::ostream                             fault_log{nullptr};
        std::unique_ptr<models::GreenFault<dim>> fault;
      };


      /** The spring-slider: no mesh, the same simulator. */
      class SpringSliderSimulation : public Simulation
      {
      public:
        SpringSliderSimulation(const Parameters &parameters,
                               ParameterHandler &prm)
          : slider(
              (check_run<2>(parameters, nullptr, launched_processes().first),
               parameters),
              prm)
        {}

        bool
        run(const ParameterHandler &prm,
            std::ostream           &log,
            const bool              resume) override
        {
          return !slider.run(prm, log, resume).interrupted;
        }

        bool
        needs_mpi() const override
        {
          return false;
        }

      private:
        models::SpringSlider slider;
      };
    } // namespace


    std::unique_ptr<Simulation>
    make_simulation(const Parameters &parameters, ParameterHandler &prm)
    {
      if (parameters.run.scene == "spring-slider")
        return std::make_unique<SpringSliderSimulation>(parameters, prm);
      if (parameters.run.dimension == 2)
        return std::make_unique<ContinuumSimulation<2>>(parameters, prm);
      return std::make_unique<ContinuumSimulation<3>>(parameters, prm);
    }


  } // namespace app
} // namespace rsfcycle
