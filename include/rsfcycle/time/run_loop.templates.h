#ifndef rsfcycle_time_run_loop_templates_h
#define rsfcycle_time_run_loop_templates_h

// The implementation of RunLoop; included (and RunLoop<State> instantiated)
// by the source file of each model.

#include <algorithm>
#include <boost/serialization/array.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <iomanip>
#include <rsfcycle/output/checkpoint.h>
#include <rsfcycle/output/files.h>
#include <rsfcycle/time/run_loop.h>
#include <sstream>

namespace rsfcycle
{
  namespace time
  {
    namespace internal
    {
      /** "1h02m03s". */
      std::string
      format_duration(double seconds);

      /**
       * Catches SIGINT and SIGTERM while it lives (the run loop then writes
       * a checkpoint and stops); restores the previous handlers after.
       */
      class StopSignals
      {
      public:
        StopSignals();
        ~StopSignals();

        /** The signal received, 0 if none. */
        int
        received() const;

      private:
        void (*old_int)(int);
        void (*old_term)(int);
      };
    } // namespace internal


    template <typename State>
    RunLoop<State>::RunLoop(const Parameters    &parameters,
                            Model<State>        &model,
                            Controller<State>   &controller,
                            std::ostream        &log,
                            dealii::TimerOutput &timer)
      : parameters(parameters)
      , model(model)
      , controller(controller)
      , log(log)
      , timer(timer)
      , dir(parameters.run.output_directory)
      , v0(model.layout().convergence_rate)
    {}


    template <typename State>
    void
    RunLoop<State>::checkpoint()
    {
      if (!controller.can_checkpoint())
        return;
      dealii::TimerOutput::Scope scope(timer, "Checkpoint");
      LoopState                 &s = *loop_state;
      s.file_sizes                 = recorder->sync();
      s.controller                 = controller.memory();
      output::write_checkpoint(dir,
                               model.checkpoint_identity(),
                               [&](boost::archive::binary_oarchive &ar) {
                                 ar << s;
                                 model.save_output(ar);
                               });
      s.controller = ControllerMemory<State>();
    }


    template <typename State>
    void
    RunLoop<State>::read_checkpoint()
    {
      if (!controller.can_checkpoint())
        throw std::invalid_argument(
          "--resume " + dir +
          ": this integrator writes no checkpoints; start the run anew");
      output::read_checkpoint(dir,
                              model.checkpoint_identity(),
                              [&](boost::archive::binary_iarchive &ar) {
                                ar >> *loop_state;
                                model.load_output(ar);
                              });
    }


    template <typename State>
    void
    RunLoop<State>::start(const bool resume)
    {
      const Layout layout = model.layout();
      loop_state          = std::make_unique<LoopState>(
        output::EventDetector(parameters.output.event_threshold * v0,
                              v0,
                              layout.positions,
                              layout.interpolate_event_times));
      LoopState &s = *loop_state;
      s.state      = model.initial_state();
      // On resume, everything that can refuse the run folder (checkpoint,
      // record files) is checked before the first byte is written to it.
      if (resume)
        read_checkpoint();
      recorder = std::make_unique<output::Recorder>(
        dir, layout, resume, s.file_sizes, parameters.output.seas);
      model.describe(log);
      if (resume)
        {
          log << "Resumed from the checkpoint at t = " << s.t << " s, step "
              << s.step << std::endl;
          controller.restore(s.controller);
        }
      s.controller = ControllerMemory<State>();
      if (!resume)
        {
          const Sample sample = model.sample(s.state);
          if (parameters.output.write_vtu && model.writes_snapshots())
            model.write_snapshot(s.state, s.t);
          // (no SEAS rows: the initial state has no slip rate yet)
          recorder->write_profile(s.t, sample.slip_rates);
          s.events.update(0., sample.slip_rates, sample.slip);
        }
    }


    template <typename State>
    RunSummary
    RunLoop<State>::run(const bool resume)
    {
      start(resume);
      LoopState            &s        = *loop_state;
      const double          end_time = parameters.run.end_time;
      internal::StopSignals signals;
      RunSummary            summary;
      wall_start = last_progress = std::chrono::steady_clock::now();
      auto last_checkpoint       = wall_start;
      t_start                    = s.t;
      events_at_start = events_at_first = s.events.n_started();
      log << "*** Time loop to t = " << end_time << " s" << std::endl;
      {
        dealii::TimerOutput::Scope scope(timer, "Time stepping");
        // t is a sum of step sizes: stop within round-off of the end time
        while (end_time - s.t > 1e-10 * end_time)
          {
            try
              {
                controller.advance(s.state, s.t, end_time);
              }
            catch (const StepSizeUnderflow &e)
              {
                report_underflow(e);
                throw;
              }
            const bool stop_for_events = record_step();

            const auto now = std::chrono::steady_clock::now();
            report_progress(now);
            const auto &out = parameters.output;
            // decided alike on every rank (clocks and signals differ)
            const bool checkpoint_due = output::on_any_rank(
              (out.checkpoint_steps > 0 &&
               s.step % out.checkpoint_steps == 0) ||
              (out.checkpoint_minutes > 0 &&
               std::chrono::duration<double>(now - last_checkpoint).count() >=
                 60 * out.checkpoint_minutes));
            const int signal = output::max_over_ranks(signals.received());
            if (checkpoint_due || signal != 0)
              {
                checkpoint();
                last_checkpoint = now;
              }
            if (signal != 0)
              {
                report_stop_signal(signal);
                summary.interrupted = true;
                break;
              }
            if (stop_for_events)
              {
                log << "*** Stop after events = "
                    << parameters.run.stop_after_events
                    << " reached: the run ends at t = " << s.t << " s"
                    << std::endl;
                break;
              }
          }
      }
      if (!summary.interrupted)
        finish();
      return summarise(summary);
    }


    template <typename State>
    void
    RunLoop<State>::report_underflow(const StepSizeUnderflow &error)
    {
      const double t = loop_state->t;
      log << "Error: at t = " << t << " s: " << error.what();
      if (const std::string why = model.last_failure(); !why.empty())
        log << "\nLast failed spatial problem: " << why;
      log << std::endl;
      if (controller.can_checkpoint())
        {
          checkpoint();
          log << "A checkpoint of the last accepted state (t = " << t
              << " s) is in " << dir << std::endl;
        }
    }


    /**
     * The TimerOutput summary of this rank (the first); on N ranks also the
     * minimum, average and maximum wall time of every section over the
     * ranks (collective).
     */
    template <typename State>
    void
    RunLoop<State>::print_timers()
    {
      timer.print_summary();
      if (model.checkpoint_identity().n_ranks > 1)
        timer.print_wall_time_statistics(MPI_COMM_WORLD);
    }


    template <typename State>
    void
    RunLoop<State>::report_stop_signal(const int signal)
    {
      const unsigned int n_ranks = model.checkpoint_identity().n_ranks;
      const std::string  launcher =
        n_ranks > 1 ? "mpirun -np " + std::to_string(n_ranks) + " " : "";
      log << "Stopped by signal " << signal << " at t = " << loop_state->t
          << " s; "
          << (controller.can_checkpoint() ?
                "checkpoint written. Continue with: " + launcher +
                  "rsfcycle --resume " + dir :
                std::string("this integrator writes no checkpoint"))
          << std::endl;
      print_timers();
    }


    template <typename State>
    RunSummary
    RunLoop<State>::summarise(RunSummary summary) const
    {
      const LoopState &s         = *loop_state;
      summary.steps              = s.step;
      summary.spatial_problems   = s.total_problems;
      summary.max_fixed_point    = s.max_fixed_point;
      summary.min_step           = s.min_dt;
      summary.max_step           = s.max_dt;
      summary.final_time         = s.t;
      summary.events             = s.events.events();
      summary.last_event_running = s.events.in_event();
      if (summary.last_event_running)
        summary.events.push_back(s.events.current());
      summary.wall_time = std::chrono::duration<double>(
                            std::chrono::steady_clock::now() - wall_start)
                            .count();
      return summary;
    }


    template <typename State>
    bool
    RunLoop<State>::record_step()
    {
      LoopState &s = *loop_state;
      ++s.step;
      s.total_problems += controller.n_spatial_problems();
      const double dt = controller.last_step_size();
      s.min_dt        = std::min(s.min_dt, dt);
      s.max_dt        = std::max(s.max_dt, dt);

      const Sample sample = model.sample(s.state);
      s.max_fixed_point =
        std::max(s.max_fixed_point, sample.statistics.fixed_point_iterations);
      const bool was_in_event = s.events.in_event();
      const bool ended = s.events.update(s.t, sample.slip_rates, sample.slip);
      const bool stop_for_events =
        ended && parameters.run.stop_after_events > 0 &&
        s.events.events().size() >= parameters.run.stop_after_events;
      if (ended)
        recorder->write_event(s.events.events().size(),
                              s.events.events().back());
      log_events(was_in_event, ended);

      recorder->write_step(
        s.t, dt, sample, controller.n_spatial_problems(), model.take_work());

      // Profiles densely while slip is fast (events and the afterslip
      // around them: max V > 2 v0), else at their interval.
      const auto  &out      = parameters.output;
      const bool   in_event = s.events.in_event();
      const double max_rate =
        sample.slip_rates.empty() ?
          0. :
          *std::max_element(sample.slip_rates.begin(), sample.slip_rates.end());
      const double eps  = 1e-12 * std::max(1., s.t);
      const bool   fast = in_event || max_rate > 2 * v0;
      if (s.t >= s.last_profile +
                   (fast ? out.event_profile_interval : out.profile_interval) -
                   eps)
        {
          recorder->write_profile(s.t, sample.slip_rates);
          s.last_profile = s.t;
        }
      // the SEAS slip profiles: at their own intervals, by the event
      // detector's definition of an event
      const auto &seas = out.seas;
      if (recorder->writes_seas() &&
          s.t >=
            s.last_seas_profile +
              (in_event ? seas.event_profile_interval : seas.profile_interval) -
              eps)
        {
          recorder->write_seas_profile(s.t, sample);
          s.last_seas_profile = s.t;
        }
      if (out.write_vtu && model.writes_snapshots() &&
          s.t >=
            s.last_output +
              (in_event ? out.event_output_interval : out.output_interval) -
              eps)
        {
          model.write_snapshot(s.state, s.t);
          s.last_output = s.t;
        }
      last_sample = sample;
      return stop_for_events;
    }


    template <typename State>
    void
    RunLoop<State>::log_events(const bool was_in_event, const bool ended)
    {
      const auto &events = loop_state->events;
      const auto  t      = loop_state->t;
      if (ended)
        {
          const auto &e = events.events().back();
          log << "    event " << events.events().size() << " ended at t = " << t
              << " s: peak slip rate " << e.peak_slip_rate / v0
              << " v0, rupture width " << e.rupture_width() << " m, slip "
              << e.slip * 1e6 << " um" << std::endl;
        }
      if (!was_in_event && events.in_event())
        log << "    event " << events.n_started()
            << " starts at t = " << events.current().start
            << " s near s = " << events.current().nucleation_position
            << " m along the base" << std::endl;
    }


    template <typename State>
    void
    RunLoop<State>::report_progress(
      const std::chrono::steady_clock::time_point &now)
    {
      const LoopState &s        = *loop_state;
      const double     end_time = parameters.run.end_time;
      const double     since =
        std::chrono::duration<double>(now - last_progress).count();
      if (!(since >= parameters.output.progress_interval || s.t >= end_time))
        return;
      last_progress = now;
      const double elapsed =
        std::chrono::duration<double>(now - wall_start).count();
      const unsigned int events = s.events.n_started();
      if (events > events_at_start && events_at_first == events_at_start)
        {
          eta_first_event = {elapsed, s.t};
          events_at_first = events;
        }
      const auto [wall_0, t_0] =
        (events > events_at_first && events_at_first > events_at_start) ?
          eta_first_event :
          std::pair<double, double>(0., t_start);
      const double eta =
        (s.t > t_0) ? (elapsed - wall_0) / (s.t - t_0) * (end_time - s.t) : 0.;
      const auto  &counts = last_sample.statistics;
      const auto  &rates  = last_sample.slip_rates;
      const double max_rate =
        rates.empty() ? 0. : *std::max_element(rates.begin(), rates.end());
      log << "*** Step " << s.step << ": t = " << std::setprecision(6) << s.t
          << " s / " << end_time << " s, dt = " << controller.last_step_size()
          << " s, max V = " << max_rate / v0
          << " v0, events = " << s.events.n_started() << ", wall "
          << internal::format_duration(elapsed) << ", ETA "
          << internal::format_duration(eta) << "\n"
          << "    solver: " << counts.fixed_point_iterations << " fixed-point, "
          << counts.tnnmg_iterations << " TNNMG, " << counts.linear_iterations
          << " linear iterations; " << controller.n_spatial_problems()
          << " spatial problems this step" << std::endl;
      recorder->flush();
    }


    template <typename State>
    void
    RunLoop<State>::finish()
    {
      const LoopState &s = *loop_state;
      checkpoint();
      if (parameters.output.write_vtu && model.writes_snapshots() &&
          model.last_snapshot_time() < s.t)
        model.write_snapshot(s.state, s.t);

      log << "Summary: " << s.step << " steps, " << s.total_problems
          << " spatial problems, " << s.events.n_started()
          << " events, step size " << s.min_dt << " s to " << s.max_dt
          << " s, max fixed-point iterations " << s.max_fixed_point
          << std::endl;
      std::ostringstream events;
      s.events.write_summary(events,
                             parameters.output.transition_time,
                             parameters.output.transition_events);
      log << events.str();
      std::ostringstream summary;
      summary << "Steps: " << s.step
              << "\nSpatial problems: " << s.total_problems
              << "\nStep size: " << s.min_dt << " s to " << s.max_dt
              << " s\nMax fixed-point iterations per step: "
              << s.max_fixed_point << "\n"
              << events.str();
      if (output::is_root())
        output::write_file(dir + "/summary.txt", summary.str());
      print_timers();
    }
  } // namespace time
} // namespace rsfcycle

#endif
