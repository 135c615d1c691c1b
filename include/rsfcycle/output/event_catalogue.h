// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_output_event_catalogue_h
#define rsfcycle_output_event_catalogue_h

#include <deal.II/base/parameter_handler.h>
#include <rsfcycle/output/csv_file.h>

namespace rsfcycle
{
  namespace output
  {
    /**
     * events.csv: the event catalogue (doc/events.md), a row when an event
     * ends, flushed at once.
     */
    class EventCatalogue : public CsvFile
    {
    public:
      /** `three_d`: the moment in N m and the magnitude (else per m). */
      EventCatalogue(const std::string &dir, const bool three_d)
        : CsvFile(dir, "events.csv")
        , three_d(three_d)
      {}

      /**
       * Its entries in subsection Output (entered by the caller): the
       * summary's Transition time and Transition events (OutputParameters
       * reads them).
       */
      static void
      declare_parameters(dealii::ParameterHandler &prm)
      {
        prm.declare_entry("Transition time",
                          "0",
                          dealii::Patterns::Double(0),
                          "Events starting before this time belong to the "
                          "initial transition and are left out of the "
                          "summary [s]");
        prm.declare_entry("Transition events",
                          "2",
                          dealii::Patterns::Integer(0),
                          "The first this many events are left out of the "
                          "summary as well [-]");
      }

      std::string
      name() const override
      {
        return "event catalogue";
      }

      void
      write(const Record &record) override
      {
        if (!writing || !record.event_ended)
          return;
        const auto &events = record.events->events();
        EventDetector::write_csv_row(file,
                                     events.size(),
                                     events.back(),
                                     three_d);
        file.flush();
        check();
      }

    private:
      void
      write_header(std::ostream &out) override
      {
        out << EventDetector::csv_header(three_d) << "\n";
      }

      const bool three_d;
    };
  } // namespace output
} // namespace rsfcycle

#endif
