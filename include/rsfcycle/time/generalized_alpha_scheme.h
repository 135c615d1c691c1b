// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_time_generalized_alpha_scheme_h
#define rsfcycle_time_generalized_alpha_scheme_h

#include <rsfcycle/format.h>
#include <rsfcycle/time/time_scheme.h>

namespace rsfcycle
{
  namespace time
  {
    /**
     * The generalized-alpha scheme of Chung and Hulbert (1993) (`Solver/
     * Time scheme = generalized-alpha`, `Solver/Spectral radius` rho_inf;
     * doc/model.md §8.3) for inertial runs:
     *
     *   M a_{n+1-alpha_m} + C v_{n+1-alpha_f} + K u_{n+1-alpha_f}
     *     = f(t_n + (1 - alpha_f) tau),   x_{n+1-alpha} = (1 - alpha) x_{n+1}
     *                                                     + alpha x_n,
     *   u_{n+1} = u_n + tau v_n + tau^2 ((1/2 - beta) a_n + beta a_{n+1}),
     *   v_{n+1} = v_n + tau ((1 - gamma) a_n + gamma a_{n+1}),
     *
     * with alpha_m = (2 rho_inf - 1)/(rho_inf + 1), alpha_f = rho_inf/
     * (rho_inf + 1), gamma = 1/2 - alpha_m + alpha_f, beta = (1 - alpha_m +
     * alpha_f)^2 / 4: second order, unconditionally stable, and the
     * amplification of a mode much stiffer than the step tends to rho_inf
     * (1: the trapezoidal rule, no dissipation; 0: such modes vanish in one
     * step), while the low modes are damped at third order only.
     *
     * The unknown of the step is w = v_{n+1-alpha_f}, the velocity at which
     * the friction acts; with the Newmark relations
     *   u_{n+1-alpha_f} = u_n + tau ((1 - alpha_f - beta/gamma) v_n
     *                     + tau (1 - alpha_f)(1/2 - beta/gamma) a_n)
     *                     + (beta/gamma) tau w,
     *   a_{n+1-alpha_m} = (1 - alpha_m)/(gamma tau (1 - alpha_f)) (w - v_n)
     *                     - ((1 - alpha_m)(1 - gamma)/gamma - alpha_m) a_n,
     * so the step matrix (1 - alpha_m)/(gamma tau (1 - alpha_f)) M + C +
     * (beta/gamma) tau K is SPD and the step's energy strictly convex, and
     *   v_{n+1} = (w - alpha_f v_n)/(1 - alpha_f). Both friction
     * quantities are taken at second order: the state update takes the mean
     * slip rate (v_n + v_{n+1})/2 = (1 - lambda) v_n + lambda w, lambda =
     * 1/(2 (1 - alpha_f)) (the paper's mean for rho_inf = 1), and the
     * friction acts at the state of t_{n+1-alpha_f}, (1 - alpha_f)
     * alpha_{n+1} + alpha_f alpha_n. (With w in the state update and
     * alpha_{n+1} in the friction both would be first order for rho_inf <
     * 1: the laboratory wedge then needed about twice the steps of the
     * trapezoidal rule.)
     *
     * The displacement update uses the acceleration, which a model without
     * inertia does not carry: the scheme is for Dynamics = dynamic only
     * (time::make_scheme() refuses the others).
     */
    class GeneralizedAlphaScheme : public TimeScheme
    {
    public:
      explicit GeneralizedAlphaScheme(const double rho_infinity)
        : rho_infinity(rho_infinity)
        , alpha_m((2 * rho_infinity - 1) / (rho_infinity + 1))
        , alpha_f(rho_infinity / (rho_infinity + 1))
        , gamma(0.5 - alpha_m + alpha_f)
        , beta(0.25 * (1 - alpha_m + alpha_f) * (1 - alpha_m + alpha_f))
      {}

      std::string
      name() const override
      {
        return "generalized-alpha";
      }

      std::string
      describe() const override
      {
        return "generalized-alpha scheme (Spectral radius " +
               format_number(rho_infinity) + ")";
      }

      std::array<double, 3>
      step_coefficients(const double tau) const override
      {
        return {{mass_coefficient(tau), 1., beta / gamma * tau}};
      }

      double
      load_fraction() const override
      {
        return 1 - alpha_f;
      }

      std::array<double, 2>
      known_displacement() const override
      {
        return {
          {1 - alpha_f - beta / gamma, (1 - alpha_f) * (0.5 - beta / gamma)}};
      }

      std::array<double, 2>
      known_inertia(const double tau) const override
      {
        return {{mass_coefficient(tau),
                 (1 - alpha_m) * (1 - gamma) / gamma - alpha_m}};
      }

      double
      state_weight() const override
      {
        return 1 / (2 * (1 - alpha_f));
      }

      double
      friction_state_weight() const override
      {
        return 1 - alpha_f;
      }

      std::array<double, 2>
      new_velocity() const override
      {
        return {{1 / (1 - alpha_f), -alpha_f / (1 - alpha_f)}};
      }

      std::array<double, 2>
      new_acceleration(const double tau) const override
      {
        return {{1 / (gamma * tau), -(1 - gamma) / gamma}};
      }

      std::array<double, 4>
      new_displacement() const override
      {
        return {{1., 0., 0.5 - beta, beta}};
      }

      /** Second order: the local error grows as tau^3. */
      double
      local_error_order() const override
      {
        return 3;
      }

    private:
      /** c_M: the weight of w in a_{n+1-alpha_m}. */
      double
      mass_coefficient(const double tau) const
      {
        return (1 - alpha_m) / (gamma * tau * (1 - alpha_f));
      }

      const double rho_infinity, alpha_m, alpha_f, gamma, beta;
    };
  } // namespace time
} // namespace rsfcycle

#endif
