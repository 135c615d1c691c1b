// SPDX-License-Identifier: LGPL-2.1-or-later
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <rsfcycle/output/events.h>

namespace rsfcycle
{
  namespace output
  {
    EventDetector::EventDetector(const double        threshold,
                                 const double        convergence_rate,
                                 std::vector<double> positions,
                                 const bool          interpolate_times,
                                 const double        merge_time,
                                 std::vector<double> moment_weights)
      : threshold(threshold)
      , v0(convergence_rate)
      , positions(std::move(positions))
      , interpolate_times(interpolate_times)
      , merge_time(merge_time)
      , moment_weights(std::move(moment_weights))
    {}


    double
    EventDetector::crossing(const double t, const double max_rate) const
    {
      const double l0 = std::log(std::max(previous_max_rate, 1e-300)),
                   l1 = std::log(std::max(max_rate, 1e-300)),
                   lc = std::log(threshold);
      if (!(std::abs(l1 - l0) > 0))
        return t;
      return previous_time +
             (t - previous_time) * std::clamp((lc - l0) / (l1 - l0), 0., 1.);
    }


    std::vector<std::array<double, 2>>
    EventDetector::slip_at(const double                              time,
                           const double                              t,
                           const std::vector<std::array<double, 2>> &slip) const
    {
      if (previous_slip.empty())
        return slip;
      std::vector<std::array<double, 2>> result(slip.size());
      for (unsigned int k = 0; k < slip.size(); ++k)
        for (unsigned int c = 0; c < 2; ++c)
          result[k][c] =
            previous_slip[k][c] + (slip[k][c] - previous_slip[k][c]) *
                                    (time - previous_time) /
                                    std::max(t - previous_time, 1e-300);
      return result;
    }


    bool
    EventDetector::update(const double                              t,
                          const std::vector<double>                &rates,
                          const std::vector<std::array<double, 2>> &slip)
    {
      const auto   fastest  = std::max_element(rates.begin(), rates.end());
      const double max_rate = (fastest == rates.end()) ? 0. : *fastest;
      bool         ended    = false;

      // an ending event: continued by a new crossing within merge_time of
      // its end, closed once merge_time has passed below the threshold
      if (pending)
        {
          const double rise =
            (max_rate > threshold) ?
              (interpolate_times ? crossing(t, max_rate) : t) :
              t;
          if (rise - running.end <= merge_time && max_rate > threshold)
            {
              pending = false;
              active  = true;
            }
          else if (t - running.end > merge_time)
            {
              catalogue.push_back(running);
              pending = false;
              ended   = true;
            }
        }

      if (!active && !pending && max_rate > threshold)
        {
          const unsigned int nucleation = fastest - rates.begin();
          active                        = true;
          running                       = Event();
          running.start = interpolate_times ? crossing(t, max_rate) : t;
          running.nucleation_position = positions[nucleation];
          running.rupture_min         = std::numeric_limits<double>::max();
          running.rupture_max         = std::numeric_limits<double>::lowest();
          running.recurrence =
            (last_start >= 0) ? running.start - last_start : 0;
          last_start = running.start;
          // slip is counted from the last step below the threshold, or from
          // the interpolated crossing
          if (interpolate_times)
            slip_at_start = slip_at(running.start, t, slip);
          else
            slip_at_start = previous_slip.empty() ? slip : previous_slip;
          running.start_slip = std::hypot(slip_at_start[nucleation][0],
                                          slip_at_start[nucleation][1]);
        }

      if (active)
        {
          running.peak_slip_rate = std::max(running.peak_slip_rate, max_rate);
          for (unsigned int k = 0; k < rates.size(); ++k)
            if (rates[k] > threshold)
              {
                running.rupture_min =
                  std::min(running.rupture_min, positions[k]);
                running.rupture_max =
                  std::max(running.rupture_max, positions[k]);
              }
          if (max_rate <= threshold)
            {
              running.end = interpolate_times ? crossing(t, max_rate) : t;
              const std::vector<std::array<double, 2>> slip_at_end =
                interpolate_times ? slip_at(running.end, t, slip) : slip;
              double peak    = 0;
              running.moment = 0;
              for (unsigned int k = 0; k < slip.size(); ++k)
                {
                  const double s =
                    std::hypot(slip_at_end[k][0] - slip_at_start[k][0],
                               slip_at_end[k][1] - slip_at_start[k][1]);
                  peak = std::max(peak, s);
                  if (k < moment_weights.size())
                    running.moment += moment_weights[k] * s;
                }
              running.slip = peak - v0 * running.duration();
              active       = false;
              if (merge_time > 0)
                pending = true;
              else
                {
                  catalogue.push_back(running);
                  ended = true;
                }
            }
        }
      previous_slip     = slip;
      previous_time     = t;
      previous_max_rate = max_rate;
      return ended;
    }


    std::string
    EventDetector::csv_header(const bool three_d)
    {
      return std::string("event,start_s,end_s,duration_s,"
                         "nucleation_position_m,peak_slip_rate_m_per_s,"
                         "rupture_width_m,slip_um,recurrence_s,start_yr,") +
             (three_d ? "moment_N_m,Mw" : "moment_N_m_per_m");
    }


    void
    EventDetector::write_csv_row(std::ostream      &out,
                                 const unsigned int index,
                                 const Event       &e,
                                 const bool         three_d)
    {
      // start and end with every digit (ms events at t ~ 1e10 s)
      out << std::setprecision(17) << index << "," << e.start << "," << e.end
          << std::setprecision(10) << "," << e.duration() << ","
          << e.nucleation_position << "," << e.peak_slip_rate << ","
          << e.rupture_width() << "," << e.slip * 1e6 << ",";
      if (e.recurrence > 0)
        out << e.recurrence;
      // a year of 365.25 days, as the SEAS descriptions count them
      out << "," << e.start / 3.15576e7 << "," << e.moment;
      if (three_d)
        {
          out << ",";
          if (e.moment > 0)
            out << std::setprecision(4)
                << 2. / 3. * (std::log10(e.moment) - 9.1);
        }
      out << "\n";
    }


    namespace
    {
      /** median, min and max of a sample (all nan if empty). */
      std::array<double, 3>
      statistics(std::vector<double> x)
      {
        if (x.empty())
          return {{std::nan(""), std::nan(""), std::nan("")}};
        std::sort(x.begin(), x.end());
        const std::size_t n = x.size();
        const double      median =
          (n % 2 == 1) ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
        return {{median, x.front(), x.back()}};
      }
    } // namespace


    void
    EventDetector::write_summary(std::ostream      &out,
                                 const double       transition_time,
                                 const unsigned int transition_events) const
    {
      std::vector<double> recurrence, width, duration, peak, slip;
      for (unsigned int i = 0; i < catalogue.size(); ++i)
        {
          const Event &e = catalogue[i];
          if (i < transition_events || e.start < transition_time)
            continue;
          if (e.recurrence > 0)
            recurrence.push_back(e.recurrence);
          width.push_back(e.rupture_width());
          duration.push_back(e.duration());
          peak.push_back(e.peak_slip_rate);
          slip.push_back(e.slip * 1e6);
        }
      out << "Events: " << catalogue.size() << " completed, " << width.size()
          << " after the transition (first " << transition_events
          << " events and those before t = " << transition_time
          << " s discarded)\n";
      if (width.empty())
        {
          out << "  no event after the transition: no statistics (the "
                 "largest slip rate "
              << (catalogue.empty() ? "never exceeded" :
                                      "exceeded only in the transition")
              << " the event threshold, " << threshold << " m/s)\n";
          return;
        }
      const auto line = [&](const std::string         &name,
                            const std::vector<double> &x,
                            const std::string         &unit) {
        const auto s = statistics(x);
        out << "  " << std::left << std::setw(24) << name << std::right
            << " median " << std::setprecision(6) << s[0] << " " << unit
            << ", range [" << s[1] << ", " << s[2] << "] " << unit << "\n";
      };
      line("recurrence time", recurrence, "s");
      line("rupture width", width, "m");
      line("duration", duration, "s");
      line("peak slip rate", peak, "m/s");
      line("slip", slip, "um");
    }
  } // namespace output
} // namespace rsfcycle
