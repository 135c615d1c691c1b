// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_time_implicit_model_h
#define rsfcycle_time_implicit_model_h

#include <array>
#include <optional>

namespace rsfcycle
{
  namespace time
  {
    /**
     * What a model gives the step-size control of its implicit steps
     * (`Time stepping/Integrator = implicit`; StepDoubling,
     * LocalExtrapolation): one step of the model's time scheme with the
     * rate/state coupling, the distance of two states in the error
     * estimate, and a prediction from three states.
     */
    template <typename State>
    class ImplicitModel
    {
    public:
      virtual ~ImplicitModel() = default;

      /**
       * One step of length tau from `old` at time t, the iterations
       * started from `guess` if given (a prediction); no value if the step
       * failed (no convergence, non-finite values).
       */
      virtual std::optional<State>
      step(const State &old, double t, double tau, const State *guess) = 0;

      /** The distance of two states in the error estimate [-]. */
      virtual double
      error_distance(const State &s1, const State &s2) const = 0;

      /**
       * The prediction sum_i w_i s_i of three states: the parts of a state
       * that a guess needs (velocity and friction state).
       */
      virtual State
      predict(const std::array<const State *, 3> &states,
              const std::array<double, 3>        &weights) const = 0;

      /** The power of tau with which the local error grows. */
      virtual double
      error_order() const = 0;

      /**
       * At most n iterations of the rate-state fixed point in the steps
       * that follow (0: the solver's own limit); a model without the fixed
       * point ignores it.
       */
      virtual void
      limit_fixed_point_iterations(const unsigned int n)
      {
        (void)n;
      }
    };
  } // namespace time
} // namespace rsfcycle

#endif
