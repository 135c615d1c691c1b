// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_time_explicit_steps_h
#define rsfcycle_time_explicit_steps_h

#include <algorithm>
#include <rsfcycle/format.h>
#include <rsfcycle/time/explicit_model.h>
#include <rsfcycle/time/integrator.h>
#include <stdexcept>
#include <string>

namespace rsfcycle
{
  namespace time
  {
    /**
     * `Time stepping/Integrator = explicit`: the model's explicit step,
     * every step `Courant number` times the model's stable step (the last
     * one shortened to end at the end time). A failed step (non-finite
     * values) ends the run with StepSizeUnderflow; the model's last failure
     * says why.
     */
    template <typename State>
    class ExplicitSteps : public Integrator<State>
    {
    public:
      ExplicitSteps(ExplicitModel<State> &model, const double courant_number)
        : model(model)
        , tau(courant_number * model.stable_step())
      {
        if (const std::string why = model.explicit_refusal(); !why.empty())
          throw std::invalid_argument("Time stepping/Integrator = explicit: " +
                                      why);
      }

      void
      advance(State &current, double &t, const double end_time) override
      {
        const double step = std::min(tau, end_time - t);
        auto         next = model.explicit_step(current, t, step);
        if (!next)
          throw StepSizeUnderflow(
            "the explicit step of " + format_number(step) +
            " s at t = " + format_number(t) + " s failed");
        current = std::move(*next);
        t += step;
        last = step;
      }

      double
      last_step_size() const override
      {
        return last;
      }

      double
      step_size() const override
      {
        return tau;
      }

      /** One explicit step per step (no spatial problem). */
      unsigned int
      n_spatial_problems() const override
      {
        return 1;
      }

      std::string
      work_unit() const override
      {
        return "explicit steps";
      }

      /** The step size only: the state is the accepted one. */
      IntegratorMemory<State>
      memory() const override
      {
        IntegratorMemory<State> memory;
        memory.controller = "explicit";
        memory.step_size  = tau;
        return memory;
      }

      void
      restore(const IntegratorMemory<State> &) override
      {}

    private:
      ExplicitModel<State> &model;
      const double          tau;
      double                last = 0;
    };
  } // namespace time
} // namespace rsfcycle

#endif
