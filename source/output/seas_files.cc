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
      const auto               &s = layout.positions;
      const unsigned int        n = s.size();
      std::vector<unsigned int> by_position(n);
      for (unsigned int k = 0; k < n; ++k)
        by_position[k] = k;
      std::sort(by_position.begin(),
                by_position.end(),
                [&](unsigned i, unsigned j) { return s[i] < s[j]; });
      for (const unsigned int k : by_position)
        {
          order.push_back(k);
          positions.push_back(s[k]);
          weights.push_back(layout.weights[k]);
        }
      element_size = n > 1 ? positions.back() - positions.front() : 0;
      for (unsigned int k = 1; k < n; ++k)
        element_size = std::min(element_size, positions[k] - positions[k - 1]);
      // the load or creep nodes one cell beyond each end of the contact
      if (parameters.boundary_slip_rate != 0 && n > 1)
        {
          const double first = positions[0] - (positions[1] - positions[0]),
                       last  = 2 * positions[n - 1] - positions[n - 2];
          order.insert(order.begin(), -1);
          positions.insert(positions.begin(), first);
          weights.insert(weights.begin(), 0.);
          order.push_back(-1);
          positions.push_back(last);
          weights.push_back(0.);
        }

      for (const double x : parameters.fault_stations)
        {
          stations.push_back(locate(parameters.origin + x, "Fault stations"));
          add_file(dir, parameters.fault_station_file(x), true);
        }
      if (conventions.off_fault)
        for (const auto &name : layout.station_names)
          {
            surface_names.push_back(name);
            add_file(dir, "srfst_" + name, true);
          }
      const auto  &range = parameters.slip_profile;
      const double count = std::floor((range[1] - range[0]) / range[2] + 1e-9);
      for (long i = 0; i <= static_cast<long>(count); ++i)
        {
          profile_positions.push_back(range[0] + i * range[2]);
          profile.push_back(locate(parameters.origin + profile_positions.back(),
                                   "Slip profile"));
        }
      if (conventions.global)
        add_file(dir, "global.dat", true);
      first_profile = file_paths.size();
      profile_fields.emplace_back("slip", "Slip (m)");
      if (normal_stress || pore_pressure)
        {
          profile_fields.emplace_back("shear_stress", "Shear stress (MPa)");
          profile_fields.emplace_back("normal_stress",
                                      "Effective normal stress (MPa, "
                                      "compression positive)");
        }
      if (darcy_velocity)
        profile_fields.emplace_back("darcy_vel", "Darcy velocity (m/s)");
      for (const auto &field : profile_fields)
        add_file(dir,
                 field.first == "slip" ? conventions.slip_profile_file :
                                         field.first + ".dat",
                 true);
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
                   << conventions.station_location;
          std::vector<Column> columns = {{"t", "Time (s)"},
                                         {"slip", "Slip (m)"},
                                         {"slip_rate", "Slip rate (log10 m/s)"},
                                         {"shear_stress",
                                          "Shear stress (MPa)"}};
          if (normal_stress)
            columns.emplace_back("normal_stress",
                                 "Normal stress (MPa, compression positive)");
          if (pore_pressure)
            columns.emplace_back("pore_pressure", "Pore pressure (MPa)");
          if (darcy_velocity)
            columns.emplace_back("darcy_vel", "Darcy velocity (m/s)");
          columns.emplace_back("state", "State (log10 s)");
          write_series_header(f, location.str(), columns);
        }
      for (const auto &name : surface_names)
        write_series_header(
          f++,
          "off fault, observation point " + name,
          components == 1 ?
            std::vector<Column>{{"t", "Time (s)"},
                                {"disp", "Displacement (m)"},
                                {"vel", "Velocity (m/s)"}} :
            std::vector<Column>{
              {"t", "Time (s)"},
              {"disp_1", "Horizontal displacement (m), positive in +x"},
              {"disp_2", "Vertical displacement (m), positive down"},
              {"vel_1", "Horizontal velocity (m/s), positive in +x"},
              {"vel_2", "Vertical velocity (m/s), positive down"}});
      if (conventions.global)
        write_series_header(f++,
                            "frictional domain",
                            {{"t", "Time (s)"},
                             {"max_slip_rate", "Max slip rate (log10 m/s)"},
                             {"moment_rate",
                              "Moment density rate (N/s), G int V ds"}});
      const std::string positions_text =
        conventions.position_name == "x_d" ? "Distance down dip (m)" :
        conventions.position_name == "z" &&
            conventions.station_location == "km depth" ?
                                             "Depth (m)" :
                                             "Position along the fault (m)";
      for (const auto &field : profile_fields)
        write_profile_header(f++,
                             positions_text,
                             conventions.position_name,
                             field,
                             profile_positions);
    }


    double
    SeasFiles::sort_sample(const double t, const Sample &sample)
    {
      const unsigned int n = order.size();
      slip.resize(n);
      rate.resize(n);
      log10_rate.resize(n);
      stress.resize(n);
      normal.resize(normal_stress || pore_pressure ? n : 0);
      log10_state.resize(n);
      pressure.resize(pore_pressure ? n : 0);
      darcy.resize(darcy_velocity ? n : 0);
      double max_rate = 0;
      for (unsigned int i = 0; i < n; ++i)
        {
          if (order[i] < 0)
            continue;
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
          if (normal_stress || pore_pressure)
            normal[i] = sample.normal_stresses[k] / 1e6;
          log10_state[i] = sample.log10_states[k];
          if (pore_pressure)
            pressure[i] = sample.pore_pressures[k] / 1e6;
          if (darcy_velocity)
            darcy[i] = sample.darcy_velocities[k][0];
          max_rate = std::max(max_rate, V);
        }
      // a boundary node: the boundary's slip, the next contact node's
      // stresses, state and fluid
      for (unsigned int i = 0; i < n; ++i)
        if (order[i] < 0)
          {
            const unsigned int j = i == 0 ? 1 : n - 2;
            const double       V = std::abs(parameters.boundary_slip_rate);
            slip[i]              = parameters.boundary_slip_rate * t;
            rate[i]              = V;
            log10_rate[i]        = std::log10(std::max(V, 1e-300));
            stress[i]            = stress[j];
            if (!normal.empty())
              normal[i] = normal[j];
            log10_state[i] = log10_state[j];
            if (pore_pressure)
              pressure[i] = pressure[j];
            if (darcy_velocity)
              darcy[i] = darcy[j];
          }
      return std::log10(std::max(max_rate, 1e-300));
    }


    void
    SeasFiles::write(const Record &record)
    {
      write_rows(record);
    }


    void
    SeasFiles::write_rows(const Record &record)
    {
      const bool profile = profile_due(record);
      if (!writing)
        return;
      current        = record.sample;
      log10_max_rate = sort_sample(record.t, *record.sample);
      write_step(record.t);
      if (profile)
        write_profile(record.t);
      check();
    }


    void
    SeasFiles::write_step(const double t)
    {
      unsigned int f = 0;
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
          write_row(f++, t);
        }
      const double  factor = parameters.mirror ? 0.5 : 1.;
      const Sample &sample = *current;
      for (unsigned int i = 0; i < surface_names.size(); ++i)
        {
          // (two components: x, and the vertical one positive down)
          row.precise(t);
          for (const auto *values :
               {&sample.observations, &sample.observation_rates})
            for (unsigned int c = 0; c < components; ++c)
              row << (c == 1 ? -1. : factor) * (*values)[components * i + c];
          write_row(f++, t);
        }
      if (conventions.global)
        {
          // G int V ds by the contact nodes' lumped weights
          double moment_rate = 0;
          for (unsigned int i = 0; i < rate.size(); ++i)
            moment_rate += weights[i] * rate[i];
          row.precise(t) << log10_max_rate
                         << parameters.shear_modulus * moment_rate;
          write_row(f, t);
        }
    }


    void
    SeasFiles::write_profile(const double t)
    {
      for (unsigned int i = 0; i < profile_fields.size(); ++i)
        {
          const std::string &name   = profile_fields[i].first;
          const double      *values = name == "slip"          ? slip.data() :
                                      name == "shear_stress"  ? stress.data() :
                                      name == "normal_stress" ? normal.data() :
                                                                darcy.data();
          row.precise(t) << log10_max_rate;
          for (const auto &where : profile)
            row << interpolate(where, values);
          write_row(first_profile + i, t);
        }
    }


  } // namespace output
} // namespace rsfcycle
