#ifndef rsfcycle_solvers_projected_cg_h
#define rsfcycle_solvers_projected_cg_h

#include <deal.II/lac/vector.h>
#include <functional>
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
     * y = (A + H) x on the non-truncated components, 0 on the truncated ones
     * (x must vanish on them): the operator of the truncated Newton system.
     */
    void
    truncated_newton_vmult(const TruncatedNewtonSystem  &system,
                           const dealii::Vector<double> &x,
                           dealii::Vector<double>       &y);

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
        std::function<void(dealii::Vector<double> &,
                           const dealii::Vector<double> &)>;

      /** Returns the number of preconditioner applications. */
      unsigned int
      solve(const TruncatedNewtonSystem   &system,
            const dealii::Vector<double>  &rhs,
            dealii::Vector<double>        &x,
            const Preconditioner          &preconditioner,
            const LinearCorrectionControl &control);

    private:
      dealii::Vector<double> r, z, p, q;
    };
  } // namespace solvers
} // namespace rsfcycle

#endif
