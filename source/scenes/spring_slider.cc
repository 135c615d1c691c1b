#include <cmath>
#include <deal.II/base/timer.h>
#include <iomanip>
#include <rsfcycle/output/files.h>
#include <rsfcycle/scenes/spring_slider.h>
#include <rsfcycle/time/make_controller.h>
#include <rsfcycle/time/run_loop.templates.h>
#include <stdexcept>

namespace rsfcycle
{
  namespace scenes
  {
    using dealii::Patterns::Anything;
    using dealii::Patterns::Double;
    using dealii::Patterns::Selection;

    namespace
    {
      /** Mean start-to-start time of the events after the first [s]. */
      double
      mean_recurrence_time(const std::vector<output::Event> &events)
      {
        if (events.size() < 3)
          return 0;
        // The first recurrence includes the transition from the initial
        // condition: average the later ones.
        return (events.back().start - events[1].start) / (events.size() - 2);
      }
    } // namespace


    void
    SpringSlider::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Spring slider");
      prm.declare_entry("Integrator",
                        "newmark",
                        Selection("newmark|arkode"),
                        "newmark: the scheme of the wedge (Newmark, "
                        "rate/state coupling, steps chosen by Time "
                        "stepping/Controller); arkode: the SUNDIALS ARKODE "
                        "reference with relative tolerance = Time "
                        "stepping/Tolerance (requires Cohesion = 0)");
      prm.declare_entry("Mass",
                        "0",
                        Double(0),
                        "Mass per unit area of the base m [kg/m^2]; 0 gives "
                        "the quasi-dynamic spring-slider (so does "
                        "Solver/Dynamics = quasi-static or quasi-dynamic)");
      prm.declare_entry("Stiffness",
                        "2.5e8",
                        Double(0),
                        "Spring stiffness per unit area k [Pa/m]; stick-slip "
                        "needs k below (b - a) |sigma_n| / L");
      prm.declare_entry("Normal stress",
                        "1e6",
                        Double(0),
                        "Magnitude of the normal stress |sigma_n| [Pa]");
      prm.declare_entry("Cohesion", "0", Double(0), "Cohesion C [Pa]");
      prm.declare_entry("Radiation damping",
                        "5e6",
                        Double(0),
                        "Radiation damping eta [Pa s/m] (e.g. G / (2 c_s))");
      prm.declare_entry("Load point velocity",
                        "1e-6",
                        Double(0),
                        "Load-point velocity v0 [m/s] (also the reference "
                        "rate of the event threshold)");
      prm.declare_entry("Velocity step time",
                        "1e300",
                        Double(0),
                        "At this time the load-point velocity jumps to "
                        "Velocity step factor * v0 [s]");
      prm.declare_entry("Velocity step factor",
                        "1",
                        Double(0),
                        "Factor of the load-point velocity step [-]");
      prm.declare_entry("a", "0.01", Double(0), "Direct effect a [-]");
      prm.declare_entry("b", "0.015", Double(0), "Evolution effect b [-]");
      prm.declare_entry("mu star",
                        "0.6",
                        Double(0),
                        "Reference friction coefficient mu* [-]");
      prm.declare_entry("V star",
                        "1e-6",
                        Double(1e-300),
                        "Reference slip rate V* [m/s]");
      prm.declare_entry("L",
                        "1e-5",
                        Double(1e-300),
                        "Characteristic slip distance L [m]");
      prm.declare_entry("Initial slip rate",
                        "2e-6",
                        Double(0),
                        "Slip rate V at t = 0 [m/s]");
      prm.declare_entry("Initial state",
                        "0",
                        Double(),
                        "State alpha = log(theta V*/L) at t = 0 [-]; 0 is "
                        "steady sliding at V*");
      prm.declare_entry("Reference output period",
                        "1",
                        Double(1e-300),
                        "ARKODE integrator only: the reference is sampled "
                        "(interpolated) at this interval [s]");
      prm.declare_entry("Reference sample spacing",
                        "0.01",
                        Double(0),
                        "ARKODE integrator only: samples are in addition at "
                        "most this multiple of L / V apart, to resolve event "
                        "starts and peak slip rates; 0: only the output "
                        "period (deal.II stops ARKODE at every sample, so "
                        "dense samples cost steps) [-]");
      prm.leave_subsection();
    }


    SpringSlider::SpringSlider(const Parameters &parameters,
                               ParameterHandler &prm)
      : parameters(parameters)
      , law(*parameters.solver.law)
      , coupling(parameters.solver.coupling == "explicit" ?
                   time::Coupling::explicit_decoupling :
                   time::Coupling::fixed_point)
    {
      prm.enter_subsection("Spring slider");
      integrator       = prm.get("Integrator");
      mass             = prm.get_double("Mass");
      stiffness        = prm.get_double("Stiffness");
      normal_stress    = prm.get_double("Normal stress");
      cohesion         = prm.get_double("Cohesion");
      damping          = prm.get_double("Radiation damping");
      v0               = prm.get_double("Load point velocity");
      step_time        = prm.get_double("Velocity step time");
      step_factor      = prm.get_double("Velocity step factor");
      friction.a       = prm.get_double("a");
      friction.b       = prm.get_double("b");
      friction.mu_star = prm.get_double("mu star");
      friction.v_star  = prm.get_double("V star");
      friction.L       = prm.get_double("L");
      initial_rate     = prm.get_double("Initial slip rate");
      initial_alpha    = prm.get_double("Initial state");
      output_period    = prm.get_double("Reference output period");
      sample_spacing   = prm.get_double("Reference sample spacing");
      prm.leave_subsection();
      // quasi-dynamic is quasi-static here: the damping is the scene's
      // `Radiation damping` in every mode
      if (parameters.solver.dynamics != "dynamic")
        mass = 0;
      if (mass == 0 && damping == 0 && stiffness == 0)
        throw std::invalid_argument(
          "Spring slider: Mass, Stiffness and Radiation damping are all 0");

      // Equilibrium at t = 0: no acceleration.
      prestress =
        normal_stress *
          law.friction_coefficient(friction, initial_alpha, initial_rate) +
        (initial_rate > 0 ? cohesion : 0.) + damping * initial_rate;
    }


    double
    SpringSlider::load_point_displacement(const double t) const
    {
      return v0 * t + (step_factor - 1) * v0 * std::max(0., t - step_time);
    }


    double
    SpringSlider::load_point_velocity(const double t) const
    {
      return t < step_time ? v0 : step_factor * v0;
    }


    double
    SpringSlider::friction_coefficient(const State &s) const
    {
      return law.friction_coefficient(friction, s.alpha, std::abs(s.velocity));
    }


    double
    SpringSlider::critical_stiffness() const
    {
      return (friction.b - friction.a) * normal_stress / friction.L;
    }


    SpringSlider::State
    SpringSlider::initial_state() const
    {
      State s;
      s.velocity = initial_rate;
      s.alpha    = initial_alpha;
      return s;
    }


    std::optional<SpringSlider::State>
    SpringSlider::newmark_step(const State &old,
                               const double t,
                               const double tau,
                               const State *guess) const
    {
      // (15) for one degree of freedom; the spring force at t + tau is
      // tau0 + k (u_lp - delta_n), delta_n = delta + tau/2 (V_old + V_n)
      // (theta = 1/2; time::ThetaScheme in general).
      const time::ThetaScheme scheme = parameters.solver.scheme();
      const auto              c      = scheme.step_coefficients(tau);
      const double A = c[0] * mass + c[1] * damping + c[2] * stiffness;
      const double rhs =
        prestress + stiffness * load_point_displacement(t + tau) -
        stiffness * scheme.displacement(old.slip, old.velocity, 0., tau) +
        (mass > 0 ?
           mass * scheme.inertia_from_old(old.velocity, old.acceleration, tau) :
           0.);

      friction::NodePotential phi;
      phi.law            = &law;
      phi.params         = friction;
      phi.normal_force   = normal_stress;
      phi.cohesion_force = cohesion;

      State      next       = old;
      double     v          = guess ? guess->velocity : old.velocity;
      double     alpha      = guess ? guess->alpha : old.alpha;
      const auto iterations = time::couple_rate_and_state(
        coupling,
        parameters.solver.fixed_point_tolerance,
        parameters.solver.max_fixed_point_iterations,
        scheme.theta,
        old.velocity,
        v,
        alpha,
        [&](const double a, double &x) {
          phi.set_state(a);
          const std::array<double, 1> guess = {{x}};
          x =
            friction::solve_local_problem<1>({{A}}, {{rhs}}, phi, &guess).x[0];
          return std::isfinite(x);
        },
        [&](const double v_new, const double weight_new, double &a) {
          const double V =
            std::abs((1 - weight_new) * old.velocity + weight_new * v_new);
          a = law.update_state(friction, old.alpha, V, tau);
        },
        [](const double a1, const double a2) { return std::abs(a1 - a2); });
      if (!iterations)
        return {};

      next.velocity               = v;
      next.alpha                  = alpha;
      next.fixed_point_iterations = *iterations;
      next.slip =
        scheme.displacement(old.slip, old.velocity, next.velocity, tau);
      next.acceleration = mass > 0 ? scheme.acceleration(old.velocity,
                                                         next.velocity,
                                                         old.acceleration,
                                                         tau) :
                                     0.;
      if (!std::isfinite(next.slip) || !std::isfinite(next.alpha) ||
          !std::isfinite(next.acceleration))
        return {};
      return next;
    }


    time::Layout
    SpringSlider::layout() const
    {
      time::Layout layout;
      layout.positions               = {0.};
      layout.weights                 = {1.}; // per unit area
      layout.observation_names       = {"slip_m",
                                        "slip_rate_m_per_s",
                                        "state_alpha",
                                        "friction_coefficient"};
      layout.convergence_rate        = v0;
      layout.interpolate_event_times = true;
      return layout;
    }


    time::Sample
    SpringSlider::sample(const State &s) const
    {
      time::Sample sample;
      sample.slip_rates                        = {std::abs(s.velocity)};
      sample.slip                              = {{{s.slip, 0.}}};
      sample.observations                      = {s.slip,
                                                  s.velocity,
                                                  s.alpha,
                                                  friction_coefficient(s)};
      sample.statistics.fixed_point_iterations = s.fixed_point_iterations;
      sample.shear_stresses = {normal_stress * friction_coefficient(s) +
                               (s.velocity != 0 ? cohesion : 0.)};
      sample.log10_states   = {friction.log_theta(s.alpha) / std::log(10.)};
      return sample;
    }


    void
    SpringSlider::describe(std::ostream &log) const
    {
      log << "Scene: spring-slider ("
          << (mass > 0 ? "dynamic" : "quasi-dynamic") << "), integrator "
          << integrator << "\n"
          << "Stiffness k / k_crit = " << stiffness / critical_stiffness()
          << " (k_crit = (b - a) |sigma_n| / L = " << critical_stiffness()
          << " Pa/m)\n";
      if (integrator == "arkode")
        log << "ARKODE reference: relative tolerance "
            << parameters.time_stepping.tolerance << ", "
            << (mass > 0 ? "variables (slip, V, alpha)" :
                           "variables (slip, log V, alpha)")
            << std::endl;
      else
        log << "Solver: " << parameters.solver.coupling << " coupling, "
            << law.name() << " law" << std::endl;
    }


    SpringSlider::Summary
    SpringSlider::run(const ParameterHandler &prm,
                      std::ostream           &log,
                      const bool              resume)
    {
      if (!resume)
        output::write_parameters(parameters.run.output_directory, prm);

      std::unique_ptr<time::Controller<State>> controller;
      if (integrator == "arkode")
        controller = make_arkode_reference(*this);
      else
        controller = time::make_controller<State>(
          parameters.time_stepping,
          [this](const State &s,
                 const double t0,
                 const double dt,
                 const State *guess) { return newmark_step(s, t0, dt, guess); },
          [](const State &s1, const State &s2) {
            return std::abs(s1.alpha - s2.alpha);
          },
          [](const std::array<const State *, 3> &s,
             const std::array<double, 3>        &w) {
            State p;
            for (unsigned int i = 0; i < 3; ++i)
              {
                p.slip += w[i] * s[i]->slip;
                p.velocity += w[i] * s[i]->velocity;
                p.acceleration += w[i] * s[i]->acceleration;
                p.alpha += w[i] * s[i]->alpha;
              }
            return p;
          },
          parameters.solver.scheme().local_error_order());

      dealii::TimerOutput  timer(log,
                                dealii::TimerOutput::never,
                                dealii::TimerOutput::wall_times);
      time::RunLoop<State> loop(parameters, *this, *controller, log, timer);

      Summary summary;
      static_cast<time::RunSummary &>(summary) = loop.run(resume);
      summary.final_state                      = loop.state();
      summary.final_friction       = friction_coefficient(loop.state());
      summary.mean_recurrence_time = mean_recurrence_time(summary.events);
      log << "Final: slip = " << std::setprecision(16)
          << summary.final_state.slip
          << " m, V = " << summary.final_state.velocity
          << " m/s, alpha = " << summary.final_state.alpha
          << ", mu = " << summary.final_friction
          << ", mean recurrence time = " << summary.mean_recurrence_time << " s"
          << std::endl;
      log << "Wall time of the time loop: " << std::setprecision(4)
          << summary.wall_time << " s" << std::endl;
      return summary;
    }
  } // namespace scenes
} // namespace rsfcycle

namespace rsfcycle
{
  namespace time
  {
    template class RunLoop<scenes::SpringSlider::State>;
  }
} // namespace rsfcycle
