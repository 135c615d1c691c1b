// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_format_h
#define rsfcycle_format_h

#include <sstream>
#include <string>

namespace rsfcycle
{
  /**
   * A number for a message, as printf's %g: six significant digits and an
   * exponent for small and large magnitudes ("5.96046e-10", "0.25", "250"),
   * never the fixed-point zeros of std::to_string ("0.000000").
   */
  inline std::string
  format_number(const double x)
  {
    std::ostringstream s;
    s << x;
    return s.str();
  }
} // namespace rsfcycle

#endif
