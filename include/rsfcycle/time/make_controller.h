#ifndef rsfcycle_time_make_controller_h
#define rsfcycle_time_make_controller_h

#include <memory>
#include <rsfcycle/parameters.h>
#include <rsfcycle/time/local_extrapolation.h>
#include <rsfcycle/time/step_doubling.h>
#include <stdexcept>

namespace rsfcycle
{
  namespace time
  {
    /**
     * The controller named by `Time stepping/Controller` (fixed steps if
     * `Adaptive` is false), for any model: its stepper (which may start from
     * a guess), its distance (14) and how to combine three of its states
     * into a prediction. `error_order` is the power of the step size that
     * the local error grows with (time::ThetaScheme::local_error_order()).
     */
    template <typename State>
    std::unique_ptr<Controller<State>>
    make_controller(const TimeSteppingParameters                &ts,
                    typename LocalExtrapolation<State>::Stepper  stepper,
                    typename LocalExtrapolation<State>::Distance distance,
                    typename LocalExtrapolation<State>::Combine  combine,
                    const double                                 error_order)
    {
      if (ts.controller == "local-extrapolation" && ts.adaptive)
        return std::make_unique<LocalExtrapolation<State>>(
          std::move(stepper),
          std::move(distance),
          std::move(combine),
          ts.extrapolated_start,
          ts.step_sizes == "ladder",
          ts.doubling_threshold,
          ts.tolerance,
          ts.initial_step,
          ts.minimum_step,
          ts.maximum_step,
          error_order);
      if (ts.controller != "step-doubling" &&
          ts.controller != "local-extrapolation")
        throw std::invalid_argument(
          "Time stepping/Controller = " + ts.controller +
          ": allowed are step-doubling|local-extrapolation");
      return std::make_unique<StepDoubling<State>>(
        [stepper](const State &s, const double t, const double tau) {
          return stepper(s, t, tau, nullptr);
        },
        std::move(distance),
        ts.tolerance,
        ts.initial_step,
        ts.minimum_step,
        ts.maximum_step,
        ts.adaptive);
    }
  } // namespace time
} // namespace rsfcycle

#endif
