// SPDX-License-Identifier: LGPL-2.1-or-later
#include <functional>
#include <rsfcycle/time/generalized_alpha_scheme.h>
#include <rsfcycle/time/schemes.h>
#include <rsfcycle/time/theta_scheme.h>
#include <stdexcept>
#include <utility>
#include <vector>

namespace rsfcycle
{
  namespace time
  {
    namespace
    {
      using Factory = std::function<std::unique_ptr<
        const TimeScheme>(const SolverParameters &, bool inertia)>;

      /** The list of schemes: one line per scheme. */
      const std::vector<std::pair<std::string, Factory>> &
      schemes()
      {
        static const std::vector<std::pair<std::string, Factory>> list = {
          {"theta",
           [](const SolverParameters &solver, bool) {
             return std::make_unique<ThetaScheme>(solver.theta);
           }},
          {"generalized-alpha",
           [](const SolverParameters &solver, const bool inertia) {
             if (!inertia)
               throw std::invalid_argument(
                 "Solver/Time scheme = generalized-alpha needs inertia "
                 "(Solver/Dynamics = dynamic; the spring-slider: Mass > 0); "
                 "without it choose theta (Theta = 1 damps stiff modes)");
             return std::make_unique<GeneralizedAlphaScheme>(
               solver.spectral_radius);
           }}};
        return list;
      }
    } // namespace


    std::string
    scheme_names()
    {
      std::string names;
      for (const auto &[name, factory] : schemes())
        names += (names.empty() ? "" : "|") + name;
      return names;
    }


    std::unique_ptr<const TimeScheme>
    make_scheme(const SolverParameters &solver, const bool inertia)
    {
      for (const auto &[name, factory] : schemes())
        if (name == solver.time_scheme)
          return factory(solver, inertia);
      throw std::invalid_argument("Solver/Time scheme = " + solver.time_scheme +
                                  ": allowed are " + scheme_names());
    }
  } // namespace time
} // namespace rsfcycle
