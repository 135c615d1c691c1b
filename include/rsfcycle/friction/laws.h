// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_friction_laws_h
#define rsfcycle_friction_laws_h

#include <memory>
#include <rsfcycle/friction/law.h>
#include <string>

namespace rsfcycle
{
  namespace friction
  {
    /**
     * The friction laws by name (`Solver/State law`): a new law is a class
     * derived from Law in its own header and one line in the list of
     * source/friction/laws.cc.
     */

    /** The names of the laws, as a Patterns::Selection ("ageing|slip"). */
    std::string
    law_names();

    /** The law of the given name; std::invalid_argument for another. */
    std::shared_ptr<const Law>
    make_law(const std::string &name);
  } // namespace friction
} // namespace rsfcycle

#endif
