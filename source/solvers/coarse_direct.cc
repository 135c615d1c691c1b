// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <rsfcycle/solvers/coarse_direct.h>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace rsfcycle
{
  namespace solvers
  {
    using namespace dealii;

    void
    CoarseDirect::initialize(const la::LocalMatrix &coarse,
                             const unsigned int     n_dofs,
                             const MPI_Comm         communicator)
    {
      // (row, column, value) of the rank's rows, then of all ranks
      std::vector<std::tuple<unsigned int, unsigned int, double>> entries;
      for (unsigned int row = 0; row < coarse.m(); ++row)
        for (unsigned int j = coarse.row_begin(row); j < coarse.row_end(row);
             ++j)
          entries.emplace_back(coarse.global_column(row),
                               coarse.global_column(coarse.column(j)),
                               coarse.value(j));
      if (Utilities::MPI::n_mpi_processes(communicator) > 1)
        {
          const auto parts = Utilities::MPI::all_gather(communicator, entries);
          entries.clear();
          for (const auto &part : parts)
            entries.insert(entries.end(), part.begin(), part.end());
        }

      if (pattern.n_rows() != n_dofs || matrix.n_nonzero_elements() == 0 ||
          !use_cholesky)
        {
          DynamicSparsityPattern dsp(n_dofs);
          for (const auto &[row, column, value] : entries)
            dsp.add(row, column);
          matrix.clear();
          pattern.copy_from(dsp);
          matrix.reinit(pattern);
        }
      matrix = 0;
      for (const auto &[row, column, value] : entries)
        matrix.add(row, column, value);

      use_cholesky = true;
      try
        {
          cholesky.factorize(matrix);
        }
      catch (const std::runtime_error &)
        {
          use_cholesky = false;
          FullMatrix<double> full(n_dofs, n_dofs);
          full.copy_from(matrix);
          householder.initialize(full);
        }
    }


    void
    CoarseDirect::operator()(const unsigned int,
                             la::Vector       &dst,
                             const la::Vector &src) const
    {
      const auto &partitioner = *src.get_partitioner();
      b.reinit(src.size(), false);
      x.reinit(dst.size(), true);
      for (unsigned int i = 0; i < src.locally_owned_size(); ++i)
        b[partitioner.local_to_global(i)] = src.local_element(i);
      if (partitioner.n_mpi_processes() > 1)
        Utilities::MPI::sum(b, partitioner.get_mpi_communicator(), b);
      if (use_cholesky)
        cholesky.solve(b, x);
      else
        householder.least_squares(x, b);
      for (unsigned int i = 0; i < dst.locally_owned_size(); ++i)
        dst.local_element(i) = x[partitioner.local_to_global(i)];
    }
  } // namespace solvers
} // namespace rsfcycle
