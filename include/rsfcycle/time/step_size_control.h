// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_time_step_size_control_h
#define rsfcycle_time_step_size_control_h

#include <memory>
#include <rsfcycle/parameters.h>
#include <rsfcycle/time/implicit_model.h>
#include <rsfcycle/time/local_extrapolation.h>
#include <rsfcycle/time/step_doubling.h>

namespace rsfcycle
{
  namespace time
  {
    /**
     * The integrator of `Time stepping/Integrator = implicit`: the model's
     * implicit step under the step-size control named by `Time stepping/
     * Controller` (fixed steps if `Adaptive` is false), with the model's
     * error distance, prediction and error order.
     */
    template <typename State>
    std::unique_ptr<Integrator<State>>
    make_step_size_control(const TimeSteppingParameters &ts,
                           ImplicitModel<State>         &model)
    {
      using Control   = TimeSteppingParameters::Controller;
      const auto step = [&model](const State &s,
                                 const double t,
                                 const double tau,
                                 const State *guess) {
        return model.step(s, t, tau, guess);
      };
      const auto distance = [&model](const State &s1, const State &s2) {
        return model.error_distance(s1, s2);
      };
      if (ts.controller == Control::local_extrapolation && ts.adaptive)
        return std::make_unique<LocalExtrapolation<State>>(
          step,
          distance,
          [&model](const std::array<const State *, 3> &s,
                   const std::array<double, 3>        &w) {
            return model.predict(s, w);
          },
          ts.extrapolated_start,
          ts.ladder,
          ts.doubling_threshold,
          ts.tolerance,
          ts.initial_step,
          ts.minimum_step,
          ts.maximum_step,
          model.error_order());
      return std::make_unique<StepDoubling<State>>(
        [step](const State &s, const double t, const double tau) {
          return step(s, t, tau, nullptr);
        },
        distance,
        ts.tolerance,
        ts.initial_step,
        ts.minimum_step,
        ts.maximum_step,
        ts.adaptive);
    }
  } // namespace time
} // namespace rsfcycle

#endif
