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
                                 std::vector<double> positions)
      : threshold(threshold)
      , v0(convergence_rate)
      , positions(std::move(positions))
    {}


    bool
    EventDetector::update(const double                              t,
                          const std::vector<double>                &rates,
                          const std::vector<std::array<double, 2>> &slip)
    {
      const auto   fastest  = std::max_element(rates.begin(), rates.end());
      const double max_rate = (fastest == rates.end()) ? 0. : *fastest;
      bool         ended    = false;

      if (!active && max_rate > threshold)
        {
          active                      = true;
          running                     = Event();
          running.start               = t;
          running.nucleation_position = positions[fastest - rates.begin()];
          running.rupture_min         = std::numeric_limits<double>::max();
          running.rupture_max         = std::numeric_limits<double>::lowest();
          running.recurrence          = (last_start >= 0) ? t - last_start : 0;
          last_start                  = t;
          // slip is counted from the last step below the threshold
          slip_at_start = previous_slip.empty() ? slip : previous_slip;
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
              running.end = t;
              double peak = 0;
              for (unsigned int k = 0; k < slip.size(); ++k)
                peak = std::max(peak,
                                std::hypot(slip[k][0] - slip_at_start[k][0],
                                           slip[k][1] - slip_at_start[k][1]));
              running.slip = peak - v0 * running.duration();
              catalogue.push_back(running);
              active = false;
              ended  = true;
            }
        }
      previous_slip = slip;
      return ended;
    }


    std::string
    EventDetector::csv_header()
    {
      return "event,start_s,end_s,duration_s,nucleation_position_m,"
             "peak_slip_rate_m_per_s,rupture_width_m,slip_um,recurrence_s";
    }


    void
    EventDetector::write_csv_row(std::ostream      &out,
                                 const unsigned int index,
                                 const Event       &e)
    {
      out << std::setprecision(10) << index << "," << e.start << "," << e.end
          << "," << e.duration() << "," << e.nucleation_position << ","
          << e.peak_slip_rate << "," << e.rupture_width() << "," << e.slip * 1e6
          << ",";
      if (e.recurrence > 0)
        out << e.recurrence;
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
