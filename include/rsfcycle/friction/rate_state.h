#ifndef rsfcycle_friction_rate_state_h
#define rsfcycle_friction_rate_state_h

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace rsfcycle
{
  namespace friction
  {
    /**
     * The state evolution laws of MODEL.md §2: the ageing law
     * (4) theta' = 1 - theta V / L and the slip law
     * theta' = -(theta V / L) log(theta V / L).
     */
    enum class StateLaw
    {
      ageing,
      slip
    };

    /** "ageing" or "slip"; throws for any other name. */
    StateLaw
    state_law_from_name(const std::string &name);

    /**
     * Rate-and-state parameters of one contact node. The state is carried as
     * alpha = log(theta V* / L) throughout (MODEL.md §2), so theta itself is
     * never formed in a code path that could overflow.
     */
    struct Parameters
    {
      double a        = 0.02;    // direct effect [-]
      double b        = 0.005;   // evolution effect [-]
      double mu_star  = 0.7;     // reference friction coefficient [-]
      double v_star   = 50e-6;   // reference slip rate [m/s]
      double L        = 22.5e-6; // characteristic slip distance [m]
      double cohesion = 0;       // C [Pa]: stick below w C (MODEL.md (13))

      /** log V_theta = log V* - (mu* + b alpha) / a, eq. (2). */
      double
      log_v_theta(const double alpha) const
      {
        return std::log(v_star) - (mu_star + b * alpha) / a;
      }

      /** log theta = alpha + log(L / V*): the state [s] of alpha. */
      double
      log_theta(const double alpha) const
      {
        return alpha + std::log(L / v_star);
      }
    };

    /**
     * The regularised friction coefficient (2),
     * mu(V) = a asinh(V / (2 V_theta)), evaluated in log space:
     * log z = log V - log 2 - log V_theta, and
     * asinh(z) = log z + log(1 + sqrt(1 + z^-2)) for z > 1. Finite for every
     * V >= 0 and every alpha, also where exp((mu* + b alpha)/a) overflows.
     */
    double
    friction_coefficient(const Parameters &p, double alpha, double V);

    /**
     * d mu / dV = a / sqrt(V^2 + 4 V_theta^2), in log space. For V -> 0 and
     * tiny V_theta the exact value exceeds the range of double; the result
     * is then capped at 1e300 (a node there is stuck for every practical
     * purpose, and the solver truncates it).
     */
    double
    friction_coefficient_derivative(const Parameters &p,
                                    double            alpha,
                                    double            V);

    /**
     * The steady-state coefficient mu_ss(V) of the regularised law: the
     * value of (2) at the state where theta' = 0, i.e. alpha = log(V* / V).
     */
    double
    steady_state_friction_coefficient(const Parameters &p, double V);

    /**
     * Closed-form state update over one step of length tau with constant slip
     * rate V, eq. (17), in the variable alpha:
     *  - ageing: theta_n = theta e^{-x} + (L/V)(1 - e^{-x}), x = V tau / L,
     *    as alpha_n = logaddexp(alpha - x, log(V* tau / L) + log(phi1(x))),
     *    phi1(x) = -expm1(-x)/x, which is exact also for V -> 0;
     *  - slip: log(theta V/L) decays like e^{-x}, so
     *    alpha_n = alpha e^{-x} - log(V/V*) expm1(-x) (alpha_n = alpha for
     *    V = 0).
     */
    double
    update_state(StateLaw          law,
                 const Parameters &p,
                 double            alpha,
                 double            V,
                 double            tau);

    /**
     * The friction coefficient (2) and its derivative d mu / dV at V >= 0
     * for a given log V_theta (the per-node quantity that depends only on
     * the state): the same values as friction_coefficient() and
     * friction_coefficient_derivative(), with one logarithm of V and one
     * exponential shared between them.
     */
    struct CoefficientAndDerivative
    {
      double mu;
      double derivative;
    };

    CoefficientAndDerivative
    friction_coefficient_and_derivative(const Parameters &p,
                                        double            log_v_theta,
                                        double            V);

    /**
     * The friction potential of one contact node with lumped quadrature,
     * phi(s) = N int_0^s mu(r) dr + W s, where N = w_i |sigma_n,i| is the
     * node's normal force and W = w_i C its cohesion force (MODEL.md (13)).
     * Only its derivatives are needed by the solver. The state alpha is set
     * with set_state(), which also computes log V_theta(alpha) once for the
     * many evaluations of a fixed-point iteration.
     */
    struct NodePotential
    {
      Parameters params;
      double     normal_force   = 0; // N = w |sigma_n|  [N/m in 2D, N in 3D]
      double     cohesion_force = 0; // W = w C

      /** Set the state alpha (after the parameters). */
      void
      set_state(const double new_alpha)
      {
        alpha       = new_alpha;
        log_v_theta = params.log_v_theta(alpha);
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
        const auto mu =
          friction_coefficient_and_derivative(params, log_v_theta, s);
        return {normal_force * mu.mu + cohesion_force,
                normal_force * mu.derivative};
      }

    private:
      double alpha       = 0;
      double log_v_theta = std::numeric_limits<double>::quiet_NaN();
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
     * sweep (MODEL.md §4.2 step 1),
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
