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
     * allows is at least R explicit steps (`Courant number` x the
     * stable step, tau_e; R = `Explicit steps per implicit step`, 16 by
     * default), the model's explicit step while it is not. An implicit step
     * solves the whole body (tens of multigrid cycles, each some stiffness
     * products), an explicit one applies the stiffness twice: R is the
     * least number of explicit steps an implicit step must stand for. Both take
     * the same state, so a change costs nothing.
     *
     * The way back is a trial: after 256 explicit steps the run takes up to
     * 32 implicit steps under the control, started at 2 R tau_e, each with
     * at most 4 iterations of the rate-state fixed point (a step that needs
     * more is refused: it would not pay). Every one of them is accepted by
     * the error estimate, as in an implicit run; the
     * trial succeeds as soon as the controlled step reaches 2 R tau_e (the
     * hysteresis), and the run stays implicit. If the controlled step falls
     * below 4 tau_e, or after the 32 steps, the run returns to explicit
     * steps and the interval to the next trial doubles (at most 4096
     * steps). A trial is a window, not one comparison: the explicit
     * step damps only the shortest waves (Explicit scheme), so waves the
     * mesh traps after an event ring on, and the error estimate follows
     * them with short steps, until they are damped by the trials' implicit
     * steps (generalized-alpha with Spectral radius < 1 damps the waves
     * whose period is a few of its steps, also below R tau_e). Waves that
     * a coarsening mesh sends back for minutes need a sponge (Mesh
     * file/Sponge damping): without one they held every trial at 4 tau_e
     * after SEAS BP3-FD's rupture at 50 m.
     *
     * Every decision counts steps, so a run is the same on any number of
     * ranks and after a resume. A model without an explicit step (viscous
     * materials) keeps the implicit step and says so once in
     * the log.
     */
    template <typename State>
    class Switching : public Integrator<State>
    {
    public:
      Switching(const TimeSteppingParameters &ts,
                ImplicitModel<State>         &implicit_model,
                ExplicitModel<State>         &explicit_model)
        : ts(ts)
        , ratio(ts.implicit_ratio)
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
            if (trial > 0)
              end_trial_step(t);
            else if (refusal.empty() &&
                     implicit->step_size() < ratio * explicit_step &&
                     t < end_time)
              {
                interval = first_interval;
                to_explicit(t,
                            "the implicit step would take " +
                              format_number(implicit->step_size()) + " s");
              }
            return;
          }
        if (countdown == 0 && t + 2 * ratio * explicit_step <= end_time)
          {
            start_trial();
            advance(current, t, end_time);
            return;
          }
        explicit_steps->advance(current, t, end_time);
        last = explicit_steps->last_step_size();
        work = 1;
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
        return refusal.empty() ? "spatial problems and explicit steps" :
                                 "spatial problems";
      }

      /**
       * "switching/" and the implicit control's name; values: whether the
       * run takes explicit steps, the steps to the next trial, the
       * interval, the implicit steps left in a trial, then the control's
       * values.
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
                              static_cast<double>(interval),
                              static_cast<double>(trial)});
        return memory;
      }

      void
      restore(const IntegratorMemory<State> &memory) override
      {
        const std::string prefix = "switching/";
        if (memory.controller.rfind(prefix, 0) != 0 ||
            memory.values.size() < n_values)
          {
            implicit->restore(memory);
            return;
          }
        // (a checkpoint of explicit steps resumed by a run whose explicit
        // step is refused goes on with the implicit step, as the log says)
        explicit_mode = memory.values[0] != 0 && refusal.empty();
        countdown     = static_cast<unsigned int>(memory.values[1]);
        interval      = static_cast<unsigned int>(memory.values[2]);
        trial =
          refusal.empty() ? static_cast<unsigned int>(memory.values[3]) : 0;
        implicit_model.limit_fixed_point_iterations(
          trial > 0 ? trial_iterations : 0);
        if (memory.values[0] == 0)
          {
            IntegratorMemory<State> inner = memory;
            inner.controller = memory.controller.substr(prefix.size());
            inner.values.erase(inner.values.begin(),
                               inner.values.begin() + n_values);
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
      /** From implicit to explicit steps at `t`, `why` for the log. */
      void
      to_explicit(const double t, const std::string &why)
      {
        explicit_mode = true;
        countdown     = interval;
        note          = "explicit steps of " + format_number(explicit_step) +
               " s from t = " + format_number(t) + " s (" + why + ")";
      }

      /** The implicit control restarted at 2 R tau_e for a trial. */
      void
      start_trial()
      {
        explicit_mode = false;
        trial         = trial_steps;
        implicit_model.limit_fixed_point_iterations(trial_iterations);
        TimeSteppingParameters restart = ts;
        restart.initial_step           = 2 * ratio * explicit_step;
        implicit = make_step_size_control(restart, implicit_model);
      }

      /**
       * After a trial's implicit step: success once the controlled step
       * reaches 2 R tau_e; after the trial's last step without it, or once
       * the controlled step falls below R tau_e, back to explicit steps
       * with the interval doubled (not logged: the log
       * says when the run takes implicit steps again).
       */
      void
      end_trial_step(const double t)
      {
        if (implicit->step_size() >= 2 * ratio * explicit_step)
          {
            trial = 0;
            implicit_model.limit_fixed_point_iterations(0);
            note = "implicit steps from t = " + format_number(t) +
                   " s (their error estimate allows " +
                   format_number(implicit->step_size()) + " s)";
            return;
          }
        // (below trial_floor tau_e the implicit step damps nothing the
        // explicit step carries: the trial ends there)
        if (--trial > 0 && implicit->step_size() >= trial_floor * explicit_step)
          return;
        trial         = 0;
        explicit_mode = true;
        implicit_model.limit_fixed_point_iterations(0);
        interval  = std::min(2 * interval, last_interval);
        countdown = interval;
      }

      static constexpr unsigned int first_interval = 256;
      static constexpr unsigned int last_interval  = 4096;
      /**
       * A trial goes on while its controlled step is at least this many
       * explicit steps: generalized-alpha damps the waves whose period is
       * a few of its steps, which the explicit step carries undamped.
       */
      static constexpr double trial_floor = 4;
      /** The implicit steps of a trial at most. */
      static constexpr unsigned int trial_steps = 32;
      /**
       * The fixed-point iterations of a trial's step at most: a step whose
       * rate and state need more does not pay (in 3D, the 20 iterations of
       * a refused step cost thousands of explicit steps).
       */
      static constexpr unsigned int trial_iterations = 4;
      /** The values of memory() before the implicit control's. */
      static constexpr unsigned int n_values = 4;

      const TimeSteppingParameters &ts;
      /** R: the explicit steps an implicit step must stand for. */
      const double                       ratio;
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
      unsigned int                          trial         = 0;
      double                                last          = 0;
      unsigned int                          work          = 0;
      std::string                           note;
    };
  } // namespace time
} // namespace rsfcycle

#endif
