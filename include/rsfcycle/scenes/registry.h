// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_scenes_registry_h
#define rsfcycle_scenes_registry_h

#include <deal.II/base/parameter_handler.h>
#include <memory>
#include <ostream>
#include <rsfcycle/parameters.h>
#include <rsfcycle/physics/scene.h>
#include <string>

namespace rsfcycle
{
  namespace scenes
  {
    using namespace dealii;
    using physics::Scene;

    using dealii::ParameterHandler;

    /**
     * The scenes by name (a plain name-to-factory map). A new scene is a
     * class in scenes/ and one line in each function of
     * scenes/registry.cc; nothing outside scenes/ changes.
     */

    /** Names of the scenes, as a Patterns::Selection. */
    std::string
    scene_names();

    /**
     * Declare every parameter of the program: Parameters (with the names of
     * the scenes, integrators and time schemes) and the subsection of every
     * scene.
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

    /**
     * The continuum scene (geometry, materials, friction) of the given name,
     * reading its subsection of prm; run by ProblemBase.
     */
    template <int dim>
    std::unique_ptr<Scene<dim>>
    make_scene(const std::string &name, ParameterHandler &prm);

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
     * mesh). Bad parameters throw std::invalid_argument here, before the run
     * folder is touched.
     */
    std::unique_ptr<Simulation>
    make_simulation(const Parameters &parameters, ParameterHandler &prm);
  } // namespace scenes
} // namespace rsfcycle

#endif
