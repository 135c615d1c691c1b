// SPDX-License-Identifier: LGPL-2.1-or-later
#include <algorithm>
#include <deal.II/base/mpi.h>
#include <deal.II/grid/tria.h>
#include <rsfcycle/models/continuum.h>

namespace rsfcycle
{
  namespace models
  {
    template <int dim>
    Continuum<dim>::Continuum(const Parameters          &parameters,
                              const physics::Scene<dim> &scene,
                              std::ostream              &log,
                              const bool                 radiation_damping,
                              const bool                 lumped_mass)
      : parameters(parameters)
      , scene(scene)
      , log(log)
      , timer(log, dealii::TimerOutput::never, dealii::TimerOutput::wall_times)
      , discretisation(parameters.mesh,
                       scene,
                       {parameters.run.antiplane,
                        radiation_damping,
                        lumped_mass})
    {}


    template <int dim>
    void
    Continuum<dim>::setup_contact()
    {
      contact.setup(discretisation.dof_handler,
                    discretisation.scalar_dof_handler,
                    discretisation.hanging_constraints,
                    *discretisation.partitioner,
                    discretisation.fixed,
                    [this](const dealii::Point<dim> &p) {
                      return scene.friction_parameters(p);
                    });
    }


    template <int dim>
    void
    Continuum<dim>::describe_scene(std::ostream &out) const
    {
      const auto &tria = discretisation.triangulation;
      out << "Scene: " << parameters.run.scene << " (" << dim << "D"
          << (parameters.run.antiplane ? ", antiplane" : "") << ")\n"
          << "Mesh: " << tria.n_global_active_cells() << " cells, "
          << tria.n_global_levels() << " levels, "
          << discretisation.dof_handler.n_dofs() << " unknowns, "
          << contact.n_global_nodes() << " contact nodes\n";
      // the sponge (Scene::sponge_damping): its cells and largest rate
      unsigned int n_sponge  = 0;
      double       alpha_max = 0;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          if (const double alpha = scene.sponge_damping(cell->center());
              alpha > 0)
            {
              ++n_sponge;
              alpha_max = std::max(alpha_max, alpha);
            }
      const MPI_Comm comm = tria.get_communicator();
      if (dealii::Utilities::MPI::sum(n_sponge, comm) > 0)
        out << "Sponge damping: " << dealii::Utilities::MPI::sum(n_sponge, comm)
            << " cells, alpha up to "
            << dealii::Utilities::MPI::max(alpha_max, comm)
            << " 1/s (C += alpha M)\n";
    }


    template <int dim>
    output::Offer
    Continuum<dim>::continuum_offer(
      const std::string                               &model,
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


    template <int dim>
    std::optional<std::pair<dealii::types::material_id, physics::Material>>
    viscous_material(const physics::Scene<dim> &scene)
    {
      dealii::Triangulation<dim> coarse;
      scene.create_coarse_mesh(coarse);
      for (const auto &cell : coarse.active_cell_iterators())
        {
          const auto id =
            scene.material_id(cell->center(), cell->material_id());
          const physics::Material m = scene.material(id);
          if (m.shear_viscosity != 0 || m.bulk_viscosity != 0)
            return std::make_pair(id, m);
        }
      return {};
    }


    template std::optional<
      std::pair<dealii::types::material_id, physics::Material>>
    viscous_material<2>(const physics::Scene<2> &);
    template std::optional<
      std::pair<dealii::types::material_id, physics::Material>>
    viscous_material<3>(const physics::Scene<3> &);
    template class Continuum<2>;
    template class Continuum<3>;
  } // namespace models
} // namespace rsfcycle
