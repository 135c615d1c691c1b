// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_output_time_series_h
#define rsfcycle_output_time_series_h

#include <rsfcycle/output/csv_file.h>
#include <rsfcycle/output/csv_row.h>
#include <rsfcycle/output/sample.h>

namespace rsfcycle
{
  namespace output
  {
    /**
     * time-series.csv: one row per accepted step: time, step size, the
     * solver counts of the step, its spatial problems, the maximum slip
     * rate, the model's observation columns (Layout::observation_names),
     * and the work of every spatial problem solved for the step (the
     * step-size control's comparisons and rejected attempts included).
     * The columns are documented in doc/output.md.
     */
    class TimeSeries : public CsvFile
    {
    public:
      TimeSeries(const std::string &dir, const Layout &layout);

      std::string
      name() const override
      {
        return "time series";
      }

      void
      write(const Record &record) override;

    private:
      void
      write_header(std::ostream &out) override;

      const std::vector<std::string> observation_names;
      CsvRow                         row{10};
    };
  } // namespace output
} // namespace rsfcycle

#endif
