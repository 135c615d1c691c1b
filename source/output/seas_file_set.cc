// SPDX-License-Identifier: LGPL-2.1-or-later
// What the SEAS writers of 2D and 3D models share (output/seas_file_set.h).
#include <cerrno>
#include <rsfcycle/output/events.h>
#include <rsfcycle/output/files.h>
#include <rsfcycle/output/seas_file_set.h>
#include <rsfcycle/version.h>
#include <sstream>

namespace rsfcycle
{
  namespace output
  {
    SeasFileSet::SeasFileSet(const SeasParameters &parameters)
      : parameters(parameters)
    {}


    unsigned int
    SeasFileSet::add_file(const std::string &dir, const std::string &name)
    {
      file_paths.push_back(dir + "/" + name);
      return file_paths.size() - 1;
    }


    void
    SeasFileSet::write_header(
      const unsigned int                                      f,
      const std::string                                      &location,
      const std::vector<std::pair<std::string, std::string>> &columns,
      const std::string                                      &label,
      const std::string                                      &preamble)
    {
      std::ostream &out = *streams[f];
      out << "# This is the file header:\n"
          << "# problem=" << parameters.problem << "\n"
          << "# code=rsfcycle " << version::number << " (commit "
          << version::commit << ")\n"
          << "# element_size=" << element_size << " m\n"
          << "# location=" << location << "\n"
          << preamble;
      std::string names;
      for (unsigned int c = 0; c < columns.size(); ++c)
        {
          out << "# Column #" << c + 1 << " = " << columns[c].second << "\n";
          names += (c ? " " : "") + columns[c].first;
        }
      out << "# The line below lists the names of the data fields:\n"
          << names << "\n# " << label << "\n";
    }


    void
    SeasFileSet::open(const bool resume)
    {
      if (!writing)
        return;
      for (const auto &path : file_paths)
        {
          streams.push_back(std::make_unique<std::ofstream>(
            path, resume ? std::ios::app : std::ios::out));
          if (!*streams.back())
            throw file_error(path, errno);
        }
      if (!resume)
        write_headers();
      flush();
    }


    bool
    SeasFileSet::profile_due(const Record &record)
    {
      // the profiles at their own intervals, by the event detector's
      // definition of an event
      const double eps = 1e-12 * std::max(1., record.t);
      if (record.t < last_profile +
                       (record.events->in_event() ?
                          parameters.event_profile_interval :
                          parameters.profile_interval) -
                       eps)
        return false;
      last_profile = record.t;
      return true;
    }


    void
    SeasFileSet::check() const
    {
      // after a failed write, errno still holds its reason
      for (unsigned int i = 0; i < streams.size(); ++i)
        if (!*streams[i])
          throw file_error(file_paths[i], errno);
    }


    void
    SeasFileSet::flush()
    {
      if (!writing)
        return;
      for (const auto &file : streams)
        file->flush();
      check();
    }


    std::vector<long long>
    SeasFileSet::sync()
    {
      if (!writing)
        return {};
      flush();
      std::vector<long long> result;
      for (const auto &file : streams)
        result.push_back(file->tellp());
      for (const auto &path : file_paths)
        sync_to_disk(path);
      return result;
    }


    void
    SeasFileSet::save(boost::archive::binary_oarchive &archive) const
    {
      archive << last_profile;
    }


    void
    SeasFileSet::load(boost::archive::binary_iarchive &archive)
    {
      archive >> last_profile;
    }
  } // namespace output
} // namespace rsfcycle
