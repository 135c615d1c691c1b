// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_app_checks_h
#define rsfcycle_app_checks_h

#include <rsfcycle/parameters.h>
#include <rsfcycle/physics/scene.h>

namespace rsfcycle
{
  namespace app
  {
    /**
     * Every rule of a run that involves more than one entry, in one pass,
     * before anything is written: the first that fails throws
     * std::invalid_argument with one line naming the entry and what is
     * allowed. In turn:
     *  - the parameters among themselves (Parameters::validate: steps,
     *    levels, intervals, the SEAS subsection, the bulk and its
     *    integrator);
     *  - the writers of `Output/Writers` against the fields the model
     *    offers (output::check_writers);
     *  - what the chosen method cannot represent in the scene: the
     *    Green's-function method's (models::GreenFault::check), the volume
     *    method's (a split fault with the geometric multigrid or gravity, a
     *    pore pressure, a shear stress perturbation);
     *  - what the number of MPI ranks allows (the spring-slider, the
     *    direct linear correction and its fallback run on one rank).
     * `scene` is null for the spring-slider (a model without a mesh);
     * `n_processes` is the launcher's (launched_processes()).
     */
    template <int dim>
    void
    check_run(const Parameters          &parameters,
              const physics::Scene<dim> *scene,
              unsigned int               n_processes);
  } // namespace app
} // namespace rsfcycle

#endif
