// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_solvers_reused_factor_correction_h
#define rsfcycle_solvers_reused_factor_correction_h

#include <array>
#include <limits>
#include <memory>
#include <rsfcycle/solvers/projected_cg.h>
#include <rsfcycle/solvers/sparse_cholesky.h>
#include <rsfcycle/solvers/spatial_problem.h>
#include <vector>

namespace rsfcycle
{
  namespace solvers
  {
    /**
     * The direct linear correction with reused factors (Solver/Direct
     * factor reuse; DirectCorrection is the exact one, whose dense Schur
     * complement suits a few hundred contact dofs). The truncated Newton
     * matrix (A plus
     * the friction's Hessian blocks on the active contact dofs, the
     * truncated dofs' rows and columns replaced by the identity) is
     * factorised with CHOLMOD (solvers/sparse_cholesky.h) on one pattern for
     * the whole run (A's and each contact node's block), so the
     * fill-reducing ordering and the symbolic factor are computed once.
     *
     * A factor is kept per step matrix (TruncatedNewtonSystem::matrix_key,
     * the last few) and reused, while the truncated set is the same, as the
     * preconditioner of conjugate gradients on the current Newton matrix:
     * the Hessians change little from one TNNMG iteration or step to the
     * next, so one or two back-substitutions reach the tolerance. When
     * `control.max_cycles` of them do not, the current matrix is factorised
     * and solved exactly. With `control.tolerance` = 0 every call factorises
     * (an exact solve). One rank (local indices are the global ones).
     */
    class ReusedFactorCorrection : public LinearCorrection
    {
    public:
      explicit ReusedFactorCorrection(const LinearCorrectionControl &control);
      ~ReusedFactorCorrection() override;

      /** Returns the number of solves with a factor. */
      unsigned int
      solve(const TruncatedNewtonSystem &system,
            const la::Vector            &rhs,
            la::Vector                  &correction) override;

      /**
       * Stop reusing the factors (they hold the Hessians of earlier
       * solves); their objects keep the pattern's analysis for the next
       * factorisations.
       */
      void
      forget() override
      {
        for (auto &f : factors)
          {
            f->key = std::numeric_limits<double>::quiet_NaN();
            f->truncated.clear();
          }
      }

    private:
      /** The pattern of the Newton matrix and where A's entries go in it. */
      void
      make_pattern(const TruncatedNewtonSystem &system);

      /** The current Newton matrix into `values`. */
      void
      fill_values(const TruncatedNewtonSystem &system);

      /** A factor; key NaN: forgotten, its object free for a new one. */
      struct Factor
      {
        double            key = 0;
        std::vector<bool> truncated;
        SparseCholesky    cholesky;
      };

      LinearCorrectionControl control;
      // upper triangle in compressed columns (SparseCholesky::factorize)
      std::vector<int>    column_start, row_index;
      std::vector<double> values;
      /** A's entry e -> its position in values, -1 below the diagonal. */
      std::vector<int> a_position;
      /** dof -> position of its diagonal entry. */
      std::vector<int> diagonal;
      /** Contact node k's entry (i, j), i <= j -> position, else -1. */
      std::vector<std::array<int, 4>>      hessian_position;
      std::vector<std::unique_ptr<Factor>> factors; // newest last
      ProjectedCG                          cg;
      dealii::Vector<double>               b, x; // work vectors
    };
  } // namespace solvers
} // namespace rsfcycle

#endif
