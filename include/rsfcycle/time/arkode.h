// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_time_arkode_h
#define rsfcycle_time_arkode_h

#include <algorithm>
#include <arkode/arkode_arkstep.h>
#include <cmath>
#include <deal.II/sundials/arkode.h>
#include <memory>
#include <rsfcycle/parameters.h>
#include <rsfcycle/time/integrator.h>
#include <rsfcycle/time/ode_model.h>
#include <stdexcept>

namespace rsfcycle
{
  namespace time
  {
    /**
     * The integrator of `Time stepping/Integrator = arkode`: the model's ODE
     * (time::OdeModel) integrated by SUNDIALS ARKODE, implicit and adaptive
     * with the relative tolerance `Time stepping/Tolerance` and the model's
     * absolute tolerances; ARKODE starts at a step of 1e-6 s and goes down
     * to 1e-14 s. Its accepted steps for the simulator are samples of the
     * solution (ARKODE interpolates between its own steps) at most the
     * model's sample interval apart; its spatial problems are ARKODE's
     * internal steps. It writes no checkpoints.
     */
    template <typename State>
    class ArkodeIntegrator : public Integrator<State>
    {
    public:
      using Vector = dealii::Vector<double>;

      ArkodeIntegrator(const Parameters      &parameters,
                       const OdeModel<State> &model)
        : model(model)
      {
        if (const std::string why = model.ode_refusal(); !why.empty())
          throw std::invalid_argument(why);
        const double end_time = parameters.run.end_time;
        const double rtol     = parameters.time_stepping.tolerance;
        using ARKode          = dealii::SUNDIALS::ARKode<Vector>;
        typename ARKode::AdditionalData data(0.0,
                                             end_time,
                                             1e-6,
                                             end_time,
                                             1e-14,
                                             5,
                                             20,
                                             false,
                                             false,
                                             false,
                                             3,
                                             0.0,
                                             rtol);
        ode                    = std::make_unique<ARKode>(data);
        ode->implicit_function = [this](const double  t,
                                        const Vector &y,
                                        Vector &dy) { return rhs(t, y, dy); };
        // Jacobian-vector products by finite differences: only the Newton
        // iteration uses them, not the accuracy of the solution.
        ode->jacobian_times_vector = [this](const Vector &v,
                                            Vector       &Jv,
                                            const double  t,
                                            const Vector &y,
                                            const Vector &fy) {
          const double norm = v.l2_norm();
          if (norm == 0)
            {
              Jv = 0;
              return 0;
            }
          const double h = 1e-7 * std::max(1., y.l2_norm()) / norm;
          Vector       yh(y), fh(y.size());
          yh.add(h, v);
          const int err = rhs(t, yh, fh);
          for (unsigned int i = 0; i < Jv.size(); ++i)
            Jv[i] = (fh[i] - fy[i]) / h;
          return err;
        };
        abs_tol                   = model.ode_absolute_tolerances(rtol);
        ode->get_local_tolerances = [this]() -> Vector & { return abs_tol; };
        ode->custom_setup = [this](void *memory) { arkode_memory = memory; };
      }

      /**
       * Sample the solution at the model's sample interval after the
       * current state, never beyond end_time.
       */
      void
      advance(State &current, double &t, const double end_time) override
      {
        if (y.size() == 0)
          y = model.to_ode(current);
        const double dt =
          std::min(model.sample_interval(current), end_time - t);
        const double t_next =
          (end_time - t - dt < 1e-12 * end_time) ? end_time : t + dt;
        ode->solve_ode_incrementally(y, t_next);
        current   = model.from_ode(y, t_next);
        last_step = t_next - t;
        t         = t_next;

        long int steps = steps_so_far;
        if (arkode_memory != nullptr)
          ARKStepGetNumSteps(arkode_memory, &steps);
        internal_steps = steps - steps_so_far;
        steps_so_far   = steps;
      }

      double
      last_step_size() const override
      {
        return last_step;
      }

      double
      step_size() const override
      {
        return last_step;
      }

      unsigned int
      n_spatial_problems() const override
      {
        return internal_steps;
      }

      std::string
      work_unit() const override
      {
        return "internal steps";
      }

      IntegratorMemory<State>
      memory() const override
      {
        return {};
      }

      void
      restore(const IntegratorMemory<State> &) override
      {}

      bool
      can_checkpoint() const override
      {
        return false;
      }

    private:
      int
      rhs(const double t, const Vector &y, Vector &dy) const
      {
        return model.ode_rhs(t, y, dy);
      }

      const OdeModel<State>                            &model;
      Vector                                            y, abs_tol;
      std::unique_ptr<dealii::SUNDIALS::ARKode<Vector>> ode;
      void                                             *arkode_memory = nullptr;
      long int                                          steps_so_far  = 0;
      unsigned int                                      internal_steps = 0;
      double                                            last_step      = 0;
    };
  } // namespace time
} // namespace rsfcycle

#endif
