// SPDX-License-Identifier: LGPL-2.1-or-later
// The names of every Patterns::Selection and their parsing into enums
// (Choice<Enum> of parameters.h).
#include <rsfcycle/parameters.h>
#include <stdexcept>

namespace rsfcycle
{
  template <>
  const std::vector<std::string> Choice<MeshParameters::RefinementLaw>::names =
    {"centre distance", "band"};
  template <>
  const std::vector<std::string>
    Choice<TimeSteppingParameters::Controller>::names = {"step-doubling",
                                                         "local-extrapolation"};
  template <>
  const std::vector<std::string>
    Choice<TimeSteppingParameters::Integrator>::names = {"implicit",
                                                         "arkode",
                                                         "runge-kutta",
                                                         "explicit",
                                                         "implicit-explicit"};
  template <>
  const std::vector<std::string>
    Choice<TimeSteppingParameters::ExplicitScheme>::names =
      {"noh-bathe", "central-differences"};
  template <>
  const std::vector<std::string>
    Choice<TimeSteppingParameters::ErrorNorm>::names = {"L2", "max"};
  template <>
  const std::vector<std::string> Choice<SolverParameters::Coupling>::names =
    {"fixed-point", "explicit"};
  template <>
  const std::vector<std::string> Choice<SolverParameters::Dynamics>::names =
    {"dynamic", "quasi-static", "quasi-dynamic"};
  template <>
  const std::vector<std::string>
    Choice<SolverParameters::LinearCorrection>::names = {"multigrid",
                                                         "direct",
                                                         "amg"};
  template <>
  const std::vector<std::string> Choice<SolverParameters::Bulk>::names =
    {"volume", "green-function"};
  template <>
  const std::vector<std::string> Choice<SolverParameters::GreenStorage>::names =
    {"automatic", "dense", "h-matrix"};


  template <typename Enum>
  std::string
  Choice<Enum>::pattern()
  {
    std::string result;
    for (const auto &name : names)
      result += (result.empty() ? "" : "|") + name;
    return result;
  }


  template <typename Enum>
  Enum
  Choice<Enum>::parse(const std::string &name)
  {
    for (unsigned int i = 0; i < names.size(); ++i)
      if (names[i] == name)
        return static_cast<Enum>(i);
    throw std::invalid_argument(name + ": allowed are " + pattern());
  }


  template <typename Enum>
  const std::string &
  Choice<Enum>::name(const Enum value)
  {
    return names.at(static_cast<unsigned int>(value));
  }


  template struct Choice<MeshParameters::RefinementLaw>;
  template struct Choice<TimeSteppingParameters::Controller>;
  template struct Choice<TimeSteppingParameters::Integrator>;
  template struct Choice<TimeSteppingParameters::ExplicitScheme>;
  template struct Choice<TimeSteppingParameters::ErrorNorm>;
  template struct Choice<SolverParameters::Coupling>;
  template struct Choice<SolverParameters::Dynamics>;
  template struct Choice<SolverParameters::LinearCorrection>;
  template struct Choice<SolverParameters::Bulk>;
  template struct Choice<SolverParameters::GreenStorage>;
} // namespace rsfcycle
