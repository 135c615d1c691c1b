#ifndef rsfcycle_local_matrix_h
#define rsfcycle_local_matrix_h

#include <deal.II/lac/sparse_matrix.h>
#include <rsfcycle/la.h>
#include <vector>

namespace rsfcycle
{
  namespace la
  {
    /**
     * A rank's rows of a square sparse matrix in compressed rows, columns
     * in the vectors' local numbering (owned entries first, ghosts after),
     * reading the values of a deal.II SparseMatrix in place (so entries
     * changed with set() are seen; the matrix must not be reinitialised
     * while the view lives). The products, the residual and the SOR
     * relaxations that the multigrid cycle, TNNMG and the Newmark step run
     * on distributed vectors, by raw index instead of the global-index
     * access of deal.II's templates for distributed vectors. On one rank
     * local numbering is the global one. The diagonal is the first entry of
     * every row (deal.II's SparsityPattern of a square matrix).
     */
    class LocalMatrix
    {
    public:
      LocalMatrix() = default;

      explicit LocalMatrix(const dealii::SparseMatrix<double> &A)
      {
        initialize(A);
      }

      void
      initialize(const dealii::SparseMatrix<double> &A)
      {
        const auto &pattern = A.get_sparsity_pattern();
        n_rows              = A.m();
        rowstart.assign(1, 0);
        colnums.clear();
        for (unsigned int row = 0; row < n_rows; ++row)
          {
            for (auto it = pattern.begin(row); it != pattern.end(row); ++it)
              colnums.push_back(it->column());
            rowstart.push_back(colnums.size());
          }
        // the value array starts with the first row's diagonal (deal.II
        // returns it by reference only from a non-const matrix)
        values =
          n_rows > 0 ?
            &const_cast<dealii::SparseMatrix<double> &>(A).diag_element(0) :
            nullptr;
      }

      unsigned int
      m() const
      {
        return n_rows;
      }

      unsigned int
      n() const
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

      /** dst = A src (src with current ghost values). */
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

      /** dst = A^T src (one rank: the ghost columns' sums stay local). */
      void
      Tvmult(Vector &dst, const Vector &src) const
      {
        dst = 0;
        Tvmult_add(dst, src);
      }

      /** dst += A^T src. */
      void
      Tvmult_add(Vector &dst, const Vector &src) const
      {
        const double *s = src.begin();
        double       *d = dst.begin();
        for (unsigned int row = 0; row < n_rows; ++row)
          for (unsigned int j = rowstart[row]; j < rowstart[row + 1]; ++j)
            d[colnums[j]] += values[j] * s[row];
      }

      /** dst = b - A x, row by row as deal.II's residual(). */
      void
      residual(Vector &dst, const Vector &x, const Vector &b) const
      {
        const double *xs = x.begin();
        for (unsigned int row = 0; row < n_rows; ++row)
          {
            double s = b.local_element(row);
            for (unsigned int j = rowstart[row]; j < rowstart[row + 1]; ++j)
              s -= values[j] * xs[colnums[j]];
            dst.local_element(row) = s;
          }
      }

      /** v^T A v over all ranks. */
      double
      matrix_norm_square(const Vector &v) const
      {
        const double *x   = v.begin();
        double        sum = 0;
        for (unsigned int row = 0; row < n_rows; ++row)
          {
            double s = 0;
            for (unsigned int j = rowstart[row]; j < rowstart[row + 1]; ++j)
              s += values[j] * x[colnums[j]];
            sum += s * x[row];
          }
        return dealii::Utilities::MPI::sum(
          sum, v.get_partitioner()->get_mpi_communicator());
      }

      /** dst = (D/omega + L)^{-1} src (deal.II's precondition_SOR). */
      void
      precondition_SOR(Vector &dst, const Vector &src, const double omega) const
      {
        dst       = src;
        double *d = dst.begin();
        for (unsigned int row = 0; row < n_rows; ++row)
          {
            double s = d[row];
            for (unsigned int j = rowstart[row]; j < rowstart[row + 1]; ++j)
              if (colnums[j] < row)
                s -= values[j] * d[colnums[j]];
            d[row] = s * omega / values[rowstart[row]];
          }
      }

      /** dst = (D/omega + U)^{-1} src (deal.II's precondition_TSOR). */
      void
      precondition_TSOR(Vector       &dst,
                        const Vector &src,
                        const double  omega) const
      {
        dst       = src;
        double *d = dst.begin();
        for (unsigned int row = n_rows; row-- > 0;)
          {
            double s = d[row];
            for (unsigned int j = rowstart[row]; j < rowstart[row + 1]; ++j)
              if (colnums[j] > row)
                s -= values[j] * d[colnums[j]];
            d[row] = s * omega / values[rowstart[row]];
          }
      }

      /** One forward sweep v += omega D^{-1} (b - A v) (SOR_step). */
      void
      SOR_step(Vector &v, const Vector &b, const double omega) const
      {
        for (unsigned int row = 0; row < n_rows; ++row)
          relax(v, b, row, omega);
      }

      /** One backward sweep (TSOR_step). */
      void
      TSOR_step(Vector &v, const Vector &b, const double omega) const
      {
        for (unsigned int row = n_rows; row-- > 0;)
          relax(v, b, row, omega);
      }

    private:
      /** dst = A src, or dst += A src. */
      template <bool add>
      void
      multiply(Vector &dst, const Vector &src) const
      {
        const double *s = src.begin();
        double       *d = dst.begin();
        for (unsigned int row = 0; row < n_rows; ++row)
          {
            double sum = 0;
            for (unsigned int j = rowstart[row]; j < rowstart[row + 1]; ++j)
              sum += values[j] * s[colnums[j]];
            d[row] = add ? d[row] + sum : sum;
          }
      }

      void
      relax(Vector            &v,
            const Vector      &b,
            const unsigned int row,
            const double       omega) const
      {
        double *x = v.begin();
        double  s = b.local_element(row);
        for (unsigned int j = rowstart[row]; j < rowstart[row + 1]; ++j)
          s -= values[j] * x[colnums[j]];
        x[row] += s * omega / values[rowstart[row]];
      }

      unsigned int              n_rows = 0;
      std::vector<unsigned int> rowstart;
      std::vector<unsigned int> colnums;
      const double             *values = nullptr;
    };
  } // namespace la
} // namespace rsfcycle

#endif
