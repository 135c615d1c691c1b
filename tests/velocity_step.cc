// SPDX-License-Identifier: LGPL-2.1-or-later
// Closed-form checks of the rate-and-state law under an imposed slip rate
//, through the friction API that every scene steps with
// (update_state (17) in steps of 0.05 L/V, friction_coefficient (2)).
// Parameters of prm/spring-slider.prm: a = 0.01, b = 0.015, mu* = 0.6,
// V* = 1e-6 m/s, L = 1e-5 m.
//  1. Steady state at constant V: from a state far from steady
//     (alpha = +-5), after a slip of 40 L the coefficient equals
//     mu_ss(V) = mu* + (a - b) log(V/V*) (the log form of the regularised
//     law, exact up to (V_theta/V)^2 ~ 1e-40) for V = 1e-9 ... 1 m/s, and
//     steady_state_friction_coefficient agrees.
//  2. Velocity step V1 -> V2 = 10 V1 (and back, 1/10) from steady sliding
//     at V1: the direct effect mu(V2, alpha_ss(V1)) - mu_ss(V1) =
//     a log(V2/V1); then, versus the slip d after the step, the evolution to
//     the new steady state along the closed forms of the ageing law,
//     theta = L/V2 + (theta1 - L/V2) e^{-d/L}, and of the slip law,
//     log(theta V2/L) = log(V2/V1) e^{-d/L}; after 20 L the change is
//     (a - b) log(V2/V1). Errors are printed as yes/no against 1e-10.
#include "tests.h"

#include <array>
#include <cmath>
#include <rsfcycle/friction/ageing_law.h>
#include <rsfcycle/friction/slip_law.h>

using namespace rsfcycle::friction;

namespace
{
  Parameters
  parameters()
  {
    Parameters p;
    p.a       = 0.01;
    p.b       = 0.015;
    p.mu_star = 0.6;
    p.v_star  = 1e-6;
    p.L       = 1e-5;
    return p;
  }

  const char *
  yes_no(const bool b)
  {
    return b ? "yes" : "no";
  }

  /** Step the state over a slip d at constant V in steps of 0.05 L. */
  double
  slide(const Law        &law,
        const Parameters &p,
        double            alpha,
        const double      V,
        const double      d)
  {
    const unsigned int n = static_cast<unsigned int>(std::round(d / p.L * 20));
    const double       tau = d / V / n;
    for (unsigned int i = 0; i < n; ++i)
      alpha = law.update_state(p, alpha, V, tau);
    return alpha;
  }
} // namespace

int
main()
{
  initlog(10);
  const Parameters p = parameters();
  using dealii::deallog;
  const AgeingLaw                  ageing;
  const SlipLaw                    slip;
  const std::array<const Law *, 2> laws = {{&ageing, &slip}};

  deallog << "1. steady state at constant V" << std::endl;
  for (const Law *law : laws)
    for (const double V : {1e-9, 1e-6, 1e-3, 1.})
      for (const double alpha0 : {-5., 5.})
        {
          const double alpha = slide(*law, p, alpha0, V, 40 * p.L);
          const double mu    = law->friction_coefficient(p, alpha, V);
          const double mu_ss = p.mu_star + (p.a - p.b) * std::log(V / p.v_star);
          // ageing: theta - L/V decays like e^{-d/L}; slip law: log(theta
          // V/L) decays like e^{-d/L}: after 40 L both are at e^{-40} ~ 4e-18
          deallog << law->name() << " V = " << V << " alpha0 = " << alpha0
                  << ": mu = " << mu << ", |mu - mu_ss| < 1e-10: "
                  << yes_no(std::abs(mu - mu_ss) < 1e-10)
                  << ", steady_state_friction_coefficient agrees: "
                  << yes_no(
                       std::abs(law->steady_state_friction_coefficient(p, V) -
                                mu_ss) < 1e-12)
                  << std::endl;
        }

  deallog << "2. velocity step" << std::endl;
  for (const Law *law : laws)
    for (const double ratio : {10., 0.1})
      {
        const double V1 = 1e-6, V2 = ratio * V1;
        const double alpha1 = std::log(p.v_star / V1); // steady at V1
        const double mu1    = law->friction_coefficient(p, alpha1, V1);
        const double direct = law->friction_coefficient(p, alpha1, V2) - mu1;
        deallog << law->name() << " V2/V1 = " << ratio
                << ": direct effect / (a log(V2/V1)) = "
                << direct / (p.a * std::log(ratio)) << ", |error| < 1e-10: "
                << yes_no(std::abs(direct - p.a * std::log(ratio)) < 1e-10)
                << std::endl;

        double alpha = alpha1, d_done = 0;
        bool   all_ok = true;
        for (const double d_over_L : {0.5, 1., 2., 5., 20.})
          {
            alpha  = slide(*law, p, alpha, V2, (d_over_L - d_done) * p.L);
            d_done = d_over_L;
            const double theta1 = p.L / p.v_star * std::exp(alpha1);
            double       alpha_exact;
            if (law == &ageing)
              alpha_exact = std::log(
                (p.L / V2 + (theta1 - p.L / V2) * std::exp(-d_over_L)) *
                p.v_star / p.L);
            else
              alpha_exact = std::log(V2 / V1) * std::exp(-d_over_L) -
                            std::log(V2 / p.v_star);
            // the unregularised law at the exact state
            const double mu_exact =
              p.mu_star + p.a * std::log(V2 / p.v_star) + p.b * alpha_exact;
            const double mu = law->friction_coefficient(p, alpha, V2);
            const bool   ok = std::abs(mu - mu_exact) < 1e-10;
            all_ok          = all_ok && ok;
            deallog << "  slip " << d_over_L
                    << " L: (mu - mu_ss(V1)) / a = " << (mu - mu1) / p.a
                    << ", |mu - closed form| < 1e-10: " << yes_no(ok)
                    << std::endl;
          }
        const double change = law->friction_coefficient(p, alpha, V2) - mu1;
        deallog << "  after 20 L: change / ((a - b) log(V2/V1)) = "
                << change / ((p.a - p.b) * std::log(ratio)) << std::endl;
      }
}
