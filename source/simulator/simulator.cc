// SPDX-License-Identifier: LGPL-2.1-or-later
#include <csignal>
#include <iomanip>
#include <rsfcycle/simulator/simulator.templates.h>
#include <sstream>

namespace rsfcycle
{
  namespace internal
  {
    namespace
    {
      volatile std::sig_atomic_t stop_signal = 0;

      extern "C" void
      handle_stop_signal(int signal)
      {
        stop_signal = signal;
      }
    } // namespace


    std::string
    format_duration(const double seconds)
    {
      std::ostringstream s;
      const long         total = static_cast<long>(seconds);
      s << total / 3600 << "h" << std::setw(2) << std::setfill('0')
        << (total / 60) % 60 << "m" << std::setw(2) << total % 60 << "s";
      return s.str();
    }


    StopSignals::StopSignals()
    {
      stop_signal = 0;
      old_int     = std::signal(SIGINT, handle_stop_signal);
      old_term    = std::signal(SIGTERM, handle_stop_signal);
    }


    StopSignals::~StopSignals()
    {
      std::signal(SIGINT, old_int);
      std::signal(SIGTERM, old_term);
    }


    int
    StopSignals::received() const
    {
      return stop_signal;
    }
  } // namespace internal
} // namespace rsfcycle
