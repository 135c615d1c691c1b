// The two sides of a split fault tied in the volume method's matrices
// (Discretisation::tie_fault_sides, physics/split_fault.h).
#include <algorithm>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
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
      /** A matrix in compressed rows, global numbering. */
      struct Rows
      {
        std::vector<std::size_t>  start;
        std::vector<unsigned int> columns;
        std::vector<double>       values;
      };

      Rows
      rows_of(const TrilinosWrappers::SparseMatrix &A, const unsigned int n)
      {
        std::vector<std::vector<std::pair<unsigned int, double>>> entries(n);
        la::for_each_entry(A,
                           [&](const types::global_dof_index row,
                               const types::global_dof_index column,
                               const double                  value) {
                             entries[row].emplace_back(column, value);
                           });
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

      /** A rebuilt on the (wider) pattern of `rows`. */
      void
      assign(TrilinosWrappers::SparseMatrix &A,
             const Rows                     &rows,
             const IndexSet                 &owned,
             const MPI_Comm                  communicator)
      {
        const unsigned int     n = rows.start.size() - 1;
        DynamicSparsityPattern pattern(n, n);
        for (unsigned int i = 0; i < n; ++i)
          for (std::size_t e = rows.start[i]; e < rows.start[i + 1]; ++e)
            pattern.add(i, rows.columns[e]);
        A.reinit(owned, owned, pattern, communicator);
        for (unsigned int i = 0; i < n; ++i)
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
    } // namespace


    template <int dim>
    void
    Discretisation<dim>::tie_fault_sides()
    {
      const MPI_Comm communicator = triangulation.get_communicator();
      if (Utilities::MPI::n_mpi_processes(communicator) > 1)
        throw std::invalid_argument(
          "Mesh file/Boundary roles: fault-opposite with Solver/Bulk = volume "
          "runs on one MPI rank (the tie of the two sides is not distributed "
          "yet); run it with one rank or with Bulk = green-function");
      const unsigned int n = dof_handler.n_dofs();
      fault_tie            = pair_fault_sides(*this, n);
      const FaultTie &tie  = fault_tie;

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

      const IndexSet &owned = dof_handler.locally_owned_dofs();
      for (const auto &[matrix, local] :
           {std::make_pair(&mass_matrix, &mass_local),
            std::make_pair(&viscosity_matrix, &viscosity_local),
            std::make_pair(&stiffness_matrix, &stiffness_local)})
        {
          Rows rows = rows_of(*matrix, n);
          if (matrix == &stiffness_matrix)
            {
              std::vector<unsigned int> contact_dofs;
              for (const auto &[a, normal] : tie.normal_of)
                contact_dofs.push_back(a);
              const auto normal_rows = normal_force_rows(
                tie, rows.start, rows.columns, rows.values, contact_dofs);
              fault_normal_rows.clear();
              for (unsigned int k = 0; k < normal_rows.size(); ++k)
                fault_normal_rows[contact_dofs[k]] = normal_rows[k];
            }
          const bool viscosity = matrix == &viscosity_matrix;
          if (viscosity)
            for (unsigned int i = 0; i < n; ++i)
              rows.values[find_entry(rows, i, i)] -= damping.local_element(i);
          tie_matrix(tie, rows.start, rows.columns, rows.values);
          if (viscosity)
            for (unsigned int i = 0; i < n; ++i)
              {
                // the damping of a + dof moves to the slip; a hanging
                // contact dof keeps its own (its pair is left untied)
                const unsigned int s =
                  tie.kind[i] == tie_mean ? tie.partner[i] : i;
                if (tie.kind[i] != tie_mean && tie.kind[i] != tie_gone)
                  rows.values[find_entry(rows, s, s)] +=
                    damping.local_element(i);
              }
          assign(*matrix, rows, owned, communicator);
          local->initialize(*matrix, partitioner);
        }

      // the loads
      for (la::Vector *force : {&body_force, &prestress_force})
        {
          std::vector<double> f(n);
          for (unsigned int i = 0; i < n; ++i)
            f[i] = force->local_element(i);
          f = tie_force(tie, f);
          for (unsigned int i = 0; i < n; ++i)
            force->local_element(i) = f[i];
        }

      // the prescribed dofs, with their backstop signs as the values (0:
      // held at rest)
      std::vector<double> sign(n, 0.);
      for (const auto &dof : backstop_dofs)
        sign[dof.index] = dof.sign;
      tie_prescribed(tie, fixed, sign);
      const std::vector<unsigned int> component = dof_components();
      backstop_dofs.clear();
      for (unsigned int i = 0; i < n; ++i)
        if (fixed[i] && sign[i] != 0 && !hanging_constraints.is_constrained(i))
          backstop_dofs.push_back({i, component[i], sign[i]});
    }


    template void
    Discretisation<2>::tie_fault_sides();
    template void
    Discretisation<3>::tie_fault_sides();
  } // namespace physics
} // namespace rsfcycle
