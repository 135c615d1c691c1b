// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_solvers_hierarchical_matrix_h
#define rsfcycle_solvers_hierarchical_matrix_h

#include <cstddef>
#include <deal.II/lac/full_matrix.h>
#include <functional>
#include <memory>
#include <vector>

namespace rsfcycle
{
  namespace solvers
  {
    /**
     * A dense matrix whose rows and columns belong to points in space (a
     * fault operator: row k is the force at node k per unit slip of every
     * node), compressed as a hierarchical matrix by hmat-oss (Debian
     * libhmat-oss-dev): the points are clustered by median splits down to
     * `leaf_size` points, a block of two clusters whose distance is at
     * least their smaller diameter / eta is stored in low rank (ACA+ with
     * partial pivoting, then recompressed, both to the relative tolerance),
     * the others dense; a symmetric matrix (the same points for rows and
     * columns) stores its lower triangle only. For an operator that decays
     * with distance the storage and the cost of a product grow like
     * n log n instead of n^2. In single precision the blocks are computed
     * in double and stored in float: half the memory, and half the time of
     * a product whose blocks do not fit the caches (it streams them), for
     * a rounding error of about 1e-7 relative per number.
     */
    class HierarchicalMatrix
    {
    public:
      /** The numbers stored and the product's arithmetic. */
      enum class Precision
      {
        double_precision,
        single_precision
      };

      /**
       * Compress the m x n matrix whose entry (i, j) is `entry(i, j)`, row
       * i belonging to the point (row_points[dim i], ...,
       * row_points[dim i + dim - 1]) and column j to the point of
       * column_points; a `symmetric` matrix (the two lists equal) has only
       * its lower triangle read and stored. `entry` is not kept. Throws
       * std::runtime_error if hmat-oss fails.
       */
      HierarchicalMatrix(
        unsigned int                                             m,
        unsigned int                                             n,
        const std::function<double(unsigned int, unsigned int)> &entry,
        const std::vector<double>                               &row_points,
        const std::vector<double>                               &column_points,
        unsigned int                                             dim,
        double                                                   tolerance,
        bool                                                     symmetric,
        Precision    precision = Precision::double_precision,
        unsigned int leaf_size = 32,
        double       eta       = 2.);
      /** The same for the entries of a dense A (A(i, j)). */
      HierarchicalMatrix(const dealii::FullMatrix<double> &A,
                         const std::vector<double>        &row_points,
                         const std::vector<double>        &column_points,
                         unsigned int                      dim,
                         double                            tolerance,
                         bool                              symmetric,
                         Precision    precision = Precision::double_precision,
                         unsigned int leaf_size = 32,
                         double       eta       = 2.);
      ~HierarchicalMatrix();
      HierarchicalMatrix(const HierarchicalMatrix &) = delete;
      HierarchicalMatrix &
      operator=(const HierarchicalMatrix &) = delete;

      /**
       * y = A x, or y += A x if `add` (x of length n, y of length m, in the
       * points' order).
       */
      void
      vmult(const double *x, double *y, bool add = false) const;

      /** y = A^T x, or y += A^T x if `add` (x of length m, y of length n). */
      void
      Tvmult(const double *x, double *y, bool add = false) const;

      unsigned int
      m() const;
      unsigned int
      n() const;

      /** Bytes of the numbers stored. */
      std::size_t
      memory_consumption() const;

      /** Numbers stored (the low-rank factors and dense blocks). */
      std::size_t
      stored_entries() const;

      /** Low-rank blocks and dense blocks of the block tree. */
      std::size_t
      n_low_rank_blocks() const;
      std::size_t
      n_dense_blocks() const;

    private:
      /** y (+)= op(A) x, op the identity ('N') or the transpose ('T'). */
      void
      product(char transpose, const double *x, double *y, bool add) const;

      struct Data;
      std::unique_ptr<Data> data;
    };
  } // namespace solvers
} // namespace rsfcycle

#endif
