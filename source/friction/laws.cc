// SPDX-License-Identifier: LGPL-2.1-or-later
#include <functional>
#include <rsfcycle/friction/ageing_law.h>
#include <rsfcycle/friction/laws.h>
#include <rsfcycle/friction/quadratic_law.h>
#include <rsfcycle/friction/slip_law.h>
#include <stdexcept>
#include <utility>
#include <vector>

namespace rsfcycle
{
  namespace friction
  {
    namespace
    {
      using Factory = std::function<std::shared_ptr<const Law>()>;

      /** The list of laws: one line per law. */
      const std::vector<std::pair<std::string, Factory>> &
      laws()
      {
        static const std::vector<std::pair<std::string, Factory>> list = {
          {"ageing", [] { return std::make_shared<AgeingLaw>(); }},
          {"slip", [] { return std::make_shared<SlipLaw>(); }},
          {"quadratic", [] { return std::make_shared<QuadraticLaw>(); }}};
        return list;
      }
    } // namespace


    std::string
    law_names()
    {
      std::string names;
      for (const auto &[name, factory] : laws())
        names += (names.empty() ? "" : "|") + name;
      return names;
    }


    std::shared_ptr<const Law>
    make_law(const std::string &name)
    {
      for (const auto &[law_name, factory] : laws())
        if (law_name == name)
          return factory();
      throw std::invalid_argument("Solver/State law = " + name +
                                  ": allowed are " + law_names());
    }
  } // namespace friction
} // namespace rsfcycle
