// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_output_writer_h
#define rsfcycle_output_writer_h

#include <any>
#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <rsfcycle/output/events.h>
#include <rsfcycle/output/sample.h>
#include <string>
#include <vector>

namespace rsfcycle
{
  namespace output
  {
    /**
     * What the simulator hands every writer: the accepted state at time t,
     * what is recorded of it (Sample), the step that produced it and the
     * event catalogue. `state` holds a pointer to the model's state (a
     * writer of one model reads it with state_as<State>()).
     */
    struct Record
    {
      double                  t                = 0;
      double                  step_size        = 0; // of the last step [s]
      unsigned int            spatial_problems = 0; // of the last step
      solvers::StepStatistics work; // of every spatial problem of the step
      const Sample           *sample      = nullptr;
      const EventDetector    *events      = nullptr;
      bool                    event_ended = false; // the last of events()
      std::any                state;

      /** The model's state (std::bad_any_cast for another State type). */
      template <typename State>
      const State &
      state_as() const
      {
        return *std::any_cast<const State *>(state);
      }
    };

    /**
     * One output of a run (ASPECT's postprocessors): a writer decides when
     * it writes, keeps what it needs from step to step in checkpoints, and
     * names the files it appends to, so that a resumed run cuts them to
     * their sizes at the checkpoint (output::cut_to_sizes) before anything
     * is appended. The simulator calls, in this order: files() and, on
     * resume, load(); open(); start() (not on resume); write() after every
     * accepted step; flush() with the progress reports; sync() and save()
     * at checkpoints; finish() at the end of the run. Files shared by the
     * ranks are written by the first (output::is_root()); every rank holds
     * the same writers. A failed write throws output::file_error.
     *
     * A new output is a class derived from Writer in output/ and one line
     * in the list of output/writers.cc (its name in `Output/Writers`, the
     * fields it needs, how it is made).
     */
    class Writer
    {
    public:
      virtual ~Writer() = default;

      /** The writer's name in checkpoints and messages. */
      virtual std::string
      name() const = 0;

      /** The files it appends to (paths in the run folder). */
      virtual std::vector<std::string>
      files() const
      {
        return {};
      }

      /**
       * Create the files with their headers, or, with `resume`, open them
       * to append (they have been cut to their sizes at the checkpoint).
       */
      virtual void
      open(bool /*resume*/)
      {}

      /** The record of the initial state at t = 0 (not on resume). */
      virtual void
      start(const Record &)
      {}

      /** After every accepted step: write what is due. */
      virtual void
      write(const Record &record) = 0;

      /** At the end of the run (not when stopped by a signal). */
      virtual void
      finish(const Record &)
      {}

      /** Flush the files. */
      virtual void
      flush()
      {}

      /** Flush the files, sync them to the disk and return their sizes. */
      virtual std::vector<long long>
      sync()
      {
        return {};
      }

      /** What the writer carries from step to step, for a checkpoint. */
      virtual void
      save(boost::archive::binary_oarchive &) const
      {}
      virtual void
      load(boost::archive::binary_iarchive &)
      {}
    };
  } // namespace output
} // namespace rsfcycle

#endif
