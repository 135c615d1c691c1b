// SPDX-License-Identifier: LGPL-2.1-or-later
// What the SEAS writers of 2D and 3D models share (output/seas_file_set.h).
#include <boost/serialization/vector.hpp>
#include <cerrno>
#include <cstdio>
#include <ctime>
#include <rsfcycle/output/events.h>
#include <rsfcycle/output/files.h>
#include <rsfcycle/output/seas_file_set.h>
#include <rsfcycle/version.h>
#include <sstream>

namespace rsfcycle
{
  namespace output
  {
    namespace
    {
      /** The width of a header field that finish() fills in. */
      constexpr unsigned int field_width = 24;

      /** The keys finish() fills in, in their order in the header. */
      const char *const step_keys[] = {"# minimum_time_step=",
                                       "# maximum_time_step=",
                                       "# num_time_steps="};

      std::string
      padded(const std::string &text)
      {
        return text + std::string(field_width > text.size() ?
                                    field_width - text.size() :
                                    0,
                                  ' ');
      }

      std::string
      today()
      {
        const std::time_t now = std::time(nullptr);
        char              text[16];
        std::strftime(text, sizeof(text), "%Y/%m/%d", std::localtime(&now));
        return text;
      }
    } // namespace


    SeasFileSet::SeasFileSet(const SeasParameters &parameters)
      : parameters(parameters)
      , conventions(parameters.conventions())
    {}


    unsigned int
    SeasFileSet::add_file(const std::string &dir,
                          const std::string &name,
                          const bool         counted)
    {
      file_paths.push_back(dir + "/" + name);
      steps.emplace_back();
      steps.back().counted = counted;
      return file_paths.size() - 1;
    }


    void
    SeasFileSet::write_keys(std::ostream &out,
                            const bool    series,
                            const bool    counted) const
    {
      const std::string version_text =
        std::string(version::number) + " (commit " + version::commit + ")";
      const std::string modeler =
        parameters.modeler.empty() ? "unknown" : parameters.modeler;
      // D3 and later: the time series' keys in this order; D1 (BP1, BP2)
      // and every profile or table: author (modeler in BP3) and
      // code_version
      const bool bp3_series = series && !conventions.bp1_keys;
      if (bp3_series)
        out << "# This is the file header:\n";
      out << "# problem=" << conventions.problem << "\n";
      if (bp3_series)
        out << "# code=rsfcycle\n# version=" << version_text
            << "\n# modeler=" << modeler << "\n# date=" << date << "\n";
      else
        out << "# "
            << (series ? std::string("author") : conventions.profile_author_key)
            << "=" << modeler << "\n# date=" << date
            << "\n# code=rsfcycle\n# code_version=" << version_text << "\n";
      out << "# element_size=" << element_size << " m\n";
      if (counted)
        for (const char *key : step_keys)
          out << key << padded("(when the run ends)") << "\n";
      if (!parameters.description.empty())
        out << "# description=" << parameters.description << "\n";
    }


    void
    SeasFileSet::write_series_header(const unsigned int         f,
                                     const std::string         &location,
                                     const std::vector<Column> &columns)
    {
      std::ostream &out = *streams[f];
      write_keys(out, true, steps[f].counted);
      out << "# location= " << location << "\n";
      std::string names;
      for (unsigned int c = 0; c < columns.size(); ++c)
        {
          out << "# Column #" << c + 1 << " = " << columns[c].second << "\n";
          names += (c ? " " : "") + columns[c].first;
        }
      out << "# The line below lists the names of the data fields\n"
          << names << "\n";
      if (!conventions.bp1_keys)
        out << "# Here is the time-series data.\n";
    }


    void
    SeasFileSet::write_profile_header(const unsigned int         f,
                                      const std::string         &positions,
                                      const std::string         &name,
                                      const Column              &field,
                                      const std::vector<double> &values)
    {
      std::ostream &out = *streams[f];
      write_keys(out, false, steps[f].counted);
      out << "# Row #1 = " << positions << " with two zeros first\n"
          << "# Column #1 = Time (s)\n"
          << "# Column #2 = Max slip rate (log10 m/s)\n"
          << "# Columns #3-" << values.size() + 2 << " = " << field.second
          << "\n# The line below lists the names of the data fields\n"
          << name << "\n";
      if (conventions.profile_name_lines == 4)
        out << "t\nmax_slip_rate\n" << field.first << "\n";
      else
        out << "t max_slip_rate " << field.first << "\n";
      out << "# Here are the data\n";
      row << 0. << 0.;
      for (const double x : values)
        row << x;
      row.write_line(out);
    }


    void
    SeasFileSet::write_table_header(const unsigned int         f,
                                    const std::vector<Column> &columns)
    {
      std::ostream &out = *streams[f];
      write_keys(out, false, false);
      std::string names;
      for (unsigned int c = 0; c < columns.size(); ++c)
        {
          out << "# Column #" << c + 1 << " = " << columns[c].second << "\n";
          names += (c ? " " : "") + columns[c].first;
        }
      out << "# The line below lists the names of the data fields\n"
          << names << "\n# Here are the data\n";
    }


    void
    SeasFileSet::write_row(const unsigned int f, const double t)
    {
      Steps &s = steps[f];
      if (s.rows > 0)
        {
          const double dt = t - s.last;
          s.min           = s.rows == 1 ? dt : std::min(s.min, dt);
          s.max           = s.rows == 1 ? dt : std::max(s.max, dt);
        }
      s.last = t;
      ++s.rows;
      row.write_line(*streams[f]);
    }


    void
    SeasFileSet::write_row(const unsigned int f)
    {
      row.write_line(*streams[f]);
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
        {
          date = today();
          write_headers();
        }
      flush();
    }


    void
    SeasFileSet::start(const Record &record)
    {
      write_rows(record);
    }


    void
    SeasFileSet::finish(const Record &)
    {
      if (!writing)
        return;
      flush();
      for (unsigned int f = 0; f < file_paths.size(); ++f)
        {
          const Steps &s = steps[f];
          if (!s.counted)
            continue;
          // the header's lines up to the data: find each key and overwrite
          // its field of fixed width
          std::fstream file(file_paths[f],
                            std::ios::in | std::ios::out | std::ios::binary);
          std::string  head(8192, '\0');
          file.read(head.data(), head.size());
          head.resize(file.gcount());
          file.clear();
          char text[3][64];
          std::snprintf(text[0], sizeof(text[0]), "%.6e", s.min);
          std::snprintf(text[1], sizeof(text[1]), "%.6e", s.max);
          std::snprintf(text[2], sizeof(text[2]), "%llu", s.rows);
          for (unsigned int k = 0; k < 3; ++k)
            {
              const auto at = head.find(step_keys[k]);
              if (at == std::string::npos)
                continue;
              file.seekp(at + std::string(step_keys[k]).size());
              file << padded(s.rows > 1 || k == 2 ? text[k] : "none");
            }
          file.flush();
          if (!file)
            throw file_error(file_paths[f], errno);
        }
    }


    bool
    SeasFileSet::profile_due(const Record &record)
    {
      // the first row of the profiles at the first record (t = 0), then
      // at their own intervals, by the event detector's definition of an
      // event
      if (!profiled)
        {
          profiled     = true;
          last_profile = record.t;
          return true;
        }
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
      archive << profiled << last_profile << steps;
    }


    void
    SeasFileSet::load(boost::archive::binary_iarchive &archive)
    {
      archive >> profiled >> last_profile >> steps;
    }
  } // namespace output
} // namespace rsfcycle
