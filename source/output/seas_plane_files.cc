// SPDX-License-Identifier: LGPL-2.1-or-later
// The SEAS files of 3D models (output/seas_plane_files.h).
#include <algorithm>
#include <boost/serialization/vector.hpp>
#include <cmath>
#include <rsfcycle/format.h>
#include <rsfcycle/output/seas_plane_files.h>
#include <sstream>
#include <stdexcept>

namespace rsfcycle
{
  namespace output
  {
    namespace
    {
      /** The distinct values of v (within tol), sorted. */
      std::vector<double>
      distinct(std::vector<double> v, const double tol)
      {
        std::sort(v.begin(), v.end());
        std::vector<double> result;
        for (const double x : v)
          if (result.empty() || x > result.back() + tol)
            result.push_back(x);
        return result;
      }

      /** The index of the value nearest x in sorted v. */
      unsigned int
      nearest(const std::vector<double> &v, const double x)
      {
        const auto upper = std::lower_bound(v.begin(), v.end(), x);
        if (upper == v.begin())
          return 0;
        if (upper == v.end() || x - *(upper - 1) < *upper - x)
          return upper - v.begin() - 1;
        return upper - v.begin();
      }

      double
      log10_of(const double v)
      {
        return std::log10(std::max(std::abs(v), 1e-300));
      }

      std::string
      km(const double x)
      {
        std::ostringstream text;
        text << x / 1e3;
        return text.str();
      }
    } // namespace


    SeasPlaneFiles::SeasPlaneFiles(const std::string    &dir,
                                   const SeasParameters &parameters,
                                   const Layout         &layout)
      : SeasFileSet(parameters)
      , weights(layout.weights)
      , axes(layout.slip_axes)
    {
      const std::string entry = "Output/SEAS/";
      const unsigned    n     = layout.points.size();
      if (n == 0)
        throw std::invalid_argument(entry +
                                    "Problem: the contact has no nodes");
      // the fault plane y = const of the mesh
      double extent = 0, y_low = layout.points[0][1], y_high = y_low;
      for (const auto &p : layout.points)
        {
          extent = std::max({extent, std::abs(p[0]), std::abs(p[2])});
          y_low  = std::min(y_low, p[1]);
          y_high = std::max(y_high, p[1]);
        }
      const double tol = 1e-6 * std::max(extent, 1.);
      if (y_high - y_low > tol)
        throw std::invalid_argument(
          entry +
          "Problem: the SEAS files of 3D models need the contact in "
          "a plane y = const of the mesh (x along strike, z up); "
          "its nodes span y = " +
          format_number(y_low) + " ... " + format_number(y_high) + " m");
      // (rounding of the mesh's rotation snapped to the planes x = 0, z = 0)
      const auto snap = [tol](const double v) {
        return std::abs(v) < tol ? 0. : v;
      };
      for (const auto &p : layout.points)
        plane.push_back({{snap(p[0]), snap(-p[2])}});

      // the nodes as a grid of lines x2 = const and x3 = const
      std::vector<double> x2s, x3s;
      for (const auto &p : plane)
        {
          x2s.push_back(p[0]);
          x3s.push_back(p[1]);
        }
      grid_x2 = distinct(x2s, tol);
      grid_x3 = distinct(x3s, tol);
      grid.assign(grid_x2.size() * grid_x3.size(), -1);
      for (unsigned int k = 0; k < n; ++k)
        grid[nearest(grid_x2, plane[k][0]) * grid_x3.size() +
             nearest(grid_x3, plane[k][1])] = k;
      element_size = std::max(extent, 1.);
      for (const auto *lines : {&grid_x2, &grid_x3})
        for (unsigned int i = 1; i < lines->size(); ++i)
          element_size = std::min(element_size, (*lines)[i] - (*lines)[i - 1]);

      for (const auto &x : parameters.plane_stations)
        {
          stations.push_back(locate(x[0], x[1], "Plane stations"));
          add_file(dir, parameters.plane_station_file(x));
        }
      if (!layout.station_names.empty() && layout.observation_components != 3)
        throw std::invalid_argument(
          "Mesh file/Observation components = up: the SEAS off-fault "
          "stations (blkst_NAME) of 3D models need all three components");
      first_block = file_paths.size();
      for (const auto &name : layout.station_names)
        {
          block_names.push_back(name);
          add_file(dir, "blkst_" + name);
        }
      global  = add_file(dir, "global.dat");
      rupture = add_file(dir, "rupture.dat");

      const auto line = [&](const std::array<double, 4> &range,
                            const bool                   along_strike,
                            std::vector<double>         &positions,
                            std::vector<Bilinear>       &where) {
        const double count =
          std::floor((range[2] - range[1]) / range[3] + 1e-9);
        for (long i = 0; i <= static_cast<long>(count); ++i)
          {
            const double s = range[1] + i * range[3];
            positions.push_back(s);
            where.push_back(along_strike ?
                              locate(s, range[0], "Strike profile") :
                              locate(range[0], s, "Depth profile"));
          }
      };
      line(parameters.strike_profile, true, strike_x2, strike_line);
      line(parameters.depth_profile, false, depth_x3, depth_line);
      first_profile = file_paths.size();
      for (const std::string suffix : {"strike", "depth"})
        for (const std::string field :
             {"slip_2", "slip_3", "shear_stress_2", "shear_stress_3"})
          add_file(dir, field + "_" + suffix + ".dat");

      armed.assign(n, 1);
    }


    SeasPlaneFiles::Bilinear
    SeasPlaneFiles::locate(const double       x2,
                           const double       x3,
                           const std::string &entry) const
    {
      const auto fail = [&](const std::string &why) {
        throw std::invalid_argument("Output/SEAS/" + entry + ": (x2, x3) = (" +
                                    format_number(x2) + ", " +
                                    format_number(x3) + ") m " + why);
      };
      const double tol = 1e-6 * element_size;
      if (x2 < grid_x2.front() - tol || x2 > grid_x2.back() + tol ||
          x3 < grid_x3.front() - tol || x3 > grid_x3.back() + tol)
        fail("lies outside the contact nodes (x2 " +
             format_number(grid_x2.front()) + " ... " +
             format_number(grid_x2.back()) + " m, x3 " +
             format_number(grid_x3.front()) + " ... " +
             format_number(grid_x3.back()) + " m)");
      // the cell [i, i + 1] x [j, j + 1] of the grid and the weights of its
      // upper lines
      const auto cell = [](const std::vector<double> &v, const double x) {
        if (v.size() == 1)
          return std::make_pair(0u, 0.);
        const unsigned int i = std::min<unsigned int>(
          std::max<long>(std::upper_bound(v.begin(), v.end(), x) - v.begin() -
                           1,
                         0),
          v.size() - 2);
        return std::make_pair(
          i, std::clamp((x - v[i]) / (v[i + 1] - v[i]), 0., 1.));
      };
      const auto [i, s] = cell(grid_x2, x2);
      const auto [j, r] = cell(grid_x3, x3);
      Bilinear                                         where;
      const std::array<std::array<unsigned int, 2>, 4> corners = {
        {{{i, j}}, {{i + 1, j}}, {{i, j + 1}}, {{i + 1, j + 1}}}};
      const std::array<double, 4> w = {
        {(1 - s) * (1 - r), s * (1 - r), (1 - s) * r, s * r}};
      for (unsigned int c = 0; c < 4; ++c)
        {
          where.weights[c] = w[c];
          where.nodes[c]   = -1;
          if (w[c] == 0)
            continue;
          where.nodes[c] = grid[corners[c][0] * grid_x3.size() + corners[c][1]];
          if (where.nodes[c] < 0)
            fail("is not surrounded by four contact nodes (the SEAS files "
                 "of 3D models interpolate on a grid of lines x = const "
                 "and z = const, as a structured mesh of the contact has)");
        }
      return where;
    }


    double
    SeasPlaneFiles::at(const Bilinear            &where,
                       const std::vector<double> &v) const
    {
      double value = 0;
      for (unsigned int c = 0; c < 4; ++c)
        if (where.nodes[c] >= 0)
          value += where.weights[c] * v[where.nodes[c]];
      return value;
    }


    void
    SeasPlaneFiles::write_headers()
    {
      const auto &p = parameters;
      for (unsigned int i = 0; i < stations.size(); ++i)
        write_header(i,
                     "on fault, " + km(p.plane_stations[i][0]) +
                       " km along strike, " + km(p.plane_stations[i][1]) +
                       " km depth",
                     {{"t", "Time (s)"},
                      {"slip_2", "Slip_2, along strike (m)"},
                      {"slip_3", "Slip_3, along dip, down (m)"},
                      {"slip_rate_2", "Slip_rate_2 (log10 |m/s|)"},
                      {"slip_rate_3", "Slip_rate_3 (log10 |m/s|)"},
                      {"shear_stress_2", "Shear_stress_2 (MPa)"},
                      {"shear_stress_3", "Shear_stress_3 (MPa)"},
                      {"state", "State (log10 s)"}});
      for (unsigned int i = 0; i < block_names.size(); ++i)
        write_header(
          first_block + i,
          "off fault, observation point " + block_names[i] +
            " (1 = fault normal, the mesh's y; 2 = along strike, x; 3 = "
            "down, -z)",
          {{"t", "Time (s)"},
           {"disp_1", "Displacement_1 (m)"},
           {"disp_2", "Displacement_2 (m)"},
           {"disp_3", "Displacement_3 (m)"},
           {"vel_1", "Velocity_1 (m/s)"},
           {"vel_2", "Velocity_2 (m/s)"},
           {"vel_3", "Velocity_3 (m/s)"}});
      write_header(global,
                   "global",
                   {{"t", "Time (s)"},
                    {"max_slip_rate", "Max slip rate (log10 m/s)"},
                    {"moment_rate", "Moment rate (N m/s)"}});
      write_header(rupture,
                   "on fault, rupture fronts: the first time of each event "
                   "at which a node's slip rate reaches " +
                     format_number(p.rupture_threshold) + " m/s",
                   {{"x2", "x2, along strike (m)"},
                    {"x3", "x3, depth (m)"},
                    {"t", "Time (s)"}},
                   "Here is the data.");
      unsigned int f = first_profile;
      for (const bool strike : {true, false})
        for (const std::string field : {"Slip_2 (m)",
                                        "Slip_3 (m)",
                                        "Shear_stress_2 (MPa)",
                                        "Shear_stress_3 (MPa)"})
          {
            const auto &range = strike ? p.strike_profile : p.depth_profile;
            std::string line =
              strike ? "along strike at depth " + km(range[0]) + " km" :
                       "down dip at " + km(range[0]) + " km along strike";
            write_header(f,
                         "on fault, profiles " + line,
                         {{"t", "Time (s)"},
                          {"max_slip_rate", "Max slip rate (log10 m/s)"},
                          {"values", field + ", one column per position"}},
                         "Here is the data.",
                         std::string("# Row #1 = 0 0, then the positions ") +
                           (strike ? "x2 (m)\n" : "x3, depth (m)\n"));
            row << 0. << 0.;
            for (const double x : strike ? strike_x2 : depth_x3)
              row << x;
            row.write_line(*streams[f++]);
          }
    }


    void
    SeasPlaneFiles::fill(const Sample &sample)
    {
      const unsigned int n = plane.size();
      for (auto *v : {&slip_2,
                      &slip_3,
                      &log10_rate_2,
                      &log10_rate_3,
                      &log10_rate,
                      &stress_2,
                      &stress_3,
                      &log10_state})
        v->resize(n);
      double max_rate = 0;
      for (unsigned int k = 0; k < n; ++k)
        {
          // the mesh-frame x and -z of a node's two tangential components
          const auto along = [&](const std::array<double, 2> &u) {
            std::array<double, 2> w{};
            for (unsigned int a = 0; a < 2; ++a)
              {
                w[0] += u[a] * axes[a][0];
                w[1] -= u[a] * axes[a][2];
              }
            return w;
          };
          const auto   s  = along(sample.slip[k]);
          const auto   v  = along(sample.slip_rate_components[k]);
          const double V  = sample.slip_rates[k];
          slip_2[k]       = s[0];
          slip_3[k]       = s[1];
          log10_rate_2[k] = log10_of(v[0]);
          log10_rate_3[k] = log10_of(v[1]);
          log10_rate[k]   = log10_of(V);
          // the friction stress acts along the slip rate
          const double tau = sample.shear_stresses[k] / 1e6;
          stress_2[k]      = V > 0 ? tau * v[0] / V : 0.;
          stress_3[k]      = V > 0 ? tau * v[1] / V : 0.;
          log10_state[k]   = sample.log10_states[k];
          max_rate         = std::max(max_rate, V);
        }
      log10_max_rate = log10_of(max_rate);
    }


    void
    SeasPlaneFiles::track_rupture(const double t)
    {
      const double       threshold = std::log10(parameters.rupture_threshold);
      const bool         first     = previous_log10_rate.empty();
      const unsigned int n         = plane.size();
      for (unsigned int k = 0; k < n; ++k)
        if (armed[k] && log10_rate[k] >= threshold)
          {
            double arrival = t;
            if (!first && previous_log10_rate[k] < threshold)
              arrival = previous_t + (t - previous_t) *
                                       (threshold - previous_log10_rate[k]) /
                                       (log10_rate[k] - previous_log10_rate[k]);
            armed[k] = 0;
            if (writing)
              {
                row << plane[k][0] << plane[k][1];
                row.precise(arrival);
                row.write_line(*streams[rupture]);
              }
          }
      if (log10_max_rate < threshold)
        armed.assign(n, 1);
      previous_log10_rate = log10_rate;
      previous_t          = t;
    }


    void
    SeasPlaneFiles::write(const Record &record)
    {
      const double t      = record.t;
      const auto  &sample = *record.sample;
      fill(sample);
      if (writing)
        {
          for (unsigned int i = 0; i < stations.size(); ++i)
            {
              const auto &w = stations[i];
              row.precise(t)
                << at(w, slip_2) << at(w, slip_3) << at(w, log10_rate_2)
                << at(w, log10_rate_3) << at(w, stress_2) << at(w, stress_3)
                << at(w, log10_state);
              row.write_line(*streams[i]);
            }
          const double factor = parameters.mirror ? 0.5 : 1.;
          for (unsigned int i = 0; i < block_names.size(); ++i)
            {
              // the mesh's x, y, z as 2, 1, -3
              const double *u = &sample.observations[3 * i];
              const double *v = &sample.observation_rates[3 * i];
              row.precise(t)
                << factor * u[1] << factor * u[0] << -factor * u[2]
                << factor * v[1] << factor * v[0] << -factor * v[2];
              row.write_line(*streams[first_block + i]);
            }
          double moment_rate = 0;
          for (unsigned int k = 0; k < plane.size(); ++k)
            moment_rate += weights[k] * sample.slip_rates[k];
          row.precise(t) << log10_max_rate
                         << parameters.shear_modulus * moment_rate;
          row.write_line(*streams[global]);
        }
      track_rupture(t);
      if (profile_due(record) && writing)
        {
          unsigned int f = first_profile;
          for (const auto *line : {&strike_line, &depth_line})
            for (const auto *field : {&slip_2, &slip_3, &stress_2, &stress_3})
              {
                row.precise(t) << log10_max_rate;
                for (const auto &w : *line)
                  row << at(w, *field);
                row.write_line(*streams[f++]);
              }
        }
      if (writing)
        check();
    }


    void
    SeasPlaneFiles::save(boost::archive::binary_oarchive &archive) const
    {
      SeasFileSet::save(archive);
      archive << previous_t << previous_log10_rate << armed;
    }


    void
    SeasPlaneFiles::load(boost::archive::binary_iarchive &archive)
    {
      SeasFileSet::load(archive);
      archive >> previous_t >> previous_log10_rate >> armed;
    }
  } // namespace output
} // namespace rsfcycle
