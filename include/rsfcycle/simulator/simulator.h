// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_simulator_simulator_h
#define rsfcycle_simulator_simulator_h

#include <chrono>
#include <deal.II/base/timer.h>
#include <memory>
#include <ostream>
#include <rsfcycle/output/events.h>
#include <rsfcycle/output/sample.h>
#include <rsfcycle/output/writer.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/time/integrator.h>
#include <rsfcycle/time/model.h>
#include <string>
#include <vector>

namespace rsfcycle
{
  /** What a run reports besides its files. */
  struct RunSummary
  {
    unsigned int  steps            = 0;
    unsigned long spatial_problems = 0;
    unsigned int  max_fixed_point  = 0;
    double        min_step         = 0; // [s]
    double        max_step         = 0; // [s]
    double        final_time       = 0; // [s]
    double        wall_time        = 0; // of the time loop [s]
    /**
     * Every event started: the completed ones and, if the run ended during
     * an event, that one last (`last_event_running`; its end and slip are
     * still 0).
     */
    std::vector<output::Event> events;
    bool                       last_event_running = false;
    bool                       interrupted        = false; // by a signal
  };

  /**
   * The one place that owns a run (ASPECT's Simulator): for any model
   * (time::Model) it builds the integrator that `Time stepping/
   * Integrator` names (time/integrators.h) and the writers
   * (output/writers.h, and the model's own), and drives the time loop from
   * t = 0 (or a checkpoint) to the end time, one accepted step of the
   * integrator at a time. After each it detects events, hands the record
   * to every writer, reports progress, writes checkpoints, and stops at the
   * end time, after `Stop after events` events, on SIGINT/SIGTERM (with a
   * checkpoint) or when the integrator cannot find a step (with a
   * checkpoint of the last accepted state). Ends with summary.txt and the
   * TimerOutput table. The implementation is in simulator.templates.h,
   * instantiated by each model's source file.
   */
  template <typename State>
  class Simulator
  {
  public:
    /**
     * The integrator of the parameters for the model (set up already);
     * throws std::invalid_argument (one line) if the model cannot be
     * integrated that way.
     */
    Simulator(const Parameters    &parameters,
              time::Model<State>  &model,
              std::ostream        &log,
              dealii::TimerOutput &timer);

    /**
     * Run to the end time; with `resume`, continue from the checkpoint in
     * the run folder, appending to its files.
     */
    RunSummary
    run(bool resume = false);

    /** The last accepted state. */
    const State &
    state() const
    {
      return loop_state->state;
    }

  private:
    /** What the loop carries from step to step: a checkpoint. */
    struct LoopState
    {
      explicit LoopState(output::EventDetector events)
        : events(std::move(events))
      {}
      State                         state;
      double                        t = 0;
      time::IntegratorMemory<State> integrator;
      unsigned int                  step            = 0;
      unsigned int                  max_fixed_point = 0;
      unsigned long                 total_problems  = 0;
      double                        min_dt = 1e300, max_dt = 0;
      output::EventDetector         events;
      /** The writers and the sizes of their files at the checkpoint. */
      std::vector<std::string>            writer_names;
      std::vector<std::vector<long long>> file_sizes;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &state &t &integrator &step &max_fixed_point &total_problems &min_dt
          &max_dt &events &writer_names &file_sizes;
      }
    };

    /**
     * The loop state at t = 0 or from the checkpoint, the writers' files,
     * the integrator's memory, the records of t = 0.
     */
    void
    start(bool resume);

    /** Read the checkpoint of the run folder; cut the writers' files. */
    void
    read_checkpoint();

    /** Write the checkpoint (the loop state and the writers' memory). */
    void
    checkpoint();

    /** The record of the current state for the writers. */
    output::Record
    record(const output::Sample &sample) const;

    /**
     * Record the step just accepted: statistics, events, the writers.
     * Returns true if `Stop after events` is reached.
     */
    bool
    record_step();

    /** Log the event that ended or started at this step. */
    void
    log_events(bool was_in_event, bool was_ending, bool ended);

    /** Progress line and solver statistics every `Progress interval`. */
    void
    report_progress(const std::chrono::steady_clock::time_point &now);

    /** Whether a checkpoint is due (decided alike on every rank). */
    bool
    checkpoint_due(const std::chrono::steady_clock::time_point &now) const;

    /** The error message (and checkpoint) when no step can be found. */
    void
    report_underflow(const time::StepSizeUnderflow &error);

    /** The message when a signal stopped the run, and the timer table. */
    void
    report_stop_signal(int signal);

    /** The timer summaries (collective on N ranks). */
    void
    print_timers();

    /** summary.txt, the summary lines, the writers' last records, timers. */
    void
    finish();

    /** The summary returned by run(). */
    RunSummary
    summarise(RunSummary summary) const;

    const Parameters                            &parameters;
    time::Model<State>                          &model;
    std::ostream                                &log;
    dealii::TimerOutput                         &timer;
    const std::string                            dir;
    const double                                 v0;
    std::unique_ptr<time::Integrator<State>>     integrator;
    std::vector<std::unique_ptr<output::Writer>> writers;
    std::unique_ptr<LoopState>                   loop_state;
    std::chrono::steady_clock::time_point        wall_start, last_progress,
      last_checkpoint;
    output::Sample last_sample;
    /**
     * The model's last failed trial step as last reported in a progress
     * line: a new one is printed once, so that a run whose steps stay
     * small because every larger trial fails (the solver, not the error
     * estimate) says why.
     */
    std::string reported_failure;
    /**
     * How often the current event returned above the threshold within the
     * merge time (logged once, counted in its end line).
     */
    unsigned int returns = 0;
    /**
     * The ETA extrapolates the mean rate (wall seconds per simulated
     * second) since the start (or resume) of the run until a whole
     * seismic cycle has been run, from the first event that starts in
     * this run to the next; then the mean rate since that first event, so
     * that it averages over whole cycles: the mean since the start would
     * include a cheap loading phase and promise too little, and the rate
     * of the last minutes swings by orders of magnitude between events
     * and the steps between them. A run resumed inside an event starts
     * its mean when that event has ended (until then the log says "ETA
     * after this event"): the rate of an event's steps would promise
     * years. (wall seconds, simulated time) of the mean's start; of the
     * first progress report after the first event; whether the run
     * resumed inside an event that has not ended yet.
     */
    std::pair<double, double> eta_start;
    std::pair<double, double> eta_first_event;
    bool                      resumed_in_event = false;
    unsigned int              events_at_start = 0, events_at_first = 0;
  };
} // namespace rsfcycle

#endif
