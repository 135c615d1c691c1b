#include <algorithm>
#include <arkode/arkode_arkstep.h>
#include <chrono>
#include <cmath>
#include <deal.II/lac/vector.h>
#include <deal.II/sundials/arkode.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <rsfcycle/scenes/spring_slider.h>
#include <rsfcycle/time/step_doubling.h>
#include <stdexcept>

namespace rsfcycle
{
  namespace scenes
  {
    namespace
    {
      /** The last lines of a spring-slider run, the same for both integrators.
       */
      void
      print_final(std::ostream &log, const SpringSlider::Summary &summary)
      {
        log << "Final: slip = " << std::setprecision(16)
            << summary.final_state.slip
            << " m, V = " << summary.final_state.velocity
            << " m/s, alpha = " << summary.final_state.alpha
            << ", mu = " << summary.final_friction
            << ", mean recurrence time = " << summary.mean_recurrence_time
            << " s" << std::endl;
        log << "Wall time of the time loop: " << std::setprecision(4)
            << summary.wall_time << " s" << std::endl;
      }
    } // namespace

    using dealii::Patterns::Anything;
    using dealii::Patterns::Double;
    using dealii::Patterns::Selection;

    namespace
    {
      /**
       * Everything a run records per accepted step, shared by the Newmark
       * scheme and the ARKODE reference: the CSV row, the event detection
       * (start and end interpolated in log V between two samples, so that
       * the recurrence time does not depend on the step size more than the
       * solution does) and the statistics.
       */
      class Recorder
      {
      public:
        Recorder(const std::string &dir,
                 const double       v0,
                 const double       threshold,
                 const double       progress_interval,
                 std::ostream      &log)
          : series(dir + "/time-series.csv")
          , events_file(dir + "/events.csv")
          , v0(v0)
          , threshold(threshold)
          , progress_interval(progress_interval)
          , log(log)
          , wall_start(std::chrono::steady_clock::now())
          , last_progress(wall_start)
        {
          series << std::setprecision(12)
                 << "time,step size,fixed-point iterations,spatial problems,"
                    "slip rate,slip,state alpha,friction coefficient\n";
          events_file << std::setprecision(12)
                      << "event,start,end,duration,peak slip rate,slip,"
                         "recurrence time\n";
        }

        void
        record(const double               t,
               const double               dt,
               const SpringSlider::State &s,
               const double               mu,
               const unsigned int         problems,
               const double               end_time,
               SpringSlider::Summary     &summary)
        {
          series << t << "," << dt << "," << s.fixed_point_iterations << ","
                 << problems << "," << s.velocity << "," << s.slip << ","
                 << s.alpha << "," << mu << "\n";
          const double V    = std::abs(s.velocity);
          summary.peak_rate = std::max(summary.peak_rate, V);
          if (summary.steps > 0)
            {
              summary.min_step = std::min(summary.min_step, dt);
              summary.max_step = std::max(summary.max_step, dt);
            }
          else
            summary.min_step = summary.max_step = dt;
          ++summary.steps;
          summary.spatial_problems += problems;
          summary.max_fixed_point =
            std::max(summary.max_fixed_point, s.fixed_point_iterations);

          if (!in_event && V > threshold)
            {
              in_event = true;
              SpringSlider::Event e;
              e.start       = crossing(t_prev, V_prev, t, V);
              e.peak_rate   = V;
              slip_at_start = slip_prev + (s.slip - slip_prev) *
                                            (e.start - t_prev) /
                                            std::max(t - t_prev, 1e-300);
              e.start_slip = slip_at_start;
              summary.events.push_back(e);
              log << "    event " << summary.events.size()
                  << " starts at t = " << std::setprecision(8) << e.start
                  << " s" << std::endl;
            }
          else if (in_event)
            {
              auto &e     = summary.events.back();
              e.peak_rate = std::max(e.peak_rate, V);
              if (V <= threshold)
                {
                  in_event = false;
                  ++n_ended;
                  e.end = crossing(t_prev, V_prev, t, V);
                  const double slip_end =
                    slip_prev + (s.slip - slip_prev) * (e.end - t_prev) /
                                  std::max(t - t_prev, 1e-300);
                  e.slip = slip_end - slip_at_start - v0 * (e.end - e.start);
                  const std::size_t n = summary.events.size();
                  events_file
                    << n << "," << e.start << "," << e.end << ","
                    << e.end - e.start << "," << e.peak_rate << "," << e.slip
                    << ","
                    << (n > 1 ? e.start - summary.events[n - 2].start : 0.)
                    << "\n";
                }
            }
          t_prev    = t;
          V_prev    = V;
          slip_prev = s.slip;

          const auto   now = std::chrono::steady_clock::now();
          const double since =
            std::chrono::duration<double>(now - last_progress).count();
          if (since >= progress_interval)
            {
              last_progress = now;
              log << "*** Step " << summary.steps
                  << ": t = " << std::setprecision(6) << t << " s / "
                  << end_time << " s, dt = " << dt << " s, V = " << V / v0
                  << " v0, events = " << summary.events.size() << "\n"
                  << "    solver: " << s.fixed_point_iterations
                  << " fixed-point iterations, " << problems
                  << " spatial problems this step" << std::endl;
            }
        }

        void
        start(const double t, const SpringSlider::State &s)
        {
          t_prev    = t;
          V_prev    = std::abs(s.velocity);
          slip_prev = s.slip;
        }

        /** Whether @p stop_after events (0: never) have ended at time t;
         * if so, say so in the log. */
        bool
        events_done(const unsigned int stop_after, const double t) const
        {
          if (stop_after == 0 || n_ended < stop_after)
            return false;
          log << "*** Stop after events = " << stop_after
              << " reached: the run ends at t = " << t << " s" << std::endl;
          return true;
        }

        /** Wall time since construction [s]. */
        double
        wall_time() const
        {
          return std::chrono::duration<double>(
                   std::chrono::steady_clock::now() - wall_start)
            .count();
        }

      private:
        /** Time where V crosses the threshold, linear in log V. */
        double
        crossing(const double t0,
                 const double V0,
                 const double t1,
                 const double V1) const
        {
          const double l0 = std::log(std::max(V0, 1e-300)),
                       l1 = std::log(std::max(V1, 1e-300)),
                       lc = std::log(threshold);
          if (!(std::abs(l1 - l0) > 0))
            return t1;
          return t0 + (t1 - t0) * std::clamp((lc - l0) / (l1 - l0), 0., 1.);
        }

        std::ofstream                         series, events_file;
        double                                v0, threshold, progress_interval;
        std::ostream                         &log;
        bool                                  in_event      = false;
        unsigned int                          n_ended       = 0;
        double                                t_prev        = 0;
        double                                V_prev        = 0;
        double                                slip_prev     = 0;
        double                                slip_at_start = 0;
        std::chrono::steady_clock::time_point wall_start, last_progress;
      };


      /** Mean start-to-start time of the events after the first [s]. */
      double
      mean_recurrence_time(const std::vector<SpringSlider::Event> &events)
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
                        "step-doubling",
                        Selection("step-doubling|arkode"),
                        "step-doubling: the scheme of the wedge (Newmark, "
                        "rate/state coupling, step doubling); arkode: the "
                        "SUNDIALS ARKODE reference with relative tolerance "
                        "= the step-doubling Tolerance (requires "
                        "Cohesion = 0)");
      prm.declare_entry("Mass",
                        "0",
                        Double(0),
                        "Mass per unit area of the base m [kg/m^2]; 0 gives "
                        "the quasi-dynamic spring-slider (so does "
                        "Solver/Dynamics = quasi-static)");
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
      , state_law(friction::state_law_from_name(parameters.solver.state_law))
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
      if (parameters.solver.dynamics == "quasi-static")
        mass = 0;
      if (mass == 0 && damping == 0 && stiffness == 0)
        throw std::invalid_argument(
          "Spring slider: Mass, Stiffness and Radiation damping are all 0");

      // Equilibrium at t = 0: no acceleration.
      prestress = normal_stress * friction::friction_coefficient(friction,
                                                                 initial_alpha,
                                                                 initial_rate) +
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
      return friction::friction_coefficient(friction,
                                            s.alpha,
                                            std::abs(s.velocity));
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
                               const double tau) const
    {
      // (15) for one degree of freedom; the spring force at t + tau is
      // tau0 + k (u_lp - delta_n), delta_n = delta + tau/2 (V_old + V_n).
      const double A = 2 * mass / tau + damping + tau * stiffness / 2;
      const double rhs =
        prestress + stiffness * load_point_displacement(t + tau) -
        stiffness * (old.slip + tau / 2 * old.velocity) +
        (mass > 0 ? mass * (2 / tau * old.velocity + old.acceleration) : 0.);

      friction::NodePotential phi;
      phi.params         = friction;
      phi.normal_force   = normal_stress;
      phi.cohesion_force = cohesion;

      State      next       = old;
      double     v          = old.velocity;
      double     alpha      = old.alpha;
      const auto iterations = time::couple_rate_and_state(
        coupling,
        parameters.solver.fixed_point_tolerance,
        parameters.solver.max_fixed_point_iterations,
        old.velocity,
        v,
        alpha,
        [&](const double a, double &x) {
          phi.alpha = a;
          x = friction::solve_local_problem<1>({{A}}, {{rhs}}, phi).x[0];
          return std::isfinite(x);
        },
        [&](const double v_new, const double weight_new, double &a) {
          const double V =
            std::abs((1 - weight_new) * old.velocity + weight_new * v_new);
          a = friction::update_state(state_law, friction, old.alpha, V, tau);
        },
        [](const double a1, const double a2) { return std::abs(a1 - a2); });
      if (!iterations)
        return {};

      next.velocity               = v;
      next.alpha                  = alpha;
      next.fixed_point_iterations = *iterations;
      next.slip = old.slip + tau / 2 * (old.velocity + next.velocity);
      next.acceleration =
        mass > 0 ? 2 / tau * (next.velocity - old.velocity) - old.acceleration :
                   0.;
      if (!std::isfinite(next.slip) || !std::isfinite(next.alpha) ||
          !std::isfinite(next.acceleration))
        return {};
      return next;
    }


    SpringSlider::Summary
    SpringSlider::run(const ParameterHandler &prm, std::ostream &log)
    {
      const std::string dir = parameters.run.output_directory;
      std::filesystem::create_directories(dir);
      {
        std::ofstream out(dir + "/parameters.prm");
        prm.print_parameters(out, ParameterHandler::PRM);
      }
      log << "Scene: spring-slider ("
          << (mass > 0 ? "dynamic" : "quasi-dynamic") << "), integrator "
          << integrator << "\n"
          << "Stiffness k / k_crit = " << stiffness / critical_stiffness()
          << " (k_crit = (b - a) |sigma_n| / L = " << critical_stiffness()
          << " Pa/m)\n";
      if (integrator == "arkode")
        return integrate_reference(log);

      log << "Solver: " << parameters.solver.coupling << " coupling, "
          << parameters.solver.state_law << " law" << std::endl;

      const double              end_time = parameters.run.end_time;
      const auto               &ts       = parameters.time_stepping;
      time::StepDoubling<State> controller(
        [this](const State &s, const double t0, const double dt) {
          return newmark_step(s, t0, dt);
        },
        [](const State &s1, const State &s2) {
          return std::abs(s1.alpha - s2.alpha);
        },
        ts.tolerance,
        ts.initial_step,
        ts.minimum_step,
        ts.maximum_step,
        ts.adaptive);

      Recorder recorder(dir,
                        v0,
                        parameters.output.event_threshold * v0,
                        parameters.output.progress_interval,
                        log);
      Summary  summary;
      State    state = initial_state();
      double   t     = 0;
      recorder.start(t, state);
      log << "*** Time loop to t = " << end_time << " s" << std::endl;
      while (end_time - t > 1e-10 * end_time)
        {
          try
            {
              controller.advance(state, t, end_time);
            }
          catch (const time::StepSizeUnderflow &e)
            {
              log << "Error: at t = " << t << " s: " << e.what() << std::endl;
              throw;
            }
          recorder.record(t,
                          controller.last_step_size(),
                          state,
                          friction_coefficient(state),
                          controller.n_spatial_problems(),
                          end_time,
                          summary);
          if (recorder.events_done(parameters.run.stop_after_events, t))
            break;
        }
      summary.final_time           = t;
      summary.final_state          = state;
      summary.final_friction       = friction_coefficient(state);
      summary.mean_recurrence_time = mean_recurrence_time(summary.events);
      summary.wall_time            = recorder.wall_time();
      log << "Summary: " << summary.steps << " steps, "
          << summary.spatial_problems << " spatial problems, "
          << summary.events.size() << " events, step size " << summary.min_step
          << " s to " << summary.max_step << " s, max fixed-point iterations "
          << summary.max_fixed_point << std::endl;
      print_final(log, summary);
      return summary;
    }


    namespace
    {
      /** d alpha / dt of the state law at slip rate V >= 0. */
      double
      state_rate(const friction::StateLaw    law,
                 const friction::Parameters &p,
                 const double                alpha,
                 const double                V)
      {
        if (law == friction::StateLaw::ageing)
          return p.v_star / p.L * std::exp(-alpha) - V / p.L;
        return V > 0 ? -V / p.L * (alpha + std::log(V / p.v_star)) : 0.;
      }

      /**
       * s = 1/sqrt(1 + z^-2), z = V/(2 V_theta): with it
       * V dmu/dV = a s and dmu/dalpha = b s (in log space, no overflow).
       */
      double
      friction_sensitivity(const friction::Parameters &p,
                           const double                alpha,
                           const double                V)
      {
        if (!(V > 0))
          return 0;
        const double log_z = std::log(V / 2) - p.log_v_theta(alpha);
        if (log_z > 300)
          return 1;
        return 1 / std::sqrt(1 + std::exp(-2 * log_z));
      }
    } // namespace


    SpringSlider::Summary
    SpringSlider::integrate_reference(std::ostream &log)
    {
      using VectorType = dealii::Vector<double>;
      if (cohesion != 0)
        throw std::invalid_argument(
          "Spring slider: the ARKODE reference requires Cohesion = 0");
      const bool   dynamic  = mass > 0;
      const double end_time = parameters.run.end_time;
      const double rtol     = parameters.time_stepping.tolerance;
      log << "ARKODE reference: relative tolerance " << rtol << ", "
          << (dynamic ? "variables (slip, V, alpha)" :
                        "variables (slip, log V, alpha)")
          << std::endl;

      // y = (delta, V or log V, alpha); f(t, y) = y'.
      const auto rate_of = [&](const VectorType &y) {
        return dynamic ? y[1] : std::exp(y[1]);
      };
      const auto f = [&](const double t, const VectorType &y, VectorType &dy) {
        const double V  = rate_of(y);
        const double Va = std::abs(V);
        const double da = state_rate(state_law, friction, y[2], Va);
        const double mu = friction::friction_coefficient(friction, y[2], Va);
        const double tau =
          prestress + stiffness * (load_point_displacement(t) - y[0]);
        dy[0] = V;
        dy[2] = da;
        if (dynamic)
          dy[1] =
            (tau - normal_stress * std::copysign(mu, V) - damping * V) / mass;
        else
          {
            // d/dt of tau0 + k(u_lp - delta) = N mu(V, alpha) + eta V
            const double s = friction_sensitivity(friction, y[2], Va);
            dy[1]          = (stiffness * (load_point_velocity(t) - V) -
                     normal_stress * friction.b * s * da) /
                    (normal_stress * friction.a * s + damping * V);
          }
        return std::isfinite(dy[0]) && std::isfinite(dy[1]) &&
                   std::isfinite(dy[2]) ?
                 0 :
                 1;
      };

      using ARKode = dealii::SUNDIALS::ARKode<VectorType>;
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
      ARKode                          ode(data);
      ode.implicit_function = f;
      // Jacobian-vector products by finite differences: only the Newton
      // iteration uses them, not the accuracy of the solution.
      ode.jacobian_times_vector = [&](const VectorType &v,
                                      VectorType       &Jv,
                                      const double      t,
                                      const VectorType &y,
                                      const VectorType &fy) {
        const double norm = v.l2_norm();
        if (norm == 0)
          {
            Jv = 0;
            return 0;
          }
        const double h = 1e-7 * std::max(1., y.l2_norm()) / norm;
        VectorType   yh(y), fh(y.size());
        yh.add(h, v);
        const int err = f(t, yh, fh);
        for (unsigned int i = 0; i < Jv.size(); ++i)
          Jv[i] = (fh[i] - fy[i]) / h;
        return err;
      };
      // Absolute tolerances: rtol times the scale of each variable.
      VectorType abs_tol(3);
      abs_tol[0]               = rtol * friction.L;
      abs_tol[1]               = dynamic ? rtol * v0 : rtol;
      abs_tol[2]               = rtol;
      ode.get_local_tolerances = [&]() -> VectorType & { return abs_tol; };

      Recorder   recorder(parameters.run.output_directory,
                        v0,
                        parameters.output.event_threshold * v0,
                        parameters.output.progress_interval,
                        log);
      Summary    summary;
      const auto to_state = [&](const VectorType &y, const double t) {
        State s;
        s.slip     = y[0];
        s.velocity = rate_of(y);
        s.alpha    = y[2];
        VectorType dy(3);
        f(t, y, dy);
        s.acceleration = dynamic ? dy[1] : s.velocity * dy[1];
        return s;
      };
      void *arkode_memory = nullptr;
      ode.custom_setup    = [&](void *memory) { arkode_memory = memory; };

      // Sample the solution (ARKODE interpolates between its own steps) at
      // the output period, and densely enough during events to see the
      // peak: at most (Reference sample spacing) L / V apart.
      VectorType y(3);
      y[0]         = 0;
      y[1]         = dynamic ? initial_rate : std::log(initial_rate);
      y[2]         = initial_alpha;
      State  state = to_state(y, 0);
      double t     = 0;
      recorder.start(t, state);
      while (end_time - t > 1e-12 * end_time)
        {
          const double dt = std::min(
            {output_period,
             sample_spacing > 0 ? sample_spacing * friction.L /
                                    std::max(std::abs(state.velocity), 1e-300) :
                                  output_period,
             end_time - t});
          const double t_next =
            (end_time - t - dt < 1e-12 * end_time) ? end_time : t + dt;
          ode.solve_ode_incrementally(y, t_next);
          state = to_state(y, t_next);
          recorder.record(t_next,
                          t_next - t,
                          state,
                          friction_coefficient(state),
                          0,
                          end_time,
                          summary);
          t = t_next;
          if (recorder.events_done(parameters.run.stop_after_events, t))
            break;
        }
      long int steps = 0;
      if (arkode_memory != nullptr)
        ARKStepGetNumSteps(arkode_memory, &steps);

      summary.spatial_problems     = steps; // internal ARKODE steps
      summary.final_time           = t;
      summary.final_state          = to_state(y, t);
      summary.final_friction       = friction_coefficient(summary.final_state);
      summary.mean_recurrence_time = mean_recurrence_time(summary.events);
      summary.wall_time            = recorder.wall_time();
      log << "Summary: " << steps << " ARKODE steps, " << summary.steps
          << " output samples, " << summary.events.size() << " events"
          << std::endl;
      print_final(log, summary);
      return summary;
    }
  } // namespace scenes
} // namespace rsfcycle
