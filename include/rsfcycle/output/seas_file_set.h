// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_output_seas_file_set_h
#define rsfcycle_output_seas_file_set_h

#include <fstream>
#include <memory>
#include <rsfcycle/output/csv_row.h>
#include <rsfcycle/output/files.h>
#include <rsfcycle/output/writer.h>
#include <rsfcycle/seas_parameters.h>
#include <string>
#include <utility>
#include <vector>

namespace rsfcycle
{
  namespace output
  {
    /**
     * What the SEAS file writers of 2D and 3D models share (output::SeasFiles,
     * output::SeasPlaneFiles): the plain-text files of one run folder,
     * written by the first rank, created or (on resume) appended to,
     * flushed and synced as one set; their headers as the benchmark's
     * description has them (SeasConventions: problem, code, version,
     * modeler, date, element size, location, the time steps, the columns
     * and the field lines); and the clock of the profile rows (every `Slip
     * profile interval`, during events every `Event slip profile
     * interval`).
     *
     * The time-step statistics of a file (`minimum_time_step`,
     * `maximum_time_step`, `num_time_steps`: the smallest and largest step
     * between its rows and the number of rows) are known when the run ends:
     * the header keeps a field of fixed width for each, which finish()
     * fills in place. The statistics travel in the checkpoints, so a
     * resumed run writes the same files as an uninterrupted one.
     */
    class SeasFileSet : public Writer
    {
    public:
      std::vector<std::string>
      files() const override
      {
        return file_paths;
      }

      /**
       * Create the files with their headers or, with `resume`, open them
       * for appending (they have been cut to their checkpoint sizes).
       */
      void
      open(bool resume) override;

      /** The rows of the initial state (t = 0). */
      void
      start(const Record &record) override;

      /** Fill in every header's time-step statistics. */
      void
      finish(const Record &record) override;

      /** Flush every file; throws file_error if one failed. */
      void
      flush() override;

      std::vector<long long>
      sync() override;

      void
      save(boost::archive::binary_oarchive &archive) const override;
      void
      load(boost::archive::binary_iarchive &archive) override;

    protected:
      explicit SeasFileSet(const SeasParameters &parameters);

      /** A column: its field name and its description with its unit. */
      using Column = std::pair<std::string, std::string>;

      /**
       * Add a file of the run folder dir; returns its index. A file with
       * `steps` counts its rows as time steps in its header.
       */
      unsigned int
      add_file(const std::string &dir, const std::string &name, bool steps);

      /** Write every file's header (open() without resume). */
      virtual void
      write_headers() = 0;

      /** The rows of a record (t = 0 included). */
      virtual void
      write_rows(const Record &record) = 0;

      /**
       * The header of a time series f (a station, global.dat): the
       * benchmark's keys, `location`, one line per column and the field
       * line.
       */
      void
      write_series_header(unsigned int               f,
                          const std::string         &location,
                          const std::vector<Column> &columns);

      /**
       * The header of a profile f: the keys, `Row #1 = positions`, the
       * columns, the field lines (`position_name`, then t, max_slip_rate
       * and `field`, on 2 or 4 lines) and the first row `0 0 positions`.
       */
      void
      write_profile_header(unsigned int               f,
                           const std::string         &positions,
                           const std::string         &position_name,
                           const Column              &field,
                           const std::vector<double> &values);

      /**
       * The header of a table f that is not a time series (catalog.dat,
       * rupture.dat): the keys, one line per column, the field line.
       */
      void
      write_table_header(unsigned int f, const std::vector<Column> &columns);

      /** Write `row` as the next line of file f (a time series: at t). */
      void
      write_row(unsigned int f, double t);
      void
      write_row(unsigned int f);

      /** Whether a profile row is due at the record (and note it). */
      bool
      profile_due(const Record &record);

      /** Throw file_error if a file failed (after a write). */
      void
      check() const;

      const SeasParameters  parameters;
      const SeasConventions conventions;
      /** Whether this process writes the files (the first rank). */
      const bool                                  writing      = is_root();
      double                                      element_size = 0;
      std::vector<std::string>                    file_paths;
      std::vector<std::unique_ptr<std::ofstream>> streams;
      CsvRow                                      row{10, ' '};

    private:
      /** The keys every header starts with. */
      void
      write_keys(std::ostream &out, bool series, bool steps) const;

      /** A file's rows as time steps: count, last time, min and max step. */
      struct Steps
      {
        bool               counted = false;
        unsigned long long rows    = 0;
        double             last = 0, min = 0, max = 0;

        template <class Archive>
        void
        serialize(Archive &ar, const unsigned int)
        {
          ar &counted &rows &last &min &max;
        }
      };
      std::vector<Steps> steps;
      bool               profiled     = false;
      double             last_profile = 0;
      /** The date the files were created (YYYY/MM/DD), kept on resume. */
      std::string date;
    };
  } // namespace output
} // namespace rsfcycle

#endif
