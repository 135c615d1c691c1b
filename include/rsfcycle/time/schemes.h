// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_time_schemes_h
#define rsfcycle_time_schemes_h

#include <memory>
#include <rsfcycle/parameters.h>
#include <rsfcycle/time/time_scheme.h>
#include <string>

namespace rsfcycle
{
  namespace time
  {
    /**
     * The time schemes of the implicit step by name (`Solver/Time scheme`):
     * a new scheme is a TimeScheme in its own header and one line in the
     * list of source/time/schemes.cc.
     */

    /** The names of the schemes, as a Patterns::Selection. */
    std::string
    scheme_names();

    /**
     * The scheme named in the parameters, with its own parameters, for a
     * model with or without inertia (a scheme that needs it refuses a model
     * without in one line).
     */
    std::unique_ptr<const TimeScheme>
    make_scheme(const SolverParameters &solver, bool inertia);
  } // namespace time
} // namespace rsfcycle

#endif
