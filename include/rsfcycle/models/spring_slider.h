// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_models_spring_slider_h
#define rsfcycle_models_spring_slider_h

#include <array>
#include <cmath>
#include <deal.II/base/parameter_handler.h>
#include <memory>
#include <optional>
#include <ostream>
#include <rsfcycle/friction/law.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/simulator/simulator.h>
#include <rsfcycle/time/implicit_model.h>
#include <rsfcycle/time/model.h>
#include <rsfcycle/time/ode_model.h>
#include <rsfcycle/time/time_scheme.h>
#include <vector>

namespace rsfcycle
{
  namespace models
  {
    using dealii::ParameterHandler;

    /** The state of the spring-slider's block after a step. */
    struct SpringSliderState
    {
      double       slip                   = 0; // delta [m]
      double       velocity               = 0; // V [m/s]
      double       acceleration           = 0; // V' [m/s^2]
      double       alpha                  = 0; // log(theta V*/L) [-]
      unsigned int fixed_point_iterations = 0;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &slip &velocity &acceleration &alpha &fixed_point_iterations;
      }
    };

    /**
     * The spring-slider: one block on a rate-and-state base, loaded through
     * a spring of stiffness k by a load point moving at v_lp(t) (v0,
     * optionally stepped to f v0 at a given time). All quantities are per
     * unit area of the base: mass m [kg/m^2], stiffness k [Pa/m], stresses
     * [Pa], radiation damping eta [Pa s/m]. The momentum balance of the
     * slip delta, V = delta',
     *
     *   m V' + eta V + N mu(|V|, alpha) sign V + C sign V
     *     = tau0 + k (u_lp(t) - delta),
     *
     * is the 1-DOF version of (1) + (10) (N = |sigma_n|, C the cohesion);
     * m = 0 gives the quasi-dynamic spring-slider with radiation damping.
     * The pre-stress tau0 is chosen so that the block is in equilibrium at
     * t = 0 with the initial slip rate and state (zero acceleration), and
     * the slip starts at 0.
     *
     * Its implicit step (time::ImplicitModel) is the continuum's: the time
     * scheme of `Solver/Time scheme` in the velocity (trapezoidal Newmark
     * (15) by default), whose 1-DOF problem
     *   (c_M m + eta + c_K k) V_n + N mu(V_n) + C sign V_n = rhs
     * is solved exactly by friction::solve_local_problem<1>; the rate/state
     * fixed point (18) or explicit decoupling (time::couple_rate_and_state);
     * the closed-form state update of the friction law; the distance (14),
     * which for one node is |alpha1 - alpha2|. As an ODE (time::OdeModel)
     * in (delta, V, alpha), quasi-dynamic in (delta, log V, alpha), where V'
     * follows from differentiating the force balance, it runs under SUNDIALS
     * ARKODE (`Time stepping/Integrator = arkode`, Cohesion = 0) as an
     * independent reference. The simulator writes the same files as for
     * the continuum, with one contact node at position 0; no mesh, no
     * multigrid and no VTU. Event times are interpolated in log V between
     * the steps (output::EventDetector).
     */
    class SpringSlider : public time::Model<SpringSliderState>,
                         public time::ImplicitModel<SpringSliderState>,
                         public time::OdeModel<SpringSliderState>
    {
    public:
      using State = SpringSliderState;

      /**
       * What a run returns besides its files: the simulator's summary, the
       * final state and friction, and the mean recurrence time of the
       * events after the first.
       */
      struct Summary : RunSummary
      {
        State  final_state          = {};
        double final_friction       = 0;
        double mean_recurrence_time = 0; // events 2.. [s]
      };

      static void
      declare_parameters(ParameterHandler &prm);

      /** Reads subsection "Spring slider" and the solver settings. */
      SpringSlider(const Parameters &parameters, ParameterHandler &prm);

      /**
       * Run to the end time (or resume from the run folder's checkpoint):
       * parameters.prm and the files of the simulator in the output
       * directory, progress and a summary to log.
       */
      Summary
      run(const ParameterHandler &prm, std::ostream &log, bool resume = false);

      /** @name The time::Model interface */
      /** @{ */
      /** The state at t = 0 (initial slip rate and state, slip 0). */
      State
      initial_state() const override;

      /** One node at position 0; slip, state and friction columns. */
      output::Layout
      layout() const override;

      output::Sample
      sample(const State &state) const override;

      /** No mesh (dimension 0), one node: the state size is 1. */
      output::CheckpointIdentity
      checkpoint_identity() const override
      {
        return {"spring-slider", 0, 1, 1};
      }

      /** Scene, stiffness, solver. */
      void
      describe(std::ostream &log) const override;
      /** @} */

      /** @name The time::ImplicitModel interface */
      /** @{ */
      /**
       * One implicit step of length tau from the state at time t, with the
       * rate/state coupling started from `guess` if given; nothing if the
       * coupling failed.
       */
      std::optional<State>
      step(const State &old,
           double       t,
           double       tau,
           const State *guess = nullptr) override;

      /** |alpha1 - alpha2|: the distance (14) of one node. */
      double
      error_distance(const State &s1, const State &s2) const override
      {
        return std::abs(s1.alpha - s2.alpha);
      }

      State
      predict(const std::array<const State *, 3> &states,
              const std::array<double, 3>        &weights) const override;

      double
      error_order() const override
      {
        return scheme->local_error_order();
      }
      /** @} */

      /** @name The time::OdeModel interface */
      /** @{ */
      std::string
      ode_refusal() const override;
      Vector
      to_ode(const State &state) const override;
      State
      from_ode(const Vector &y, double t) const override;
      int
      ode_rhs(double t, const Vector &y, Vector &dy) const override;
      /** rtol L for the slip, rtol v0 for V (rtol for log V), rtol for alpha.
       */
      Vector
      ode_absolute_tolerances(double relative) const override;
      /**
       * `Reference output period`, and at most `Reference sample spacing`
       * L / V, to resolve event starts and peak slip rates.
       */
      double
      sample_interval(const State &state) const override;
      /** @} */

      /** Load-point displacement u_lp(t) [m] and velocity v_lp(t) [m/s]. */
      double
      load_point_displacement(double t) const;
      double
      load_point_velocity(double t) const;

      /** The friction coefficient of a state. */
      double
      friction_coefficient(const State &s) const;

      /** The friction law (Solver/State law). */
      const friction::Law &
      friction_law() const
      {
        return law;
      }

      /** The rate-and-state parameters of the base. */
      const friction::Parameters &
      friction_parameters() const
      {
        return friction;
      }

      /** The critical stiffness (b - a) N / L [Pa/m]. */
      double
      critical_stiffness() const;

    private:
      const Parameters                             &parameters;
      friction::Parameters                          friction;
      const friction::Law                          &law;
      const std::unique_ptr<const time::TimeScheme> scheme;
      double                                        mass;
      double                                        stiffness;
      double                                        normal_stress;
      double                                        cohesion;
      double                                        damping;
      double                                        v0;
      double                                        step_time;
      double                                        step_factor;
      double                                        initial_rate;
      double                                        initial_alpha;
      double                                        prestress;
      double                                        output_period;
      double                                        sample_spacing;
    };
  } // namespace models
} // namespace rsfcycle

#endif
