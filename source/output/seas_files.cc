#include <algorithm>
#include <cerrno>
#include <cmath>
#include <iomanip>
#include <rsfcycle/format.h>
#include <rsfcycle/output/files.h>
#include <rsfcycle/output/seas_files.h>
#include <rsfcycle/version.h>
#include <sstream>
#include <stdexcept>

namespace rsfcycle
{
  namespace output
  {
    SeasFiles::SeasFiles(const std::string    &dir,
                         const SeasParameters &parameters,
                         const Layout         &layout)
      : parameters(parameters)
      , pore_pressure(layout.pore_pressure)
      , darcy_velocity(layout.darcy_velocity)
    {
      if (!layout.lateral_positions.empty())
        throw std::invalid_argument(
          "Output/SEAS/Problem: SEAS files are written for 2D models only");
      const auto        &s = layout.positions;
      const unsigned int n = s.size();
      order.resize(n);
      for (unsigned int k = 0; k < n; ++k)
        order[k] = k;
      std::sort(order.begin(), order.end(), [&](unsigned i, unsigned j) {
        return s[i] < s[j];
      });
      for (const unsigned int k : order)
        {
          positions.push_back(s[k]);
          weights.push_back(layout.weights[k]);
        }
      element_size = n > 1 ? positions.back() - positions.front() : 0;
      for (unsigned int k = 1; k < n; ++k)
        element_size = std::min(element_size, positions[k] - positions[k - 1]);

      for (const double x : parameters.fault_stations)
        {
          stations.push_back(locate(parameters.origin + x, "Fault stations"));
          file_paths.push_back(dir + "/" + parameters.fault_station_file(x));
        }
      for (const auto &name : layout.station_names)
        {
          surface_names.push_back(name);
          file_paths.push_back(dir + "/srfst_" + name);
        }
      const auto  &range = parameters.slip_profile;
      const double count = std::floor((range[1] - range[0]) / range[2] + 1e-9);
      for (long i = 0; i <= static_cast<long>(count); ++i)
        {
          profile_positions.push_back(range[0] + i * range[2]);
          profile.push_back(locate(parameters.origin + profile_positions.back(),
                                   "Slip profile"));
        }
      file_paths.push_back(dir + "/global.dat");
      file_paths.push_back(dir + "/slip.dat");
    }


    SeasFiles::Interpolation
    SeasFiles::locate(const double x, const std::string &entry) const
    {
      const double tolerance = 1e-9 * std::max(1., std::abs(x));
      if (positions.empty() || x < positions.front() - tolerance ||
          x > positions.back() + tolerance)
        throw std::invalid_argument(
          "Output/SEAS/" + entry + ": " + format_number(x) +
          " m lies outside the contact (along-base coordinates " +
          (positions.empty() ? std::string("none") :
                               format_number(positions.front()) + " ... " +
                                 format_number(positions.back())) +
          " m)");
      if (positions.size() == 1)
        return {0, 0.};
      const auto upper =
        std::upper_bound(positions.begin(), positions.end(), x);
      const unsigned int k =
        std::min<long>(std::max<long>(upper - positions.begin() - 1, 0),
                       positions.size() - 2);
      const double weight =
        std::clamp((x - positions[k]) / (positions[k + 1] - positions[k]),
                   0.,
                   1.);
      return {k, weight};
    }


    double
    SeasFiles::interpolate(const Interpolation &where,
                           const double        *values) const
    {
      if (where.weight == 0)
        return values[where.k];
      return (1 - where.weight) * values[where.k] +
             where.weight * values[where.k + 1];
    }


    std::string
    SeasFiles::header(const std::string &location) const
    {
      std::ostringstream text;
      text << "# This is the file header:\n"
           << "# problem=" << parameters.problem << "\n"
           << "# code=rsfcycle " << version::number << " (commit "
           << version::commit << ")\n"
           << "# element_size=" << element_size << " m\n"
           << "# location=" << location << "\n";
      return text.str();
    }


    void
    SeasFiles::open(const bool resume)
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


    void
    SeasFiles::write_headers()
    {
      unsigned int f = 0;
      for (unsigned int i = 0; i < stations.size(); ++i, ++f)
        {
          std::ostringstream location;
          location << "on fault, " << parameters.fault_stations[i] / 1e3
                   << (parameters.strike_names ?
                         " km along strike" :
                         " km along the contact (down-dip distance)");
          std::vector<std::pair<std::string, std::string>> columns = {
            {"t", "Time (s)"},
            {"slip", "Slip (m)"},
            {"slip_rate", "Slip rate (log10 m/s)"},
            {"shear_stress", "Shear stress (MPa)"}};
          if (pore_pressure)
            columns.emplace_back("pore_pressure", "Pore pressure (MPa)");
          if (darcy_velocity)
            columns.emplace_back("darcy_vel", "Darcy velocity (m/s)");
          columns.emplace_back("state", "State (log10 s)");
          *streams[f] << header(location.str());
          std::string names;
          for (unsigned int c = 0; c < columns.size(); ++c)
            {
              *streams[f] << "# Column #" << c + 1 << " = " << columns[c].second
                          << "\n";
              names += (c ? " " : "") + columns[c].first;
            }
          *streams[f] << "# The line below lists the names of the data "
                         "fields:\n"
                      << names << "\n# Here is the time-series data.\n";
        }
      for (const auto &name : surface_names)
        *streams[f++]
          << header("off fault, observation point " + name)
          << "# Column #1 = Time (s)\n"
             "# Column #2 = Displacement (m)\n"
             "# Column #3 = Velocity (m/s)\n"
             "# The line below lists the names of the data fields:\n"
             "t disp vel\n"
             "# Here is the time-series data.\n";
      *streams[f++] << header("global")
                    << "# Column #1 = Time (s)\n"
                       "# Column #2 = Max slip rate (log10 m/s)\n"
                       "# Column #3 = Moment rate (N/s per m along strike)\n"
                       "# The line below lists the names of the data fields:\n"
                       "t max_slip_rate moment_rate\n"
                       "# Here is the time-series data.\n";
      *streams[f]
        << header("on fault, slip profiles")
        << "# Row #1 = 0 0, then the positions along the contact (m)\n"
           "# Column #1 = Time (s)\n"
           "# Column #2 = Max slip rate (log10 m/s)\n"
           "# Column #3 ... = Slip (m)\n"
           "# The line below lists the names of the data fields:\n"
           "t max_slip_rate slip\n"
           "# Here is the data.\n";
      row << 0. << 0.;
      for (const double x : profile_positions)
        row << x;
      row.write_line(*streams[f]);
    }


    double
    SeasFiles::sort_sample(const Sample &sample)
    {
      const unsigned int n = order.size();
      slip.resize(n);
      rate.resize(n);
      log10_rate.resize(n);
      stress.resize(n);
      log10_state.resize(n);
      pressure.resize(pore_pressure ? n : 0);
      darcy.resize(darcy_velocity ? n : 0);
      double max_rate = 0;
      for (unsigned int i = 0; i < n; ++i)
        {
          const unsigned int k = order[i];
          const double       V = sample.slip_rates[k];
          slip[i]              = sample.slip[k][0];
          rate[i]              = V;
          log10_rate[i]        = std::log10(std::max(V, 1e-300));
          stress[i]            = sample.shear_stresses[k] / 1e6;
          log10_state[i]       = sample.log10_states[k];
          if (pore_pressure)
            pressure[i] = sample.pore_pressures[k] / 1e6;
          if (darcy_velocity)
            darcy[i] = sample.darcy_velocities[k];
          max_rate = std::max(max_rate, V);
        }
      return std::log10(std::max(max_rate, 1e-300));
    }


    void
    SeasFiles::write(const Record &record)
    {
      if (writing)
        write_step(record.t, *record.sample);
      // the slip profiles at their own intervals, by the event detector's
      // definition of an event
      const double eps = 1e-12 * std::max(1., record.t);
      if (record.t >= last_profile +
                        (record.events->in_event() ?
                           parameters.event_profile_interval :
                           parameters.profile_interval) -
                        eps)
        {
          if (writing)
            write_profile(record.t, *record.sample);
          last_profile = record.t;
        }
    }


    void
    SeasFiles::write_step(const double t, const Sample &sample)
    {
      const double log10_max_rate = sort_sample(sample);
      unsigned int f              = 0;
      for (const auto &where : stations)
        {
          row.precise(t) << interpolate(where, slip.data())
                         << interpolate(where, log10_rate.data())
                         << interpolate(where, stress.data());
          if (pore_pressure)
            row << interpolate(where, pressure.data());
          if (darcy_velocity)
            row << interpolate(where, darcy.data());
          row << interpolate(where, log10_state.data());
          row.write_line(*streams[f++]);
        }
      const double factor = parameters.mirror ? 0.5 : 1.;
      for (unsigned int i = 0; i < surface_names.size(); ++i)
        {
          row.precise(t) << factor * sample.observations[i]
                         << factor * sample.observation_rates[i];
          row.write_line(*streams[f++]);
        }
      // G int V ds by the nodes' lumped weights
      double moment_rate = 0;
      for (unsigned int i = 0; i < rate.size(); ++i)
        moment_rate += weights[i] * rate[i];
      row.precise(t) << log10_max_rate
                     << parameters.shear_modulus * moment_rate;
      row.write_line(*streams[f]);
      check();
    }


    void
    SeasFiles::write_profile(const double t, const Sample &sample)
    {
      row.precise(t) << sort_sample(sample);
      for (const auto &where : profile)
        row << interpolate(where, slip.data());
      row.write_line(*streams.back());
      check();
    }


    void
    SeasFiles::check() const
    {
      // after a failed write, errno still holds its reason
      for (unsigned int i = 0; i < streams.size(); ++i)
        if (!*streams[i])
          throw file_error(file_paths[i], errno);
    }


    void
    SeasFiles::flush()
    {
      if (!writing)
        return;
      for (const auto &file : streams)
        file->flush();
      check();
    }


    std::vector<long long>
    SeasFiles::sync()
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
    SeasFiles::save(boost::archive::binary_oarchive &archive) const
    {
      archive << last_profile;
    }


    void
    SeasFiles::load(boost::archive::binary_iarchive &archive)
    {
      archive >> last_profile;
    }
  } // namespace output
} // namespace rsfcycle
