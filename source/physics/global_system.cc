// SPDX-License-Identifier: LGPL-2.1-or-later
// The assembled system gathered onto every rank (physics/global_system.h).
#include <array>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>
#include <rsfcycle/la.h>
#include <rsfcycle/physics/global_system.h>
#include <stdexcept>

namespace rsfcycle
{
  namespace physics
  {
    template <int dim>
    std::vector<ObservationRow>
    observation_rows(const Discretisation<dim> &discretisation,
                     const Scene<dim>          &scene,
                     const bool                 antiplane)
    {
      const auto                 &fe = discretisation.fe;
      const MappingQ1<dim>        mapping;
      const auto                 &hanging = discretisation.hanging_constraints;
      std::vector<ObservationRow> rows;
      const auto                  directions = scene.observation_directions();
      for (const auto &[name, point] : scene.observation_points())
        {
          const std::size_t first = rows.size();
          rows.resize(first + directions.size());
          std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>
            cell_and_point;
          try
            {
              cell_and_point = GridTools::find_active_cell_around_point(
                mapping, discretisation.dof_handler, point);
            }
          catch (const std::exception &)
            {
              continue; // not in this rank's part of the mesh
            }
          if (cell_and_point.first.state() != IteratorState::valid ||
              !cell_and_point.first->is_locally_owned())
            continue;
          const Quadrature<dim> q(
            GeometryInfo<dim>::project_to_unit_cell(cell_and_point.second));
          FEValues<dim> fe_values(mapping, fe, q, update_values);
          fe_values.reinit(cell_and_point.first);
          std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
          cell_and_point.first->get_dof_indices(indices);
          for (unsigned int d = 0; d < directions.size(); ++d)
            {
              const Tensor<1, dim> &along = directions[d].second;
              ObservationRow       &row   = rows[first + d];
              for (unsigned int i = 0; i < indices.size(); ++i)
                {
                  const unsigned int c = fe.system_to_component_index(i).first;
                  const double       w =
                    fe_values.shape_value(i, 0) * (antiplane ? 1. : along[c]);
                  if (w == 0)
                    continue;
                  // a hanging node's value is that of the dofs it depends on
                  if (const auto *entries =
                        hanging.get_constraint_entries(indices[i]))
                    for (const auto &[j, factor] : *entries)
                      row.emplace_back(j, w * factor);
                  else
                    row.emplace_back(indices[i], w);
                }
            }
        }
      return rows;
    }


    template <int dim>
    GlobalSystem
    gather_system(const Discretisation<dim>         &discretisation,
                  const solvers::ContactSet         &contact,
                  const std::vector<ObservationRow> &local_rows)
    {
      const MPI_Comm comm = discretisation.triangulation.get_communicator();
      const la::LocalMatrix &K           = discretisation.stiffness_local;
      const auto            &partitioner = *discretisation.partitioner;
      const unsigned int     n           = discretisation.dof_handler.n_dofs();
      la::Vector             v_b;
      discretisation.reinit(v_b);
      discretisation.set_fixed_values(v_b, 0.);

      // the owned rows as (row, column, value) and the owned dofs as
      // (index, fixed, f, v_b), indices as doubles (exact below 2^53)
      std::vector<std::array<double, 3>> entries;
      std::vector<std::array<double, 4>> dofs;
      for (unsigned int i = 0; i < K.m(); ++i)
        {
          const double row = partitioner.local_to_global(i);
          for (unsigned int e = K.row_begin(i); e < K.row_end(i); ++e)
            entries.push_back(
              {{row,
                double(partitioner.local_to_global(K.column(e))),
                K.value(e)}});
          dofs.push_back({{row,
                           discretisation.fixed[i] ? 1. : 0.,
                           discretisation.body_force.local_element(i) +
                             discretisation.prestress_force.local_element(i),
                           v_b.local_element(i)}});
        }
      std::vector<double> contact_dofs;
      for (const auto &node : contact.nodes)
        for (unsigned int d = 0; d < node.n_dofs; ++d)
          contact_dofs.push_back(partitioner.local_to_global(node.dofs[d]));

      GlobalSystem system;
      system.fixed.assign(n, false);
      system.force.assign(n, 0.);
      system.fixed_velocity.assign(n, 0.);
      for (const auto &[i, fixed, f, v] : la::all_gather(comm, dofs))
        {
          system.fixed[i]          = fixed != 0;
          system.force[i]          = f;
          system.fixed_velocity[i] = v;
        }
      // compressed rows: the rows arrive whole and in increasing order per
      // rank, the ranks' ranges in increasing order
      const auto all = la::all_gather(comm, entries);
      system.row_start.assign(n + 1, 0);
      for (const auto &entry : all)
        ++system.row_start[static_cast<unsigned int>(entry[0]) + 1];
      for (unsigned int i = 0; i < n; ++i)
        system.row_start[i + 1] += system.row_start[i];
      system.columns.resize(all.size());
      system.values.resize(all.size());
      std::vector<std::size_t> next(system.row_start.begin(),
                                    system.row_start.end() - 1);
      for (const auto &entry : all)
        {
          const std::size_t e = next[static_cast<unsigned int>(entry[0])]++;
          system.columns[e]   = static_cast<unsigned int>(entry[1]);
          system.values[e]    = entry[2];
        }
      for (const double i : la::all_gather(comm, contact_dofs))
        system.contact_dofs.push_back(static_cast<unsigned int>(i));
      const auto counts = dealii::Utilities::MPI::all_gather(
        comm, static_cast<unsigned int>(contact_dofs.size()));
      system.rank_offsets.assign(1, 0);
      for (const unsigned int count : counts)
        system.rank_offsets.push_back(system.rank_offsets.back() + count);

      const auto rows = dealii::Utilities::MPI::all_gather(comm, local_rows);
      for (unsigned int p = 0; p < local_rows.size(); ++p)
        {
          unsigned int r = 0;
          while (r < rows.size() && rows[r][p].empty())
            ++r;
          if (r == rows.size())
            throw std::invalid_argument(
              "Solver/Bulk = green-function: observation point " +
              std::to_string(p + 1) + " lies in no cell of the mesh");
          system.observations.push_back(rows[r][p]);
        }
      return system;
    }


    template std::vector<ObservationRow>
    observation_rows(const Discretisation<2> &, const Scene<2> &, bool);
    template std::vector<ObservationRow>
    observation_rows(const Discretisation<3> &, const Scene<3> &, bool);
    template GlobalSystem
    gather_system(const Discretisation<2> &,
                  const solvers::ContactSet &,
                  const std::vector<ObservationRow> &);
    template GlobalSystem
    gather_system(const Discretisation<3> &,
                  const solvers::ContactSet &,
                  const std::vector<ObservationRow> &);
  } // namespace physics
} // namespace rsfcycle
