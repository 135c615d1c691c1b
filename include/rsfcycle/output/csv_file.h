// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_output_csv_file_h
#define rsfcycle_output_csv_file_h

#include <fstream>
#include <rsfcycle/output/files.h>
#include <rsfcycle/output/writer.h>
#include <string>
#include <vector>

namespace rsfcycle
{
  namespace output
  {
    /**
     * A writer of one text file of the run folder, written by the first rank
     * (the others keep the interface and write nothing): created with its
     * header, or opened to append on resume; every failed write is a
     * file_error naming it.
     */
    class CsvFile : public Writer
    {
    public:
      /** The file `name` in the run folder `dir`. */
      CsvFile(const std::string &dir, const std::string &name);

      std::vector<std::string>
      files() const override
      {
        return {path};
      }

      void
      open(bool resume) override;

      void
      flush() override;

      std::vector<long long>
      sync() override;

    protected:
      /** The header lines, written when the file is created. */
      virtual void
      write_header(std::ostream &out) = 0;

      /** Throw file_error if the file failed (after a write). */
      void
      check() const;

      const std::string path;
      /** Whether this process writes the file (the first rank). */
      const bool    writing = is_root();
      std::ofstream file;
    };
  } // namespace output
} // namespace rsfcycle

#endif
