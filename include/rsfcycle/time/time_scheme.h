// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_time_time_scheme_h
#define rsfcycle_time_time_scheme_h

#include <array>
#include <string>

namespace rsfcycle
{
  namespace time
  {
    /**
     * The time discretisation of an implicit step of M a + C v + K u = f
     * with friction (`Solver/Time scheme`, time/schemes.h), written for the
     * unknown w of the step: the velocity at which the friction acts, so
     * that the step minimises the convex energy
     * 1/2 w^T A w - r^T w + j(w) of (15) with the step matrix
     * A = c_M M + c_C C + c_K K (doc/model.md §4.2, §8.3). The step's equation
     * is M a* + C w + K u* = f(t + load_fraction() tau) with
     *   u* = u_n + tau (d[0] v_n + tau d[1] a_n) + c_K w
     *                                             (d = known_displacement),
     *   a* = c_M w - (m[0] v_n + m[1] a_n)        (m = known_inertia);
     * after the solve the new state is
     *   v_{n+1} = e[0] w + e[1] v_n               (e = new_velocity),
     *   a_{n+1} = g[0] (v_{n+1} - v_n) + g[1] a_n (g = new_acceleration),
     *   u_{n+1} = u_n + tau (h[0] v_n + h[1] v_{n+1})
     *             + tau^2 (h[2] a_n + h[3] a_{n+1}) (h = new_displacement).
     * The state update (17) over the step takes the slip rate of
     * (1 - state_weight()) v_n + state_weight() w, the friction the state
     * (1 - friction_state_weight()) alpha_n + friction_state_weight()
     * alpha_{n+1}. The step matrix is a
     * positive combination of M, C and K, so every scheme keeps the
     * spatial problem strictly convex and TNNMG unchanged.
     *
     * A new scheme is a class derived from TimeScheme in its own header and
     * one line in schemes() of source/time/schemes.cc.
     */
    class TimeScheme
    {
    public:
      virtual ~TimeScheme() = default;

      /** The name in `Solver/Time scheme`. */
      virtual std::string
      name() const = 0;

      /** The name with the scheme's parameters, for the log. */
      virtual std::string
      describe() const = 0;

      /** c_M, c_C, c_K of the step matrix. */
      virtual std::array<double, 3>
      step_coefficients(double tau) const = 0;

      /** The load and the prescribed velocities are taken at t + this tau. */
      virtual double
      load_fraction() const = 0;

      /** d: the old state's part of u*. */
      virtual std::array<double, 2>
      known_displacement() const = 0;

      /** m: the old state's part of the inertia, M (m[0] v_n + m[1] a_n). */
      virtual std::array<double, 2>
      known_inertia(double tau) const = 0;

      /** The weight of w in the slip rate of the state update. */
      virtual double
      state_weight() const = 0;

      /**
       * The friction of the step acts at the state (1 - sigma) alpha_n +
       * sigma alpha_{n+1}, sigma this weight: at the time at which w is the
       * velocity (1 for a scheme whose w is v_{n+1}).
       */
      virtual double
      friction_state_weight() const
      {
        return 1;
      }

      /** e: v_{n+1} from w. */
      virtual std::array<double, 2>
      new_velocity() const = 0;

      /** g: a_{n+1} from v_{n+1} - v_n and a_n. */
      virtual std::array<double, 2>
      new_acceleration(double tau) const = 0;

      /** h: u_{n+1} from v_n, v_{n+1}, a_n and a_{n+1}. */
      virtual std::array<double, 4>
      new_displacement() const = 0;

      /** The power of tau with which the local error grows. */
      virtual double
      local_error_order() const = 0;
    };


    /**
     * The step matrix coefficients of `scheme`, without the mass matrix
     * for a model without inertia (quasi-static, quasi-dynamic).
     */
    inline std::array<double, 3>
    step_coefficients(const TimeScheme &scheme,
                      const double      tau,
                      const bool        inertia)
    {
      std::array<double, 3> c = scheme.step_coefficients(tau);
      if (!inertia)
        c[0] = 0;
      return c;
    }
  } // namespace time
} // namespace rsfcycle

#endif
