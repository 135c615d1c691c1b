#ifndef rsfcycle_solvers_sparse_cholesky_h
#define rsfcycle_solvers_sparse_cholesky_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <memory>

namespace rsfcycle
{
  namespace solvers
  {
    /**
     * Sparse Cholesky factorisation (SuiteSparse CHOLMOD, supernodal) of a
     * symmetric positive definite deal.II SparseMatrix. Unlike deal.II's
     * UMFPACK wrapper it does no iterative refinement and solves many
     * right-hand sides at once (BLAS 3), which is what the Schur complement
     * of the direct linear correction needs.
     */
    class SparseCholesky
    {
    public:
      SparseCholesky();
      ~SparseCholesky();
      SparseCholesky(const SparseCholesky &) = delete;
      SparseCholesky &
      operator=(const SparseCholesky &) = delete;

      /** Factorise A (symmetric; only its upper triangle is read). */
      void
      factorize(const dealii::SparseMatrix<double> &A);

      /** x = A^{-1} b. */
      void
      solve(const dealii::Vector<double> &b, dealii::Vector<double> &x) const;

      /** X = A^{-1} B for all columns of B (n x m, row-major in deal.II). */
      void
      solve(const dealii::FullMatrix<double> &B,
            dealii::FullMatrix<double>       &X) const;

    private:
      struct Data;
      std::unique_ptr<Data> data;
    };
  } // namespace solvers
} // namespace rsfcycle

#endif
