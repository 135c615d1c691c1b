// SPDX-License-Identifier: LGPL-2.1-or-later
// The SEAS files of 3D models (output/seas_plane_files.h).
#include <algorithm>
#include <boost/serialization/vector.hpp>
#include <cmath>
#include <deal.II/base/function_parser.h>
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

      /**
       * The nodes (x2, x3) where the function `expression` of x2 and x3 is
       * > 0 (the SEAS regions); entry names it in a refusal.
       */
      std::vector<char>
      region(const std::string                        &expression,
             const std::vector<std::array<double, 2>> &points,
             const std::string                        &entry)
      {
        std::vector<char> inside(points.size(), 1);
        if (expression == "1")
          return inside;
        dealii::FunctionParser<2> f(1);
        try
          {
            f.initialize("x2,x3", expression, {});
          }
        catch (...)
          {
            throw std::invalid_argument("Output/SEAS/" + entry + " = '" +
                                        expression +
                                        "': not a function of x2 and x3");
          }
        // (to the micrometre: a node on the region's edge is inside)
        const auto um = [](const double x) {
          return std::round(x * 1e6) / 1e6;
        };
        for (unsigned int k = 0; k < points.size(); ++k)
          inside[k] =
            f.value(dealii::Point<2>(um(points[k][0]), um(points[k][1]))) > 0;
        return inside;
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
      , pore_pressure(layout.pore_pressure)
      , darcy_velocity(layout.darcy_velocity)
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
      grid_x2      = distinct(x2s, tol);
      grid_x3      = distinct(x3s, tol);
      element_size = std::max(extent, 1.);
      for (const auto *lines : {&grid_x2, &grid_x3})
        for (unsigned int i = 1; i < lines->size(); ++i)
          element_size = std::min(element_size, (*lines)[i] - (*lines)[i - 1]);
      in_moment = region(parameters.moment_region, plane, "Moment rate region");
      in_rupture = region(parameters.rupture_region, plane, "Rupture region");
      if (!parameters.vw_moment_region.empty())
        in_vw =
          region(parameters.vw_moment_region, plane, "VW moment rate region");
      // the load or creep nodes one cell beyond the contact's grid: every
      // node of the widened grid that is no contact node but lies next to
      // one along a grid line
      const bool boundary = parameters.boundary_slip_rate != 0 &&
                            grid_x2.size() > 1 && grid_x3.size() > 1;
      if (boundary)
        for (auto *lines : {&grid_x2, &grid_x3})
          {
            auto &v = *lines;
            v.insert(v.begin(), 2 * v[0] - v[1]);
            v.push_back(2 * v.back() - v[v.size() - 2]);
          }
      const unsigned int m2 = grid_x2.size(), m3 = grid_x3.size();
      grid.assign(m2 * m3, -1);
      for (unsigned int k = 0; k < n; ++k)
        grid[nearest(grid_x2, plane[k][0]) * m3 +
             nearest(grid_x3, plane[k][1])] = k;
      if (boundary)
        for (unsigned int i = 0; i < m2; ++i)
          for (unsigned int j = 0; j < m3; ++j)
            {
              if (grid[i * m3 + j] >= 0)
                continue;
              int next = -1;
              for (const auto &[di, dj] : {std::make_pair(-1, 0),
                                           std::make_pair(1, 0),
                                           std::make_pair(0, -1),
                                           std::make_pair(0, 1)})
                {
                  const long a = long(i) + di, b = long(j) + dj;
                  if (a >= 0 && a < long(m2) && b >= 0 && b < long(m3) &&
                      grid[a * m3 + b] >= 0 && grid[a * m3 + b] < long(n))
                    next = grid[a * m3 + b];
                }
              if (next < 0)
                continue;
              grid[i * m3 + j] = plane.size();
              plane.push_back({{grid_x2[i], grid_x3[j]}});
              neighbour.push_back(next);
            }

      for (unsigned int i = 0; i < parameters.plane_stations.size(); ++i)
        {
          const auto &x = parameters.plane_stations[i];
          stations.push_back(locate(x[0], x[1], "Plane stations"));
          add_file(dir,
                   parameters.plane_station_file(i) +
                     conventions.station_extension,
                   true);
        }
      if (conventions.off_fault && !layout.station_names.empty() &&
          layout.observation_components != 3)
        throw std::invalid_argument(
          "Mesh file/Observation components = up: the SEAS off-fault "
          "stations (blkst_NAME) of 3D models need all three components");
      first_block = file_paths.size();
      if (conventions.off_fault)
        for (const auto &name : layout.station_names)
          {
            block_names.push_back(name);
            add_file(dir, "blkst_" + name, true);
          }
      if (conventions.global)
        global = add_file(dir, "global.dat", true);
      if (conventions.rupture)
        rupture = add_file(dir, "rupture.dat", false);
      if (conventions.catalog)
        catalog = add_file(dir, "catalog.dat", false);

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
        for (const auto &field : profile_fields())
          add_file(dir, field.first + "_" + suffix + ".dat", true);

      std::vector<double> area(weights);
      events = SeasEvents(parameters.rupture_threshold, 10., area);
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
      const auto         &p       = parameters;
      std::vector<Column> columns = {{"t", "Time (s)"},
                                     {"slip_2", "Slip_2 (m)"},
                                     {"slip_3", "Slip_3 (m)"},
                                     {"slip_rate_2", "Slip_rate_2 (log10 m/s)"},
                                     {"slip_rate_3", "Slip_rate_3 (log10 m/s)"},
                                     {"shear_stress_2", "Shear_stress_2 (MPa)"},
                                     {"shear_stress_3",
                                      "Shear_stress_3 (MPa)"}};
      if (pore_pressure)
        columns.emplace_back("pore_pressure", "Pore_pressure (MPa)");
      if (darcy_velocity)
        {
          columns.emplace_back("darcy_vel_2", "Darcy_velocity_2 (m/s)");
          columns.emplace_back("darcy_vel_3", "Darcy_velocity_3 (m/s)");
        }
      columns.emplace_back("state", "State (log10 s)");
      for (unsigned int i = 0; i < stations.size(); ++i)
        write_series_header(i,
                            "on fault, " + km(p.plane_stations[i][0]) +
                              "km along strike, " + km(p.plane_stations[i][1]) +
                              "km depth",
                            columns);
      for (unsigned int i = 0; i < block_names.size(); ++i)
        write_series_header(first_block + i,
                            "off fault, observation point " + block_names[i] +
                              " (1 = fault normal, the mesh's y; 2 = along "
                              "strike, x; 3 = down, -z)",
                            {{"t", "Time (s)"},
                             {"disp_1", "Displacement_1 (m)"},
                             {"disp_2", "Displacement_2 (m)"},
                             {"disp_3", "Displacement_3 (m)"},
                             {"vel_1", "Velocity_1 (m/s)"},
                             {"vel_2", "Velocity_2 (m/s)"},
                             {"vel_3", "Velocity_3 (m/s)"}});
      if (conventions.global)
        {
          columns = {{"t", "Time (s)"},
                     {"max_slip_rate", "Max slip rate (log10 m/s)"},
                     {"moment_rate", "Moment rate (N-m/s)"}};
          if (!in_vw.empty())
            columns.emplace_back("moment_rate_vw",
                                 "Moment rate of VW patch (N-m/s)");
          write_series_header(global,
                              p.moment_region == "1" ?
                                "the whole frictional domain" :
                                "the region " + p.moment_region,
                              columns);
        }
      if (conventions.rupture)
        write_table_header(rupture,
                           {{"x2", "x2 (m)"},
                            {"x3", "x3 (m)"},
                            {"t",
                             "time (s) the slip rate first reaches " +
                               format_number(p.rupture_threshold) +
                               " m/s in the first event; 1e9: never"}});
      if (conventions.catalog)
        write_table_header(catalog,
                           {{"event_no", "Event number"},
                            {"t_start", "Event start time (s)"},
                            {"t_end", "Event end time (s)"},
                            {"rup_area", "Rupture area (m^2)"},
                            {"avg_stress_start",
                             "Stress avg at start time (MPa)"},
                            {"avg_stress_end", "Stress avg at end time (MPa)"},
                            {"avg_slip", "Avg slip in rupture area (m)"}});
      unsigned int f = first_profile;
      for (const bool strike : {true, false})
        for (const auto &[field, text] : profile_fields())
          write_profile_header(f++,
                               strike ? "Strike (m)" : "Depth (m)",
                               strike ? "x2" : "x3",
                               {field, text},
                               strike ? strike_x2 : depth_x3);
    }


    void
    SeasPlaneFiles::fill(const double t, const Sample &sample)
    {
      const unsigned int n = sample.slip_rates.size(), m = plane.size();
      for (auto *v : {&slip_2,
                      &slip_3,
                      &log10_rate_2,
                      &log10_rate_3,
                      &log10_rate,
                      &stress_2,
                      &stress_3,
                      &log10_state,
                      &pressure,
                      &darcy_2,
                      &darcy_3})
        v->resize(m);
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
          pressure[k] = pore_pressure ? sample.pore_pressures[k] / 1e6 : 0.;
          darcy_2[k]  = darcy_velocity ? sample.darcy_velocities[k][0] : 0.;
          darcy_3[k]  = darcy_velocity ? sample.darcy_velocities[k][1] : 0.;
          if (in_moment[k])
            max_rate = std::max(max_rate, V);
        }
      // the creep nodes beyond the contact: the boundary's slip along
      // strike, the stresses and state of the contact node next to them
      const double V_b = parameters.boundary_slip_rate;
      for (unsigned int k = n; k < m; ++k)
        {
          const unsigned int j = neighbour[k - n];
          slip_2[k]            = V_b * t;
          slip_3[k]            = 0;
          log10_rate_2[k] = log10_rate[k] = log10_of(V_b);
          log10_rate_3[k]                 = log10_of(0);
          stress_2[k]                     = stress_2[j];
          stress_3[k]                     = stress_3[j];
          log10_state[k]                  = log10_state[j];
          pressure[k]                     = pressure[j];
          darcy_2[k]                      = darcy_2[j];
          darcy_3[k]                      = darcy_3[j];
        }
      log10_max_rate = log10_of(max_rate);
    }


    void
    SeasPlaneFiles::write_events(const std::optional<SeasEvents::Row> &row)
    {
      if (row && conventions.catalog && writing)
        {
          this->row << row->number;
          this->row.precise(row->start);
          this->row.precise(row->end)
            << row->area << row->stress_start << row->stress_end << row->slip;
          write_row(catalog);
        }
      if (events.first_over())
        write_rupture();
    }


    void
    SeasPlaneFiles::write_rupture()
    {
      if (rupture_written)
        return;
      rupture_written = true;
      if (!writing || !conventions.rupture)
        return;
      const auto &times = events.rupture_times();
      for (unsigned int k = 0; k < times.size(); ++k)
        if (in_rupture[k])
          {
            row << plane[k][0] << plane[k][1];
            row.precise(times[k]);
            write_row(rupture);
          }
    }


    void
    SeasPlaneFiles::write(const Record &record)
    {
      write_rows(record);
    }


    void
    SeasPlaneFiles::write_rows(const Record &record)
    {
      const double t      = record.t;
      const auto  &sample = *record.sample;
      fill(t, sample);
      const bool profile = profile_due(record);
      write_events(
        events.update(t,
                      {&log10_rate, &stress_2, &stress_3, &slip_2, &slip_3}));
      if (!writing)
        return;
      for (unsigned int i = 0; i < stations.size(); ++i)
        {
          const auto &w = stations[i];
          row.precise(t) << at(w, slip_2) << at(w, slip_3)
                         << at(w, log10_rate_2) << at(w, log10_rate_3)
                         << at(w, stress_2) << at(w, stress_3);
          if (pore_pressure)
            row << at(w, pressure);
          if (darcy_velocity)
            row << at(w, darcy_2) << at(w, darcy_3);
          row << at(w, log10_state);
          write_row(i, t);
        }
      const double factor = parameters.mirror ? 0.5 : 1.;
      for (unsigned int i = 0; i < block_names.size(); ++i)
        {
          // the mesh's x, y, z as 2, 1, -3
          const double *u = &sample.observations[3 * i];
          const double *v = &sample.observation_rates[3 * i];
          row.precise(t) << factor * u[1] << factor * u[0] << -factor * u[2]
                         << factor * v[1] << factor * v[0] << -factor * v[2];
          write_row(first_block + i, t);
        }
      if (conventions.global)
        {
          double moment_rate = 0, vw_rate = 0;
          for (unsigned int k = 0; k < sample.slip_rates.size(); ++k)
            {
              const double m = weights[k] * sample.slip_rates[k];
              moment_rate += in_moment[k] ? m : 0.;
              vw_rate += !in_vw.empty() && in_vw[k] ? m : 0.;
            }
          row.precise(t) << log10_max_rate
                         << parameters.shear_modulus * moment_rate;
          if (!in_vw.empty())
            row << parameters.shear_modulus * vw_rate;
          write_row(global, t);
        }
      if (profile)
        {
          unsigned int f = first_profile;
          for (const auto *line : {&strike_line, &depth_line})
            for (const auto *field :
                 {&slip_2, &slip_3, &stress_2, &stress_3, &pressure})
              if (field != &pressure || pore_pressure)
                {
                  row.precise(t) << log10_max_rate;
                  for (const auto &w : *line)
                    row << at(w, *field);
                  write_row(f++, t);
                }
        }
      check();
    }


    void
    SeasPlaneFiles::finish(const Record &record)
    {
      // an event below the threshold for less than the quiet time when the
      // run ends is over; rupture.dat in any case
      write_events(events.pending());
      write_rupture();
      SeasFileSet::finish(record);
    }


    void
    SeasPlaneFiles::save(boost::archive::binary_oarchive &archive) const
    {
      SeasFileSet::save(archive);
      archive << events << rupture_written;
    }


    void
    SeasPlaneFiles::load(boost::archive::binary_iarchive &archive)
    {
      SeasFileSet::load(archive);
      archive >> events >> rupture_written;
    }
  } // namespace output
} // namespace rsfcycle
