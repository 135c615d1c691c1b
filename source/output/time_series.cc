// SPDX-License-Identifier: LGPL-2.1-or-later
#include <algorithm>
#include <rsfcycle/output/time_series.h>

namespace rsfcycle
{
  namespace output
  {
    TimeSeries::TimeSeries(const std::string &dir, const Layout &layout)
      : CsvFile(dir, "time-series.csv")
      , observation_names(layout.observation_names)
    {}


    void
    TimeSeries::write_header(std::ostream &out)
    {
      out << "time_s,step_size_s,fixed_point_iterations,tnnmg_iterations,"
             "linear_iterations,spatial_problems,max_slip_rate_m_per_s";
      for (const auto &name : observation_names)
        out << "," << name;
      out << ",all_tnnmg_iterations,all_linear_iterations\n";
    }


    void
    TimeSeries::write(const Record &record)
    {
      if (!writing)
        return;
      const Sample &sample = *record.sample;
      const auto    fastest =
        std::max_element(sample.slip_rates.begin(), sample.slip_rates.end());
      const double max_rate =
        (fastest == sample.slip_rates.end()) ? 0. : *fastest;
      const auto &counts = sample.statistics;
      row.precise(record.t)
        << record.step_size << counts.fixed_point_iterations
        << counts.tnnmg_iterations << counts.linear_iterations
        << record.spatial_problems << max_rate;
      for (const double value : sample.observations)
        row << value;
      row << record.work.tnnmg_iterations << record.work.linear_iterations;
      row.write_line(file);
      check();
    }
  } // namespace output
} // namespace rsfcycle
