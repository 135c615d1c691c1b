// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_friction_slip_law_h
#define rsfcycle_friction_slip_law_h

#include <cmath>
#include <rsfcycle/friction/law.h>

namespace rsfcycle
{
  namespace friction
  {
    /**
     * The slip law, theta' = -(theta V / L) log(theta V / L) (doc/model.md §2),
     * in alpha = log(theta V* / L): log(theta V / L) = alpha + log(V / V*)
     * decays like e^{-V t / L} at constant V.
     */
    class SlipLaw : public Law
    {
    public:
      std::string
      name() const override
      {
        return "slip";
      }

      double
      state_rate(const Parameters &p,
                 const double      alpha,
                 const double      V) const override
      {
        return V > 0 ? -V / p.L * (alpha + std::log(V / p.v_star)) : 0.;
      }

      /** alpha_n = alpha e^{-x} - log(V/V*) expm1(-x); alpha for V = 0. */
      double
      update_state(const Parameters &p,
                   const double      alpha,
                   const double      V,
                   const double      tau) const override
      {
        if (!(V > 0))
          return alpha;
        const double x = V * tau / p.L;
        return alpha * std::exp(-x) + std::log(V / p.v_star) * std::expm1(-x);
      }
    };
  } // namespace friction
} // namespace rsfcycle

#endif
