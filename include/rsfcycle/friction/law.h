// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_friction_law_h
#define rsfcycle_friction_law_h

#include <array>
#include <cmath>
#include <string>

namespace rsfcycle
{
  namespace friction
  {
    /**
     * Rate-and-state parameters of one contact node. The state is carried as
     * alpha = log(theta V* / L) throughout (doc/model.md §2), so theta itself
     * is never formed in a code path that could overflow.
     */
    struct Parameters
    {
      double a        = 0.02;    // direct effect [-]
      double b        = 0.005;   // evolution effect [-]
      double mu_star  = 0.7;     // reference friction coefficient [-]
      double v_star   = 50e-6;   // reference slip rate [m/s]
      double L        = 22.5e-6; // characteristic slip distance [m]
      double cohesion = 0;       // C [Pa]: stick below w C (doc/model.md (13))

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

    /** A friction coefficient mu and its derivative d mu / dV. */
    struct CoefficientAndDerivative
    {
      double mu;
      double derivative;
    };

    /**
     * A rate-and-state friction law (doc/model.md §2): the friction coefficient
     * mu(V, alpha) with its derivatives, and the evolution of the state
     * alpha = log(theta V* / L). Every part of the program that evaluates
     * friction takes the law from here (`Solver/State law`, friction/laws.h):
     * the node-local solves of TNNMG (through NodePotential), the rate/state
     * coupling of the implicit step, the SEAS and VTU output, the
     * spring-slider and ODE integrators.
     *
     * The friction coefficient is the regularised law (2) of the paper,
     * mu = a asinh(V / (2 V_theta)), V_theta = V* exp(-(mu* + b alpha) / a),
     * evaluated in log space; the state laws derive from this class and
     * give the state's rate and its closed-form update over a step. A law
     * with another coefficient overrides state_term() and
     * coefficient_and_derivative() (and sensitivities()) as well.
     */
    class Law
    {
    public:
      virtual ~Law() = default;

      /** The name of the law in `Solver/State law`. */
      virtual std::string
      name() const = 0;

      /**
       * The part of mu that depends on the state alone, computed once per
       * state for the many evaluations of a fixed-point iteration: for (2),
       * log V_theta(alpha).
       */
      virtual double
      state_term(const Parameters &p, const double alpha) const
      {
        return p.log_v_theta(alpha);
      }

      /**
       * mu(V) and d mu / dV at V >= 0 for the state term of state_term():
       * for (2), log z = log V - log 2 - log V_theta and
       * asinh(z) = log z + log(1 + sqrt(1 + z^-2)) for z > 1,
       * d mu / dV = a / sqrt(V^2 + 4 V_theta^2). Finite for every V >= 0
       * and every alpha, also where exp((mu* + b alpha)/a) overflows; the
       * derivative is capped at 1e300 for V -> 0 and tiny V_theta (the node
       * is then stuck for every practical purpose, and TNNMG truncates it).
       */
      virtual CoefficientAndDerivative
      coefficient_and_derivative(const Parameters &p,
                                 double            state_term,
                                 double            V) const;

      /**
       * The sensitivities of mu at V > 0 that an ODE for log V needs:
       * V d mu / dV and d mu / d alpha. For (2) they are a s and b s with
       * s = 1 / sqrt(1 + z^-2), z = V / (2 V_theta), in log space.
       */
      virtual std::array<double, 2>
      sensitivities(const Parameters &p, double alpha, double V) const;

      /** d alpha / dt at the slip rate V >= 0. */
      virtual double
      state_rate(const Parameters &p, double alpha, double V) const = 0;

      /**
       * The state after a step of length tau at the constant slip rate
       * V >= 0, in closed form (the paper's (17) for the ageing law), from
       * the state alpha at the start of the step.
       */
      virtual double
      update_state(const Parameters &p,
                   double            alpha,
                   double            V,
                   double            tau) const = 0;

      /** mu(V, alpha) (doc/model.md (2)). */
      double
      friction_coefficient(const Parameters &p,
                           const double      alpha,
                           const double      V) const
      {
        return coefficient_and_derivative(p, state_term(p, alpha), V).mu;
      }

      /** d mu / dV at (V, alpha). */
      double
      friction_coefficient_derivative(const Parameters &p,
                                      const double      alpha,
                                      const double      V) const
      {
        return coefficient_and_derivative(p, state_term(p, alpha), V)
          .derivative;
      }

      /**
       * The steady state at the slip rate V > 0, where the state does not
       * change: theta = L / V, alpha = log(V* / V), for both state laws.
       */
      virtual double
      steady_state(const Parameters &p, const double V) const
      {
        return std::log(p.v_star / V);
      }

      /** The steady-state coefficient mu(V, steady_state(V)). */
      double
      steady_state_friction_coefficient(const Parameters &p,
                                        const double      V) const
      {
        return friction_coefficient(p, steady_state(p, V), V);
      }
    };
  } // namespace friction
} // namespace rsfcycle

#endif
