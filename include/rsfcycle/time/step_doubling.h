// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_time_step_doubling_h
#define rsfcycle_time_step_doubling_h

#include <algorithm>
#include <functional>
#include <optional>
#include <rsfcycle/format.h>
#include <rsfcycle/time/integrator.h>
#include <string>

namespace rsfcycle
{
  namespace time
  {
    /**
     * Adaptive time stepping by step doubling (doc/model.md §4.3), generic in
     * the state type so that every scene (wedge, spring-slider) uses the same
     * controller. At time t with guess tau:
     *  - coarsening: compare two steps of tau with one of 2 tau; while the
     *    distance is <= tolerance, double tau;
     *  - if no coarsening happened, refinement: compare one step of tau with
     *    two of tau/2; while the distance is > tolerance, halve tau.
     * The accepted step is one step of the final tau; the second step of tau
     * computed for the comparison is kept and becomes the next accepted
     * candidate, so no accepted step is computed twice. A failed spatial
     * problem (the stepper returns no state) counts as "refine".
     */
    template <typename State>
    class StepDoubling : public Integrator<State>
    {
    public:
      /** One step of length tau from the given state at time t. */
      using Stepper = std::function<
        std::optional<State>(const State &, double t, double tau)>;
      /** The distance (14) between two candidate states. */
      using Distance = std::function<double(const State &, const State &)>;

      StepDoubling(Stepper      stepper,
                   Distance     distance,
                   const double tolerance,
                   const double initial_step,
                   const double min_step,
                   const double max_step,
                   const bool   adaptive = true)
        : stepper(std::move(stepper))
        , distance(std::move(distance))
        , tolerance(tolerance)
        , tau(initial_step)
        , min_step(min_step)
        , max_step(max_step)
        , adaptive(adaptive)
      {}

      /**
       * Advance `current` from time t by one accepted step (t is updated).
       * Throws StepSizeUnderflow if tau would fall below the minimum.
       */
      void
      advance(State &current, double &t, const double end_time) override
      {
        spatial_problems = 0;
        if (t + tau > end_time * (1 + 1e-12))
          {
            tau = end_time - t;
            forget();
          }
        if (!adaptive)
          {
            auto next = call(current, t, tau);
            if (!next)
              throw StepSizeUnderflow("spatial problem failed at fixed step");
            current = std::move(*next);
            t += tau;
            return;
          }

        if (!r1)
          r1 = call(current, t, tau);
        bool coarsened = false;
        if (r1)
          while (t + 2 * tau <= end_time * (1 + 1e-12) && 2 * tau <= max_step)
            {
              r2          = call(*r1, t + tau, tau);
              auto single = call(current, t, 2 * tau);
              if (!r2 || !single || !(distance(*r2, *single) <= tolerance))
                break;
              coarsened = true;
              tau *= 2;
              r1 = std::move(single);
              r2.reset();
            }
        if (!coarsened)
          for (;;)
            {
              auto half  = call(current, t, tau / 2);
              auto twice = half ? call(*half, t + tau / 2, tau / 2) :
                                  std::optional<State>();
              if (r1 && twice && distance(*r1, *twice) <= tolerance)
                break;
              if (tau / 2 < min_step)
                throw StepSizeUnderflow(
                  "step size " + format_number(tau / 2) +
                  " s below the minimum " + format_number(min_step) +
                  " s: the spatial problem " +
                  (half && twice ? "is not resolved to the tolerance" :
                                   "failed to converge"));
              tau /= 2;
              r1 = std::move(half);
              r2 = std::move(twice);
            }
        last_step = tau;
        current   = std::move(*r1);
        t += tau;
        r1 = std::move(r2);
        r2.reset();
      }

      /** The step size of the last accepted step. */
      double
      last_step_size() const override
      {
        return last_step;
      }

      /** The current guess for the next step. */
      double
      step_size() const override
      {
        return tau;
      }

      /** Set the guess (e.g. on restart); forgets cached candidates. */
      void
      set_step_size(const double new_tau)
      {
        tau = new_tau;
        forget();
      }

      /** The step size and the candidate. */
      IntegratorMemory<State>
      memory() const override
      {
        IntegratorMemory<State> memory;
        memory.controller = "step-doubling";
        memory.step_size  = tau;
        if (r1)
          memory.states.push_back(*r1);
        return memory;
      }

      void
      restore(const IntegratorMemory<State> &memory) override
      {
        tau = memory.step_size;
        r2.reset();
        if (memory.states.empty() || memory.controller != "step-doubling")
          r1.reset();
        else
          r1 = memory.states.front();
      }

      /** Spatial problems solved (stepper calls) in the last advance(). */
      unsigned int
      n_spatial_problems() const override
      {
        return spatial_problems;
      }

      /** Forget cached candidate steps (after the state was changed). */
      void
      forget()
      {
        r1.reset();
        r2.reset();
      }

    private:
      std::optional<State>
      call(const State &s, const double t0, const double dt)
      {
        ++spatial_problems;
        return stepper(s, t0, dt);
      }

      Stepper              stepper;
      Distance             distance;
      double               tolerance;
      double               tau;
      double               min_step;
      double               max_step;
      bool                 adaptive;
      double               last_step        = 0;
      unsigned int         spatial_problems = 0;
      std::optional<State> r1, r2;
    };
  } // namespace time
} // namespace rsfcycle

#endif
