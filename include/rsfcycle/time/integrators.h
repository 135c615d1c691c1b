// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_time_integrators_h
#define rsfcycle_time_integrators_h

#include <memory>
#include <rsfcycle/parameters.h>
#include <rsfcycle/time/arkode.h>
#include <rsfcycle/time/explicit_model.h>
#include <rsfcycle/time/explicit_steps.h>
#include <rsfcycle/time/implicit_model.h>
#include <rsfcycle/time/integrator.h>
#include <rsfcycle/time/model.h>
#include <rsfcycle/time/ode_model.h>
#include <rsfcycle/time/runge_kutta.h>
#include <rsfcycle/time/step_size_control.h>
#include <rsfcycle/time/switching.h>
#include <stdexcept>
#include <string>

namespace rsfcycle
{
  namespace time
  {
    /**
     * The part of the model an integrator needs (an ImplicitModel, an
     * OdeModel), or one line naming the entry if the model has none.
     */
    template <typename Interface, typename State>
    Interface &
    model_as(Model<State>                            &model,
             const TimeSteppingParameters::Integrator integrator)
    {
      if (auto *part = dynamic_cast<Interface *>(&model))
        return *part;
      throw std::invalid_argument(
        "Time stepping/Integrator = " + name_of(integrator) + ": this model (" +
        model.checkpoint_identity().scene + ") cannot be integrated that way");
    }


    /** The integrator of `Time stepping/Integrator` for the model. */
    template <typename State>
    std::unique_ptr<Integrator<State>>
    make_integrator(const Parameters &parameters, Model<State> &model)
    {
      using Kind      = TimeSteppingParameters::Integrator;
      const Kind name = parameters.time_stepping.integrator;
      switch (name)
        {
          case Kind::implicit:
            return make_step_size_control(parameters.time_stepping,
                                          model_as<ImplicitModel<State>>(model,
                                                                         name));
          case Kind::arkode:
            return std::make_unique<ArkodeIntegrator<State>>(
              parameters, model_as<OdeModel<State>>(model, name));
          case Kind::runge_kutta:
            return std::make_unique<RungeKuttaIntegrator<State>>(
              parameters.time_stepping, model_as<OdeModel<State>>(model, name));
          case Kind::explicit_steps:
            return std::make_unique<ExplicitSteps<State>>(
              model_as<ExplicitModel<State>>(model, name),
              parameters.time_stepping.courant_number);
          case Kind::implicit_explicit:
            return std::make_unique<Switching<State>>(
              parameters.time_stepping,
              model_as<ImplicitModel<State>>(model, name),
              model_as<ExplicitModel<State>>(model, name));
        }
      throw std::logic_error("make_integrator: a Kind without its case");
    }
  } // namespace time
} // namespace rsfcycle

#endif
