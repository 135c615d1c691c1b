// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_local_matrix_h
#define rsfcycle_local_matrix_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <memory>
#include <rsfcycle/la.h>
#include <utility>
#include <vector>

namespace rsfcycle
{
  namespace la
  {
    /**
     * A rank's rows of a square sparse matrix in compressed rows, columns
     * in the local numbering of a partitioner (owned entries first, ghosts
     * after), the diagonal first in every row. The products, the residual
     * and the SOR relaxations that the multigrid cycle, TNNMG and the
     * implicit step run on distributed vectors, by raw index instead of the
     * global-index access of deal.II's templates for distributed vectors.
     *
     * Ghosts. A kernel that reads other ranks' entries of its argument
     * first brings them in: a vector on the matrix's own partitioner gets
     * update_ghost_values() (and zero_out_ghost_values() after the
     * kernel: ghost values are valid inside a kernel only, so that the
     * vector operations between kernels communicate nothing); a vector on
     * another partitioner with the same owned range (the multigrid
     * transfer makes the level vectors) is copied into a buffer on the
     * matrix's partitioner. The relaxations are
     * processor-local: a sweep reads the other ranks' entries as they were
     * at its start (hybrid Gauss-Seidel/Jacobi); products with the
     * transpose send their contributions to the owners (compress). On one
     * rank there are no ghosts and the kernels read the vectors directly.
     */
    /**
     * f(row, column, value&) for every stored entry of the rank's rows of
     * a Trilinos matrix (global indices; the value may be changed). Reads
     * Epetra's row views: deal.II's Trilinos row iterators cost O(columns
     * of the whole matrix) each (their cache is sized so), which made the
     * set-up quadratic in the unknowns.
     */
    template <class Function>
    void
    for_each_entry(const dealii::TrilinosWrappers::SparseMatrix &A,
                   const Function                               &f)
    {
      const Epetra_CrsMatrix &matrix = A.trilinos_matrix();
      for (int row = 0; row < matrix.NumMyRows(); ++row)
        {
          int     n       = 0;
          double *values  = nullptr;
          int    *columns = nullptr;
          matrix.ExtractMyRowView(row, n, values, columns);
          const dealii::types::global_dof_index global_row =
            matrix.RowMap().GID64(row);
          for (int k = 0; k < n; ++k)
            f(global_row,
              static_cast<dealii::types::global_dof_index>(
                matrix.ColMap().GID64(columns[k])),
              values[k]);
        }
    }

    /**
     * The ghost indices of the vectors that a LocalMatrix of the owned rows
     * of `pattern` reads: the locally relevant indices and every column of
     * an owned row.
     */
    dealii::IndexSet
    matrix_ghosts(const dealii::DynamicSparsityPattern &pattern,
                  const dealii::IndexSet               &owned,
                  const dealii::IndexSet               &relevant);

    class LocalMatrix
    {
    public:
      LocalMatrix() = default;

      /**
       * The owned rows of a Trilinos matrix whose row range is the
       * partitioner's owned range; every column must be an owned or ghost
       * index of the partitioner.
       */
      LocalMatrix(
        const dealii::TrilinosWrappers::SparseMatrix &A,
        const std::shared_ptr<const dealii::Utilities::MPI::Partitioner>
          &partitioner)
      {
        initialize(A, partitioner);
      }

      void
      initialize(
        const dealii::TrilinosWrappers::SparseMatrix &A,
        const std::shared_ptr<const dealii::Utilities::MPI::Partitioner>
          &partitioner);

      /**
       * The same sparsity as `terms` (all of one pattern), with the values
       * sum_k c_k B_k.
       */
      void
      combine(const std::vector<std::pair<double, const LocalMatrix *>> &terms);

      unsigned int
      m() const
      {
        return n_rows;
      }

      /** Entries [row_begin(row), row_end(row)) of a row. */
      unsigned int
      row_begin(const unsigned int row) const
      {
        return rowstart[row];
      }

      unsigned int
      row_end(const unsigned int row) const
      {
        return rowstart[row + 1];
      }

      /** Column (local numbering) and value of entry j. */
      unsigned int
      column(const unsigned int j) const
      {
        return colnums[j];
      }

      double
      value(const unsigned int j) const
      {
        return values[j];
      }

      double
      diagonal(const unsigned int row) const
      {
        return values[rowstart[row]];
      }

      /** The entry (row, column) in local numbering; it must exist. */
      double &
      entry(unsigned int row, unsigned int column);

      double
      el(const unsigned int row, const unsigned int column) const
      {
        return const_cast<LocalMatrix *>(this)->entry(row, column);
      }

      const std::shared_ptr<const dealii::Utilities::MPI::Partitioner> &
      get_partitioner() const
      {
        return partitioner;
      }

      /** Global index of a local column. */
      dealii::types::global_dof_index
      global_column(const unsigned int column) const
      {
        return partitioner->local_to_global(column);
      }

      /** dst = A src. */
      void
      vmult(Vector &dst, const Vector &src) const
      {
        multiply<false>(dst, src);
      }

      /** dst += A src. */
      void
      vmult_add(Vector &dst, const Vector &src) const
      {
        multiply<true>(dst, src);
      }

      /** dst = A^T src. */
      void
      Tvmult(Vector &dst, const Vector &src) const
      {
        dst = 0;
        Tvmult_add(dst, src);
      }

      /** dst += A^T src. */
      void
      Tvmult_add(Vector &dst, const Vector &src) const;

      /** dst = b - A x. */
      void
      residual(Vector &dst, const Vector &x, const Vector &b) const;

      /** v^T A v over all ranks. */
      double
      matrix_norm_square(const Vector &v) const;

      /**
       * n Gauss-Seidel sweeps over the rank's rows (forward or backward),
       * reading the other ranks' entries of v as they are on entry (one
       * exchange), or as zero if `ghosts_zero` (no exchange: v starts at
       * zero).
       */
      void
      relax(Vector       &v,
            const Vector &b,
            unsigned int  n,
            bool          forward,
            bool          ghosts_zero) const;

      /**
       * The entries of v on this matrix's partitioner, ghosts current:
       * v's own storage if it is on this partitioner (after
       * update_ghost_values) or has no ghosts to read, else a buffer.
       */
      const double *
      ghosted(const Vector &v) const;

      /**
       * After a kernel that read v's ghosts in place: mark them stale
       * again (zero), so that deal.II's vector operations on v do not
       * re-import them after every change.
       */
      void
      release(const Vector &v) const
      {
        if (partitioner->n_ghost_indices() > 0 &&
            v.get_partitioner().get() == partitioner.get())
          v.zero_out_ghost_values();
      }

    private:
      template <bool add>
      void
      multiply(Vector &dst, const Vector &src) const
      {
        const double *s = ghosted(src);
        double       *d = dst.begin();
        for (unsigned int row = 0; row < n_rows; ++row)
          {
            double sum = 0;
            for (unsigned int j = rowstart[row]; j < rowstart[row + 1]; ++j)
              sum += values[j] * s[colnums[j]];
            d[row] = add ? d[row] + sum : sum;
          }
        release(src);
      }


      unsigned int                                               n_rows = 0;
      std::vector<unsigned int>                                  rowstart;
      std::vector<unsigned int>                                  colnums;
      std::vector<double>                                        values;
      std::shared_ptr<const dealii::Utilities::MPI::Partitioner> partitioner;
      mutable Vector                                             buffer;
    };
  } // namespace la
} // namespace rsfcycle

#endif
