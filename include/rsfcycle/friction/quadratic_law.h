// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_friction_quadratic_law_h
#define rsfcycle_friction_quadratic_law_h

#include <cmath>
#include <rsfcycle/friction/law.h>

namespace rsfcycle
{
  namespace friction
  {
    /**
     * The quadratic ("PRZ") law of Perrin, Rice and Zheng (1995),
     * theta' = 1 - (theta V / (2 L))^2: the ageing law's healing at rest,
     * the slip law's symmetric response to velocity steps. In alpha =
     * log(theta V* / L): alpha' = (V* / L) e^{-alpha} - (V / (2 L))^2 (L /
     * V*) e^{alpha}. Its steady state is theta = 2 L / V (the ageing
     * law's L / V with L doubled).
     */
    class QuadraticLaw : public Law
    {
    public:
      std::string
      name() const override
      {
        return "quadratic";
      }

      double
      state_rate(const Parameters &p,
                 const double      alpha,
                 const double      V) const override
      {
        const double k = V / (2 * p.L);
        return p.v_star / p.L * std::exp(-alpha) -
               k * k * p.L / p.v_star * std::exp(alpha);
      }

      /**
       * The exact update for constant V: with k = V / (2 L) and y = k
       * theta, y' = k (1 - y^2), so y(tau) = tanh(k tau + atanh y0) (coth
       * for y0 > 1), by the addition theorem (T + y0) / (1 + T y0) with T =
       * tanh(k tau) in both cases: theta = (T/k + theta0) / (1 + k theta0
       * T), where T/k -> tau for k tau -> 0 (theta grows by tau at rest).
       */
      double
      update_state(const Parameters &p,
                   const double      alpha,
                   const double      V,
                   const double      tau) const override
      {
        const double k      = V / (2 * p.L);
        const double x      = k * tau;
        const double T      = std::tanh(x);
        const double T_k    = (x > 1e-8) ? T / k : tau * (1 - x * x / 3);
        const double theta0 = p.L / p.v_star * std::exp(alpha);
        return std::log(p.v_star / p.L) + std::log(T_k + theta0) -
               std::log1p(k * theta0 * T);
      }
    };
  } // namespace friction
} // namespace rsfcycle

#endif
