// SPDX-License-Identifier: LGPL-2.1-or-later
#include <cmath>
#include <deal.II/base/timer.h>
#include <iomanip>
#include <rsfcycle/friction/local_solve.h>
#include <rsfcycle/models/spring_slider.h>
#include <rsfcycle/output/files.h>
#include <rsfcycle/simulator/simulator.templates.h>
#include <rsfcycle/time/rate_state_coupling.h>
#include <rsfcycle/time/schemes.h>
#include <stdexcept>

namespace rsfcycle
{
  namespace models
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
                        "With Time stepping/Integrator = arkode: the "
                        "solution is sampled (interpolated) at this "
                        "interval [s]");
      prm.declare_entry("Reference sample spacing",
                        "0.01",
                        Double(0),
                        "With Time stepping/Integrator = arkode: samples are "
                        "in addition at "
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
      , scheme(time::make_scheme(parameters.solver, mass > 0))
    {
      prm.enter_subsection("Spring slider");
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
      if (parameters.solver.dynamics != SolverParameters::Dynamics::dynamic)
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
    SpringSlider::step(const State &old,
                       const double t,
                       const double tau,
                       const State *guess)
    {
      // The step (15) of the time scheme for one degree of freedom: the
      // spring force at the scheme's time is tau0 + k (u_lp - delta*),
      // delta* = delta_n + tau (d[0] V_n + tau d[1] V'_n) + c_K V (theta =
      // 1/2:
      // delta_n + tau/2 (V_n + V)).
      const auto   c = time::step_coefficients(*scheme, tau, mass > 0);
      const double A = c[0] * mass + c[1] * damping + c[2] * stiffness;
      const auto   d = scheme->known_displacement();
      const auto   m = scheme->known_inertia(tau);
      const double rhs =
        prestress +
        stiffness * load_point_displacement(t + scheme->load_fraction() * tau) -
        stiffness * (old.slip + tau * (d[0] * old.velocity +
                                       tau * d[1] * old.acceleration)) +
        (mass > 0 ? mass * (m[0] * old.velocity + m[1] * old.acceleration) :
                    0.);

      friction::NodePotential phi;
      phi.law            = &law;
      phi.params         = friction;
      phi.normal_force   = normal_stress;
      phi.cohesion_force = cohesion;

      double     w          = guess ? guess->velocity : old.velocity;
      double     alpha      = guess ? guess->alpha : old.alpha;
      const auto iterations = time::couple_rate_and_state(
        parameters.solver.coupling,
        parameters.solver.fixed_point_tolerance,
        parameters.solver.max_fixed_point_iterations,
        scheme->state_weight(),
        old.velocity,
        w,
        alpha,
        [&](const double a, double &x) {
          const double sigma = scheme->friction_state_weight();
          phi.set_state((1 - sigma) * old.alpha + sigma * a);
          const std::array<double, 1> guess = {{x}};
          x =
            friction::solve_local_problem<1>({{A}}, {{rhs}}, phi, &guess).x[0];
          return std::isfinite(x);
        },
        [&](const double w_new, const double weight_new, double &a) {
          const double V =
            std::abs((1 - weight_new) * old.velocity + weight_new * w_new);
          a = law.update_state(friction, old.alpha, V, tau);
        },
        [](const double a1, const double a2) { return std::abs(a1 - a2); });
      if (!iterations)
        return {};

      State      next             = old;
      const auto e                = scheme->new_velocity();
      const auto g                = scheme->new_acceleration(tau);
      const auto h                = scheme->new_displacement();
      next.velocity               = e[0] * w + e[1] * old.velocity;
      next.alpha                  = alpha;
      next.fixed_point_iterations = *iterations;
      next.acceleration = mass > 0 ? g[0] * (next.velocity - old.velocity) +
                                       g[1] * old.acceleration :
                                     0.;
      next.slip =
        old.slip + tau * (h[0] * old.velocity + h[1] * next.velocity) +
        tau * tau * (h[2] * old.acceleration + h[3] * next.acceleration);
      if (!std::isfinite(next.slip) || !std::isfinite(next.alpha) ||
          !std::isfinite(next.acceleration))
        return {};
      return next;
    }


    SpringSlider::State
    SpringSlider::predict(const std::array<const State *, 3> &s,
                          const std::array<double, 3>        &w) const
    {
      State p;
      for (unsigned int i = 0; i < 3; ++i)
        {
          p.slip += w[i] * s[i]->slip;
          p.velocity += w[i] * s[i]->velocity;
          p.acceleration += w[i] * s[i]->acceleration;
          p.alpha += w[i] * s[i]->alpha;
        }
      return p;
    }


    output::Layout
    SpringSlider::layout() const
    {
      output::Layout layout;
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


    output::Sample
    SpringSlider::sample(const State &s) const
    {
      output::Sample sample;
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
          << name_of(parameters.time_stepping.integrator) << "\n"
          << "Stiffness k / k_crit = " << stiffness / critical_stiffness()
          << " (k_crit = (b - a) |sigma_n| / L = " << critical_stiffness()
          << " Pa/m)\n"
          << "Solver: " << scheme->describe() << ", "
          << name_of(parameters.solver.coupling) << " coupling, " << law.name()
          << " law; as an ODE in "
          << (mass > 0 ? "(slip, V, alpha)" : "(slip, log V, alpha)")
          << std::endl;
    }


    std::string
    SpringSlider::ode_refusal() const
    {
      if (cohesion != 0)
        return "Spring slider/Cohesion = " + std::to_string(cohesion) +
               ": Time stepping/Integrator = arkode requires Cohesion = 0 "
               "(the cohesion makes the ODE non-smooth at V = 0)";
      return {};
    }


    SpringSlider::Vector
    SpringSlider::to_ode(const State &state) const
    {
      Vector y(3);
      y[0] = state.slip;
      y[1] = mass > 0 ? state.velocity : std::log(state.velocity);
      y[2] = state.alpha;
      return y;
    }


    SpringSlider::State
    SpringSlider::from_ode(const Vector &y, const double t) const
    {
      State s;
      s.slip     = y[0];
      s.velocity = mass > 0 ? y[1] : std::exp(y[1]);
      s.alpha    = y[2];
      Vector dy(3);
      ode_rhs(t, y, dy);
      s.acceleration = mass > 0 ? dy[1] : s.velocity * dy[1];
      return s;
    }


    int
    SpringSlider::ode_rhs(const double t, const Vector &y, Vector &dy) const
    {
      const bool   dynamic = mass > 0;
      const double V       = dynamic ? y[1] : std::exp(y[1]);
      const double Va      = std::abs(V);
      const double da      = law.state_rate(friction, y[2], Va);
      const double mu      = law.friction_coefficient(friction, y[2], Va);
      const double tau =
        prestress + stiffness * (load_point_displacement(t) - y[0]);
      dy[0] = V;
      dy[2] = da;
      if (dynamic)
        dy[1] =
          (tau - normal_stress * std::copysign(mu, V) - damping * V) / mass;
      else
        {
          // d/dt of tau0 + k(u_lp - delta) = N mu(V, alpha) + eta V, with
          // V dmu/dV and dmu/dalpha
          const auto sens = law.sensitivities(friction, y[2], Va);
          dy[1]           = (stiffness * (load_point_velocity(t) - V) -
                   normal_stress * sens[1] * da) /
                  (normal_stress * sens[0] + damping * V);
        }
      return std::isfinite(dy[0]) && std::isfinite(dy[1]) &&
                 std::isfinite(dy[2]) ?
               0 :
               1;
    }


    SpringSlider::Vector
    SpringSlider::ode_absolute_tolerances(const double relative) const
    {
      Vector tolerances(3);
      tolerances[0] = relative * friction.L;
      tolerances[1] = mass > 0 ? relative * v0 : relative;
      tolerances[2] = relative;
      return tolerances;
    }


    double
    SpringSlider::sample_interval(const State &state) const
    {
      return std::min(output_period,
                      sample_spacing > 0 ?
                        sample_spacing * friction.L /
                          std::max(std::abs(state.velocity), 1e-300) :
                        output_period);
    }


    SpringSlider::Summary
    SpringSlider::run(const ParameterHandler &prm,
                      std::ostream           &log,
                      const bool              resume)
    {
      if (!resume)
        output::write_parameters(parameters.run.output_directory, prm);

      dealii::TimerOutput timer(log,
                                dealii::TimerOutput::never,
                                dealii::TimerOutput::wall_times);
      Simulator<State>    simulator(parameters, *this, log, timer);

      Summary summary;
      static_cast<RunSummary &>(summary) = simulator.run(resume);
      summary.final_state                = simulator.state();
      summary.final_friction       = friction_coefficient(simulator.state());
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
  } // namespace models
} // namespace rsfcycle

namespace rsfcycle
{
  template class Simulator<models::SpringSlider::State>;
} // namespace rsfcycle
