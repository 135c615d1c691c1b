// SPDX-License-Identifier: LGPL-2.1-or-later
#include <rsfcycle/models/continuum.h>

namespace rsfcycle
{
  namespace models
  {
    template <int dim>
    void
    describe_scene(std::ostream                          &log,
                   const Parameters                      &parameters,
                   const physics::Discretisation<dim>    &discretisation,
                   const physics::ContactQuadrature<dim> &contact)
    {
      const auto &tria = discretisation.triangulation;
      log << "Scene: " << parameters.run.scene << " (" << dim << "D"
          << (parameters.run.antiplane ? ", antiplane" : "") << ")\n"
          << "Mesh: " << tria.n_global_active_cells() << " cells, "
          << tria.n_global_levels() << " levels, "
          << discretisation.dof_handler.n_dofs() << " unknowns, "
          << contact.n_global_nodes() << " contact nodes\n";
    }


    template <int dim>
    output::Offer
    continuum_offer(const std::string                     &model,
                    const Parameters                      &parameters,
                    const physics::Scene<dim>             &scene,
                    const physics::Discretisation<dim>    &discretisation,
                    const physics::ContactQuadrature<dim> &contact,
                    dealii::TimerOutput                   &timer,
                    std::function<BodyState(const output::Record &)> body)
    {
      output::Offer offer;
      offer.model  = model;
      offer.fields = continuum_fields();
      offer.body   = output::BodySource<dim>{&discretisation,
                                             &contact,
                                             parameters.solver.law.get(),
                                             scene.convergence_rate(),
                                             scene.output_frame(),
                                             &timer,
                                             std::move(body)};
      return offer;
    }


    template void
    describe_scene<2>(std::ostream &,
                      const Parameters &,
                      const physics::Discretisation<2> &,
                      const physics::ContactQuadrature<2> &);
    template void
    describe_scene<3>(std::ostream &,
                      const Parameters &,
                      const physics::Discretisation<3> &,
                      const physics::ContactQuadrature<3> &);
    template output::Offer
    continuum_offer<2>(const std::string &,
                       const Parameters &,
                       const physics::Scene<2> &,
                       const physics::Discretisation<2> &,
                       const physics::ContactQuadrature<2> &,
                       dealii::TimerOutput &,
                       std::function<BodyState(const output::Record &)>);
    template output::Offer
    continuum_offer<3>(const std::string &,
                       const Parameters &,
                       const physics::Scene<3> &,
                       const physics::Discretisation<3> &,
                       const physics::ContactQuadrature<3> &,
                       dealii::TimerOutput &,
                       std::function<BodyState(const output::Record &)>);
  } // namespace models
} // namespace rsfcycle
