#ifndef rsfcycle_output_events_h
#define rsfcycle_output_events_h

#include <array>
#include <ostream>
#include <string>
#include <vector>

namespace rsfcycle
{
  namespace output
  {
    /**
     * One slip event (MODEL.md §7, doc/events.md): a maximal time interval
     * in which the maximum slip rate on the contact exceeds the threshold.
     */
    struct Event
    {
      double start               = 0; // first accepted step above threshold [s]
      double end                 = 0; // first accepted step below it [s]
      double nucleation_position = 0; // along-base position of the fastest
                                      // node at the start [m]
      double peak_slip_rate = 0;      // [m/s]
      double rupture_min    = 0;      // along-base extent of the nodes
      double rupture_max    = 0;      // above threshold during the event [m]
      double slip           = 0;      // max over nodes of the slip during the
                                      // event minus v0 * duration [m]
      double recurrence = 0;          // start - previous start [s]; 0 first

      double
      duration() const
      {
        return end - start;
      }
      double
      rupture_width() const
      {
        return rupture_max - rupture_min;
      }

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &start &end &nucleation_position &peak_slip_rate &rupture_min
          &rupture_max &slip &recurrence;
      }
    };

    /**
     * Detects events in the time loop from the slip rates and tangential
     * displacements of the contact nodes after every accepted step, and
     * keeps the catalogue. Knows nothing about meshes: positions are the
     * nodes' along-base coordinates.
     */
    class EventDetector
    {
    public:
      EventDetector(double              threshold,
                    double              convergence_rate,
                    std::vector<double> positions);

      /**
       * Record the accepted state at time t. `slip` holds the tangential
       * displacement (up to 2 components) of each node. Returns true if an
       * event ended at this step (it is then the last of events()).
       */
      bool
      update(double                                    t,
             const std::vector<double>                &rates,
             const std::vector<std::array<double, 2>> &slip);

      bool
      in_event() const
      {
        return active;
      }

      /** Completed events. */
      const std::vector<Event> &
      events() const
      {
        return catalogue;
      }

      /** Number of events started (completed and running). */
      unsigned int
      n_started() const
      {
        return catalogue.size() + (active ? 1 : 0);
      }

      /** The event in progress (valid if in_event()). */
      const Event &
      current() const
      {
        return running;
      }

      /** Header and one row of events.csv. */
      static std::string
      csv_header();
      static void
      write_csv_row(std::ostream &out, unsigned int index, const Event &e);

      /**
       * Statistics after discarding the transition: events that start
       * before `transition_time` or are among the first `transition_events`.
       * Writes number of events, median and range of recurrence time,
       * rupture width, duration, peak slip rate and slip.
       */
      void
      write_summary(std::ostream &out,
                    double        transition_time,
                    unsigned int  transition_events) const;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &threshold &v0 &positions &active &running &previous_slip
          &slip_at_start &last_start &catalogue;
      }

    private:
      double                             threshold, v0;
      std::vector<double>                positions;
      bool                               active = false;
      Event                              running;
      std::vector<std::array<double, 2>> previous_slip, slip_at_start;
      double                             last_start = -1;
      std::vector<Event>                 catalogue;
    };
  } // namespace output
} // namespace rsfcycle

#endif
