// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_time_local_extrapolation_h
#define rsfcycle_time_local_extrapolation_h

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <rsfcycle/format.h>
#include <rsfcycle/time/integrator.h>
#include <string>
#include <vector>

namespace rsfcycle
{
  namespace time
  {
    /**
     * Step doubling with local extrapolation (`Time stepping/Controller =
     * local-extrapolation`). Every step of tau is computed once whole and
     * once as two halves; the distance (14) between the two results is the
     * error estimate of step doubling (doc/model.md §4.3). If it is at most the
     * tolerance, the two half steps (the more accurate result) are the next
     * two accepted steps (the second is returned by the next advance()
     * without a new solve); otherwise tau is halved and the step repeated.
     * After an accepted pair, tau is doubled if the estimate of the
     * doubled step, 2^p x estimate (the estimate grows as tau^p: p = 3
     * for the trapezoidal scheme, 2 for theta > 1/2), is at most
     * `doubling_threshold` x tolerance (`Time stepping/Doubling
     * threshold`, default 1). That is 3 spatial problems per two accepted
     * steps, against 3 - 4 per accepted step for the paper's controller,
     * whose coarsening test fails in most steps.
     *
     * With `ladder` (`Time stepping/Step sizes = ladder`, the default),
     * step sizes stay on the power-of-two ladder Initial step x 2^k, so
     * that step matrices, factorisations and level matrices are reused.
     * Without it, every pair and every rejection sets the next step from
     * the estimate, tau x min(2, max(0.2, 0.9 (tolerance/estimate)^(1/3)))
     * (at most 0.9 tau after a rejection, half of it after a failed
     * solve), and every new step size needs new matrices.
     *
     * With `extrapolate`, every spatial problem starts its fixed-point
     * iteration from a prediction instead of the old state: the whole step
     * from the quadratic extrapolation through the last three accepted
     * states, the first half from the quadratic through the last two and
     * the whole step's result, the second half from the whole step's
     * result.
     */
    template <typename State>
    class LocalExtrapolation : public Integrator<State>
    {
    public:
      /**
       * One step of length tau from the given state at time t, its
       * iterations started from `guess` if given.
       */
      using Stepper = std::function<std::optional<
        State>(const State &, double t, double tau, const State *guess)>;
      /** The distance (14) between two states. */
      using Distance = std::function<double(const State &, const State &)>;
      /**
       * The prediction sum_i w_i s_i from three states (the parts of a
       * state that a guess needs).
       */
      using Combine = std::function<State(const std::array<const State *, 3> &,
                                          const std::array<double, 3> &)>;

      LocalExtrapolation(Stepper      stepper,
                         Distance     distance,
                         Combine      combine,
                         const bool   extrapolate,
                         const bool   ladder,
                         const double doubling_threshold,
                         const double tolerance,
                         const double initial_step,
                         const double min_step,
                         const double max_step,
                         const double error_order = 3)
        : stepper(std::move(stepper))
        , distance(std::move(distance))
        , combine(std::move(combine))
        , extrapolate(extrapolate)
        , ladder(ladder)
        , doubling_threshold(doubling_threshold)
        , tolerance(tolerance)
        , tau(initial_step)
        , min_step(min_step)
        , max_step(max_step)
        , error_order(error_order)
      {}

      void
      advance(State &current, double &t, const double end_time) override
      {
        spatial_problems = 0;
        if (pending)
          {
            last_step = pending_step;
            accept(current, t, std::move(*pending), pending_step);
            pending.reset();
            return;
          }
        for (;;)
          {
            // the last step ends on the end time; the ladder step stays
            const bool   clamped = t + tau > end_time * (1 + 1e-12);
            const double dt      = clamped ? end_time - t : tau;
            double       estimate;
            if (step_pair(current, t, dt, estimate))
              {
                last_step = dt / 2;
                if (clamped)
                  return; // the step size of the interior steps stays
                if (!ladder)
                  tau = std::min(dt * factor(estimate, 2.), max_step);
                else if (std::pow(2., error_order) * estimate <=
                           doubling_threshold * tolerance &&
                         2 * tau <= max_step)
                  tau *= 2;
                return;
              }
            const double next =
              ladder ?
                dt / 2 :
                dt * (failed ? 0.5 : std::min(0.9, factor(estimate, 1.)));
            if (next < min_step)
              throw StepSizeUnderflow(
                "step size " + format_number(next) + " s below the minimum " +
                format_number(min_step) + " s: the spatial problem " +
                (failed ? "failed to converge" :
                          "is not resolved to the tolerance"));
            tau = next;
          }
      }

      double
      last_step_size() const override
      {
        return last_step;
      }

      double
      step_size() const override
      {
        return tau;
      }

      unsigned int
      n_spatial_problems() const override
      {
        return spatial_problems;
      }

      /**
       * The step size, the pending half step and the history: states =
       * {pending,} history; values = {pending step length or 0}, history
       * times.
       */
      IntegratorMemory<State>
      memory() const override
      {
        IntegratorMemory<State> memory;
        memory.controller = "local-extrapolation";
        memory.step_size  = tau;
        memory.values     = {pending ? pending_step : 0.};
        if (pending)
          memory.states.push_back(*pending);
        memory.states.insert(memory.states.end(),
                             history.begin(),
                             history.end());
        memory.values.insert(memory.values.end(),
                             history_times.begin(),
                             history_times.end());
        return memory;
      }

      void
      restore(const IntegratorMemory<State> &memory) override
      {
        tau = memory.step_size;
        pending.reset();
        history.clear();
        history_times.clear();
        if (memory.controller != "local-extrapolation")
          return;
        pending_step = memory.values.empty() ? 0. : memory.values[0];
        auto state   = memory.states.begin();
        if (pending_step > 0)
          pending = *state++;
        history.assign(state, memory.states.end());
        history_times.assign(memory.values.begin() +
                               (memory.values.empty() ? 0 : 1),
                             memory.values.end());
      }

    private:
      /**
       * The free step sizes' factor 0.9 (tolerance/estimate)^(1/p) (the
       * estimate grows as tau^p, p = error_order), between 0.2 and
       * `largest`.
       */
      double
      factor(const double estimate, const double largest) const
      {
        if (!(estimate > 0))
          return largest;
        const double ratio = tolerance / estimate;
        return std::min(largest,
                        std::max(0.2,
                                 0.9 * (error_order == 3 ?
                                          std::cbrt(ratio) :
                                          std::pow(ratio, 1 / error_order))));
      }

      /**
       * The whole step of dt and its two halves; if they agree, accept the
       * first half and keep the second pending. `estimate` receives their
       * distance.
       */
      bool
      step_pair(State &current, double &t, const double dt, double &estimate)
      {
        std::optional<State> guess;
        if (extrapolate && history.size() == 2)
          guess = predict({{&history[0], &history[1], &current}},
                          {{history_times[0], history_times[1], t}},
                          t + dt);
        auto full = call(current, t, dt, guess ? &*guess : nullptr);
        if (extrapolate && full)
          guess = history.empty() ?
                    combine({{&current, &current, &*full}}, {{0., 0.5, 0.5}}) :
                    predict({{&history.back(), &current, &*full}},
                            {{history_times.back(), t, t + dt}},
                            t + dt / 2);
        auto half  = call(current, t, dt / 2, guess ? &*guess : nullptr);
        auto twice = half ? call(*half,
                                 t + dt / 2,
                                 dt / 2,
                                 (extrapolate && full) ? &*full : nullptr) :
                            std::nullopt;
        estimate   = (full && twice) ? distance(*full, *twice) : 1e300;
        if (!(estimate <= tolerance))
          return false;
        accept(current, t, std::move(*half), dt / 2);
        pending      = std::move(twice);
        pending_step = dt / 2;
        return true;
      }

      /** The quadratic through three states at times t3, evaluated at t. */
      State
      predict(const std::array<const State *, 3> &s,
              const std::array<double, 3>        &t3,
              const double                        t) const
      {
        std::array<double, 3> w;
        for (unsigned int i = 0; i < 3; ++i)
          {
            w[i] = 1;
            for (unsigned int j = 0; j < 3; ++j)
              if (j != i)
                w[i] *= (t - t3[j]) / (t3[i] - t3[j]);
          }
        return combine(s, w);
      }

      /** Move the current state into the history; advance. */
      void
      accept(State &current, double &t, State &&next, const double dt)
      {
        history.push_back(std::move(current));
        history_times.push_back(t);
        if (history.size() > 2)
          {
            history.erase(history.begin());
            history_times.erase(history_times.begin());
          }
        current = std::move(next);
        t += dt;
      }

      std::optional<State>
      call(const State &s, const double t0, const double dt, const State *guess)
      {
        ++spatial_problems;
        auto result = stepper(s, t0, dt, guess);
        failed      = !result.has_value();
        return result;
      }

      Stepper              stepper;
      Distance             distance;
      Combine              combine;
      bool                 extrapolate;
      bool                 ladder;
      double               doubling_threshold;
      double               tolerance;
      double               tau;
      double               min_step;
      double               max_step;
      double               error_order; // the estimate grows as tau^p
      double               last_step        = 0;
      unsigned int         spatial_problems = 0;
      bool                 failed           = false;
      std::vector<State>   history; // the accepted states before current
      std::vector<double>  history_times;
      std::optional<State> pending; // second half of the last pair
      double               pending_step = 0;
    };
  } // namespace time
} // namespace rsfcycle

#endif
