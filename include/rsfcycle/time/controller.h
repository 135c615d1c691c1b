#ifndef rsfcycle_time_controller_h
#define rsfcycle_time_controller_h

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
     * What a controller carries from one advance() to the next, in a form a
     * checkpoint can hold: the step size, states it keeps (a step already
     * computed, or the history of accepted states) and numbers (their
     * times).
     */
    template <typename State>
    struct ControllerMemory
    {
      std::string         controller; // the name of the controller
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
     * A step-size controller: advances a state by one accepted step. The
     * run loop (RunLoop) uses only this interface, so that step doubling
     * (MODEL.md §4.3), other controllers and, for the spring-slider, an
     * external ODE integrator plug in without touching the loop.
     */
    template <typename State>
    class Controller
    {
    public:
      virtual ~Controller() = default;

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

      /**
       * Everything the next advance() depends on: a checkpoint stores it so
       * that a resumed run repeats the uninterrupted one exactly.
       */
      virtual ControllerMemory<State>
      memory() const = 0;

      /**
       * Restore the memory from a checkpoint; of another controller's
       * memory (a run resumed with another `Controller`), only the step
       * size.
       */
      virtual void
      restore(const ControllerMemory<State> &memory) = 0;

      /** Whether the controller's state fits in a checkpoint. */
      virtual bool
      can_checkpoint() const
      {
        return true;
      }
    };
  } // namespace time
} // namespace rsfcycle

#endif
