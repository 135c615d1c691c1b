// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_solvers_projected_cg_h
#define rsfcycle_solvers_projected_cg_h

#include <deal.II/lac/vector.h>
#include <functional>
#include <rsfcycle/la.h>
#include <rsfcycle/solvers/spatial_problem.h>

namespace rsfcycle
{
  namespace solvers
  {
    /** When the iterative linear corrections stop. */
    struct LinearCorrectionControl
    {
      /** Preconditioner applications (multigrid cycles) per correction. */
      unsigned int max_cycles = 5;
      /** Stop when ||residual|| <= tolerance * ||rhs|| (Euclidean). */
      double tolerance = 1e-2;
    };

    /**
     * The diagonal factor (1 + penalty) that the preconditioners of the
     * iterative corrections put on truncated contact dofs, so that their
     * smoothers and coarse solves keep those corrections at ~0.
     */
    constexpr double truncation_penalty = 1e8;

    /**
     * Entry (i, j) of the d x d contact block of node k (row-major index
     * d i + j) in a preconditioner's matrix: the original entry of A plus
     * `scale` times the friction Hessian for a sliding node, the diagonal
     * times (1 + truncation_penalty) for a truncated one. Applied to the
     * original values every time, so that earlier changes are undone.
     */
    inline double
    contact_block_entry(const TruncatedNewtonSystem &system,
                        const unsigned int           k,
                        const unsigned int           i,
                        const unsigned int           j,
                        const double                 original,
                        const double                 scale = 1.)
    {
      const ContactNode &node = system.contact->nodes[k];
      if ((*system.truncated)[node.dofs[0]])
        return (i == j) ? original * (1. + truncation_penalty) : original;
      return original + scale * (*system.node_hessians)[k][node.n_dofs * i + j];
    }

    /**
     * y = (A + H) x on the non-truncated components, 0 on the truncated ones
     * (x must vanish on them): the operator of the truncated Newton system.
     */
    void
    truncated_newton_vmult(const TruncatedNewtonSystem &system,
                           const la::Vector            &x,
                           la::Vector                  &y);

    /**
     * Conjugate gradients for the truncated Newton system, restricted to the
     * non-truncated components: x starts at 0, every preconditioned residual
     * is projected (truncated components set to 0), so a symmetric positive
     * (semi)definite preconditioner B gives the preconditioner T B T on the
     * subspace. With max_cycles = 1 this is one preconditioned Richardson
     * step with the optimal step length. The work vectors are kept, so no
     * O(n) allocation happens per call.
     */
    class ProjectedCG
    {
    public:
      using Preconditioner =
        std::function<void(la::Vector &, const la::Vector &)>;

      /** Returns the number of preconditioner applications. */
      unsigned int
      solve(const TruncatedNewtonSystem   &system,
            const la::Vector              &rhs,
            la::Vector                    &x,
            const Preconditioner          &preconditioner,
            const LinearCorrectionControl &control);

      /** ||residual|| / ||rhs|| at the end of the last solve(). */
      double
      relative_residual() const
      {
        return reduction;
      }

    private:
      la::Vector r, z, p, q;
      double     reduction = 0;
    };
  } // namespace solvers
} // namespace rsfcycle

#endif
