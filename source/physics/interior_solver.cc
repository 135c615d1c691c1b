// SPDX-License-Identifier: LGPL-2.1-or-later
// The bulk's equilibrium of a gathered system with its contact and fixed
// dofs given (physics/interior_solver.h).
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <rsfcycle/physics/interior_solver.h>

namespace rsfcycle
{
  namespace physics
  {
    InteriorSolver::InteriorSolver(const GlobalSystem &K,
                                   const MPI_Comm      communicator)
    {
      const unsigned int n = K.n();
      index.assign(n, -1);
      std::vector<bool> contact(n, false);
      for (const unsigned int c : K.contact_dofs)
        contact[c] = true;
      for (unsigned int i = 0; i < n; ++i)
        if (!K.fixed[i] && !contact[i])
          {
            index[i] = interior.size();
            interior.push_back(i);
          }
      const unsigned int n_I = interior.size();

      // K_II on the node's first rank, which factorises it for the node
      if (!solvers::SparseCholesky::first_on_node(communicator))
        {
          cholesky.factorize_shared(nullptr, communicator);
          return;
        }
      dealii::DynamicSparsityPattern dsp(n_I, n_I);
      for (unsigned int k = 0; k < n_I; ++k)
        for (auto e = K.row_begin(interior[k]); e < K.row_end(interior[k]); ++e)
          if (index[K.columns[e]] >= 0)
            dsp.add(k, index[K.columns[e]]);
      dealii::SparsityPattern pattern;
      pattern.copy_from(dsp);
      dealii::SparseMatrix<double> K_II(pattern);
      for (unsigned int k = 0; k < n_I; ++k)
        for (auto e = K.row_begin(interior[k]); e < K.row_end(interior[k]); ++e)
          if (index[K.columns[e]] >= 0)
            K_II.set(k, index[K.columns[e]], K.values[e]);
      cholesky.factorize_shared(&K_II, communicator);
    }


    void
    InteriorSolver::solve(const dealii::FullMatrix<double> &B,
                          dealii::FullMatrix<double>       &X) const
    {
      cholesky.solve(B, X);
    }


    void
    InteriorSolver::equilibrium(const GlobalSystem  &K,
                                std::vector<double> &u,
                                const bool           with_force) const
    {
      const unsigned int     n_I = interior.size();
      dealii::Vector<double> b(n_I), x(n_I);
      for (unsigned int k = 0; k < n_I; ++k)
        {
          const unsigned int i = interior[k];
          b[k]                 = with_force ? K.force[i] : 0.;
          for (auto e = K.row_begin(i); e < K.row_end(i); ++e)
            if (index[K.columns[e]] < 0)
              b[k] -= K.values[e] * u[K.columns[e]];
        }
      cholesky.solve(b, x);
      for (unsigned int k = 0; k < n_I; ++k)
        u[interior[k]] = x[k];
    }
  } // namespace physics
} // namespace rsfcycle
