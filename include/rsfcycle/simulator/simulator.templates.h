// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_simulator_simulator_templates_h
#define rsfcycle_simulator_simulator_templates_h

// The implementation of Simulator; included (and Simulator<State>
// instantiated) by the source file of each model.

#include <algorithm>
#include <boost/serialization/array.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <cctype>
#include <iomanip>
#include <rsfcycle/output/checkpoint.h>
#include <rsfcycle/output/files.h>
#include <rsfcycle/output/writers.h>
#include <rsfcycle/simulator/simulator.h>
#include <rsfcycle/time/integrators.h>
#include <rsfcycle/version.h>
#include <sstream>

namespace rsfcycle
{
  namespace internal
  {
    /** "1h02m03s". */
    std::string
    format_duration(double seconds);

    /**
     * Catches SIGINT and SIGTERM while it lives (the simulator then writes
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
  Simulator<State>::Simulator(const Parameters    &parameters,
                              time::Model<State>  &model,
                              std::ostream        &log,
                              dealii::TimerOutput &timer)
    : parameters(parameters)
    , model(model)
    , log(log)
    , timer(timer)
    , dir(parameters.run.output_directory)
    , v0(model.layout().convergence_rate)
    , integrator(time::make_integrator(parameters, model))
  {}


  template <typename State>
  void
  Simulator<State>::checkpoint()
  {
    if (!integrator->can_checkpoint())
      return;
    dealii::TimerOutput::Scope scope(timer, "Checkpoint");
    LoopState                 &s = *loop_state;
    s.writer_names.clear();
    s.file_sizes.clear();
    for (const auto &writer : writers)
      {
        s.writer_names.push_back(writer->name());
        s.file_sizes.push_back(writer->sync());
      }
    s.integrator = integrator->memory();
    output::write_checkpoint(dir,
                             model.checkpoint_identity(),
                             [&](boost::archive::binary_oarchive &ar) {
                               ar << s;
                               for (const auto &writer : writers)
                                 writer->save(ar);
                             });
    s.integrator = time::IntegratorMemory<State>();
  }


  template <typename State>
  void
  Simulator<State>::read_checkpoint()
  {
    if (!integrator->can_checkpoint())
      throw std::invalid_argument(
        "--resume " + dir +
        ": this integrator writes no checkpoints; start the run anew");
    LoopState &s = *loop_state;
    output::read_checkpoint(dir,
                            model.checkpoint_identity(),
                            [&](boost::archive::binary_iarchive &ar) {
                              ar >> s;
                              std::vector<std::string> names;
                              for (const auto &writer : writers)
                                names.push_back(writer->name());
                              if (names != s.writer_names)
                                throw std::invalid_argument(
                                  dir + "/checkpoint.bin: written with " +
                                  std::to_string(s.writer_names.size()) +
                                  " outputs, parameters.prm asks for " +
                                  std::to_string(names.size()) +
                                  " (was Output/Writers changed?)");
                              for (const auto &writer : writers)
                                writer->load(ar);
                            });
    // drop what was written after the checkpoint (the first rank writes
    // the files); every file is checked before one is cut
    std::vector<std::string> paths;
    std::vector<long long>   sizes;
    for (unsigned int i = 0; i < writers.size(); ++i)
      if (output::is_root())
        {
          const auto files = writers[i]->files();
          if (files.size() != s.file_sizes[i].size())
            throw std::invalid_argument(dir + "/checkpoint.bin: recorded " +
                                        std::to_string(s.file_sizes[i].size()) +
                                        " files of the " + writers[i]->name() +
                                        ", parameters.prm asks for " +
                                        std::to_string(files.size()));
          paths.insert(paths.end(), files.begin(), files.end());
          sizes.insert(sizes.end(),
                       s.file_sizes[i].begin(),
                       s.file_sizes[i].end());
        }
    output::cut_to_sizes(paths, sizes);
  }


  template <typename State>
  output::Record
  Simulator<State>::record(const output::Sample &sample) const
  {
    output::Record record;
    record.t      = loop_state->t;
    record.sample = &sample;
    record.events = &loop_state->events;
    record.state  = static_cast<const State *>(&loop_state->state);
    return record;
  }


  template <typename State>
  void
  Simulator<State>::start(const bool resume)
  {
    const output::Layout layout = model.layout();
    // the events' moments with the body's shear modulus at each node, or
    // the SEAS benchmark's (`Output/SEAS/Shear modulus`: the full G of a
    // model computed against a rigid mirror)
    std::vector<double> moment_weights;
    const double        seas_G = parameters.output.seas.enabled() ?
                                   parameters.output.seas.shear_modulus :
                                   0.;
    for (unsigned int k = 0; k < layout.shear_moduli.size(); ++k)
      moment_weights.push_back(layout.weights[k] *
                               (seas_G > 0 ? seas_G : layout.shear_moduli[k]));
    loop_state = std::make_unique<LoopState>(
      output::EventDetector(parameters.output.event_threshold * v0,
                            v0,
                            layout.positions,
                            layout.interpolate_event_times,
                            parameters.output.event_merge_time,
                            moment_weights));
    LoopState &s = *loop_state;
    s.state      = model.initial_state();
    writers      = output::make_writers(parameters, layout, model.offer());
    // On resume, everything that can refuse the run folder (checkpoint,
    // record files) is checked before the first byte is written to it.
    if (resume)
      read_checkpoint();
    for (const auto &writer : writers)
      writer->open(resume);
    // the first line of log.txt (and of each resumed part of it)
    log << version::describe() << std::endl;
    model.describe(log);
    if (resume)
      {
        log << "Resumed from the checkpoint at t = " << s.t << " s, step "
            << s.step << std::endl;
        integrator->restore(s.integrator);
      }
    s.integrator = time::IntegratorMemory<State>();
    if (!resume)
      {
        const output::Sample sample = model.sample(s.state);
        for (const auto &writer : writers)
          writer->start(record(sample));
        s.events.update(0., sample.slip_rates, sample.slip);
      }
  }


  template <typename State>
  RunSummary
  Simulator<State>::run(const bool resume)
  {
    start(resume);
    LoopState            &s        = *loop_state;
    const double          end_time = parameters.run.end_time;
    internal::StopSignals signals;
    RunSummary            summary;
    int                   signal = 0;
    wall_start = last_progress = last_checkpoint =
      std::chrono::steady_clock::now();
    eta_start        = {0., s.t};
    resumed_in_event = resume && (s.events.in_event() || s.events.ending());
    events_at_start = events_at_first = s.events.n_started();
    log << "*** Time loop to t = " << end_time << " s" << std::endl;
    {
      dealii::TimerOutput::Scope scope(timer, "Time stepping");
      // t is a sum of step sizes: stop within round-off of the end time
      while (end_time - s.t > 1e-10 * end_time)
        {
          try
            {
              integrator->advance(s.state, s.t, end_time);
              model.step_accepted();
            }
          catch (const time::StepSizeUnderflow &e)
            {
              report_underflow(e);
              throw;
            }
          catch (const time::CompressionLost &e)
            {
              // the files end at the last accepted step, complete
              log << "*** Stop: " << e.what() << "; the run ends at t = " << s.t
                  << " s, the last accepted step" << std::endl;
              finish();
              throw;
            }
          if (const std::string note = integrator->take_note(); !note.empty())
            log << "    " << note << std::endl;
          if (const std::string warning = integrator->take_warning();
              !warning.empty())
            log << "*** Warning: " << warning << std::endl;
          const bool stop_for_events = record_step();

          const auto now = std::chrono::steady_clock::now();
          report_progress(now);
          // decided alike on every rank (clocks and signals differ)
          signal = output::max_over_ranks(signals.received());
          if (checkpoint_due(now) || signal != 0)
            {
              checkpoint();
              last_checkpoint = now;
            }
          if (signal != 0)
            break;
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
    summary.interrupted = signal != 0;
    if (summary.interrupted)
      report_stop_signal(signal);
    else
      finish();
    return summarise(summary);
  }


  template <typename State>
  bool
  Simulator<State>::checkpoint_due(
    const std::chrono::steady_clock::time_point &now) const
  {
    const auto &out = parameters.output;
    return output::on_any_rank(
      (out.checkpoint_steps > 0 &&
       loop_state->step % out.checkpoint_steps == 0) ||
      (out.checkpoint_minutes > 0 &&
       std::chrono::duration<double>(now - last_checkpoint).count() >=
         60 * out.checkpoint_minutes));
  }


  template <typename State>
  void
  Simulator<State>::report_underflow(const time::StepSizeUnderflow &error)
  {
    const double t = loop_state->t;
    log << "Error: at t = " << t << " s: " << error.what();
    if (const std::string why = model.last_failure(); !why.empty())
      log << "\nLast failed spatial problem: " << why;
    log << std::endl;
    if (integrator->can_checkpoint())
      {
        checkpoint();
        log << "A checkpoint of the last accepted state (t = " << t
            << " s) is in " << dir << std::endl;
      }
  }


  /**
   * The TimerOutput summary of this rank (the first); on N ranks also the
   * minimum, average and maximum wall time of every section over the ranks
   * (collective).
   */
  template <typename State>
  void
  Simulator<State>::print_timers()
  {
    timer.print_summary();
    if (model.checkpoint_identity().n_ranks > 1)
      timer.print_wall_time_statistics(MPI_COMM_WORLD);
  }


  template <typename State>
  void
  Simulator<State>::report_stop_signal(const int signal)
  {
    const unsigned int n_ranks = model.checkpoint_identity().n_ranks;
    const std::string  launcher =
      n_ranks > 1 ? "mpirun -np " + std::to_string(n_ranks) + " " : "";
    log << "Stopped by signal " << signal << " at t = " << loop_state->t
        << " s; "
        << (integrator->can_checkpoint() ?
              "checkpoint written. Continue with: " + launcher +
                "rsfcycle --resume " + dir :
              std::string("this integrator writes no checkpoint"))
        << std::endl;
    print_timers();
  }


  template <typename State>
  RunSummary
  Simulator<State>::summarise(RunSummary summary) const
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
    // an event within its merge time has ended unless a resumed run
    // continues it
    if (s.events.in_event() || s.events.ending())
      summary.events.push_back(s.events.current());
    summary.wall_time = std::chrono::duration<double>(
                          std::chrono::steady_clock::now() - wall_start)
                          .count();
    return summary;
  }


  template <typename State>
  bool
  Simulator<State>::record_step()
  {
    LoopState &s = *loop_state;
    ++s.step;
    s.total_problems += integrator->n_spatial_problems();
    const double dt = integrator->last_step_size();
    s.min_dt        = std::min(s.min_dt, dt);
    s.max_dt        = std::max(s.max_dt, dt);

    const output::Sample sample = model.sample(s.state);
    s.max_fixed_point =
      std::max(s.max_fixed_point, sample.statistics.fixed_point_iterations);
    const bool was_in_event = s.events.in_event();
    const bool was_ending   = s.events.ending();
    const bool ended = s.events.update(s.t, sample.slip_rates, sample.slip);
    const bool stop_for_events =
      ended && parameters.run.stop_after_events > 0 &&
      s.events.events().size() >= parameters.run.stop_after_events;
    log_events(was_in_event, was_ending, ended);

    output::Record step   = record(sample);
    step.step_size        = dt;
    step.spatial_problems = integrator->n_spatial_problems();
    step.work             = model.take_work();
    step.event_ended      = ended;
    for (const auto &writer : writers)
      writer->write(step);
    last_sample = sample;
    return stop_for_events;
  }


  template <typename State>
  void
  Simulator<State>::log_events(const bool was_in_event,
                               const bool was_ending,
                               const bool ended)
  {
    const auto &events = loop_state->events;
    const auto  t      = loop_state->t;
    if (ended)
      {
        const auto &e = events.events().back();
        log << "    event " << events.events().size()
            << " ended at t = " << (was_ending ? e.end : t) << " s";
        if (was_ending)
          log << " (closed at t = " << t << " s, after the event merge time)";
        log << ": peak slip rate " << e.peak_slip_rate / v0
            << " v0, rupture width " << e.rupture_width() << " m, slip "
            << e.slip * 1e6 << " um";
        if (returns > 1)
          log << "; it returned above the threshold " << returns << " times";
        log << std::endl;
      }
    if (was_ending && !ended && events.in_event())
      {
        // an arresting rupture's slip rate may cross the threshold often:
        // the first return is logged, the others counted
        if (returns++ == 0)
          log << "    event " << events.n_started() << " continues at t = " << t
              << " s, within the event merge time of its end" << std::endl;
      }
    else if (!was_in_event && events.in_event())
      {
        returns = 0;
        log << "    event " << events.n_started()
            << " starts at t = " << events.current().start
            << " s near s = " << events.current().nucleation_position
            << " m along the base" << std::endl;
      }
  }


  template <typename State>
  void
  Simulator<State>::report_progress(
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
    if (resumed_in_event && !s.events.in_event() && !s.events.ending())
      {
        resumed_in_event = false;
        eta_start        = {elapsed, s.t};
      }
    const unsigned int events = s.events.n_started();
    if (events > events_at_start && events_at_first == events_at_start)
      {
        eta_first_event = {elapsed, s.t};
        events_at_first = events;
      }
    const auto [wall_0, t_0] =
      (events > events_at_first && events_at_first > events_at_start) ?
        eta_first_event :
        eta_start;
    const double eta =
      (s.t > t_0) ? (elapsed - wall_0) / (s.t - t_0) * (end_time - s.t) : 0.;
    const std::string eta_text = resumed_in_event ?
                                   std::string("after this event") :
                                   internal::format_duration(eta);
    const auto       &counts   = last_sample.statistics;
    const auto       &rates    = last_sample.slip_rates;
    const double      max_rate =
      rates.empty() ? 0. : *std::max_element(rates.begin(), rates.end());
    log << "*** Step " << s.step << ": t = " << std::setprecision(6) << s.t
        << " s / " << end_time << " s, dt = " << integrator->last_step_size()
        << " s, max V = " << max_rate / v0
        << " v0, events = " << s.events.n_started() << ", wall "
        << internal::format_duration(elapsed) << ", ETA " << eta_text << "\n"
        << "    solver: ";
    // (an explicit integrator iterates nothing: only its work is shown)
    if (counts.fixed_point_iterations > 0)
      log << counts.fixed_point_iterations << " fixed-point, "
          << counts.tnnmg_iterations << " TNNMG, " << counts.linear_iterations
          << " linear iterations; ";
    log << integrator->n_spatial_problems() << " " << integrator->work_unit()
        << " this step" << std::endl;
    if (std::string why = model.last_failure();
        !why.empty() && why != reported_failure)
      {
        log << "    a trial step was refused: " << why << std::endl;
        reported_failure = std::move(why);
      }
    for (const auto &writer : writers)
      writer->flush();
  }


  template <typename State>
  void
  Simulator<State>::finish()
  {
    const LoopState &s = *loop_state;
    checkpoint();
    for (const auto &writer : writers)
      writer->finish(record(last_sample));

    std::string unit = integrator->work_unit();
    log << "Summary: " << s.step << " steps, " << s.total_problems << " "
        << unit << ", " << s.events.n_started() << " events, step size "
        << s.min_dt << " s to " << s.max_dt << " s, max fixed-point iterations "
        << s.max_fixed_point << std::endl;
    std::ostringstream events;
    s.events.write_summary(events,
                           parameters.output.transition_time,
                           parameters.output.transition_events);
    log << events.str();
    std::ostringstream summary;
    unit[0] = std::toupper(unit[0]);
    summary << "Steps: " << s.step << "\n"
            << unit << ": " << s.total_problems << "\nStep size: " << s.min_dt
            << " s to " << s.max_dt
            << " s\nMax fixed-point iterations per step: " << s.max_fixed_point
            << "\n"
            << events.str();
    if (output::is_root())
      output::write_file(dir + "/summary.txt", summary.str());
    print_timers();
  }
} // namespace rsfcycle

#endif
