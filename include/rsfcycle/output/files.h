// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_output_files_h
#define rsfcycle_output_files_h

#include <deal.II/base/parameter_handler.h>
#include <stdexcept>
#include <string>
#include <vector>

namespace rsfcycle
{
  namespace output
  {
    /**
     * The error of a failed read or write: "path: reason", the reason being
     * std::strerror(error) ("No space left on device", "File too large").
     * main() prints it as one line.
     */
    /**
     * Whether this process writes the run's shared files (log, CSVs,
     * parameters, PVD records, checkpoint): the first MPI rank, or the only
     * process when MPI is not started.
     */
    bool
    is_root();

    /** The largest value over the MPI ranks (the value if MPI is off). */
    int
    max_over_ranks(int value);

    /** Whether the condition holds on some MPI rank. */
    inline bool
    on_any_rank(const bool condition)
    {
      return max_over_ranks(condition ? 1 : 0) > 0;
    }

    std::runtime_error
    file_error(const std::string &path, int error);

    /**
     * Write `content` to the file `path` (created or truncated) with POSIX
     * calls, so that every failure is seen with its errno; with `durable`,
     * fsync the file before closing it, so that its data are on the disk
     * when the function returns. A failure removes the partial file and
     * throws file_error.
     */
    void
    write_file(const std::string &path,
               const std::string &content,
               bool               durable = false);

    /**
     * Replace the file `path` by `content` as a whole: written to
     * path + ".tmp" and renamed, so that a failed write leaves the old file
     * as it was.
     */
    void
    replace_file(const std::string &path, const std::string &content);

    /**
     * fsync the file or folder `path`: for a file, its data reach the disk;
     * for a folder, the names created or renamed in it do.
     */
    void
    sync_to_disk(const std::string &path);

    /**
     * Cut each file paths[i] to sizes[i] bytes (resume: drop what was
     * written after the checkpoint). All are checked first: a file shorter
     * than its size (cut after the checkpoint was written) or missing is a
     * std::invalid_argument, thrown before any file is changed.
     */
    void
    cut_to_sizes(const std::vector<std::string> &paths,
                 const std::vector<long long>   &sizes);

    /**
     * Create the run folder `dir` if needed and write every parameter of
     * `prm` to dir/parameters.prm (the record of the run, and what
     * `--resume` reads).
     */
    void
    write_parameters(const std::string              &dir,
                     const dealii::ParameterHandler &prm);
  } // namespace output
} // namespace rsfcycle

#endif
