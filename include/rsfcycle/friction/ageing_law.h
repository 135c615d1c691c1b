// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_friction_ageing_law_h
#define rsfcycle_friction_ageing_law_h

#include <algorithm>
#include <cmath>
#include <limits>
#include <rsfcycle/friction/law.h>

namespace rsfcycle
{
  namespace friction
  {
    /**
     * The ageing law (4), theta' = 1 - theta V / L, in alpha =
     * log(theta V* / L): alpha' = (V* / L) e^{-alpha} - V / L.
     */
    class AgeingLaw : public Law
    {
    public:
      std::string
      name() const override
      {
        return "ageing";
      }

      double
      state_rate(const Parameters &p,
                 const double      alpha,
                 const double      V) const override
      {
        return p.v_star / p.L * std::exp(-alpha) - V / p.L;
      }

      /**
       * (17): theta_n = theta e^{-x} + (L/V)(1 - e^{-x}), x = V tau / L, as
       * alpha_n = logaddexp(alpha - x, log(V* tau / L) + log(phi1(x))),
       * phi1(x) = -expm1(-x)/x, which is exact also for V -> 0 (theta grows
       * by tau) and never divides by V.
       */
      double
      update_state(const Parameters &p,
                   const double      alpha,
                   const double      V,
                   const double      tau) const override
      {
        const double x    = V * tau / p.L;
        const double phi1 = (x > 1e-300) ? -std::expm1(-x) / x : 1.;
        return log_add_exp(alpha - x,
                           std::log(p.v_star * tau / p.L) + std::log(phi1));
      }

    private:
      /** log(exp(x) + exp(y)) without overflow. */
      static double
      log_add_exp(const double x, const double y)
      {
        const double m = std::max(x, y);
        if (m == -std::numeric_limits<double>::infinity())
          return m;
        return m + std::log1p(std::exp(-std::abs(x - y)));
      }
    };
  } // namespace friction
} // namespace rsfcycle

#endif
