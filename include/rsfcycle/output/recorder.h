#ifndef rsfcycle_output_recorder_h
#define rsfcycle_output_recorder_h

#include <fstream>
#include <rsfcycle/output/csv_row.h>
#include <rsfcycle/output/events.h>
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
      long long series = 0, profile = 0, catalogue = 0;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &series &profile &catalogue;
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
     *  - events.csv: the event catalogue.
     * It decides nothing: the run loop says what to write and when.
     */
    class Recorder
    {
    public:
      /**
       * Create the files with their headers in dir or, with `resume`, cut
       * them to the sizes of the checkpoint and append.
       */
      Recorder(const std::string  &dir,
               const time::Layout &layout,
               bool                resume,
               const FileSizes    &sizes = {});

      /** One row of time-series.csv. */
      void
      write_step(double                      t,
                 double                      step_size,
                 const time::Sample         &sample,
                 unsigned int                spatial_problems,
                 const time::StepStatistics &work);

      /** One row of base-profile.csv. */
      void
      write_profile(double t, const std::vector<double> &slip_rates);

      /** One row of events.csv (flushed at once). */
      void
      write_event(unsigned int index, const Event &event);

      /** Flush the files to disk (progress, checkpoints). */
      void
      flush();

      /** The current sizes (for a checkpoint); flushes first. */
      FileSizes
      sizes();

    private:
      void
      write_headers(const time::Layout &layout);

      std::ofstream             series, profile, catalogue;
      CsvRow                    series_row{10}, profile_row{8};
      std::vector<unsigned int> order; // node order along the base
    };
  } // namespace output
} // namespace rsfcycle

#endif
