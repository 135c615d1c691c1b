// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_solvers_fault_solver_h
#define rsfcycle_solvers_fault_solver_h

#include <functional>
#include <mpi.h>
#include <rsfcycle/friction/local_solve.h>
#include <vector>

namespace rsfcycle
{
  namespace solvers
  {
    /**
     * The spatial problem (15) of an implicit step reduced to the fault
     * (the Green's-function method's implicit step, doc/model.md §8.1): with
     * the bulk's Schur complement S on the contact's tangential dofs (one
     * per node),
     *   min J(w) = 1/2 w^T A w - r^T w + sum_k phi_k(|w_k|),
     *   A = c S + D,  D diagonal (the radiation damping),
     * over the slip rates w of all contact nodes. Every rank holds w for
     * all nodes and the rows first ... first + n_own - 1 of A, r, the
     * potentials; products and node-local work are done on the own rows
     * and gathered.
     */
    struct FaultProblem
    {
      /** y = S x on this rank's rows, x given for all nodes. */
      std::function<void(const double *x, double *y)> apply_S;
      /** Makes an all-node vector whose own rows are set whole. */
      std::function<void(double *values)> gather;
      /** c [s] */
      double stiffness_factor = 0;
      /** S_kk of this rank's rows. */
      const std::vector<double> *S_diagonal = nullptr;
      /** D_k of this rank's rows. */
      const std::vector<double> *damping = nullptr;
      /** r of this rank's rows. */
      const std::vector<double> *rhs = nullptr;
      /** phi_k of this rank's rows, their state set. */
      const std::vector<friction::NodePotential> *potentials   = nullptr;
      unsigned int                                first        = 0;
      MPI_Comm                                    communicator = MPI_COMM_SELF;
    };

    /** What one solve did. */
    struct FaultSolverStatistics
    {
      unsigned int iterations        = 0;
      unsigned int linear_iterations = 0; // products with S in CG
      bool         converged         = false;
    };

    /**
     * The fault-only analogue of TNNMG (solvers/tnnmg.h) for a dense or
     * compressed A that is only available as a product: per iteration a
     * nonlinear Jacobi sweep (the exact node-local solves of TNNMG's
     * smoother, all nodes against the same residual) followed by an exact
     * line search along it, then a truncated Newton correction (CG with the
     * diagonal of A + H as preconditioner; nodes whose friction Hessian H_k
     * exceeds `truncation_ratio` A_kk are held) and an exact line search
     * along that. Both directions descend and J is strictly convex, so J
     * decreases in every iteration. Converged when the change of an
     * iteration is at most `tolerance` times ||w||_A.
     */
    class FaultSolver
    {
    public:
      explicit FaultSolver(unsigned int max_iterations   = 100,
                           double       truncation_ratio = 1e10);

      FaultSolverStatistics
      solve(const FaultProblem  &problem,
            std::vector<double> &w,
            double               tolerance) const;

    private:
      const unsigned int max_iterations;
      const double       truncation_ratio;
    };
  } // namespace solvers
} // namespace rsfcycle

#endif
