// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_solvers_coarse_direct_h
#define rsfcycle_solvers_coarse_direct_h

#include <deal.II/lac/householder.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deal.II/multigrid/mg_base.h>
#include <rsfcycle/la.h>
#include <rsfcycle/local_matrix.h>
#include <rsfcycle/solvers/sparse_cholesky.h>

namespace rsfcycle
{
  namespace solvers
  {
    /**
     * The coarse level of the geometric multigrid, solved directly: the
     * coarse matrix (the rank's rows of a la::LocalMatrix) is gathered onto
     * every rank as a sparse matrix and factorised there by CHOLMOD (the
     * coarse mesh does not grow with the number of ranks); the right-hand
     * side is summed onto every rank in each solve. The contact nodes'
     * friction Hessians change the matrix in every TNNMG iteration; the
     * multigrid correction factorises it again only when they moved far
     * from the factorised ones (MultigridCorrection), since a 3D coarse
     * mesh of ten thousand vertices takes about a second to factorise. A
     * sparse Cholesky factorisation is used, where a dense Householder QR
     * would grow as n^3; a matrix that CHOLMOD
     * does not accept as positive definite falls back to Householder least
     * squares.
     */
    class CoarseDirect : public dealii::MGCoarseGridBase<la::Vector>
    {
    public:
      /** Gather and factorise the coarse matrix (all ranks call this). */
      void
      initialize(const la::LocalMatrix &coarse,
                 unsigned int           n_dofs,
                 MPI_Comm               communicator);

      void
      operator()(const unsigned int level,
                 la::Vector        &dst,
                 const la::Vector  &src) const override;

    private:
      dealii::SparsityPattern      pattern;
      dealii::SparseMatrix<double> matrix;
      SparseCholesky               cholesky;
      bool                         use_cholesky = true;
      dealii::Householder<double>  householder;
      // buffers kept: the coarse solve runs in every V-cycle
      mutable dealii::Vector<double> b, x;
    };
  } // namespace solvers
} // namespace rsfcycle

#endif
