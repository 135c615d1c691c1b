// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_output_writers_h
#define rsfcycle_output_writers_h

#include <memory>
#include <rsfcycle/output/sample.h>
#include <rsfcycle/output/writer.h>
#include <rsfcycle/parameters.h>
#include <vector>

namespace rsfcycle
{
  namespace output
  {
    /**
     * The outputs every model writes, by the parameters: time-series.csv,
     * base-profile.csv, events.csv and, with `Output/SEAS/Problem` given,
     * the SEAS files. A new output of every model is a Writer in output/
     * and one line here (source/output/writers.cc). Bad SEAS positions
     * throw std::invalid_argument (one line naming the entry) on every rank
     * before a file is written.
     */
    std::vector<std::unique_ptr<Writer>>
    make_writers(const Parameters &parameters, const Layout &layout);
  } // namespace output
} // namespace rsfcycle

#endif
