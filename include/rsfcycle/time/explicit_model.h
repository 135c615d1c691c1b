// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_time_explicit_model_h
#define rsfcycle_time_explicit_model_h

#include <optional>
#include <string>

namespace rsfcycle
{
  namespace time
  {
    /**
     * What a model gives an integrator of explicit steps (`Time
     * stepping/Integrator = explicit`): the longest stable step and one
     * explicit step. The state is the one of the model's implicit steps,
     * so that an integrator may take either.
     */
    template <typename State>
    class ExplicitModel
    {
    public:
      virtual ~ExplicitModel() = default;

      /** The longest stable explicit step of the model [s]. */
      virtual double
      stable_step() const = 0;

      /**
       * One explicit step of length tau (at most stable_step()) from `old`
       * at time t; no value if it failed (non-finite values; the reason in
       * the model's last failure).
       */
      virtual std::optional<State>
      explicit_step(const State &old, double t, double tau) = 0;

      /** Why this model cannot take explicit steps; empty: it can. */
      virtual std::string
      explicit_refusal() const
      {
        return {};
      }
    };
  } // namespace time
} // namespace rsfcycle

#endif
