// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <rsfcycle/solvers/coarse_direct.h>
#include <stdexcept>
#include <type_traits>
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
      // (row, column, value) of the rank's rows, then of all ranks (plain
      // MPI_Allgatherv: the coarse matrix of a 3D mesh has millions of
      // entries, too many to serialise)
      std::vector<unsigned int> rows, columns;
      std::vector<double>       values;
      for (unsigned int row = 0; row < coarse.m(); ++row)
        for (unsigned int j = coarse.row_begin(row); j < coarse.row_end(row);
             ++j)
          {
            rows.push_back(coarse.global_column(row));
            columns.push_back(coarse.global_column(coarse.column(j)));
            values.push_back(coarse.value(j));
          }
      if (Utilities::MPI::n_mpi_processes(communicator) > 1)
        {
          const auto counts =
            Utilities::MPI::all_gather(communicator,
                                       static_cast<int>(rows.size()));
          std::vector<int> offsets(counts.size() + 1, 0);
          for (unsigned int r = 0; r < counts.size(); ++r)
            offsets[r + 1] = offsets[r] + counts[r];
          const auto gather = [&](auto &local, MPI_Datatype type) {
            std::remove_reference_t<decltype(local)> all(offsets.back());
            MPI_Allgatherv(local.data(),
                           local.size(),
                           type,
                           all.data(),
                           counts.data(),
                           offsets.data(),
                           type,
                           communicator);
            local.swap(all);
          };
          gather(rows, MPI_UNSIGNED);
          gather(columns, MPI_UNSIGNED);
          gather(values, MPI_DOUBLE);
        }

      if (pattern.n_rows() != n_dofs || matrix.n_nonzero_elements() == 0 ||
          !use_cholesky)
        {
          DynamicSparsityPattern dsp(n_dofs);
          for (std::size_t k = 0; k < rows.size(); ++k)
            dsp.add(rows[k], columns[k]);
          matrix.clear();
          pattern.copy_from(dsp);
          matrix.reinit(pattern);
        }
      matrix = 0;
      for (std::size_t k = 0; k < rows.size(); ++k)
        matrix.add(rows[k], columns[k], values[k]);

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
