// SPDX-License-Identifier: LGPL-2.1-or-later
#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <iomanip>
#include <rsfcycle/format.h>
#include <rsfcycle/output/files.h>
#include <rsfcycle/output/seas_files.h>
#include <sstream>
#include <stdexcept>

namespace rsfcycle
{
  namespace output
  {
    SeasFiles::SeasFiles(const std::string    &dir,
                         const SeasParameters &parameters,
                         const Layout         &layout)
      : SeasFileSet(parameters)
      , pore_pressure(layout.pore_pressure)
      , darcy_velocity(layout.darcy_velocity)
      , normal_stress(layout.normal_stress)
      , components(layout.observation_components)
    {
      if (!layout.lateral_positions.empty())
        throw std::invalid_argument(
          "Output/SEAS/Problem: output::SeasFiles writes 2D models only");
      if (components > 2 || (components == 2 && parameters.mirror))
        throw std::invalid_argument(
          "Mesh file/Observation components = all: the SEAS surface "
          "stations of 2D models take the vertical component or both in "
          "plane strain, and one with Output/SEAS/Mirror model");
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
          add_file(dir, parameters.fault_station_file(x));
        }
      for (const auto &name : layout.station_names)
        {
          surface_names.push_back(name);
          add_file(dir, "srfst_" + name);
        }
      const auto  &range = parameters.slip_profile;
      const double count = std::floor((range[1] - range[0]) / range[2] + 1e-9);
      for (long i = 0; i <= static_cast<long>(count); ++i)
        {
          profile_positions.push_back(range[0] + i * range[2]);
          profile.push_back(locate(parameters.origin + profile_positions.back(),
                                   "Slip profile"));
        }
      add_file(dir, "global.dat");
      first_profile = stations.size() + surface_names.size() + 1;
      add_file(dir, "slip.dat");
      if (normal_stress)
        {
          add_file(dir, "shear_stress.dat");
          add_file(dir, "normal_stress.dat");
        }
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
          if (normal_stress)
            columns.emplace_back("normal_stress",
                                 "Normal stress (MPa, compression positive)");
          if (pore_pressure)
            columns.emplace_back("pore_pressure", "Pore pressure (MPa)");
          if (darcy_velocity)
            columns.emplace_back("darcy_vel", "Darcy velocity (m/s)");
          columns.emplace_back("state", "State (log10 s)");
          write_header(f, location.str(), columns);
        }
      for (const auto &name : surface_names)
        write_header(f++,
                     "off fault, observation point " + name,
                     components == 1 ?
                       std::vector<std::pair<std::string, std::string>>{
                         {"t", "Time (s)"},
                         {"disp", "Displacement (m)"},
                         {"vel", "Velocity (m/s)"}} :
                       std::vector<std::pair<std::string, std::string>>{
                         {"t", "Time (s)"},
                         {"disp_1", "Horizontal displacement (m, +x)"},
                         {"disp_2", "Vertical displacement (m, down)"},
                         {"vel_1", "Horizontal velocity (m/s, +x)"},
                         {"vel_2", "Vertical velocity (m/s, down)"}});
      write_header(f++,
                   "global",
                   {{"t", "Time (s)"},
                    {"max_slip_rate", "Max slip rate (log10 m/s)"},
                    {"moment_rate", "Moment rate (N/s per m along strike)"}});
      const std::array<std::array<std::string, 3>, 3> profiles = {
        {{{"slip profiles", "slip", "Slip (m)"}},
         {{"shear stress profiles", "shear_stress", "Shear stress (MPa)"}},
         {{"normal stress profiles",
           "normal_stress",
           "Normal stress (MPa, compression positive)"}}}};
      for (unsigned int i = 0; i < (normal_stress ? 3 : 1); ++i, ++f)
        {
          write_header(f,
                       "on fault, " + profiles[i][0],
                       {{"t", "Time (s)"},
                        {"max_slip_rate", "Max slip rate (log10 m/s)"},
                        {profiles[i][1],
                         profiles[i][2] +
                           ", one column per position of row 1"}},
                       "Here is the data.",
                       "# Row #1 = 0 0, then the positions along the "
                       "contact (m)\n");
          row << 0. << 0.;
          for (const double x : profile_positions)
            row << x;
          row.write_line(*streams[f]);
        }
    }


    double
    SeasFiles::sort_sample(const Sample &sample)
    {
      const unsigned int n = order.size();
      slip.resize(n);
      rate.resize(n);
      log10_rate.resize(n);
      stress.resize(n);
      normal.resize(normal_stress ? n : 0);
      log10_state.resize(n);
      pressure.resize(pore_pressure ? n : 0);
      darcy.resize(darcy_velocity ? n : 0);
      double max_rate = 0;
      for (unsigned int i = 0; i < n; ++i)
        {
          const unsigned int k = order[i];
          const double       V = sample.slip_rates[k];
          // (the friction stress has the direction of the slip rate)
          const double sign =
            parameters.slip_sign * (!sample.slip_rate_components.empty() &&
                                        sample.slip_rate_components[k][0] < 0 ?
                                      -1. :
                                      1.);
          slip[i]       = parameters.slip_sign * sample.slip[k][0];
          rate[i]       = V;
          log10_rate[i] = std::log10(std::max(V, 1e-300));
          stress[i]     = sign * sample.shear_stresses[k] / 1e6;
          if (normal_stress)
            normal[i] = sample.normal_stresses[k] / 1e6;
          log10_state[i] = sample.log10_states[k];
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
      if (profile_due(record) && writing)
        write_profile(record.t, *record.sample);
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
          if (normal_stress)
            row << interpolate(where, normal.data());
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
          // (two components: x, and the vertical one positive down)
          row.precise(t);
          for (const auto *values :
               {&sample.observations, &sample.observation_rates})
            for (unsigned int c = 0; c < components; ++c)
              row << (c == 1 ? -1. : factor) * (*values)[components * i + c];
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
      const double log10_max_rate = sort_sample(sample);
      for (unsigned int i = 0; i < (normal_stress ? 3 : 1); ++i)
        {
          const double *values = i == 0 ? slip.data() :
                                 i == 1 ? stress.data() :
                                          normal.data();
          row.precise(t) << log10_max_rate;
          for (const auto &where : profile)
            row << interpolate(where, values);
          row.write_line(*streams[first_profile + i]);
        }
      check();
    }


  } // namespace output
} // namespace rsfcycle
