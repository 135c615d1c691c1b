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
     * written by the first rank, with the SEAS header (problem, code,
     * element size, location, the columns), created or (on resume) appended
     * to, flushed and synced as one set; and the clock of the profile rows
     * (every `Slip profile interval`, during events every `Event slip
     * profile interval`).
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

      /** Add a file of the run folder dir; returns its index. */
      unsigned int
      add_file(const std::string &dir, const std::string &name);

      /** Write every file's header (open() without resume). */
      virtual void
      write_headers() = 0;

      /**
       * The SEAS header of file f: problem, code, element size, location,
       * the preamble (comment lines), one line per column (name,
       * description), the names, and `label`.
       */
      void
      write_header(
        unsigned int                                            f,
        const std::string                                      &location,
        const std::vector<std::pair<std::string, std::string>> &columns,
        const std::string &label    = "Here is the time-series data.",
        const std::string &preamble = "");

      /** Whether a profile row is due at the record (and note it). */
      bool
      profile_due(const Record &record);

      /** Throw file_error if a file failed (after a write). */
      void
      check() const;

      const SeasParameters parameters;
      /** Whether this process writes the files (the first rank). */
      const bool                                  writing      = is_root();
      double                                      element_size = 0;
      std::vector<std::string>                    file_paths;
      std::vector<std::unique_ptr<std::ofstream>> streams;
      CsvRow                                      row{10, ' '};

    private:
      double last_profile = 0;
    };
  } // namespace output
} // namespace rsfcycle

#endif
