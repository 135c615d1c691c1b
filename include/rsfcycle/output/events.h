// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_output_events_h
#define rsfcycle_output_events_h

#include <array>
#include <boost/serialization/version.hpp>
#include <ostream>
#include <string>
#include <vector>

namespace rsfcycle
{
  namespace output
  {
    /**
     * One slip event (doc/model.md §7, doc/events.md): a maximal time interval
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
      double start_slip = 0;          // |slip| of the nucleation node at
                                      // the start [m]
      double moment = 0; // sum of G w |slip during the event| over the
                         // nodes [N m; in 2D N m per m along strike]

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
          &rupture_max &slip &recurrence &start_slip &moment;
      }
    };

    /**
     * Detects events in the time loop from the slip rates and tangential
     * displacements of the contact nodes after every accepted step, and
     * keeps the catalogue. Knows nothing about meshes: positions are the
     * nodes' along-base coordinates.
     *
     * Event times are those of the accepted steps at which the maximum slip
     * rate crosses the threshold (doc/events.md), or, with
     * `interpolate_times`, the times at which it crosses it when log V is
     * interpolated linearly between the two steps around the crossing; the
     * slip is then counted between the nodes' displacements interpolated
     * linearly to those times. The interpolation makes the event times as
     * accurate as the solution even where the steps are long compared with
     * the rise of V (the spring-slider against its ARKODE reference, which
     * is sampled sparsely).
     *
     * With a `merge_time` > 0, a crossing of the threshold that comes at
     * most `merge_time` after an event's end continues that event (the
     * ringing of a fully dynamic run after its rupture): the event is
     * closed, and update() returns true, only once `merge_time` has passed
     * below the threshold; its end is the last drop below the threshold.
     */
    class EventDetector
    {
    public:
      /**
       * `moment_weights`: each node's shear modulus times its lumped
       * weight (length or area) [N/m, N/m^0 in 2D], for the events'
       * seismic moments; empty: no moments.
       */
      EventDetector(double              threshold,
                    double              convergence_rate,
                    std::vector<double> positions,
                    bool                interpolate_times = false,
                    double              merge_time        = 0,
                    std::vector<double> moment_weights    = {});

      /**
       * Record the accepted state at time t. `slip` holds the tangential
       * displacement (up to 2 components) of each node. Returns true if an
       * event ended at this step (it is then the last of events()).
       */
      bool
      update(double                                    t,
             const std::vector<double>                &rates,
             const std::vector<std::array<double, 2>> &slip);

      /** True while the maximum slip rate is above the threshold. */
      bool
      in_event() const
      {
        return active;
      }

      /**
       * True while the last event has dropped below the threshold but may
       * still be continued (`merge_time`).
       */
      bool
      ending() const
      {
        return pending;
      }

      /** Completed events. */
      const std::vector<Event> &
      events() const
      {
        return catalogue;
      }

      /** Number of events started (completed, running and ending). */
      unsigned int
      n_started() const
      {
        return catalogue.size() + ((active || pending) ? 1 : 0);
      }

      /** The event in progress (valid if in_event() or ending()). */
      const Event &
      current() const
      {
        return running;
      }

      /**
       * Header and one row of events.csv: besides the event's figures its
       * start in years (of 365.25 days) and its seismic moment, per metre
       * along strike in 2D (moment_N_m_per_m), with the moment magnitude
       * Mw = 2/3 (log10 M0 - 9.1) in 3D (moment_N_m, Mw).
       */
      static std::string
      csv_header(bool three_d);
      static void
      write_csv_row(std::ostream &out,
                    unsigned int  index,
                    const Event  &e,
                    bool          three_d);

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

      /**
       * Class version 1 (BOOST_CLASS_VERSION below) adds `pending`, 2 the
       * events' moments; `merge_time` and the moment weights are the
       * run's parameters, not stored.
       */
      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int version)
      {
        ar &threshold &v0 &positions &interpolate_times &active &running
          &previous_slip &slip_at_start &last_start &catalogue &previous_time
            &previous_max_rate;
        if (version >= 1)
          ar &pending;
      }

    private:
      /** Time at which the maximum rate crosses the threshold (log V). */
      double
      crossing(double t, double max_rate) const;

      /** The nodes' slip interpolated linearly from the last step to t. */
      std::vector<std::array<double, 2>>
      slip_at(double                                    time,
              double                                    t,
              const std::vector<std::array<double, 2>> &slip) const;

      double                             threshold, v0;
      std::vector<double>                positions;
      bool                               interpolate_times = false;
      double                             merge_time        = 0;
      std::vector<double>                moment_weights;
      bool                               active  = false;
      bool                               pending = false;
      Event                              running;
      std::vector<std::array<double, 2>> previous_slip, slip_at_start;
      double                             last_start = -1;
      std::vector<Event>                 catalogue;
      double                             previous_time     = 0;
      double                             previous_max_rate = 0;
    };
  } // namespace output
} // namespace rsfcycle

BOOST_CLASS_VERSION(rsfcycle::output::EventDetector, 2)

#endif
