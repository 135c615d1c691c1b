// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_solvers_tnnmg_h
#define rsfcycle_solvers_tnnmg_h

#include <deal.II/base/timer.h>
#include <memory>
#include <optional>
#include <rsfcycle/la.h>
#include <rsfcycle/solvers/spatial_problem.h>
#include <string>

namespace rsfcycle
{
  namespace solvers
  {
    /** Settings of the TNNMG iteration. */
    struct TNNMGControl
    {
      /** Give up (failure) after this many iterations. */
      unsigned int max_iterations = 100;
      /**
       * A sliding contact node whose friction Hessian exceeds this multiple
       * of the diagonal of A is "effectively stuck" and is truncated too
       * (doc/model.md §4.2, conditioning).
       */
      double truncation_ratio = 1e10;
    };

    /** What one TNNMG solve did. */
    struct TNNMGStatistics
    {
      unsigned int iterations        = 0;
      unsigned int linear_iterations = 0;
      bool         converged         = false;
      double       relative_change   = 0;
    };

    /**
     * Truncated nonsmooth Newton multigrid (Graeser, Sack, Sander 2009) for
     * the spatial problem: per iteration a nonlinear block Gauss-Seidel sweep
     * with exact node-local friction solves, truncation of the non-smooth
     * and effectively stuck contact nodes, a linear correction, and an exact
     * line search along the correction (doc/model.md §4.2, steps 1-4).
     */
    class TNNMG
    {
    public:
      /**
       * With a fallback correction, a solve that does not converge within
       * max_iterations goes on from its last iterate with the fallback for
       * up to max_iterations more (Solver/Direct fallback).
       */
      TNNMG(LinearCorrection   &correction,
            const TNNMGControl &control,
            LinearCorrection   *fallback = nullptr);

      /**
       * Minimise J starting from v (fixed entries must hold their values),
       * until ||v_k - v_{k-1}||_A <= tolerance * ||v_k||_A (the caller
       * chooses it per solve: the inexact fixed point loosens it in early
       * iterations). Returns statistics; v holds the last iterate.
       * Non-finite values give converged = false (and no fallback).
       */
      TNNMGStatistics
      solve(const SpatialProblem &problem,
            la::Vector           &v,
            const double          tolerance);

      /**
       * One nonlinear block Gauss-Seidel sweep over all free dofs: a linear
       * update for dofs without friction, the exact node-local friction
       * solve for contact nodes (doc/model.md §4.2 step 1).
       */
      static void
      gauss_seidel_sweep(const SpatialProblem &problem, la::Vector &v);

      /**
       * Time the four steps of every iteration in these TimerOutput
       * sections ("TNNMG: nonlinear smoother", "TNNMG: truncation",
       * "TNNMG: linear correction", "TNNMG: line search"); nullptr: none.
       */
      void
      set_timer(dealii::TimerOutput *timer);

    private:
      /**
       * Step 2: the residual, truncation of stuck nodes, the friction
       * Hessians and the right-hand side of the truncated Newton system at
       * the smoothed iterate v.
       */
      void
      truncate_and_linearise(const SpatialProblem &problem,
                             const la::Vector     &v);

      /** A timer section if a timer is attached. */
      std::optional<dealii::TimerOutput::Scope>
      section(const char *name) const;

      double
      line_search(const SpatialProblem &problem,
                  const la::Vector     &v,
                  const la::Vector     &c);

      /** The iterations of solve() with one linear correction. */
      void
      iterate(const SpatialProblem &problem,
              la::Vector           &v,
              double                tolerance,
              LinearCorrection     &linear,
              const char           *section_name,
              TNNMGStatistics      &stats);

      LinearCorrection    &correction;
      LinearCorrection    *fallback;
      TNNMGControl         control;
      dealii::TimerOutput *timer = nullptr;

      la::Vector residual, increment, newton_rhs, correction_vector, Ac, Av,
        Av_old, v_old;
      std::vector<bool>                  truncated;
      std::vector<std::array<double, 4>> hessians;
    };


  } // namespace solvers
} // namespace rsfcycle

#endif
