// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_time_switching_h
#define rsfcycle_time_switching_h

#include <algorithm>
#include <memory>
#include <rsfcycle/format.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/time/explicit_model.h>
#include <rsfcycle/time/explicit_steps.h>
#include <rsfcycle/time/implicit_model.h>
#include <rsfcycle/time/integrator.h>
#include <rsfcycle/time/step_size_control.h>
#include <string>

namespace rsfcycle
{
  namespace time
  {
    /**
     * `Time stepping/Integrator = implicit-explicit`: the model's implicit
     * step under the step-size control of `Controller` while the step it
     * allows is at least R = 16 explicit steps (`Courant number` x the
     * stable step, tau_e), the model's explicit step while it is not. An
     * implicit step solves the whole body (tens of multigrid cycles, each
     * some stiffness products), an explicit one applies the stiffness once:
     * R is the least number of explicit steps an implicit step must stand
     * for. Both take the same state, so a change costs nothing. From
     * explicit steps the run returns when the implicit step's own error
     * estimate allows 2 R explicit steps at once (the hysteresis): after
     * 256 explicit steps a probe solves one implicit step of 2 R tau_e and
     * two of R tau_e and compares them as the step-size control does; if
     * the distance is within `Tolerance`, the two steps are accepted and
     * the control takes over at 2 R tau_e, else the interval to the next
     * probe doubles (at most 4096 steps). Every decision counts steps, so a run
     * is the same on any number of ranks and after a resume. A model without an
     * explicit step (viscous materials, a split fault) keeps the implicit step
     * and says so once in the log.
     */
    template <typename State>
    class Switching : public Integrator<State>
    {
    public:
      Switching(const TimeSteppingParameters &ts,
                ImplicitModel<State>         &implicit_model,
                ExplicitModel<State>         &explicit_model)
        : ts(ts)
        , implicit_model(implicit_model)
        , explicit_model(explicit_model)
        , refusal(explicit_model.explicit_refusal())
        , explicit_step(ts.courant_number *
                        (refusal.empty() ? explicit_model.stable_step() : 0.))
        , implicit(make_step_size_control(ts, implicit_model))
      {
        if (refusal.empty())
          explicit_steps =
            std::make_unique<ExplicitSteps<State>>(explicit_model,
                                                   ts.courant_number);
        else
          note = "implicit steps only: " + refusal;
      }

      void
      advance(State &current, double &t, const double end_time) override
      {
        if (!explicit_mode)
          {
            implicit->advance(current, t, end_time);
            last = implicit->last_step_size();
            work = implicit->n_spatial_problems();
            if (refusal.empty() &&
                implicit->step_size() < ratio * explicit_step && t < end_time)
              {
                explicit_mode = true;
                interval = countdown = first_interval;
                note = "explicit steps of " + format_number(explicit_step) +
                       " s from t = " + format_number(t) +
                       " s (the implicit step would take " +
                       format_number(implicit->step_size()) + " s)";
              }
            return;
          }
        work = 0;
        if (countdown == 0 && probe(current, t, end_time))
          return;
        explicit_steps->advance(current, t, end_time);
        last = explicit_steps->last_step_size();
        work += 1;
        if (countdown > 0)
          --countdown;
      }

      double
      last_step_size() const override
      {
        return last;
      }

      double
      step_size() const override
      {
        return explicit_mode ? explicit_step : implicit->step_size();
      }

      unsigned int
      n_spatial_problems() const override
      {
        return work;
      }

      std::string
      work_unit() const override
      {
        return explicit_mode ? "spatial problems and explicit steps" :
                               "spatial problems";
      }

      /**
       * "switching/" and the implicit control's name; values: whether the
       * run takes explicit steps, the steps to the next probe, the
       * interval, then the control's values.
       */
      IntegratorMemory<State>
      memory() const override
      {
        IntegratorMemory<State> memory;
        if (!explicit_mode)
          memory = implicit->memory();
        memory.controller = "switching/" + memory.controller;
        memory.values.insert(memory.values.begin(),
                             {explicit_mode ? 1. : 0.,
                              static_cast<double>(countdown),
                              static_cast<double>(interval)});
        return memory;
      }

      void
      restore(const IntegratorMemory<State> &memory) override
      {
        const std::string prefix = "switching/";
        if (memory.controller.rfind(prefix, 0) != 0 || memory.values.size() < 3)
          {
            implicit->restore(memory);
            return;
          }
        explicit_mode = memory.values[0] != 0;
        countdown     = static_cast<unsigned int>(memory.values[1]);
        interval      = static_cast<unsigned int>(memory.values[2]);
        if (!explicit_mode)
          {
            IntegratorMemory<State> inner = memory;
            inner.controller = memory.controller.substr(prefix.size());
            inner.values.erase(inner.values.begin(), inner.values.begin() + 3);
            implicit->restore(inner);
          }
      }

      std::string
      take_note() override
      {
        std::string result;
        std::swap(result, note);
        return result;
      }

    private:
      /**
       * One implicit step of 2 R tau_e against two of R tau_e from
       * `current`; within Tolerance: the two accepted, the control
       * restarted at 2 R tau_e, true. Else the next probe later, false.
       */
      bool
      probe(State &current, double &t, const double end_time)
      {
        const double tau = 2 * ratio * explicit_step;
        if (t + tau > end_time)
          return false;
        const auto full = implicit_model.step(current, t, tau, nullptr);
        auto       half = implicit_model.step(current, t, tau / 2, nullptr);
        auto       twice =
          half ? implicit_model.step(*half, t + tau / 2, tau / 2, nullptr) :
                       std::optional<State>();
        work = 3;
        if (full && twice &&
            implicit_model.error_distance(*full, *twice) <= ts.tolerance)
          {
            current = std::move(*twice);
            t += tau;
            last                           = tau / 2;
            explicit_mode                  = false;
            TimeSteppingParameters restart = ts;
            restart.initial_step           = tau;
            implicit = make_step_size_control(restart, implicit_model);
            note     = "implicit steps from t = " + format_number(t) +
                   " s (their error estimate allows " + format_number(tau) +
                   " s)";
            return true;
          }
        interval  = std::min(2 * interval, last_interval);
        countdown = interval;
        return false;
      }

      /** R: the explicit steps an implicit step must stand for. */
      static constexpr double       ratio          = 16;
      static constexpr unsigned int first_interval = 256;
      static constexpr unsigned int last_interval  = 4096;

      const TimeSteppingParameters      &ts;
      ImplicitModel<State>              &implicit_model;
      ExplicitModel<State>              &explicit_model;
      const std::string                  refusal;
      const double                       explicit_step;
      std::unique_ptr<Integrator<State>> implicit;
      /** The explicit steps (none if the model has no explicit step). */
      std::unique_ptr<ExplicitSteps<State>> explicit_steps;
      bool                                  explicit_mode = false;
      unsigned int                          countdown     = 0;
      unsigned int                          interval      = 0;
      double                                last          = 0;
      unsigned int                          work          = 0;
      std::string                           note;
    };
  } // namespace time
} // namespace rsfcycle

#endif
