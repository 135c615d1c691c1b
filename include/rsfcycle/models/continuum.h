// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_models_continuum_h
#define rsfcycle_models_continuum_h

#include <deal.II/base/timer.h>
#include <functional>
#include <optional>
#include <ostream>
#include <rsfcycle/output/snapshots.h>
#include <rsfcycle/output/writers.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/physics/body_state.h>
#include <rsfcycle/physics/contact_quadrature.h>
#include <rsfcycle/physics/discretisation.h>
#include <rsfcycle/physics/scene.h>
#include <string>
#include <utility>
#include <vector>

namespace rsfcycle
{
  namespace models
  {
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
     * The first material of the scene's coarse mesh with Kelvin-Voigt
     * viscosity, with its id; none if the body is elastic.
     */
    template <int dim>
    std::optional<std::pair<dealii::types::material_id, physics::Material>>
    viscous_material(const physics::Scene<dim> &scene);

    /**
     * What the two continuum models (the volume method ProblemBase and the
     * Green's-function method GreenFault) share: the parameters, the scene
     * and the log they were made with, the timer of their run, the
     * discretisation of the scene's body and the contact quadrature on it;
     * their description's scene and mesh lines and their offer to the
     * writers.
     */
    template <int dim>
    class Continuum
    {
    protected:
      /**
       * `radiation_damping`: the quasi-dynamic dashpot on the contact in C;
       * `lumped_mass`: M lumped (physics::Discretisation::Options).
       */
      Continuum(const Parameters          &parameters,
                const physics::Scene<dim> &scene,
                std::ostream              &log,
                bool                       radiation_damping,
                bool                       lumped_mass = false);

      /**
       * The contact quadrature on the discretisation's contact faces (after
       * its boundary conditions), with the scene's friction parameters.
       */
      void
      setup_contact();

      /**
       * The lines "Scene: NAME (dD[, antiplane])" and "Mesh: N cells, L
       * levels, U unknowns, C contact nodes" of the description in log.txt.
       */
      void
      describe_scene(std::ostream &out) const;

      /**
       * The offer to the writers: continuum_fields() and the body, whose
       * snapshots show the discretisation's fields in the scene's output
       * frame; `body` makes a BodyState of a record (empty: the record's
       * state is one). `model` names the method in refusals.
       */
      output::Offer
      continuum_offer(const std::string                               &model,
                      std::function<BodyState(const output::Record &)> body);

      const Parameters               &parameters;
      const physics::Scene<dim>      &scene;
      std::ostream                   &log;
      mutable dealii::TimerOutput     timer;
      physics::Discretisation<dim>    discretisation;
      physics::ContactQuadrature<dim> contact;
    };
  } // namespace models
} // namespace rsfcycle

#endif
