// The fault's Green's functions from the assembled stiffness
// (physics/green_operator.h, MODEL.md §8.1).
#include <algorithm>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <rsfcycle/physics/green_operator.h>
#include <rsfcycle/solvers/sparse_cholesky.h>
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
      for (const auto &[name, point] : scene.observation_points())
        {
          const auto cell_and_point =
            GridTools::find_active_cell_around_point(mapping,
                                                     discretisation.dof_handler,
                                                     point);
          const Quadrature<dim> q(
            GeometryInfo<dim>::project_to_unit_cell(cell_and_point.second));
          FEValues<dim> fe_values(mapping, fe, q, update_values);
          fe_values.reinit(cell_and_point.first);
          std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
          cell_and_point.first->get_dof_indices(indices);
          const Tensor<1, dim> up = scene.vertical();
          ObservationRow       row;
          const auto add = [&](const types::global_dof_index i, double w) {
            row.emplace_back(discretisation.local_index(i), w);
          };
          for (unsigned int i = 0; i < indices.size(); ++i)
            {
              const unsigned int c = fe.system_to_component_index(i).first;
              const double       w =
                fe_values.shape_value(i, 0) * (antiplane ? 1. : up[c]);
              if (w == 0)
                continue;
              // a hanging node's value is that of the dofs it depends on
              if (const auto *entries =
                    hanging.get_constraint_entries(indices[i]))
                for (const auto &[j, factor] : *entries)
                  add(j, w * factor);
              else
                add(indices[i], w);
            }
          rows.push_back(row);
        }
      return rows;
    }


    template <int dim>
    GreenOperator
    compute_green_operator(const Discretisation<dim>         &discretisation,
                           const solvers::ContactSet         &contact,
                           const std::vector<ObservationRow> &observations,
                           const unsigned int                 block_size)
    {
      if (Utilities::MPI::n_mpi_processes(
            discretisation.triangulation.get_communicator()) > 1)
        throw std::invalid_argument(
          "Solver/Bulk = green-function runs on one MPI rank in this "
          "version: start it without mpirun");
      // one rank: local indices are the global ones
      const la::LocalMatrix   &K     = discretisation.stiffness_local;
      const std::vector<bool> &fixed = discretisation.fixed;
      const unsigned int       n     = K.m();
      const unsigned int       n_c   = contact.nodes.size();
      const unsigned int       n_o   = observations.size();

      // the contact's dofs (c), the unknowns besides them (I)
      std::vector<int>          contact_index(n, -1), interior_index(n, -1);
      std::vector<unsigned int> contact_dofs, interior;
      for (unsigned int k = 0; k < n_c; ++k)
        {
          if (contact.nodes[k].n_dofs != 1)
            throw std::invalid_argument(
              "Solver/Bulk = green-function: contact nodes with two "
              "tangential dofs (3D) are not done yet");
          contact_index[contact.nodes[k].dofs[0]] = k;
          contact_dofs.push_back(contact.nodes[k].dofs[0]);
        }
      for (unsigned int i = 0; i < n; ++i)
        if (!fixed[i] && contact_index[i] < 0)
          {
            interior_index[i] = interior.size();
            interior.push_back(i);
          }
      const unsigned int n_I = interior.size();

      GreenOperator op;
      op.n_interior = n_I;

      // K_II and its Cholesky factor
      dealii::DynamicSparsityPattern dsp(n_I, n_I);
      for (unsigned int k = 0; k < n_I; ++k)
        for (unsigned int e = K.row_begin(interior[k]);
             e < K.row_end(interior[k]);
             ++e)
          if (interior_index[K.column(e)] >= 0)
            dsp.add(k, interior_index[K.column(e)]);
      dealii::SparsityPattern pattern;
      pattern.copy_from(dsp);
      dealii::SparseMatrix<double> K_II(pattern);
      for (unsigned int k = 0; k < n_I; ++k)
        for (unsigned int e = K.row_begin(interior[k]);
             e < K.row_end(interior[k]);
             ++e)
          if (interior_index[K.column(e)] >= 0)
            K_II.set(k, interior_index[K.column(e)], K.value(e));
      solvers::SparseCholesky cholesky;
      cholesky.factorize(K_II);

      // The loads: the force f (body force and shear prestress) and the
      // prescribed velocity v_b of the fixed dofs (zero but on loads).
      la::Vector v_b;
      discretisation.reinit(v_b);
      discretisation.set_fixed_values(v_b, 0.);
      const auto f = [&](const unsigned int i) {
        return discretisation.body_force.local_element(i) +
               discretisation.prestress_force.local_element(i);
      };
      // sum over the fixed columns j of row i of K: K_ij v_b,j
      const auto K_fixed_v = [&](const unsigned int i) {
        double sum = 0;
        for (unsigned int e = K.row_begin(i); e < K.row_end(i); ++e)
          if (fixed[K.column(e)])
            sum += K.value(e) * v_b.local_element(K.column(e));
        return sum;
      };

      // Z = K_II^-1 [f_I, -K_Ib v_b]
      {
        dealii::FullMatrix<double> B(n_I, 2), Z;
        for (unsigned int k = 0; k < n_I; ++k)
          {
            B(k, 0) = f(interior[k]);
            B(k, 1) = -K_fixed_v(interior[k]);
          }
        cholesky.solve(B, Z);
        ++op.n_blocks;
        op.g0.reinit(n_c);
        op.g1.reinit(n_c);
        for (unsigned int r = 0; r < n_c; ++r)
          {
            const unsigned int row = contact_dofs[r];
            op.g0[r]               = f(row);
            op.g1[r]               = -K_fixed_v(row);
            for (unsigned int e = K.row_begin(row); e < K.row_end(row); ++e)
              if (const int i = interior_index[K.column(e)]; i >= 0)
                {
                  op.g0[r] -= K.value(e) * Z(i, 0);
                  op.g1[r] -= K.value(e) * Z(i, 1);
                }
          }
        op.o0.reinit(n_o);
        op.o1.reinit(n_o);
        for (unsigned int p = 0; p < n_o; ++p)
          for (const auto &[j, w] : observations[p])
            if (const int i = interior_index[j]; i >= 0)
              {
                op.o0[p] += w * Z(i, 0);
                op.o1[p] += w * Z(i, 1);
              }
            else if (fixed[j])
              op.o1[p] += w * v_b.local_element(j);
      }

      // S and O, block_size columns at a time: X = K_II^-1 K_Ic
      op.S.reinit(n_c, n_c);
      op.O.reinit(n_o, n_c);
      for (unsigned int b0 = 0; b0 < n_c; b0 += block_size)
        {
          const unsigned int         nb = std::min(block_size, n_c - b0);
          dealii::FullMatrix<double> B(n_I, nb), X;
          // K symmetric: column j of K_Ic is row c_j restricted to I
          for (unsigned int jj = 0; jj < nb; ++jj)
            {
              const unsigned int row = contact_dofs[b0 + jj];
              for (unsigned int e = K.row_begin(row); e < K.row_end(row); ++e)
                if (const int i = interior_index[K.column(e)]; i >= 0)
                  B(i, jj) = K.value(e);
            }
          cholesky.solve(B, X);
          ++op.n_blocks;
          for (unsigned int r = 0; r < n_c; ++r)
            {
              const unsigned int row = contact_dofs[r];
              for (unsigned int e = K.row_begin(row); e < K.row_end(row); ++e)
                {
                  const unsigned int col = K.column(e);
                  if (const int i = interior_index[col]; i >= 0)
                    for (unsigned int jj = 0; jj < nb; ++jj)
                      op.S(r, b0 + jj) -= K.value(e) * X(i, jj);
                  else if (const int q = contact_index[col];
                           q >= static_cast<int>(b0) &&
                           q < static_cast<int>(b0 + nb))
                    op.S(r, q) += K.value(e);
                }
            }
          for (unsigned int p = 0; p < n_o; ++p)
            for (const auto &[j, w] : observations[p])
              if (const int i = interior_index[j]; i >= 0)
                for (unsigned int jj = 0; jj < nb; ++jj)
                  op.O(p, b0 + jj) -= w * X(i, jj);
              else if (const int q = contact_index[j];
                       q >= static_cast<int>(b0) &&
                       q < static_cast<int>(b0 + nb))
                op.O(p, q) += w;
        }
      return op;
    }


    template std::vector<ObservationRow>
    observation_rows(const Discretisation<2> &, const Scene<2> &, bool);
    template std::vector<ObservationRow>
    observation_rows(const Discretisation<3> &, const Scene<3> &, bool);
    template GreenOperator
    compute_green_operator(const Discretisation<2> &,
                           const solvers::ContactSet &,
                           const std::vector<ObservationRow> &,
                           unsigned int);
    template GreenOperator
    compute_green_operator(const Discretisation<3> &,
                           const solvers::ContactSet &,
                           const std::vector<ObservationRow> &,
                           unsigned int);
  } // namespace physics
} // namespace rsfcycle
