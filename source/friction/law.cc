// SPDX-License-Identifier: LGPL-2.1-or-later
#include <cmath>
#include <rsfcycle/friction/law.h>

namespace rsfcycle
{
  namespace friction
  {
    namespace
    {
      constexpr double log_two        = 0.69314718055994530942;
      constexpr double max_exponent   = 690.; // exp(690) ~ 1e300
      constexpr double derivative_cap = 1e300;
    } // namespace


    CoefficientAndDerivative
    Law::coefficient_and_derivative(const Parameters &p,
                                    const double      log_v_theta,
                                    const double      V) const
    {
      const auto capped_exp = [](const double exponent) {
        return exponent > max_exponent ? derivative_cap : std::exp(exponent);
      };
      if (!(V > 0))
        return {0., capped_exp(std::log(p.a) - log_two - log_v_theta)};
      const double log_z = std::log(V) - log_two - log_v_theta;
      if (log_z > 0)
        {
          // asinh(z) = log z + log(1 + sqrt(1 + z^-2)); z^-2 <= 1 here;
          // d mu / dV = a / (V sqrt(1 + z^-2))
          const double root = std::sqrt(1. + std::exp(-2. * log_z));
          return {p.a * (log_z + std::log1p(root)), p.a / (V * root)};
        }
      // d mu / dV = a / (2 V_theta sqrt(1 + z^2)), in log space
      const double z = std::exp(log_z);
      return {p.a * std::asinh(z),
              capped_exp(std::log(p.a) - log_two - log_v_theta -
                         0.5 * std::log1p(z * z))};
    }


    std::array<double, 2>
    Law::sensitivities(const Parameters &p,
                       const double      alpha,
                       const double      V) const
    {
      if (!(V > 0))
        return {{0., 0.}};
      const double log_z = std::log(V / 2) - p.log_v_theta(alpha);
      const double s =
        log_z > 300 ? 1. : 1 / std::sqrt(1 + std::exp(-2 * log_z));
      return {{p.a * s, p.b * s}};
    }
  } // namespace friction
} // namespace rsfcycle
