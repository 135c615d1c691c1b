#ifndef rsfcycle_time_run_loop_h
#define rsfcycle_time_run_loop_h

#include <chrono>
#include <deal.II/base/timer.h>
#include <memory>
#include <optional>
#include <ostream>
#include <rsfcycle/output/events.h>
#include <rsfcycle/output/recorder.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/time/controller.h>
#include <rsfcycle/time/model.h>
#include <string>
#include <vector>

namespace rsfcycle
{
  namespace time
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
      double        wall_time        = 0; // of the loop [s]
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
     * The time loop of every model (ASPECT's time_stepping/, SUNDIALS' split
     * of integrator and right-hand side): from t = 0 (or a checkpoint) to
     * the end time, one accepted step of the Controller at a time; after
     * each, it records the Model's sample (time series, base profile,
     * events, snapshots at their intervals), reports progress, writes
     * checkpoints, and stops at the end time, after `Stop after events`
     * events, on SIGINT/SIGTERM (with a checkpoint) or when the controller
     * cannot find a step (with a checkpoint of the last accepted state).
     * Ends with summary.txt and the TimerOutput table.
     */
    template <typename State>
    class RunLoop
    {
    public:
      RunLoop(const Parameters    &parameters,
              Model<State>        &model,
              Controller<State>   &controller,
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
        State                   state;
        double                  t = 0;
        ControllerMemory<State> controller;
        unsigned int            step            = 0;
        unsigned int            max_fixed_point = 0;
        unsigned long           total_problems  = 0;
        double                  min_dt = 1e300, max_dt = 0;
        double                  last_output = 0, last_profile = 0;
        double                  last_seas_profile = 0;
        output::EventDetector   events;
        output::FileSizes       file_sizes;

        template <class Archive>
        void
        serialize(Archive &ar, const unsigned int)
        {
          ar &state &t &controller &step &max_fixed_point &total_problems
            &min_dt &max_dt &last_output &last_profile &last_seas_profile
              &events &file_sizes;
        }
      };

      /**
       * The loop state at t = 0 or from the checkpoint, the record files,
       * the controller's step size and candidate, the records of t = 0.
       */
      void
      start(bool resume);

      /** The error message (and checkpoint) when no step can be found. */
      void
      report_underflow(const StepSizeUnderflow &error);

      /** The message when a signal stopped the run, and the timer table. */
      /** The timer summaries (collective on N ranks). */
      void
      print_timers();

      void
      report_stop_signal(int signal);

      /** The summary returned by run(). */
      RunSummary
      summarise(RunSummary summary) const;

      /** Write the checkpoint (the loop state and the model's writers). */
      void
      checkpoint();

      /** Read the checkpoint of the run folder into the loop state. */
      void
      read_checkpoint();

      /**
       * Record the step just accepted: statistics, events, time-series row,
       * profile and snapshot when due. Returns true if `Stop after events`
       * is reached.
       */
      bool
      record_step();

      /** Log the event that ended or started at this step. */
      void
      log_events(bool was_in_event, bool ended);

      /** Progress line and solver statistics every `Progress interval`. */
      void
      report_progress(const std::chrono::steady_clock::time_point &now);

      /** summary.txt, the summary lines and the timer table. */
      void
      finish();

      const Parameters                     &parameters;
      Model<State>                         &model;
      Controller<State>                    &controller;
      std::ostream                         &log;
      dealii::TimerOutput                  &timer;
      const std::string                     dir;
      const double                          v0;
      std::unique_ptr<LoopState>            loop_state;
      std::unique_ptr<output::Recorder>     recorder;
      std::chrono::steady_clock::time_point wall_start, last_progress;
      Sample                                last_sample;
      /**
       * The ETA extrapolates the mean rate (wall seconds per simulated
       * second) since the start (or resume) of the run until a whole
       * seismic cycle has been run, from the first event that starts in
       * this run to the next; then the mean rate since that first event, so
       * that it averages over whole cycles: the mean since the start would
       * include a cheap loading phase and promise too little, and the rate
       * of the last minutes swings by orders of magnitude between events
       * and the steps between them. The simulated time at the start;
       * (wall seconds, simulated time) of the first progress report after
       * the first event.
       */
      double                    t_start = 0;
      std::pair<double, double> eta_first_event;
      unsigned int              events_at_start = 0, events_at_first = 0;
    };
  } // namespace time
} // namespace rsfcycle

#endif
