// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_time_runge_kutta_h
#define rsfcycle_time_runge_kutta_h

#include <algorithm>
#include <arkode/arkode_arkstep.h>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <nvector/nvector_serial.h>
#include <rsfcycle/format.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/time/integrator.h>
#include <rsfcycle/time/ode_model.h>
#include <stdexcept>
#include <string>
#include <sundials/sundials_context.h>
#include <utility>

namespace rsfcycle
{
  namespace time
  {
    /**
     * The integrator of `Time stepping/Integrator = runge-kutta`: the
     * model's ODE (time::OdeModel) integrated by SUNDIALS ARKODE's
     * explicit embedded Dormand-Prince 5(4) pair (ARKStep, ERK table
     * ARKODE_DORMAND_PRINCE_7_4_5), adaptive with the relative tolerance
     * `Time stepping/Tolerance` and the model's absolute tolerances, steps
     * between `Minimum step` and `Maximum step`, the first one `Initial
     * step`. ARKODE is called in its one-step mode, so every accepted
     * Runge-Kutta step is an accepted step of the run (its records, events
     * and checkpoints), without the interpolated samples of
     * ArkodeIntegrator (deal.II's wrapper stops ARKODE at every sample,
     * which costs a step per sample). A checkpoint keeps the state and the
     * step size; a resumed run restarts ARKODE there (its error history is
     * lost, so the resumed steps agree with the uninterrupted run's to the
     * tolerance, not bitwise). A stage that is not finite (a step far too
     * large for the explicit method: it overflows before the error test
     * can reject it) restarts ARKODE with a tenth of the step and caps the
     * following steps at half the failed one, the cap growing by 5 % per
     * accepted step.
     */
    template <typename State>
    class RungeKuttaIntegrator : public Integrator<State>
    {
    public:
      using Vector = dealii::Vector<double>;

      RungeKuttaIntegrator(const TimeSteppingParameters &parameters,
                           const OdeModel<State>        &model)
        : parameters(parameters)
        , model(model)
        , next_step(parameters.initial_step)
        , ceiling(parameters.maximum_step)
      {
        if (const std::string why = model.ode_refusal(); !why.empty())
          throw std::invalid_argument(why);
        if (SUNContext_Create(nullptr, &context) != 0)
          throw std::runtime_error("SUNDIALS: no context");
      }

      ~RungeKuttaIntegrator() override
      {
        if (arkode != nullptr)
          ARKStepFree(&arkode);
        if (y != nullptr)
          N_VDestroy(y);
        if (tolerances != nullptr)
          N_VDestroy(tolerances);
        SUNContext_Free(&context);
      }

      RungeKuttaIntegrator(const RungeKuttaIntegrator &) = delete;
      RungeKuttaIntegrator &
      operator=(const RungeKuttaIntegrator &) = delete;

      /** One accepted Runge-Kutta step, never beyond end_time. */
      void
      advance(State &current, double &t, const double end_time) override
      {
        if (arkode == nullptr)
          start(current, t);
        // every 50th step, the stiffness at its end (the unknowns before it
        // give the first direction of the power iteration)
        const bool check = !warned && ++steps_since_check >= check_interval;
        if (check)
          previous = values();
        // (a fresh start evaluates the right-hand side once more, at t:
        // not counted, so that a resumed run writes the same counts)
        rhs_evaluations  = fresh ? -1 : 0;
        fresh            = false;
        double t_reached = t;
        int    flag      = 0;
        for (unsigned int restarts = 0;; ++restarts)
          {
            ARKStepSetStopTime(arkode, end_time);
            long int stages_before = 0, stages = 0, dummy = 0;
            ARKStepGetNumRhsEvals(arkode, &stages_before, &dummy);
            flag = ARKStepEvolve(arkode, end_time, y, &t_reached, ARK_ONE_STEP);
            ARKStepGetNumRhsEvals(arkode, &stages, &dummy);
            rhs_evaluations += stages - stages_before;
            if (failure)
              {
                const std::exception_ptr e = failure;
                failure                    = nullptr;
                std::rethrow_exception(e);
              }
            // A stage outside the region where the right-hand side is
            // finite (the model returned 1: a step far too large at the
            // onset of an event) ends ARKStep's step; restart from the last
            // accepted state with a tenth of the step, a few times.
            if (flag != ARK_UNREC_RHSFUNC_ERR || restarts == max_restarts)
              break;
            double attempted = next_step;
            ARKStepGetCurrentStep(arkode, &attempted);
            next_step = std::max(parameters.minimum_step,
                                 0.1 * std::min(attempted, next_step));
            ceiling   = std::max(parameters.minimum_step, 0.5 * attempted);
            start(current, t);
            --rhs_evaluations; // (its evaluation at t, as above)
            fresh     = false;
            t_reached = t;
          }
        if (flag < 0)
          {
            char *const       name_c = ARKStepGetReturnFlagName(flag);
            const std::string name(name_c);
            std::free(name_c);
            throw StepSizeUnderflow(
              "ARKODE's explicit Runge-Kutta found no step at t = " +
              format_number(t) + " s (" + name +
              "): the ODE is too stiff for an explicit method here; " +
              model.stiff_alternative() + " is the way out");
          }
        ARKStepGetCurrentStep(arkode, &next_step);
        if (ceiling < parameters.maximum_step)
          {
            ceiling =
              std::min(parameters.maximum_step, ceiling_growth * ceiling);
            ARKStepSetMaxStep(arkode, ceiling);
          }
        last_step = t_reached - t;
        t         = t_reached;
        current   = model.from_ode(values(), t);
        if (check)
          check_stiffness(t, end_time);
      }

      /**
       * Once per run, when the steps have been held by the explicit
       * method's stability rather than by its accuracy for 10 checks in a
       * row (500 steps) and the run would need more than a million of them
       * to its end (it crawls; BP1-QD's stability-limited interseismic
       * steps of months do not count): one line saying so and naming the
       * model's way out.
       */
      std::string
      take_warning() override
      {
        return std::exchange(warning, std::string());
      }

      double
      last_step_size() const override
      {
        return last_step;
      }

      double
      step_size() const override
      {
        return next_step;
      }

      /** The right-hand side evaluations (stages) of the last step. */
      unsigned int
      n_spatial_problems() const override
      {
        return rhs_evaluations;
      }

      std::string
      work_unit() const override
      {
        return "right-hand sides";
      }

      IntegratorMemory<State>
      memory() const override
      {
        IntegratorMemory<State> memory;
        memory.controller = "runge-kutta";
        memory.step_size  = next_step;
        memory.values     = {ceiling};
        return memory;
      }

      /** The step size; ARKODE restarts from the resumed state. */
      void
      restore(const IntegratorMemory<State> &memory) override
      {
        if (memory.step_size > 0)
          next_step = memory.step_size;
        if (memory.values.size() == 1 && memory.values[0] > 0)
          ceiling = memory.values[0];
        if (arkode != nullptr)
          ARKStepFree(&arkode);
        arkode = nullptr;
      }

    private:
      /**
       * h rho after the step that ended at t, rho the spectral radius of
       * the Jacobian of the right-hand side estimated by three steps of a
       * power iteration with finite differences, started from the step's
       * change of the unknowns, in the norm of the error test (weights
       * 1 / (atol + rtol |y|)). Dormand-Prince 5(4) is stable for h |lambda|
       * up to about 3.3 on the negative real axis; above 1.5 the step
       * counts as stability-limited (the estimate is a lower bound). Where
       * the eigenvalues are far off the real axis (an inertial
       * spring-slider) the estimate misses and the steps are rejected
       * instead: half of the steps since the last check rejected counts
       * too.
       */
      void
      check_stiffness(const double t, const double end_time)
      {
        steps_since_check  = 0;
        const Vector &y    = values();
        const double *a    = N_VGetArrayPointer(tolerances);
        const auto    norm = [&](const Vector &v) {
          double sum = 0;
          for (unsigned int j = 0; j < v.size(); ++j)
            {
              const double w =
                1. / (a[j] + parameters.tolerance * std::abs(y[j]));
              sum += v[j] * w * v[j] * w;
            }
          return std::sqrt(sum / std::max<unsigned int>(v.size(), 1));
        };
        Vector direction(y), f0(y.size()), f(y.size()), moved(y.size());
        direction -= previous;
        double rho  = 0;
        double size = norm(direction);
        if (size > 0 && model.ode_rhs(t, y, f0) == 0)
          for (unsigned int iteration = 0; iteration < 3; ++iteration)
            {
              // a perturbation of a hundredth of the tolerances
              const double epsilon = 1e-2 / size;
              moved                = y;
              moved.add(epsilon, direction);
              if (model.ode_rhs(t, moved, f) != 0)
                break;
              f -= f0;
              f /= epsilon; // J d
              const double image = norm(f);
              rho                = image / size;
              if (!(rho > 0))
                break;
              direction = f;
              size      = image;
            }
        // the error-test failures since the last check (ARKStep counts
        // from its last start)
        long int fails = 0;
        ARKStepGetNumErrTestFails(arkode, &fails);
        const long int rejected =
          fails >= fails_at_check ? fails - fails_at_check : fails;
        fails_at_check = fails;
        window_rejected += rejected;
        // held by stability, or rejecting every other step, and more than
        // a million such steps to go
        if ((last_step * rho > 1.5 || 2 * rejected >= check_interval) &&
            end_time - t > 1e6 * last_step)
          ++limited_checks;
        else
          {
            limited_checks  = 0;
            window_rejected = 0;
          }
        if (limited_checks >= 10)
          {
            warned  = true;
            warning = "the explicit Runge-Kutta has crawled for the last " +
                      std::to_string(10 * check_interval) +
                      " steps, held by stability or rejecting its steps, "
                      "not by accuracy (step " +
                      format_number(last_step) +
                      " s at t = " + format_number(t) +
                      " s, h |lambda| about " + format_number(last_step * rho) +
                      ", " + std::to_string(window_rejected) +
                      " steps rejected): the ODE is stiff here; " +
                      model.stiff_alternative() + " is the way out";
          }
      }

      /** ARKStep with the Dormand-Prince table from the state at t. */
      void
      start(const State &current, const double t)
      {
        const Vector y0 = model.to_ode(current);
        const Vector a  = model.ode_absolute_tolerances(parameters.tolerance);
        if (arkode != nullptr)
          ARKStepFree(&arkode);
        fresh          = true;
        fails_at_check = 0;
        if (y != nullptr)
          N_VDestroy(y);
        if (tolerances != nullptr)
          N_VDestroy(tolerances);
        y          = N_VNew_Serial(y0.size(), context);
        tolerances = N_VNew_Serial(y0.size(), context);
        std::copy(y0.begin(), y0.end(), N_VGetArrayPointer(y));
        std::copy(a.begin(), a.end(), N_VGetArrayPointer(tolerances));
        work.reinit(y0.size());
        work_rate.reinit(y0.size());

        arkode =
          ARKStepCreate(&RungeKuttaIntegrator::rhs, nullptr, t, y, context);
        if (arkode == nullptr)
          throw std::runtime_error("ARKODE: ARKStepCreate failed");
        ARKStepSetUserData(arkode, this);
        ARKStepSetErrFile(arkode, nullptr);
        ARKStepSVtolerances(arkode, parameters.tolerance, tolerances);
        ARKStepSetTableNum(arkode,
                           ARKODE_DIRK_NONE,
                           ARKODE_DORMAND_PRINCE_7_4_5);
        ARKStepSetInitStep(arkode, next_step);
        ARKStepSetMinStep(arkode, parameters.minimum_step);
        ARKStepSetMaxStep(arkode, ceiling);
        ARKStepSetMaxErrTestFails(arkode, 20);
        // A step size control without memory (the I controller, and the
        // first step's growth limited like every other's): the step after
        // a restart (resume, or the retry above) is the step the
        // uninterrupted run takes, so that a resumed run repeats it
        // exactly.
        ARKStepSetAdaptivityMethod(arkode, 2, 1, 0, nullptr);
        ARKStepSetMaxFirstGrowth(arkode, 20.);
      }

      /** The current unknowns as a deal.II vector. */
      const Vector &
      values()
      {
        const double *data = N_VGetArrayPointer(y);
        std::copy(data, data + work.size(), work.begin());
        return work;
      }

      /** ARKODE's right-hand side: the model's, through deal.II vectors. */
      static int
      rhs(const realtype t, N_Vector yy, N_Vector ydot, void *user_data)
      {
        auto         &self = *static_cast<RungeKuttaIntegrator *>(user_data);
        const double *in   = N_VGetArrayPointer(yy);
        std::copy(in, in + self.work.size(), self.work.begin());
        int status = 1;
        try
          {
            status = self.model.ode_rhs(t, self.work, self.work_rate);
          }
        catch (...)
          {
            self.failure = std::current_exception();
            return -1;
          }
        std::copy(self.work_rate.begin(),
                  self.work_rate.end(),
                  N_VGetArrayPointer(ydot));
        return status;
      }

      const TimeSteppingParameters &parameters;
      const OdeModel<State>        &model;
      SUNContext                    context    = nullptr;
      void                         *arkode     = nullptr;
      N_Vector                      y          = nullptr;
      N_Vector                      tolerances = nullptr;
      Vector                        work, work_rate;
      std::exception_ptr            failure;
      double                        next_step       = 0;
      double                        last_step       = 0;
      int                           rhs_evaluations = 0;
      bool                          fresh           = false;
      /** The stiffness check (check_stiffness()). */
      static constexpr unsigned int check_interval    = 50;
      unsigned int                  steps_since_check = 0, limited_checks = 0;
      long int                      fails_at_check = 0, window_rejected = 0;
      bool                          warned = false;
      Vector                        previous;
      std::string                   warning;
      /** Restarts of one advance() after a non-finite right-hand side. */
      static constexpr unsigned int max_restarts = 8;
      /**
       * The largest step ARKODE may try [s]: half the step whose stage went
       * non-finite, growing by ceiling_growth per accepted step back to
       * `Maximum step`. Without it ARKODE's controller, which knows
       * nothing of the failure, grows the step straight back to the size
       * that failed, and every step is tried twice (BP5-QD's interseismic
       * steps, where an explicit stage of a stiff step overflows before
       * the error test can reject it).
       */
      double                  ceiling        = 0;
      static constexpr double ceiling_growth = 1.05;
    };
  } // namespace time
} // namespace rsfcycle

#endif
