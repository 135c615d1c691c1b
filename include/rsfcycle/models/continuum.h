// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_models_continuum_h
#define rsfcycle_models_continuum_h

#include <deal.II/base/timer.h>
#include <functional>
#include <ostream>
#include <rsfcycle/output/snapshots.h>
#include <rsfcycle/output/writers.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/physics/body_state.h>
#include <rsfcycle/physics/contact_quadrature.h>
#include <rsfcycle/physics/discretisation.h>
#include <rsfcycle/physics/scene.h>
#include <string>
#include <vector>

namespace rsfcycle
{
  namespace models
  {
    /**
     * What the two continuum models (ProblemBase, GreenFault) share of
     * their description in log.txt: the lines "Scene: NAME (dD[,
     * antiplane])" and "Mesh: N cells, L levels, U unknowns, C contact
     * nodes".
     */
    template <int dim>
    void
    describe_scene(std::ostream                          &log,
                   const Parameters                      &parameters,
                   const physics::Discretisation<dim>    &discretisation,
                   const physics::ContactQuadrature<dim> &contact);

    /**
     * The fields a continuum model offers the writers (output/writers.h):
     * the contact's slip and stresses and the body on its mesh.
     */
    inline std::vector<output::Field>
    continuum_fields()
    {
      return {output::Field::contact,
              output::Field::stresses,
              output::Field::body};
    }

    /**
     * What a continuum model offers the writers (output/writers.h): the
     * contact's fields and the body, whose snapshots show the
     * discretisation's fields in the scene's output frame; `body` makes a
     * BodyState of a record (empty: the record's state is one).
     */
    template <int dim>
    output::Offer
    continuum_offer(const std::string                     &model,
                    const Parameters                      &parameters,
                    const physics::Scene<dim>             &scene,
                    const physics::Discretisation<dim>    &discretisation,
                    const physics::ContactQuadrature<dim> &contact,
                    dealii::TimerOutput                   &timer,
                    std::function<BodyState(const output::Record &)> body);
  } // namespace models
} // namespace rsfcycle

#endif
