// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_output_seas_events_h
#define rsfcycle_output_seas_events_h

#include <boost/serialization/vector.hpp>
#include <optional>
#include <vector>

namespace rsfcycle
{
  namespace output
  {
    /**
     * The earthquakes of the 3D SEAS descriptions (BP5 and BP7, section 4.4
     * "earthquake catalog" and 4.6 "rupture time contour"), which define an
     * event apart from rsfcycle's own events.csv: it starts when the largest
     * slip rate on the fault reaches the threshold (1 mm/s) and is over
     * when it has stayed below it for `quiet_time` (10 s); its end is the
     * time it dropped below. Per event: the rupture area Omega_R (the nodes
     * whose slip rate reached the threshold during it), the amplitude of the
     * mean shear stress vector over Omega_R at its start and at its end, and
     * the amplitude of the mean slip vector over Omega_R during it. For the
     * first event, each node's rupture time: the first time its slip rate
     * reaches the threshold, interpolated in log10 V between two records.
     * Every rank keeps the same copy (the records are the same).
     */
    class SeasEvents
    {
    public:
      /** One completed event: a row of catalog.dat [s, m^2, Pa, m]. */
      struct Row
      {
        unsigned int number = 0;
        double start = 0, end = 0, area = 0, stress_start = 0, stress_end = 0,
               slip = 0;
      };

      /** The node values of one record (the benchmark's components). */
      struct Nodes
      {
        const std::vector<double> *log10_rate, *stress_2, *stress_3, *slip_2,
          *slip_3;
      };

      SeasEvents() = default;
      SeasEvents(double threshold, double quiet_time, std::vector<double> area);

      /**
       * Record the nodes at time t (nodes beyond the vectors' first
       * area.size() entries are ignored). Returns the event completed at
       * this record, if one was.
       */
      std::optional<Row>
      update(double t, const Nodes &nodes);

      /** At the run's end: the event that had dropped below, if any. */
      std::optional<Row>
      pending() const;

      /** Whether the first event is over (its rupture times are final). */
      bool
      first_over() const
      {
        return completed > 0;
      }

      /** Each node's rupture time in the first event; 1e9: none. */
      const std::vector<double> &
      rupture_times() const
      {
        return arrival;
      }

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &threshold &quiet_time &area &active &below &start &dropped
          &completed &ruptured &stress_start &slip_start &stress_dropped
            &slip_dropped &arrival &previous_t &previous_log10_rate;
      }

    private:
      /** The completed row of the current event, ending at `dropped`. */
      Row
      row() const;

      double              threshold = 1e-3, quiet_time = 10;
      std::vector<double> area;
      bool                active = false, below = false;
      double              start = 0, dropped = 0;
      unsigned int        completed = 0;
      std::vector<char>   ruptured;
      // per node (x2, x3 interleaved): at the start and at the last drop
      std::vector<double> stress_start, slip_start, stress_dropped,
        slip_dropped;
      std::vector<double> arrival;
      double              previous_t = 0;
      std::vector<double> previous_log10_rate;
    };
  } // namespace output
} // namespace rsfcycle

#endif
