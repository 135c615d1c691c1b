#ifndef rsfcycle_scenes_spring_slider_h
#define rsfcycle_scenes_spring_slider_h

#include <deal.II/base/parameter_handler.h>
#include <memory>
#include <optional>
#include <ostream>
#include <rsfcycle/friction/local_solve.h>
#include <rsfcycle/output/events.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/time/controller.h>
#include <rsfcycle/time/model.h>
#include <rsfcycle/time/rate_state_coupling.h>
#include <rsfcycle/time/run_loop.h>
#include <vector>

namespace rsfcycle
{
  namespace scenes
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
     * The spring-slider (issue 4): one block on a rate-and-state base,
     * loaded through a spring of stiffness k by a load point moving at
     * v_lp(t) (v0, optionally stepped to f v0 at a given time). All
     * quantities are per unit area of the base: mass m [kg/m^2], stiffness
     * k [Pa/m], stresses [Pa], radiation damping eta [Pa s/m]. The momentum
     * balance of the slip delta, V = delta',
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
     * It is time-stepped exactly like the wedge: trapezoidal Newmark in the
     * velocity (15), whose 1-DOF problem
     *   (2m/tau + eta + tau k/2) V_n + N mu(V_n) + C sign V_n = rhs
     * is solved exactly by friction::solve_local_problem<1>; the
     * rate/state fixed point (18) or explicit decoupling
     * (time::couple_rate_and_state); the closed-form state update (17);
     * and the controller of `Time stepping/Controller` with the distance
     * (14), which for one node is |alpha1 - alpha2|. It advances through the
     * same run loop (time::RunLoop) and writes the same files as the wedge,
     * with one contact node at position 0; it allocates no mesh, no multigrid
     * and no VTU writer. Event times are interpolated in log V between the
     * steps (output::EventDetector).
     *
     * Alternatively (`Integrator = arkode`) the same ODE is integrated by
     * SUNDIALS ARKODE (implicit, adaptive, relative tolerance = the
     * step-doubling tolerance), as an independent reference; it is a
     * time::Controller of the run loop whose steps are ARKODE's samples
     * (scenes/spring_slider_reference.cc). It writes no checkpoints.
     */
    class SpringSlider : public time::Model<SpringSliderState>
    {
    public:
      using State = SpringSliderState;

      /**
       * What a run returns besides its files: the run loop's summary, the
       * final state and friction, and the mean recurrence time of the
       * events after the first.
       */
      struct Summary : time::RunSummary
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
       * parameters.prm and the files of the run loop in the output
       * directory, progress and a summary to log.
       */
      Summary
      run(const ParameterHandler &prm, std::ostream &log, bool resume = false);

      /** The state at t = 0 (initial slip rate and state, slip 0). */
      State
      initial_state() const override;

      /** One node at position 0; slip, state and friction columns. */
      time::Layout
      layout() const override;

      time::Sample
      sample(const State &state) const override;

      /** No mesh (dimension 0), one node: the state size is 1. */
      output::CheckpointIdentity
      checkpoint_identity() const override
      {
        return {"spring-slider", 0, 1, 1};
      }

      /** Scene, stiffness, solver (or the ARKODE reference). */
      void
      describe(std::ostream &log) const override;

      /**
       * One Newmark step (15) of length tau from the state at time t, with
       * the rate/state coupling started from `guess` if given; nothing if
       * the coupling failed.
       */
      std::optional<State>
      newmark_step(const State &old,
                   double       t,
                   double       tau,
                   const State *guess = nullptr) const;

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
      friend class ArkodeReference;

      const Parameters    &parameters;
      friction::Parameters friction;
      const friction::Law &law;
      time::Coupling       coupling;
      std::string          integrator;
      double               mass;
      double               stiffness;
      double               normal_stress;
      double               cohesion;
      double               damping;
      double               v0;
      double               step_time;
      double               step_factor;
      double               initial_rate;
      double               initial_alpha;
      double               prestress;
      double               output_period;
      double               sample_spacing;
    };


    /**
     * The reference integrator of the spring-slider: the ODE integrated by
     * SUNDIALS ARKODE, as a time::Controller whose steps are its samples
     * (`Reference output period`, and at most `Reference sample spacing`
     * L / V apart). Dynamic (m > 0) in the variables (delta, V, alpha),
     * quasi-dynamic in (delta, log V, alpha), where V follows from
     * differentiating the force balance. Requires C = 0 (the cohesion makes
     * the ODE non-smooth at V = 0). Its spatial problems are ARKODE's
     * internal steps.
     */
    std::unique_ptr<time::Controller<SpringSliderState>>
    make_arkode_reference(const SpringSlider &slider);
  } // namespace scenes
} // namespace rsfcycle

#endif
