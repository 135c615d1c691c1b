// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_time_integrator_h
#define rsfcycle_time_integrator_h

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rsfcycle
{
  namespace time
  {
    /** Thrown when the step size would fall below its minimum. */
    class StepSizeUnderflow : public std::runtime_error
    {
    public:
      using std::runtime_error::runtime_error;
    };

    /**
     * Thrown when a pore pressure leaves a fault node without compression
     * (sigma_n - p <= 0): rate-and-state friction has no solution there.
     * The run ends at its last accepted step with its files complete.
     */
    class CompressionLost : public std::runtime_error
    {
    public:
      using std::runtime_error::runtime_error;
    };

    /**
     * What an integrator carries from one advance() to the next, in a form
     * a checkpoint can hold: the step size, states it keeps (a step already
     * computed, or the history of accepted states) and numbers (their
     * times).
     */
    template <typename State>
    struct IntegratorMemory
    {
      std::string         controller; // the name of the step-size control
      double              step_size = 0;
      std::vector<State>  states;
      std::vector<double> values;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &controller &step_size &states &values;
      }
    };

    /**
     * A time integrator: advances a model's state by one accepted step. The
     * simulator uses only this interface. The implicit step of a model under
     * step-size control (StepDoubling, LocalExtrapolation: doc/model.md §4.3)
     * and an ODE integrator that chooses its own steps (ArkodeIntegrator)
     * are integrators; time/integrators.h makes the one that
     * `Time stepping/Integrator` names.
     */
    template <typename State>
    class Integrator
    {
    public:
      virtual ~Integrator() = default;

      /**
       * Advance `current` from time t by one accepted step (t is updated),
       * never beyond end_time. Throws StepSizeUnderflow if no step can be
       * accepted.
       */
      virtual void
      advance(State &current, double &t, double end_time) = 0;

      /** The step size of the last accepted step. */
      virtual double
      last_step_size() const = 0;

      /** The current guess for the next step. */
      virtual double
      step_size() const = 0;

      /** Spatial problems solved (stepper calls) in the last advance(). */
      virtual unsigned int
      n_spatial_problems() const = 0;

      /** What n_spatial_problems() counts, in the progress line. */
      virtual std::string
      work_unit() const
      {
        return "spatial problems";
      }

      /**
       * Everything the next advance() depends on: a checkpoint stores it so
       * that a resumed run repeats the uninterrupted one exactly.
       */
      virtual IntegratorMemory<State>
      memory() const = 0;

      /**
       * Restore the memory from a checkpoint; of another step-size
       * control's memory (a run resumed with another `Controller`), only
       * the step size.
       */
      virtual void
      restore(const IntegratorMemory<State> &memory) = 0;

      /**
       * A note on how the run is advanced (one line, such as a change of
       * step) that the last advance() raised and the simulator writes to
       * the log; empty if none. Each is returned once.
       */
      virtual std::string
      take_note()
      {
        return {};
      }

      /**
       * A warning about the run (one line, without "Warning:") that the
       * last advance() raised and the simulator writes to the log; empty
       * if none. Each is returned once.
       */
      virtual std::string
      take_warning()
      {
        return {};
      }

      /** Whether the integrator's state fits in a checkpoint. */
      virtual bool
      can_checkpoint() const
      {
        return true;
      }
    };
  } // namespace time
} // namespace rsfcycle

#endif
