// SPDX-License-Identifier: LGPL-2.1-or-later
// Checks the closed-form state update (17) in the variable
// alpha = log(theta V*/L) against the analytic solution of the ageing law
// for constant V, theta(t) = L/V + (theta0 - L/V) exp(-V t / L), after
// 100 steps of 0.01 s (the update is exact for constant V, so the error is
// at round-off level), for V from 1e-3 to 1e-300 m/s and V = 0 (where
// theta = theta0 + t, and no division by V may happen); and the slip law
// against its analytic solution log(theta V/L) = log(theta0 V/L) e^{-Vt/L},
// with V = 0 leaving the state unchanged; and the quadratic law (Perrin,
// Rice and Zheng) against its analytic solution for constant V, with k =
// V/(2L): theta(t) = tanh(k t + atanh(k theta0))/k (coth and acoth when k
// theta0 > 1: V = 1e-3 and 50e-6 here), theta0 + t at V = 0, and its
// steady state theta = 2L/V kept.
#include "tests.h"

#include <cmath>
#include <rsfcycle/friction/ageing_law.h>
#include <rsfcycle/friction/quadratic_law.h>
#include <rsfcycle/friction/slip_law.h>

using namespace rsfcycle::friction;

int
main()
{
  initlog(10);
  const AgeingLaw ageing;
  const SlipLaw   slip;
  Parameters      p;
  p.v_star = 50e-6;
  p.L      = 22.5e-6;

  const double theta0 = 2.0; // seconds
  const double alpha0 = std::log(theta0 * p.v_star / p.L);
  const double tau = 0.01, t_end = 1.0;

  for (const double V : {1e-3, 50e-6, 1e-9, 1e-20, 1e-300, 0.})
    {
      double alpha = alpha0;
      for (int n = 0; n < 100; ++n)
        alpha = ageing.update_state(p, alpha, V, tau);
      // theta0 e^{-x} + (L/V)(1 - e^{-x}), x = V t/L, written so that it
      // stays exact for tiny V (L/V (1 - e^{-x}) = t (1 - e^{-x})/x)
      const double x = V * t_end / p.L;
      const double theta_exact =
        (x > 1e-8) ? theta0 * std::exp(-x) + p.L / V * (-std::expm1(-x)) :
                     theta0 * std::exp(-x) + t_end * (1. - x / 2. + x * x / 6.);
      const double alpha_exact = std::log(theta_exact * p.v_star / p.L);
      dealii::deallog << "ageing V = " << V << ": alpha = " << alpha
                      << ", |error| < 1e-12: "
                      << (std::abs(alpha - alpha_exact) < 1e-12 ? "yes" : "no")
                      << std::endl;
    }

  for (const double V : {1e-3, 50e-6, 1e-9, 0.})
    {
      double alpha = alpha0;
      for (int n = 0; n < 100; ++n)
        alpha = slip.update_state(p, alpha, V, tau);
      double alpha_exact = alpha0;
      if (V > 0)
        {
          const double psi0 = std::log(theta0 * V / p.L);
          alpha_exact =
            psi0 * std::exp(-V * t_end / p.L) - std::log(V / p.v_star);
        }
      dealii::deallog << "slip V = " << V << ": alpha = " << alpha
                      << ", |error| < 1e-12: "
                      << (std::abs(alpha - alpha_exact) < 1e-12 ? "yes" : "no")
                      << std::endl;
    }

  const QuadraticLaw quadratic;
  for (const double V : {1e-3, 50e-6, 1e-9, 1e-300, 0.})
    {
      double alpha = alpha0;
      for (int n = 0; n < 100; ++n)
        alpha = quadratic.update_state(p, alpha, V, tau);
      const double k = V / (2 * p.L), y0 = k * theta0;
      double       theta_exact = theta0 + t_end;
      if (k * t_end > 1e-8)
        theta_exact =
          (y0 < 1 ?
             std::tanh(k * t_end + std::atanh(y0)) :
             1 / std::tanh(k * t_end + 0.5 * std::log((y0 + 1) / (y0 - 1)))) /
          k;
      const double alpha_exact = std::log(theta_exact * p.v_star / p.L);
      dealii::deallog << "quadratic V = " << V << ": alpha = " << alpha
                      << ", |error| < 1e-12: "
                      << (std::abs(alpha - alpha_exact) < 1e-12 ? "yes" : "no")
                      << std::endl;
    }
  dealii::deallog << "quadratic steady state stays: "
                  << quadratic.update_state(p,
                                            std::log(2 * p.v_star / 1e-4),
                                            1e-4,
                                            10.) -
                       std::log(2 * p.v_star / 1e-4)
                  << std::endl;

  // Steady state of the ageing law: theta = L/V is a fixed point.
  const double V  = 1e-4;
  const double as = std::log(p.v_star / V);
  dealii::deallog << "steady state stays: "
                  << ageing.update_state(p, as, V, 10.) - as << std::endl;
  // Very long step: alpha -> log(V*/V).
  dealii::deallog << "long step reaches steady state: "
                  << ageing.update_state(p, 5., V, 1e3) - as << std::endl;
}
