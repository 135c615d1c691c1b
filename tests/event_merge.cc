// SPDX-License-Identifier: LGPL-2.1-or-later
// Checks `Output/Event merge time` (output::EventDetector): one contact
// node, steps of 1 s, threshold 1e-3 m/s, v0 = 1e-9 m/s, times of the
// accepted steps (no interpolation). The slip rate is 1 m/s at t = 10 ... 20
// s (the rupture), 1e-6 m/s at 21 ... 24 s, 2e-3 m/s at 25 and 26 s (the
// ringing after it), 1e-6 m/s from 27 s on, and 1 m/s again at 150 ... 155 s;
// 1e-9 m/s before 10 s. The slip grows by the rate times 1 s at each step.
// Closed forms:
//  - merge time 0: three events, [10, 21], [25, 27] and [150, 156] s;
//  - merge time 30 s: the ringing 4 s after the first end continues the
//    first event, [10, 27] s, closed (update() returns true) at the first
//    step more than 30 s after its end, t = 58 s; the rise at 150 s, 123 s
//    after that end, is a new event [150, 156] s with recurrence 140 s,
//    closed at t = 187 s;
//  - the merged event's slip: 11 + 4e-6 + 4e-3 + 1e-6 m minus v0 * 17 s,
//    its peak rate 1 m/s;
//  - a detector written to a boost archive while its event is ending
//    (t = 23 s) and read back into one with the same merge time gives the
//    same catalogue (the checkpoint; class version 1 stores the ending).
// Printed: each event and yes/no against those values (1e-12).
#include "tests.h"

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/array.hpp>
#include <boost/serialization/vector.hpp>
#include <cmath>
#include <rsfcycle/output/events.h>
#include <sstream>

using rsfcycle::output::Event;
using rsfcycle::output::EventDetector;

double
rate(const double t)
{
  if (t >= 10 && t <= 20)
    return 1;
  if (t >= 21 && t <= 24)
    return 1e-6;
  if (t >= 25 && t <= 26)
    return 2e-3;
  if (t >= 150 && t <= 155)
    return 1;
  return t < 10 ? 1e-9 : 1e-6;
}

const double threshold = 1e-3, v0 = 1e-9;

/**
 * Steps from `from` to `to` (inclusive) with slip carried in `slip`;
 * returns the times at which update() reported an ended event.
 */
std::vector<double>
run(EventDetector &detector, double &slip, const int from, const int to)
{
  std::vector<double> closed;
  for (int t = from; t <= to; ++t)
    {
      slip += rate(t);
      if (detector.update(t, {rate(t)}, {{{slip, 0.}}}))
        closed.push_back(t);
    }
  return closed;
}

bool
near(const double a, const double b)
{
  return std::abs(a - b) < 1e-12 * std::max(1., std::abs(b));
}

void
print(const std::string         &name,
      const std::vector<Event>  &events,
      const std::vector<double> &closed,
      const std::vector<Event>  &expected,
      const std::vector<double> &expected_closed)
{
  bool ok = events.size() == expected.size() && closed == expected_closed;
  dealii::deallog << name << ": " << events.size() << " events" << std::endl;
  for (unsigned int i = 0; i < events.size(); ++i)
    {
      const Event &e = events[i];
      dealii::deallog << "  [" << e.start << ", " << e.end << "] s, peak "
                      << e.peak_slip_rate << " m/s, slip " << e.slip * 1e6
                      << " um, recurrence " << e.recurrence << " s, closed at "
                      << closed[i] << " s" << std::endl;
      if (i < expected.size())
        ok = ok && near(e.start, expected[i].start) &&
             near(e.end, expected[i].end) &&
             near(e.peak_slip_rate, expected[i].peak_slip_rate) &&
             near(e.slip, expected[i].slip) &&
             near(e.recurrence, expected[i].recurrence);
    }
  dealii::deallog << name << " as the closed form: " << (ok ? "yes" : "no")
                  << std::endl;
}

Event
event(const double start,
      const double end,
      const double peak,
      const double slip,
      const double recurrence)
{
  Event e;
  e.start          = start;
  e.end            = end;
  e.peak_slip_rate = peak;
  e.slip           = slip - v0 * (end - start);
  e.recurrence     = recurrence;
  return e;
}

int
main()
{
  initlog(10);
  {
    EventDetector detector(threshold, v0, {0.});
    double        slip = 0;
    detector.update(0, {rate(0)}, {{{0., 0.}}});
    const auto closed = run(detector, slip, 1, 200);
    print("merge time 0",
          detector.events(),
          closed,
          {event(10, 21, 1, 11 + 1e-6, 0),
           event(25, 27, 2e-3, 4e-3 + 1e-6, 15),
           event(150, 156, 1, 6 + 1e-6, 125)},
          {21, 27, 156});
  }
  const std::vector<Event> merged = {
    event(10, 27, 1, 11 + 4e-6 + 4e-3 + 1e-6, 0),
    event(150, 156, 1, 6 + 1e-6, 140)};
  {
    EventDetector detector(threshold, v0, {0.}, false, 30);
    double        slip = 0;
    detector.update(0, {rate(0)}, {{{0., 0.}}});
    const auto closed = run(detector, slip, 1, 200);
    print("merge time 30 s", detector.events(), closed, merged, {58, 187});
  }
  {
    EventDetector detector(threshold, v0, {0.}, false, 30);
    double        slip = 0;
    detector.update(0, {rate(0)}, {{{0., 0.}}});
    auto closed = run(detector, slip, 1, 23);
    dealii::deallog << "at t = 23 s: ending " << detector.ending()
                    << ", in event " << detector.in_event() << ", started "
                    << detector.n_started() << std::endl;
    std::stringstream archive;
    {
      boost::archive::binary_oarchive out(archive);
      out << detector;
    }
    EventDetector restored(0, 0, {}, false, 30);
    {
      boost::archive::binary_iarchive in(archive);
      in >> restored;
    }
    for (const double t : run(restored, slip, 24, 200))
      closed.push_back(t);
    print("merge time 30 s, written and read at t = 23 s",
          restored.events(),
          closed,
          merged,
          {58, 187});
  }
}
