// SPDX-License-Identifier: LGPL-2.1-or-later
// The two sides of a split fault tied in the volume method's matrices
// (Discretisation::tie_fault_sides, physics/split_fault.h).
#include <algorithm>
#include <array>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <map>
#include <rsfcycle/ids.h>
#include <rsfcycle/physics/discretisation.h>
#include <rsfcycle/physics/split_fault.h>
#include <stdexcept>

namespace rsfcycle
{
  namespace physics
  {
    namespace
    {
      /**
       * A matrix in compressed rows, global numbering: the rank's rows and
       * the rows of every paired dof (their tie reads the partner's row).
       */
      struct Rows
      {
        std::vector<std::size_t>  start;
        std::vector<unsigned int> columns;
        std::vector<double>       values;
      };

      Rows
      rows_of(const TrilinosWrappers::SparseMatrix &A,
              const FaultTie                       &tie,
              const IndexSet                       &owned,
              const MPI_Comm                        communicator)
      {
        const unsigned int n = tie.kind.size();
        std::vector<std::vector<std::pair<unsigned int, double>>> entries(n);
        std::vector<std::array<double, 3>>                        paired;
        la::for_each_entry(
          A,
          [&](const types::global_dof_index row,
              const types::global_dof_index column,
              const double                  value) {
            entries[row].emplace_back(column, value);
            if (tie.kind[row] != tie_none)
              paired.push_back({{double(row), double(column), value}});
          });
        for (const auto &[row, column, value] :
             la::all_gather(communicator, paired))
          if (!owned.is_element(static_cast<unsigned int>(row)))
            entries[static_cast<unsigned int>(row)].emplace_back(
              static_cast<unsigned int>(column), value);
        Rows rows;
        rows.start.push_back(0);
        for (auto &row : entries)
          {
            std::sort(row.begin(), row.end());
            for (const auto &[column, value] : row)
              {
                rows.columns.push_back(column);
                rows.values.push_back(value);
              }
            rows.start.push_back(rows.columns.size());
          }
        return rows;
      }

      /** A rebuilt from the rank's rows of `rows` (a wider pattern). */
      void
      assign(TrilinosWrappers::SparseMatrix &A,
             const Rows                     &rows,
             const IndexSet                 &owned,
             const MPI_Comm                  communicator)
      {
        const unsigned int     n = rows.start.size() - 1;
        DynamicSparsityPattern pattern(n, n, owned);
        for (const auto i : owned)
          for (std::size_t e = rows.start[i]; e < rows.start[i + 1]; ++e)
            pattern.add(i, rows.columns[e]);
        A.reinit(owned, owned, pattern, communicator);
        for (const auto i : owned)
          for (std::size_t e = rows.start[i]; e < rows.start[i + 1]; ++e)
            A.set(i, rows.columns[e], rows.values[e]);
        A.compress(VectorOperation::insert);
      }

      std::size_t
      find_entry(const Rows &rows, const unsigned int i, const unsigned int j)
      {
        for (std::size_t e = rows.start[i]; e < rows.start[i + 1]; ++e)
          if (rows.columns[e] == j)
            return e;
        throw std::logic_error("split fault: a diagonal entry is missing");
      }

      /**
       * A vector's values by global index: the rank's own and those of
       * every paired dof (zero elsewhere).
       */
      std::vector<double>
      paired_values(const la::Vector &v, const FaultTie &tie)
      {
        const auto                        &partitioner = *v.get_partitioner();
        std::vector<double>                values(tie.kind.size(), 0.);
        std::vector<std::array<double, 2>> paired;
        for (unsigned int l = 0; l < partitioner.locally_owned_size(); ++l)
          {
            const auto i = partitioner.local_to_global(l);
            values[i]    = v.local_element(l);
            if (tie.kind[i] != tie_none)
              paired.push_back({{double(i), values[i]}});
          }
        for (const auto &[i, value] :
             la::all_gather(partitioner.get_mpi_communicator(), paired))
          values[static_cast<unsigned int>(i)] = value;
        return values;
      }
    } // namespace


    template <int dim>
    void
    Discretisation<dim>::tie_fault_sides()
    {
      const MPI_Comm     communicator = triangulation.get_communicator();
      const unsigned int n            = dof_handler.n_dofs();
      const IndexSet    &owned        = dof_handler.locally_owned_dofs();
      fault_tie                       = pair_fault_sides(*this, n);
      const FaultTie &tie             = fault_tie;

      // The radiation damping eta w_i of the + side's tangential contact
      // dofs (quasi-dynamic) damps the slip rate: taken off C's diagonal
      // before the tie and put on the slip's after it.
      la::Vector damping;
      reinit(damping);
      if (options.radiation_damping)
        {
          const unsigned int                   n_cell = fe.n_dofs_per_cell();
          FullMatrix<double>                   cell_viscosity(n_cell);
          Vector<double>                       cell_damping(n_cell);
          std::vector<types::global_dof_index> indices(n_cell);
          for (const auto &cell : dof_handler.active_cell_iterators())
            if (cell->is_locally_owned())
              {
                const physics::Material material =
                  scene.material(cell->material_id());
                cell_viscosity = 0;
                add_contact_terms(cell, &material, &cell_viscosity, nullptr);
                for (unsigned int i = 0; i < n_cell; ++i)
                  cell_damping(i) = cell_viscosity(i, i);
                cell->get_dof_indices(indices);
                hanging_constraints.distribute_local_to_global(cell_damping,
                                                               indices,
                                                               damping);
              }
          damping.compress(VectorOperation::add);
        }
      // (by global index: the rank's and the paired dofs', whose rows the
      // tie reads)
      const std::vector<double> damping_of = paired_values(damping, tie);

      // T^T A T of M, C and K in the rank's rows; the normal force rows of
      // the rank's contact dofs from K's
      std::array<Rows, 3>                                   tied;
      const std::array<TrilinosWrappers::SparseMatrix *, 3> matrices = {
        {&mass_matrix, &viscosity_matrix, &stiffness_matrix}};
      for (unsigned int m = 0; m < 3; ++m)
        {
          Rows &rows = tied[m];
          rows       = rows_of(*matrices[m], tie, owned, communicator);
          const bool viscosity = matrices[m] == &viscosity_matrix;
          if (!viscosity)
            {
              // the + side's elastic (K) and inertial (M) normal force
              std::vector<unsigned int> contact_dofs;
              for (const auto &[a, normal] : tie.normal_of)
                if (owned.is_element(a))
                  contact_dofs.push_back(a);
              const auto normal_rows = normal_force_rows(
                tie, rows.start, rows.columns, rows.values, contact_dofs);
              auto &target = matrices[m] == &stiffness_matrix ?
                               fault_normal_rows :
                               fault_normal_inertia_rows;
              target.clear();
              for (unsigned int k = 0; k < normal_rows.size(); ++k)
                target[contact_dofs[k]] = normal_rows[k];
            }
          if (viscosity)
            for (unsigned int i = 0; i < n; ++i)
              if (damping_of[i] != 0)
                rows.values[find_entry(rows, i, i)] -= damping_of[i];
          tie_matrix(tie, rows.start, rows.columns, rows.values);
          if (viscosity)
            for (const auto i : owned)
              // the damping of a + dof stays with the slip in its place; a
              // hanging contact dof keeps its own (its pair is left untied)
              if (tie.kind[i] != tie_mean && tie.kind[i] != tie_gone)
                rows.values[find_entry(rows, i, i)] += damping_of[i];
        }

      // the loads and the prescribed dofs (with their backstop signs as the
      // values, 0: held at rest) by global index, the paired ones of every
      // rank included
      std::array<std::vector<double>, 2> loads = {
        {tie_force(tie, paired_values(body_force, tie)),
         tie_force(tie, paired_values(prestress_force, tie))}};
      la::Vector flags;
      reinit(flags);
      for (unsigned int l = 0; l < partitioner->locally_owned_size(); ++l)
        flags.local_element(l) = fixed[l] ? 1. : 0.;
      std::vector<double> fixed_value = paired_values(flags, tie);
      flags                           = 0;
      for (const auto &dof : backstop_dofs)
        flags.local_element(dof.index) = dof.sign;
      std::vector<double> sign = paired_values(flags, tie);
      std::vector<bool>   is_fixed(n);
      for (unsigned int i = 0; i < n; ++i)
        is_fixed[i] = fixed_value[i] != 0;
      tie_prescribed(tie, is_fixed, sign);

      // The vectors' ghosts: as before, every column of the tied rows and
      // the partners of the relevant dofs (the untie reads them).
      IndexSet ghosts = partitioner->ghost_indices();
      {
        std::vector<types::global_dof_index> columns;
        for (const auto &rows : tied)
          for (const auto i : owned)
            for (std::size_t e = rows.start[i]; e < rows.start[i + 1]; ++e)
              columns.push_back(rows.columns[e]);
        for (const IndexSet *set : {&owned, &partitioner->ghost_indices()})
          for (const auto i : *set)
            if (tie.kind[i] != tie_none)
              columns.push_back(tie.partner[i]);
        std::sort(columns.begin(), columns.end());
        columns.erase(std::unique(columns.begin(), columns.end()),
                      columns.end());
        ghosts.add_indices(columns.begin(), columns.end());
        ghosts.subtract_set(owned);
      }
      partitioner = std::make_shared<Utilities::MPI::Partitioner>(owned,
                                                                  ghosts,
                                                                  communicator);
      step_matrices.clear();
      const std::array<la::LocalMatrix *, 3> locals = {
        {&mass_local, &viscosity_local, &stiffness_local}};
      for (unsigned int m = 0; m < 3; ++m)
        {
          assign(*matrices[m], tied[m], owned, communicator);
          locals[m]->initialize(*matrices[m], partitioner);
        }
      // the normal rows in local indices of the new partitioner (read in
      // every fixed-point iteration)
      for (auto *rows : {&fault_normal_rows, &fault_normal_inertia_rows})
        {
          std::map<unsigned int, ObservationRow> normal_rows;
          for (auto &[a, row] : *rows)
            {
              for (auto &[j, weight] : row)
                j = local_index(j);
              normal_rows[local_index(a)] = std::move(row);
            }
          *rows = std::move(normal_rows);
        }
      for (unsigned int f = 0; f < 2; ++f)
        {
          la::Vector &force = f == 0 ? body_force : prestress_force;
          reinit(force);
          for (unsigned int l = 0; l < partitioner->locally_owned_size(); ++l)
            force.local_element(l) = loads[f][partitioner->local_to_global(l)];
        }

      // fixed by the new local index (ghosts from their owners), the
      // backstop from the rank's dofs
      reinit(flags);
      const std::vector<unsigned int> component = dof_components();
      backstop_dofs.clear();
      for (unsigned int l = 0; l < partitioner->locally_owned_size(); ++l)
        {
          const auto i           = partitioner->local_to_global(l);
          flags.local_element(l) = is_fixed[i] ? 1. : 0.;
          if (is_fixed[i] && sign[i] != 0 &&
              !hanging_constraints.is_constrained(i))
            backstop_dofs.push_back({l, component[l], sign[i]});
        }
      flags.update_ghost_values();
      fixed.assign(partitioner->locally_owned_size() +
                     partitioner->n_ghost_indices(),
                   false);
      for (unsigned int l = 0; l < fixed.size(); ++l)
        fixed[l] = flags.local_element(l) != 0;
    }


    template <int dim>
    bool
    split_normal_stresses(const Discretisation<dim>    &discretisation,
                          const ContactQuadrature<dim> &contact,
                          const la::Vector             &u,
                          const la::Vector             *a,
                          std::vector<double>          &stresses)
    {
      u.update_ghost_values();
      if (a != nullptr)
        a->update_ghost_values();
      const auto &rows         = discretisation.fault_normal_rows;
      const auto &inertia_rows = discretisation.fault_normal_inertia_rows;
      const auto &nodes        = contact.contact_set().nodes;
      stresses.resize(nodes.size());
      bool compressed = true;
      for (unsigned int k = 0; k < nodes.size(); ++k)
        {
          double force = contact.nodes()[k].normal_force;
          for (const auto &[j, weight] : rows.at(nodes[k].dofs[0]))
            force += weight * u.local_element(j);
          if (a != nullptr)
            for (const auto &[j, weight] : inertia_rows.at(nodes[k].dofs[0]))
              force += weight * a->local_element(j);
          stresses[k] = force / contact.nodes()[k].weight;
          compressed  = compressed && force > 0;
        }
      return Utilities::MPI::min(
               compressed ? 1 : 0,
               discretisation.triangulation.get_communicator()) == 1;
    }


    template bool
    split_normal_stresses(const Discretisation<2> &,
                          const ContactQuadrature<2> &,
                          const la::Vector &,
                          const la::Vector *,
                          std::vector<double> &);
    template bool
    split_normal_stresses(const Discretisation<3> &,
                          const ContactQuadrature<3> &,
                          const la::Vector &,
                          const la::Vector *,
                          std::vector<double> &);
    template void
    Discretisation<2>::tie_fault_sides();
    template void
    Discretisation<3>::tie_fault_sides();
  } // namespace physics
} // namespace rsfcycle
