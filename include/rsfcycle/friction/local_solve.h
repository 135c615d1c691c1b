// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_friction_local_solve_h
#define rsfcycle_friction_local_solve_h

#include <array>
#include <limits>
#include <rsfcycle/friction/law.h>
#include <utility>

namespace rsfcycle
{
  namespace friction
  {
    /**
     * The friction potential of one contact node with lumped quadrature,
     * phi(s) = N int_0^s mu(r) dr + W s, where N = w_i |sigma_n,i| is the
     * node's normal force and W = w_i C its cohesion force (doc/model.md (13)).
     * Only its derivatives are needed by the solver. The state alpha is set
     * with set_state(), which also computes the law's state term (log
     * V_theta(alpha)) once for the many evaluations of a fixed-point
     * iteration.
     */
    struct NodePotential
    {
      /** The friction law (Solver/State law). */
      const Law *law = nullptr;
      Parameters params;
      double     normal_force   = 0; // N = w |sigma_n|  [N/m in 2D, N in 3D]
      double     cohesion_force = 0; // W = w C

      /** Set the state alpha (after the parameters). */
      void
      set_state(const double new_alpha)
      {
        alpha      = new_alpha;
        state_term = law->state_term(params, alpha);
      }

      /** The state alpha of the last set_state(). */
      double
      state() const
      {
        return alpha;
      }

      /** phi'(s) = N mu(s) + W for s > 0; phi'(0+) = W. */
      double
      derivative(const double s) const
      {
        return derivatives(s).first;
      }

      /** phi''(s) = N mu'(s). */
      double
      second_derivative(const double s) const
      {
        return derivatives(s).second;
      }

      /** phi'(s) and phi''(s) together (one logarithm of s). */
      std::pair<double, double>
      derivatives(const double s) const
      {
        const auto mu = law->coefficient_and_derivative(params, state_term, s);
        return {normal_force * mu.mu + cohesion_force,
                normal_force * mu.derivative};
      }

    private:
      double alpha      = 0;
      double state_term = std::numeric_limits<double>::quiet_NaN();
    };

    /** Result of one per-node local solve. */
    template <int d>
    struct LocalSolution
    {
      std::array<double, d> x{};
      bool                  stuck      = false;
      unsigned int          iterations = 0;
    };

    /**
     * Exact minimiser of the node-local problem of the nonlinear Gauss-Seidel
     * sweep (doc/model.md §4.2 step 1),
     *   min_x  1/2 x^T A x - rho^T x + phi(|x|),   x in R^d, d = dim - 1,
     * with A symmetric positive definite (d x d, row-major).
     * x = 0 if |rho| <= phi'(0+) = W (stick below cohesion). Otherwise the
     * solution is x = (A + lambda I)^{-1} rho with the unique lambda > 0 where
     *   F(lambda) = lambda s(lambda) - phi'(s(lambda)),  s = |x(lambda)|
     * vanishes; F is increasing in lambda, and the root is found by a
     * safeguarded Newton iteration in log lambda. For d = 1 this is the
     * monotone scalar equation a s + phi'(s) = |rho|; for d = 2 it handles an
     * anisotropic A exactly. A guess of x (the node's last value) only
     * chooses where the iteration starts: near the solution it converges in
     * two or three evaluations instead of about eight.
     */
    template <int d>
    LocalSolution<d>
    solve_local_problem(const std::array<double, d * d> &A,
                        const std::array<double, d>     &rho,
                        const NodePotential             &phi,
                        const std::array<double, d>     *guess = nullptr);
  } // namespace friction
} // namespace rsfcycle

#endif
