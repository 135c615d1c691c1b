// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_app_simulation_h
#define rsfcycle_app_simulation_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <memory>
#include <optional>
#include <ostream>
#include <rsfcycle/parameters.h>
#include <rsfcycle/physics/scene.h>
#include <string>
#include <utility>

namespace rsfcycle
{
  namespace app
  {
    using namespace dealii;
    using physics::Scene;

    using dealii::ParameterHandler;

    /**
     * The composition root of a run: every subsection's parameters, the
     * rules that involve more than one entry (in one pass, check_run() of
     * app/checks.h, before anything is written), the choice of the model
     * and the run itself.
     * main.cc parses the command line and calls run().
     */

    /**
     * Declare every parameter of the program: Parameters (with the names of
     * the scenes, time schemes and writers), the subsection of every scene
     * and the spring-slider's.
     */
    void
    declare_parameters(ParameterHandler &prm);

    /**
     * Read the parameter file `file` into prm (declared by
     * declare_parameters()) with its includes and its input-file entries
     * (`Mesh file/File`) resolved relative to its own folder first, then
     * to the working directory (rsfcycle::parse_parameter_file()).
     */
    void
    parse_parameter_file(ParameterHandler &prm, const std::string &file);

    /** A configured run of one scene, built before anything is written. */
    class Simulation
    {
    public:
      virtual ~Simulation() = default;

      /**
       * The set-up that may still refuse the input because it needs MPI,
       * the mesh or an input file (the Green's-function operator, computed
       * or read), after MPI has started and before the run folder is
       * touched: what it refuses leaves nothing written. `resume`: the run
       * will continue from its run folder.
       */
      virtual void
      prepare(bool /*resume*/)
      {}

      /**
       * Run the scene (or resume it from the checkpoint in its run folder),
       * writing into the run folder and to log. Returns false if the run
       * was interrupted by SIGINT/SIGTERM.
       */
      virtual bool
      run(const ParameterHandler &prm, std::ostream &log, bool resume) = 0;

      /**
       * Whether the run needs MPI (Trilinos, distributed meshes); the
       * driver starts it only then.
       */
      virtual bool
      needs_mpi() const
      {
        return true;
      }
    };

    /**
     * The simulation of `Scene` in `Dimension`: the continuum scenes through
     * ProblemBase, the spring-slider model (models/spring_slider.h, no
     * mesh), after check_run(): bad parameters throw std::invalid_argument
     * here, before the run folder is touched.
     */
    std::unique_ptr<Simulation>
    make_simulation(const Parameters &parameters, ParameterHandler &prm);

    /**
     * The number of processes and this process's rank as the MPI launcher
     * (Open MPI's mpirun, or a PMI launcher such as MPICH's or Slurm's) set
     * them in the environment, known before MPI is started (the spring-slider
     * never starts it); 1 and 0 without a launcher.
     */
    std::pair<unsigned int, unsigned int>
    launched_processes();

    /**
     * Build the scene's simulation (bad input fails here, before anything is
     * written: check_run()), start MPI if
     * the simulation needs it (one thread either way), let the simulation
     * prepare what may still refuse the input, prepare the run folder and
     * the log (log.txt: the screen's lines), run. `mpi` holds MPI once it is
     * started. Returns false if the run was interrupted by a signal.
     */
    bool
    run(const Parameters                                        &parameters,
        ParameterHandler                                        &prm,
        bool                                                     resume,
        std::optional<dealii::Utilities::MPI::MPI_InitFinalize> &mpi,
        int                                                     &argc,
        char                                                  **&argv);
  } // namespace app
} // namespace rsfcycle

#endif
