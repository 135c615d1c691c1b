// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_solvers_sparse_cholesky_h
#define rsfcycle_solvers_sparse_cholesky_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <memory>
#include <mpi.h>
#include <vector>

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

      /**
       * Factorise the symmetric matrix whose upper triangle is given in
       * compressed columns: column j has the rows i[p[j]] ... i[p[j+1]-1]
       * (each <= j) with the values x. While p and i stay the same, the
       * symbolic analysis (ordering, supernodes) of the first call is kept
       * and only the numerical factorisation is repeated.
       */
      void
      factorize(const std::vector<int>    &p,
                const std::vector<int>    &i,
                const std::vector<double> &x);

      /**
       * Factorise A once per node: the first rank of each node of
       * `communicator` (MPI_COMM_TYPE_SHARED) factorises A, which it alone
       * passes (the others pass nullptr), and puts the factor into an MPI
       * shared-memory window from which every rank of the node solves. So
       * a node holds one factor whatever its number of ranks. Collective on
       * `communicator`; the factor is freed collectively on the node (by
       * the destructor or the next factorisation).
       */
      void
      factorize_shared(const dealii::SparseMatrix<double> *A,
                       MPI_Comm                            communicator);

      /**
       * Whether this rank is the first of its node in `communicator` (the
       * one that passes the matrix to factorize_shared()). Collective.
       */
      static bool
      first_on_node(MPI_Comm communicator);

      /**
       * The factor's size in bytes (its arrays; one window per node for a
       * shared factor).
       */
      std::size_t
      memory_bytes() const;

      /** x = A^{-1} b. */
      void
      solve(const dealii::Vector<double> &b, dealii::Vector<double> &x) const;

      /**
       * The Schur complement S = C - B^T A^{-1} B of this factor's matrix A
       * (factorize() first) in the symmetric positive definite matrix
       * M = [A B; B^T C], whose upper triangle is given in compressed
       * columns as for factorize() (its leading columns those of A). M is
       * factorised once more, in A's fill-reducing order with the trailing
       * rows last, and S = L_cc L_cc^T from the trailing block L_cc of that
       * factor (which is then freed): the cost of a factorisation and of
       * one dense product of the trailing size, instead of one solve per
       * trailing column.
       */
      void
      schur_complement(const std::vector<int>           &p,
                       const std::vector<int>           &i,
                       const std::vector<double>        &x,
                       dealii::LAPACKFullMatrix<double> &S) const;

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
