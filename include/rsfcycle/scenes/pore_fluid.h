// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_scenes_pore_fluid_h
#define rsfcycle_scenes_pore_fluid_h

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>
#include <memory>
#include <string>

namespace rsfcycle
{
  namespace scenes
  {
    using namespace dealii;

    /**
     * The subsection `Pore fluid` of a scene's Friction: where the pore
     * pressure p and the Darcy velocity q on the contact come from. Either
     * the expressions `Pore pressure` and `Darcy velocity` of Friction
     * (Source = function, SEAS BP6's closed form), or the pressure
     * diffusing in the fault zone from an injection
     * (physics::FaultDiffusion<dim - 1>, doc/model.md section 9: Source =
     * gaussian, point or well), solved on a mesh of its own: the line
     * [-l, l] in 2D, the square [-l, l]^2 in 3D. `Plane coordinates` maps
     * a point of the contact (the scene's physical coordinates) to the
     * fluid domain's; the Darcy velocity's components are along the fluid
     * domain's axes.
     */
    class PoreFluid
    {
    public:
      /** The functions of the friction field (null: none). */
      template <int dim>
      struct Functions
      {
        /** p(x, t) [Pa], time-dependent (Function::set_time()). */
        std::shared_ptr<Function<dim>> pressure;
        /** q(x, t) [m/s], dim - 1 components, time-dependent. */
        std::shared_ptr<Function<dim>> darcy_velocity;
      };

      /** The subsection `Pore fluid` in the current subsection. */
      static void
      declare_parameters(ParameterHandler &prm);

      /**
       * Whether the subsection (of the current subsection) asks for the
       * expressions of Friction (Source = function), or for none.
       */
      static std::string
      source(ParameterHandler &prm);

      /**
       * The diffusion's functions for Source = gaussian, point or well
       * (null functions otherwise), read from the subsection `Pore fluid`
       * of the current subsection, named `section` in messages. Entries
       * that do not fit throw std::invalid_argument in one line naming the
       * entry and what is allowed.
       */
      template <int dim>
      static Functions<dim>
      parse(ParameterHandler &prm, const std::string &section);
    };
  } // namespace scenes
} // namespace rsfcycle

#endif
