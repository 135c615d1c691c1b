// SPDX-License-Identifier: LGPL-2.1-or-later
#include <cerrno>
#include <rsfcycle/output/csv_file.h>

namespace rsfcycle
{
  namespace output
  {
    CsvFile::CsvFile(const std::string &dir, const std::string &name)
      : path(dir + "/" + name)
    {}


    void
    CsvFile::open(const bool resume)
    {
      if (!writing)
        return;
      file.open(path, resume ? std::ios::app : std::ios::out);
      if (!file)
        throw file_error(path, errno);
      if (!resume)
        {
          write_header(file);
          flush();
        }
    }


    void
    CsvFile::flush()
    {
      if (!writing)
        return;
      file.flush();
      check();
    }


    std::vector<long long>
    CsvFile::sync()
    {
      if (!writing)
        return {};
      flush();
      sync_to_disk(path);
      return {static_cast<long long>(file.tellp())};
    }


    void
    CsvFile::check() const
    {
      // after a failed write, errno still holds its reason: the stream
      // makes no system call after it
      if (!file)
        throw file_error(path, errno);
    }
  } // namespace output
} // namespace rsfcycle
