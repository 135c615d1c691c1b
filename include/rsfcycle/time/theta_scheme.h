#ifndef rsfcycle_time_theta_scheme_h
#define rsfcycle_time_theta_scheme_h

#include <array>

namespace rsfcycle
{
  namespace time
  {
    /**
     * The one-step theta scheme of the time step, for the displacement u,
     * the velocity v and the acceleration a alike:
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
     * v_{n+1}; with M a_{n+1} + C v_{n+1} + K u_{n+1} = f the step matrix is
     * M / (theta tau) + C + theta tau K (quasi-static: without M).
     */
    struct ThetaScheme
    {
      double theta   = 0.5;
      bool   dynamic = true;

      /** The factors of M, C and K in the step matrix. */
      std::array<double, 3>
      step_coefficients(const double tau) const
      {
        return {{dynamic ? 1. / (theta * tau) : 0., 1., theta * tau}};
      }

      /** The weight of v_n in u_{n+1} and in the state update: 1 - theta. */
      double
      old_weight() const
      {
        return 1 - theta;
      }

      /** u_{n+1} = u_n + tau (old_weight() v_n + theta v_{n+1}). */
      template <typename Number>
      Number
      displacement(const Number u_old,
                   const Number v_old,
                   const Number v_new,
                   const double tau) const
      {
        return u_old + tau * (old_weight() * v_old + theta * v_new);
      }

      /**
       * The part of M a_{n+1} known from the old step, divided by M:
       * v_n / (theta tau) + (1 - theta) / theta a_n.
       */
      template <typename Number>
      Number
      inertia_from_old(const Number v_old,
                       const Number a_old,
                       const double tau) const
      {
        return 1. / (theta * tau) * v_old + old_weight() / theta * a_old;
      }

      /** a_{n+1} = (v_{n+1} - v_n) / (theta tau) - (1 - theta) / theta a_n. */
      template <typename Number>
      Number
      acceleration(const Number v_old,
                   const Number v_new,
                   const Number a_old,
                   const double tau) const
      {
        return 1. / (theta * tau) * (v_new - v_old) -
               old_weight() / theta * a_old;
      }

      /**
       * The power of tau of the local error: 3 for theta = 1/2 (second
       * order), 2 otherwise.
       */
      double
      local_error_order() const
      {
        return theta == 0.5 ? 3. : 2.;
      }
    };
  } // namespace time
} // namespace rsfcycle

#endif
