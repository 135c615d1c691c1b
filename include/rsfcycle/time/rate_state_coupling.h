// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_time_rate_state_coupling_h
#define rsfcycle_time_rate_state_coupling_h

#include <cmath>
#include <optional>
#include <rsfcycle/parameters.h>
#include <utility>

namespace rsfcycle
{
  namespace time
  {
    /**
     * The coupling between slip rate and state within one time step, generic
     * in the velocity and state types so that every model (continuum,
     * spring-slider) runs the same logic (`Solver/Coupling`):
     *  - fixed point (18): alpha^0 = the old state; for k = 1, 2, ...:
     *    solve the velocity v^k with alpha^{k-1}; alpha^k = state update with
     *    the slip rate |(1 - lambda) v_old + lambda v^k| of the time step's
     *    scheme (lambda = TimeScheme::state_weight(); the theta scheme's
     *    theta, for 1/2 the mean of old and new); stop when
     *    distance(alpha^k, alpha^{k-1}) <= tolerance (19);
     *  - explicit decoupling: the state is updated once with the old slip
     *    rate |v_old|, then the velocity is solved once.
     *
     * The callables:
     *  - solve_velocity(alpha, v) -> bool: solve (15) for v with the state
     *    alpha (v holds the previous iterate on entry); false on failure;
     *  - update_state(v_new, weight_new, alpha): alpha = the state update
     *    from the old state over the step with the velocity
     *    (1 - weight_new) v_old + weight_new v_new;
     *  - distance(alpha1, alpha2): the distance (14).
     *
     * On success v and alpha hold the new velocity and state, and the number
     * of velocity solves (fixed-point iterations) is returned; on failure
     * (a failed velocity solve, a non-finite distance, or no convergence
     * within max_iterations) nothing is returned, and the caller rejects the
     * step. If `last_distance` is given, it receives the distance of the
     * last fixed-point iteration (for diagnoses). The fixed point is not
     * accepted before `min_iterations` iterations (2 when the first velocity
     * solve was inexact, see `Inner tolerance factor`).
     */
    template <typename Velocity,
              typename StateVector,
              typename SolveVelocity,
              typename UpdateState,
              typename Distance>
    std::optional<unsigned int>
    couple_rate_and_state(const SolverParameters::Coupling coupling,
                          const double                     tolerance,
                          const unsigned int               max_iterations,
                          const double                     state_weight,
                          const Velocity                  &v_old,
                          Velocity                        &v,
                          StateVector                     &alpha,
                          SolveVelocity                  &&solve_velocity,
                          UpdateState                    &&update_state,
                          Distance                       &&distance,
                          double            *last_distance  = nullptr,
                          const unsigned int min_iterations = 1)
    {
      if (coupling == SolverParameters::Coupling::explicit_decoupling)
        {
          update_state(v_old, 0., alpha);
          if (!solve_velocity(alpha, v))
            return {};
          return 1u;
        }

      StateVector alpha_new = alpha;
      for (unsigned int k = 1; k <= max_iterations; ++k)
        {
          if (!solve_velocity(alpha, v))
            return {};
          update_state(v, state_weight, alpha_new);
          const double d = distance(alpha_new, alpha);
          if (last_distance != nullptr)
            *last_distance = d;
          std::swap(alpha, alpha_new);
          if (!std::isfinite(d))
            return {};
          if (d <= tolerance && k >= min_iterations)
            return k;
        }
      return {};
    }
  } // namespace time
} // namespace rsfcycle

#endif
