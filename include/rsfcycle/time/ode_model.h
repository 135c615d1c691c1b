// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_time_ode_model_h
#define rsfcycle_time_ode_model_h

#include <deal.II/lac/vector.h>
#include <string>

namespace rsfcycle
{
  namespace time
  {
    /**
     * What a model gives an ODE integrator (`Time stepping/Integrator =
     * arkode`): its state as the unknowns y of an ODE y' = f(t, y), the
     * right-hand side f, the scales of the unknowns for the absolute
     * tolerances, and how far apart the integrator's samples (the
     * simulator's accepted steps) may be.
     */
    template <typename State>
    class OdeModel
    {
    public:
      using Vector = dealii::Vector<double>;

      virtual ~OdeModel() = default;

      /**
       * Why the model with its parameters is no ODE an integrator can
       * solve (one line naming the entry); empty if it is one.
       */
      virtual std::string
      ode_refusal() const
      {
        return {};
      }

      /** The unknowns y of a state. */
      virtual Vector
      to_ode(const State &state) const = 0;

      /** The state of the unknowns y at time t. */
      virtual State
      from_ode(const Vector &y, double t) const = 0;

      /** dy = f(t, y); 0 if it is finite, 1 otherwise (ARKODE retries). */
      virtual int
      ode_rhs(double t, const Vector &y, Vector &dy) const = 0;

      /** The absolute tolerances of the unknowns for a relative one. */
      virtual Vector
      ode_absolute_tolerances(double relative) const = 0;

      /**
       * What to use where the ODE is too stiff for an explicit method (the
       * entries to set), for the messages of time::RungeKuttaIntegrator.
       */
      virtual std::string
      stiff_alternative() const
      {
        return "Time stepping/Integrator = implicit (the implicit step) or "
               "arkode (ARKODE's implicit method)";
      }

      /** The longest interval to the next sample after `state` [s]. */
      virtual double
      sample_interval(const State &state) const = 0;
    };
  } // namespace time
} // namespace rsfcycle

#endif
