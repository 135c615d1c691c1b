// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_time_theta_scheme_h
#define rsfcycle_time_theta_scheme_h

#include <rsfcycle/format.h>
#include <rsfcycle/time/time_scheme.h>

namespace rsfcycle
{
  namespace time
  {
    /**
     * The one-step theta scheme (`Solver/Time scheme = theta`, `Solver/
     * Theta`), for the displacement u, the velocity v and the acceleration
     * a alike:
     *
     *   u_{n+1} = u_n + tau ((1 - theta) v_n + theta v_{n+1}),
     *   v_{n+1} = v_n + tau ((1 - theta) a_n + theta a_{n+1}).
     *
     * theta = 1/2 is the paper's Newmark scheme (15) (beta = 1/4, gamma =
     * 1/2): second order, A-stable, without numerical damping, so that stiff
     * modes (Kelvin-Voigt relaxation eta/G much shorter than the step, or
     * elastic modes in the quasi-static equation) change sign from step to
     * step and hardly decay. theta = 1 is backward Euler: first order,
     * L-stable, such modes vanish within a step. The unknown of the step is
     * w = v_{n+1}; the step matrix is M / (theta tau) + C + theta tau K, and
     * the state update takes the slip rate of (1 - theta) v_n + theta
     * v_{n+1} (the paper's mean of old and new for theta = 1/2, (16)).
     */
    class ThetaScheme : public TimeScheme
    {
    public:
      explicit ThetaScheme(const double theta = 0.5)
        : theta(theta)
      {}

      std::string
      name() const override
      {
        return "theta";
      }

      std::string
      describe() const override
      {
        return "theta scheme (Theta " + format_number(theta) + ")";
      }

      std::array<double, 3>
      step_coefficients(const double tau) const override
      {
        return {{1. / (theta * tau), 1., theta * tau}};
      }

      double
      load_fraction() const override
      {
        return 1;
      }

      std::array<double, 2>
      known_displacement() const override
      {
        return {{old_weight(), 0.}};
      }

      std::array<double, 2>
      known_inertia(const double tau) const override
      {
        return {{1. / (theta * tau), old_weight() / theta}};
      }

      double
      state_weight() const override
      {
        return theta;
      }

      std::array<double, 2>
      new_velocity() const override
      {
        return {{1., 0.}};
      }

      std::array<double, 2>
      new_acceleration(const double tau) const override
      {
        return {{1. / (theta * tau), -old_weight() / theta}};
      }

      std::array<double, 4>
      new_displacement() const override
      {
        return {{old_weight(), theta, 0., 0.}};
      }

      /** 3 for theta = 1/2 (second order), 2 otherwise. */
      double
      local_error_order() const override
      {
        return theta == 0.5 ? 3. : 2.;
      }

    private:
      /** The weight of the old step, 1 - theta. */
      double
      old_weight() const
      {
        return 1 - theta;
      }

      const double theta;
    };
  } // namespace time
} // namespace rsfcycle

#endif
