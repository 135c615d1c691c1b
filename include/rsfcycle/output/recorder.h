#ifndef rsfcycle_output_recorder_h
#define rsfcycle_output_recorder_h

#include <array>
#include <fstream>
#include <memory>
#include <rsfcycle/output/csv_row.h>
#include <rsfcycle/output/events.h>
#include <rsfcycle/output/files.h>
#include <rsfcycle/output/seas_files.h>
#include <rsfcycle/time/model.h>
#include <string>
#include <vector>

namespace rsfcycle
{
  namespace output
  {
    /** Bytes of the record files at a checkpoint (dropped after it). */
    struct FileSizes
    {
      long long              series = 0, profile = 0, catalogue = 0;
      std::vector<long long> seas; // in the order of SeasFiles::paths()

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &series &profile &catalogue &seas;
      }
    };

    /**
     * The CSV records of a run folder, the same for every model (their
     * columns are documented once, in README.md "Output"):
     *  - time-series.csv: one row per accepted step: time, step size, the
     *    solver counts, the maximum slip rate, the model's observation
     *    columns, the work of all spatial problems of the step;
     *  - base-profile.csv: the slip rate of every contact node, nodes
     *    ordered along the base;
     *  - events.csv: the event catalogue;
     *  - with `Output/SEAS/Problem` given, the SEAS files (SeasFiles).
     * It decides nothing: the run loop says what to write and when.
     */
    class Recorder
    {
    public:
      /**
       * Create the files with their headers in dir or, with `resume`, cut
       * them to the sizes of the checkpoint and append. A file shorter than
       * the checkpoint says (cut after the checkpoint was written) is an
       * std::invalid_argument, thrown before any file is changed. Every
       * failure to open or write a file is a std::runtime_error naming it.
       */
      Recorder(const std::string    &dir,
               const time::Layout   &layout,
               bool                  resume,
               const FileSizes      &sizes = {},
               const SeasParameters &seas  = {});

      /** One row of time-series.csv and the SEAS rows of the step. */
      void
      write_step(double                      t,
                 double                      step_size,
                 const time::Sample         &sample,
                 unsigned int                spatial_problems,
                 const time::StepStatistics &work);

      /** One row of base-profile.csv. */
      void
      write_profile(double t, const std::vector<double> &slip_rates);

      /** One row of the SEAS slip.dat (if SEAS is on). */
      void
      write_seas_profile(double t, const time::Sample &sample);

      /** Whether the SEAS files are written. */
      bool
      writes_seas() const
      {
        return seas != nullptr;
      }

      /** One row of events.csv (flushed at once). */
      void
      write_event(unsigned int index, const Event &event);

      /** Flush the files (progress reports). */
      void
      flush();

      /**
       * Flush the files and sync them to the disk (before a checkpoint):
       * their sizes, which the checkpoint records, are then on the disk
       * too. Returns the sizes.
       */
      FileSizes
      sync();

    private:
      void
      write_headers(const time::Layout &layout);

      /** Throw if a file failed (after a write). */
      void
      check() const;

      std::array<std::string, 3> paths; // of series, profile, catalogue
      std::ofstream              series, profile, catalogue;
      /** Whether this process writes the files (the first rank). */
      bool                       writing = is_root();
      CsvRow                     series_row{10}, profile_row{8};
      std::vector<unsigned int>  order; // node order along the base
      std::unique_ptr<SeasFiles> seas;
    };
  } // namespace output
} // namespace rsfcycle

#endif
