// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_output_base_profile_h
#define rsfcycle_output_base_profile_h

#include <rsfcycle/output/csv_file.h>
#include <rsfcycle/output/csv_row.h>
#include <rsfcycle/output/sample.h>
#include <rsfcycle/parameters.h>

namespace rsfcycle
{
  namespace output
  {
    /**
     * base-profile.csv: the slip rate of every contact node, the nodes
     * ordered along the base (then by z in 3D), at t = 0 and then densely
     * while slip is fast (in an event, or max V > 2 v0: `Output/Event
     * profile interval`), else every `Output/Profile interval`.
     */
    class BaseProfile : public CsvFile
    {
    public:
      BaseProfile(const std::string      &dir,
                  const Layout           &layout,
                  const OutputParameters &output);

      /**
       * Its entries in subsection Output (entered by the caller): Profile
       * interval and Event profile interval (OutputParameters reads them).
       */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      std::string
      name() const override
      {
        return "base profile";
      }

      void
      start(const Record &record) override;

      void
      write(const Record &record) override;

      void
      save(boost::archive::binary_oarchive &archive) const override;
      void
      load(boost::archive::binary_iarchive &archive) override;

    private:
      void
      write_header(std::ostream &out) override;

      void
      write_row(double t, const std::vector<double> &rates);

      const Layout              layout;
      const double              interval, fast_interval;
      std::vector<unsigned int> order; // node order along the base
      double                    last_time = 0;
      CsvRow                    row{8};
    };
  } // namespace output
} // namespace rsfcycle

#endif
