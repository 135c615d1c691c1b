// SPDX-License-Identifier: LGPL-2.1-or-later
#include <algorithm>
#include <rsfcycle/output/base_profile.h>

namespace rsfcycle
{
  namespace output
  {
    void
    BaseProfile::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.declare_entry("Profile interval",
                        "1",
                        Double(0),
                        "Simulated time between rows of base-profile.csv "
                        "while slip is slow (max V at most 2 v0 and no "
                        "event) [s]");
      prm.declare_entry("Event profile interval",
                        "0.005",
                        Double(0),
                        "Simulated time between rows of base-profile.csv "
                        "during events and while max V exceeds 2 v0 [s]");
    }


    BaseProfile::BaseProfile(const std::string      &dir,
                             const Layout           &layout,
                             const OutputParameters &output)
      : CsvFile(dir, "base-profile.csv")
      , layout(layout)
      , interval(output.profile_interval)
      , fast_interval(output.event_profile_interval)
    {
      const auto        &s = layout.positions;
      const auto        &z = layout.lateral_positions;
      const unsigned int n = s.size();
      order.resize(n);
      for (unsigned int k = 0; k < n; ++k)
        order[k] = k;
      std::sort(order.begin(), order.end(), [&](unsigned int i, unsigned j) {
        if (s[i] != s[j])
          return s[i] < s[j];
        return !z.empty() && z[i] < z[j];
      });
    }


    void
    BaseProfile::write_header(std::ostream &out)
    {
      const bool lateral = !layout.lateral_positions.empty();
      out << "# slip rate [m/s] of the contact nodes; first row: "
             "position along the base [m]"
          << (lateral ? " (then the z coordinate in the second row)" : "")
          << "\n"
          << "time_s";
      for (const unsigned int k : order)
        out << "," << layout.positions[k];
      out << "\n";
      if (lateral)
        {
          out << "z_m";
          for (const unsigned int k : order)
            out << "," << layout.lateral_positions[k];
          out << "\n";
        }
    }


    void
    BaseProfile::start(const Record &record)
    {
      write_row(record.t, record.sample->slip_rates);
    }


    void
    BaseProfile::write(const Record &record)
    {
      const auto  &rates = record.sample->slip_rates;
      const double max_rate =
        rates.empty() ? 0. : *std::max_element(rates.begin(), rates.end());
      const bool fast =
        record.events->in_event() || max_rate > 2 * layout.convergence_rate;
      const double eps = 1e-12 * std::max(1., record.t);
      if (record.t >= last_time + (fast ? fast_interval : interval) - eps)
        {
          write_row(record.t, rates);
          last_time = record.t;
        }
    }


    void
    BaseProfile::write_row(const double t, const std::vector<double> &rates)
    {
      if (!writing)
        return;
      row.precise(t);
      for (const unsigned int k : order)
        row << rates[k];
      row.write_line(file);
      check();
    }


    void
    BaseProfile::save(boost::archive::binary_oarchive &archive) const
    {
      archive << last_time;
    }


    void
    BaseProfile::load(boost::archive::binary_iarchive &archive)
    {
      archive >> last_time;
    }
  } // namespace output
} // namespace rsfcycle
