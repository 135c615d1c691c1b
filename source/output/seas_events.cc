// SPDX-License-Identifier: LGPL-2.1-or-later
// The earthquakes of the 3D SEAS descriptions (output/seas_events.h).
#include <algorithm>
#include <array>
#include <cmath>
#include <rsfcycle/output/seas_events.h>

namespace rsfcycle
{
  namespace output
  {
    SeasEvents::SeasEvents(const double        threshold,
                           const double        quiet_time,
                           std::vector<double> area)
      : threshold(threshold)
      , quiet_time(quiet_time)
      , area(std::move(area))
      , arrival(this->area.size(), 1e9)
    {}


    std::optional<SeasEvents::Row>
    SeasEvents::update(const double t, const Nodes &nodes)
    {
      const unsigned int n         = area.size();
      const double       log10_thr = std::log10(threshold);
      const auto        &lr        = *nodes.log10_rate;
      double             largest   = -1e300;
      for (unsigned int k = 0; k < n; ++k)
        largest = std::max(largest, lr[k]);
      const bool above = largest >= log10_thr;
      const auto keep  = [&](std::vector<double> &stress,
                            std::vector<double> &slip) {
        stress.resize(2 * n);
        slip.resize(2 * n);
        for (unsigned int k = 0; k < n; ++k)
          {
            stress[2 * k]     = (*nodes.stress_2)[k];
            stress[2 * k + 1] = (*nodes.stress_3)[k];
            slip[2 * k]       = (*nodes.slip_2)[k];
            slip[2 * k + 1]   = (*nodes.slip_3)[k];
          }
      };

      std::optional<Row> done;
      if (active && below && above)
        below = false; // it rose again within the quiet time: the same event
      else if (active && !below && !above)
        {
          below   = true;
          dropped = t;
          keep(stress_dropped, slip_dropped);
        }
      else if (active && below && t - dropped >= quiet_time)
        {
          done   = row();
          active = below = false;
          ++completed;
        }
      if (!active && above)
        {
          active = true;
          below  = false;
          start  = t;
          ruptured.assign(n, 0);
          keep(stress_start, slip_start);
        }
      if (active)
        for (unsigned int k = 0; k < n; ++k)
          if (lr[k] >= log10_thr)
            {
              ruptured[k] = 1;
              // the first event's rupture times, between two records
              if (completed == 0 && arrival[k] == 1e9)
                arrival[k] =
                  previous_log10_rate.empty() ||
                      previous_log10_rate[k] >= log10_thr ?
                    t :
                    previous_t + (t - previous_t) *
                                   (log10_thr - previous_log10_rate[k]) /
                                   (lr[k] - previous_log10_rate[k]);
            }
      previous_t = t;
      previous_log10_rate.assign(lr.begin(), lr.begin() + n);
      return done;
    }


    std::optional<SeasEvents::Row>
    SeasEvents::pending() const
    {
      if (active && below)
        return row();
      return std::nullopt;
    }


    SeasEvents::Row
    SeasEvents::row() const
    {
      Row                   r;
      std::array<double, 6> sum{}; // stress start, end, slip (x2, x3)
      for (unsigned int k = 0; k < area.size(); ++k)
        if (ruptured[k])
          {
            r.area += area[k];
            for (unsigned int c = 0; c < 2; ++c)
              {
                sum[c] += area[k] * stress_start[2 * k + c];
                sum[2 + c] += area[k] * stress_dropped[2 * k + c];
                sum[4 + c] +=
                  area[k] * (slip_dropped[2 * k + c] - slip_start[2 * k + c]);
              }
          }
      const double A = std::max(r.area, 1e-300);
      r.number       = completed + 1;
      r.start        = start;
      r.end          = dropped;
      r.stress_start = std::hypot(sum[0], sum[1]) / A;
      r.stress_end   = std::hypot(sum[2], sum[3]) / A;
      r.slip         = std::hypot(sum[4], sum[5]) / A;
      return r;
    }
  } // namespace output
} // namespace rsfcycle
