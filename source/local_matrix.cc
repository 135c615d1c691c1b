// SPDX-License-Identifier: LGPL-2.1-or-later
#include <algorithm>
#include <rsfcycle/local_matrix.h>
#include <stdexcept>

namespace rsfcycle
{
  namespace la
  {
    dealii::IndexSet
    matrix_ghosts(const dealii::DynamicSparsityPattern &pattern,
                  const dealii::IndexSet               &owned,
                  const dealii::IndexSet               &relevant)
    {
      std::vector<dealii::types::global_dof_index> columns;
      for (const auto row : owned)
        for (auto it = pattern.begin(row); it != pattern.end(row); ++it)
          columns.push_back(it->column());
      std::sort(columns.begin(), columns.end());
      columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
      dealii::IndexSet ghosts = relevant;
      ghosts.add_indices(columns.begin(), columns.end());
      return ghosts;
    }


    void
    LocalMatrix::initialize(
      const dealii::TrilinosWrappers::SparseMatrix &A,
      const std::shared_ptr<const dealii::Utilities::MPI::Partitioner>
        &new_partitioner)
    {
      partitioner = new_partitioner;
      n_rows      = partitioner->locally_owned_size();
      rowstart.assign(1, 0);
      colnums.clear();
      values.clear();
      // Epetra's row views (deal.II's Trilinos row iterators cost
      // O(columns of the matrix) each)
      const Epetra_CrsMatrix &matrix = A.trilinos_matrix();
      for (unsigned int row = 0; row < n_rows; ++row)
        {
          const long long global      = partitioner->local_to_global(row);
          int             n           = 0;
          double         *row_values  = nullptr;
          int            *row_columns = nullptr;
          matrix.ExtractMyRowView(matrix.RowMap().LID(global),
                                  n,
                                  row_values,
                                  row_columns);
          const auto first    = colnums.size();
          bool       diagonal = false;
          for (int k = 0; k < n; ++k)
            {
              const unsigned int column = partitioner->global_to_local(
                matrix.ColMap().GID64(row_columns[k]));
              colnums.push_back(column);
              values.push_back(row_values[k]);
              if (column == row)
                {
                  // the diagonal first (the relaxations read it there)
                  std::swap(colnums[first], colnums.back());
                  std::swap(values[first], values.back());
                  diagonal = true;
                }
            }
          if (!diagonal)
            {
              // (an interface matrix): a zero diagonal entry, first
              colnums.insert(colnums.begin() + first, row);
              values.insert(values.begin() + first, 0.);
            }
          rowstart.push_back(colnums.size());
        }
    }


    void
    LocalMatrix::combine(
      const std::vector<std::pair<double, const LocalMatrix *>> &terms)
    {
      const LocalMatrix &first = *terms.front().second;
      partitioner              = first.partitioner;
      n_rows                   = first.n_rows;
      rowstart                 = first.rowstart;
      colnums                  = first.colnums;
      values.assign(first.values.size(), 0.);
      for (const auto &[factor, matrix] : terms)
        if (factor != 0)
          for (std::size_t j = 0; j < values.size(); ++j)
            values[j] += factor * matrix->values[j];
    }


    double &
    LocalMatrix::entry(const unsigned int row, const unsigned int column)
    {
      for (unsigned int j = rowstart[row]; j < rowstart[row + 1]; ++j)
        if (colnums[j] == column)
          return values[j];
      throw std::logic_error("LocalMatrix: no such entry");
    }


    const double *
    LocalMatrix::ghosted(const Vector &v) const
    {
      if (partitioner->n_ghost_indices() == 0)
        return v.begin();
      if (v.get_partitioner().get() == partitioner.get())
        {
          v.update_ghost_values();
          return v.begin();
        }
      if (buffer.get_partitioner().get() != partitioner.get())
        buffer.reinit(partitioner);
      std::copy(v.begin(), v.end(), buffer.begin());
      buffer.update_ghost_values();
      return buffer.begin();
    }


    void
    LocalMatrix::Tvmult_add(Vector &dst, const Vector &src) const
    {
      double *d = dst.begin();
      if (partitioner->n_ghost_indices() > 0)
        {
          // contributions to ghost columns go to their owners
          if (buffer.get_partitioner().get() != partitioner.get())
            buffer.reinit(partitioner);
          buffer = 0;
          buffer.zero_out_ghost_values();
          d = buffer.begin();
        }
      for (unsigned int row = 0; row < n_rows; ++row)
        {
          const double s = src.local_element(row);
          for (unsigned int j = rowstart[row]; j < rowstart[row + 1]; ++j)
            d[colnums[j]] += values[j] * s;
        }
      if (partitioner->n_ghost_indices() > 0)
        {
          buffer.compress(dealii::VectorOperation::add);
          double *out = dst.begin();
          for (unsigned int i = 0; i < n_rows; ++i)
            out[i] += buffer.local_element(i);
        }
    }


    void
    LocalMatrix::residual(Vector &dst, const Vector &x, const Vector &b) const
    {
      const double *xs = ghosted(x);
      const double *bs = b.begin();
      double       *d  = dst.begin();
      for (unsigned int row = 0; row < n_rows; ++row)
        {
          double s = bs[row];
          for (unsigned int j = rowstart[row]; j < rowstart[row + 1]; ++j)
            s -= values[j] * xs[colnums[j]];
          d[row] = s;
        }
      release(x);
    }


    double
    LocalMatrix::matrix_norm_square(const Vector &v) const
    {
      const double *x   = ghosted(v);
      double        sum = 0;
      for (unsigned int row = 0; row < n_rows; ++row)
        {
          double s = 0;
          for (unsigned int j = rowstart[row]; j < rowstart[row + 1]; ++j)
            s += values[j] * x[colnums[j]];
          sum += s * x[row];
        }
      release(v);
      return dealii::Utilities::MPI::sum(sum,
                                         partitioner->get_mpi_communicator());
    }


    void
    LocalMatrix::relax(Vector            &v,
                       const Vector      &b,
                       const unsigned int n,
                       const bool         forward,
                       const bool         ghosts_zero) const
    {
      const bool has_ghosts = partitioner->n_ghost_indices() > 0;
      const bool own_layout = v.get_partitioner().get() == partitioner.get();
      double    *x          = v.begin();
      if (has_ghosts && ghosts_zero)
        {
          if (own_layout)
            v.zero_out_ghost_values();
          else
            {
              if (buffer.get_partitioner().get() != partitioner.get())
                buffer.reinit(partitioner);
              std::copy(v.begin(), v.end(), buffer.begin());
              buffer.zero_out_ghost_values();
              x = buffer.begin();
            }
        }
      else if (has_ghosts)
        x = const_cast<double *>(ghosted(v));
      const double *bs       = b.begin();
      const auto    relax_at = [&](const unsigned int row) {
        double s = bs[row];
        for (unsigned int j = rowstart[row]; j < rowstart[row + 1]; ++j)
          s -= values[j] * x[colnums[j]];
        x[row] += s / values[rowstart[row]];
      };
      for (unsigned int sweep = 0; sweep < n; ++sweep)
        if (forward)
          for (unsigned int row = 0; row < n_rows; ++row)
            relax_at(row);
        else
          for (unsigned int row = n_rows; row-- > 0;)
            relax_at(row);
      if (x != v.begin())
        std::copy(x, x + n_rows, v.begin());
      else
        release(v);
    }
  } // namespace la
} // namespace rsfcycle
