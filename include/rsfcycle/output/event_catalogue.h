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
      explicit EventCatalogue(const std::string &dir)
        : CsvFile(dir, "events.csv")
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
        EventDetector::write_csv_row(file, events.size(), events.back());
        file.flush();
        check();
      }

    private:
      void
      write_header(std::ostream &out) override
      {
        out << EventDetector::csv_header() << "\n";
      }
    };
  } // namespace output
} // namespace rsfcycle

#endif
