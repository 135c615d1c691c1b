// SPDX-License-Identifier: LGPL-2.1-or-later
#include <algorithm>
#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <map>
#include <rsfcycle/ids.h>
#include <rsfcycle/physics/contact_quadrature.h>

namespace rsfcycle
{
  namespace physics
  {
    template <int dim>
    void
    ContactQuadrature<dim>::setup(
      const DoFHandler<dim>             &dof_handler,
      const DoFHandler<dim>             &scalar_dof_handler,
      const AffineConstraints<double>   &hanging_constraints,
      const Utilities::MPI::Partitioner &partitioner,
      const std::vector<bool>           &fixed,
      const std::function<friction::Parameters(const Point<dim> &)>
        &parameters_at)
    {
      communicator = partitioner.get_mpi_communicator();
      n_ranks      = Utilities::MPI::n_mpi_processes(communicator);
      const auto               &fe = dof_handler.get_fe();
      la::Vector                weights(partitioner.locally_owned_range(),
                         partitioner.ghost_indices(),
                         communicator);
      const QTrapezoid<dim - 1> trapezoid;
      FEFaceValues<dim>         fe_face(fe,
                                trapezoid,
                                update_values | update_JxW_values);
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      Vector<double>                       cell_weights(fe.n_dofs_per_cell());
      struct BaseVertex
      {
        Point<dim>              position;
        types::global_dof_index scalar_dof, normal_dof, lateral_dof;
        types::material_id      material;
      };
      std::map<types::global_dof_index, BaseVertex> base_vertices; // by x dof

      // The rank's base vertices (from its cells and their ghost
      // neighbours); the weights from its own cells, summed over ranks and
      // condensed onto the masters of hanging nodes.
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (cell->is_artificial())
            continue;
          for (const unsigned int f : cell->face_indices())
            {
              const auto face = cell->face(f);
              if (!face->at_boundary() ||
                  face->boundary_id() != boundary_id::contact)
                continue;
              const typename DoFHandler<dim>::active_cell_iterator scalar_cell(
                &dof_handler.get_triangulation(),
                cell->level(),
                cell->index(),
                &scalar_dof_handler);
              // the normal component y and, in 3D, the lateral z (the
              // antiplane model has one, tangential, component)
              const unsigned int n_components = fe.n_components();
              for (const unsigned int v : face->vertex_indices())
                if (partitioner.in_local_range(face->vertex_dof_index(v, 0)))
                  base_vertices[face->vertex_dof_index(v, 0)] = {
                    face->vertex(v),
                    scalar_cell->face(f)->vertex_dof_index(v, 0),
                    n_components > 1 ? face->vertex_dof_index(v, 1) :
                                       numbers::invalid_dof_index,
                    n_components == 3 ? face->vertex_dof_index(v, 2) :
                                        numbers::invalid_dof_index,
                    cell->material_id()};
              if (!cell->is_locally_owned())
                continue;
              fe_face.reinit(cell, f);
              cell->get_dof_indices(dof_indices);
              cell_weights = 0;
              for (const unsigned int i : fe_face.dof_indices())
                if (fe.system_to_component_index(i).first == 0)
                  for (const unsigned int q :
                       fe_face.quadrature_point_indices())
                    cell_weights(i) +=
                      fe_face.shape_value_component(i, q, 0) * fe_face.JxW(q);
              hanging_constraints.distribute_local_to_global(cell_weights,
                                                             dof_indices,
                                                             weights);
            }
        }
      weights.compress(VectorOperation::add);

      // Contact nodes: base vertices with a free tangential component.
      contact.nodes.clear();
      node_info.clear();
      area = 0;
      for (const auto &[x_dof, vertex] : base_vertices)
        {
          if (hanging_constraints.is_constrained(x_dof))
            continue;
          solvers::ContactNode node;
          NodeInfo             info;
          // (x is component 0, the lateral z component 2)
          std::vector<std::pair<types::global_dof_index, unsigned int>>
            tangential = {{x_dof, 0}};
          if (vertex.lateral_dof != numbers::invalid_dof_index)
            tangential.emplace_back(vertex.lateral_dof, 2);
          for (const auto &[dof, component] : tangential)
            if (!fixed[partitioner.global_to_local(dof)])
              {
                info.components[node.n_dofs] = component;
                node.dofs[node.n_dofs++]     = partitioner.global_to_local(dof);
              }
          if (node.n_dofs == 0)
            continue;
          info.position   = vertex.position;
          info.material   = vertex.material;
          info.weight     = weights(x_dof);
          info.params     = parameters_at(vertex.position);
          info.scalar_dof = vertex.scalar_dof;
          info.normal_dof = vertex.normal_dof != numbers::invalid_dof_index ?
                              partitioner.global_to_local(vertex.normal_dof) :
                              numbers::invalid_dof_index;
          contact.nodes.push_back(node);
          node_info.push_back(info);
          area += info.weight;
        }
      area = Utilities::MPI::sum(area, communicator);
      contact.build_index(partitioner.locally_owned_size() +
                          partitioner.n_ghost_indices());

      // The order of all nodes by position, the same on every rank.
      std::vector<Point<dim>> positions;
      for (const auto &info : node_info)
        positions.push_back(info.position);
      const std::vector<Point<dim>> all =
        la::all_gather(communicator, positions);
      order.resize(all.size());
      for (unsigned int k = 0; k < order.size(); ++k)
        order[k] = k;
      std::sort(order.begin(),
                order.end(),
                [&all](const unsigned int i, const unsigned int j) {
                  for (unsigned int d = 0; d < dim; ++d)
                    if (all[i][d] != all[j][d])
                      return all[i][d] < all[j][d];
                  return false;
                });
    }


    template <int dim>
    unsigned int
    ContactQuadrature<dim>::set_normal_forces(const la::Vector &reaction)
    {
      unsigned int n_tensile = 0;
      double       total     = 0;
      for (const auto &info : node_info)
        total += reaction.local_element(info.normal_dof);
      total = Utilities::MPI::sum(total, communicator);
      for (auto &info : node_info)
        {
          const double r    = reaction.local_element(info.normal_dof);
          info.normal_force = std::abs(r);
          if (r * total < 0)
            ++n_tensile;
        }
      return Utilities::MPI::sum(n_tensile, communicator);
    }


    template <int dim>
    void
    ContactQuadrature<dim>::set_normal_forces(
      const std::function<double(const Point<dim> &)> &normal_stress)
    {
      for (auto &info : node_info)
        info.normal_force = info.weight * normal_stress(info.position);
    }


    template <int dim>
    double
    ContactQuadrature<dim>::state_distance(
      const std::vector<double> &alpha1,
      const std::vector<double> &alpha2) const
    {
      double sum = 0;
      for (unsigned int k = 0; k < alpha1.size(); ++k)
        {
          const double d = alpha1[k] - alpha2[k];
          sum += node_info[k].weight * d * d;
        }
      if (n_ranks > 1)
        sum = Utilities::MPI::sum(sum, communicator);
      return std::sqrt(sum / area);
    }


    template <int dim>
    double
    ContactQuadrature<dim>::state_max_distance(
      const std::vector<double> &alpha1,
      const std::vector<double> &alpha2) const
    {
      double largest = 0;
      for (unsigned int k = 0; k < alpha1.size(); ++k)
        largest = std::max(largest, std::abs(alpha1[k] - alpha2[k]));
      if (n_ranks > 1)
        largest = Utilities::MPI::max(largest, communicator);
      return largest;
    }


    template <int dim>
    std::vector<double>
    ContactQuadrature<dim>::slip_rates(const la::Vector &v) const
    {
      std::vector<double> rates(contact.nodes.size());
      for (unsigned int k = 0; k < contact.nodes.size(); ++k)
        rates[k] = solvers::tangential_norm(contact.nodes[k], v);
      return rates;
    }


    template <int dim>
    std::vector<std::array<double, 2>>
    ContactQuadrature<dim>::tangential_displacement(const la::Vector &u) const
    {
      std::vector<std::array<double, 2>> slip(contact.nodes.size(), {{0., 0.}});
      for (unsigned int k = 0; k < contact.nodes.size(); ++k)
        for (unsigned int l = 0; l < contact.nodes[k].n_dofs; ++l)
          slip[k][l] = u.local_element(contact.nodes[k].dofs[l]);
      return slip;
    }


    template <int dim>
    std::vector<friction::NodePotential>
    ContactQuadrature<dim>::potentials(const friction::Law &law) const
    {
      std::vector<friction::NodePotential> result(node_info.size());
      for (unsigned int k = 0; k < node_info.size(); ++k)
        {
          result[k].law          = &law;
          result[k].params       = node_info[k].params;
          result[k].normal_force = node_info[k].normal_force;
          result[k].cohesion_force =
            node_info[k].weight * node_info[k].params.cohesion;
        }
      return result;
    }


    template <int dim>
    std::vector<typename solvers::MultigridCorrection<dim>::ContactVertex>
    ContactQuadrature<dim>::multigrid_vertices() const
    {
      std::vector<typename solvers::MultigridCorrection<dim>::ContactVertex>
        vertices(node_info.size());
      for (unsigned int k = 0; k < node_info.size(); ++k)
        {
          vertices[k].position     = node_info[k].position;
          vertices[k].weight       = node_info[k].weight;
          vertices[k].n_components = contact.nodes[k].n_dofs;
          vertices[k].components   = node_info[k].components;
        }
      if (n_ranks == 1)
        return vertices;
      std::vector<typename solvers::MultigridCorrection<dim>::ContactVertex>
        all;
      for (const auto &part :
           Utilities::MPI::all_gather(communicator, vertices))
        all.insert(all.end(), part.begin(), part.end());
      return all;
    }


    template class ContactQuadrature<2>;
    template class ContactQuadrature<3>;
  } // namespace physics
} // namespace rsfcycle
