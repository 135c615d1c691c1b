// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_output_event_catalogue_h
#define rsfcycle_output_event_catalogue_h

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
