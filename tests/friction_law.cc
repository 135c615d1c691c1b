// SPDX-License-Identifier: LGPL-2.1-or-later
// Checks the regularised rate-and-state friction coefficient (2) and its
// derivative, evaluated in log space (doc/model.md §2, "Working in log space"):
//  - Table 1 values (a = 0.002, b = 0.017, mu* = 0.7): mu equals the plain
//    formula a asinh(V / (2 V_theta)) wherever that is representable
//    (relative difference printed, must be < 1e-12);
//  - at V = V*, alpha = 0 the classical law gives mu = mu*; the regularised
//    law differs by a*log(1 + sqrt(1 + z^-2)) - a log 2 = O(z^-2): printed;
//  - the extreme case a = 1e-3, mu* = 0.8 (mu*/a = 800: exp(800) overflows
//    double), at V = 0, 1e-300, 1e-12, 1 and 10 m/s: finite values,
//    mu(0) = 0, mu increasing in V, mu' > 0 and finite (capped at 1e300);
//  - mu' against a centred difference quotient of mu;
//  - the steady-state coefficient against mu* + (a - b) log(V/V*).
#include "tests.h"

#include <cmath>
#include <limits>
#include <rsfcycle/friction/ageing_law.h>

using namespace rsfcycle::friction;

int
main()
{
  initlog(10);
  // the coefficient (2) is the same for every state law
  const AgeingLaw law;

  Parameters p;
  p.a       = 0.002;
  p.b       = 0.017;
  p.mu_star = 0.7;
  p.v_star  = 50e-6;
  p.L       = 22.5e-6;

  // Plain formula where representable (mu*/a = 350: V_theta ~ 1e-152 V*).
  double max_rel = 0;
  for (const double alpha : {-2., 0., 3.})
    for (const double V : {1e-160, 1e-155, 1e-12, 1e-6, 50e-6, 1e-3, 1.})
      {
        const double v_theta =
          p.v_star * std::exp(-(p.mu_star + p.b * alpha) / p.a);
        const double plain = p.a * std::asinh(V / (2 * v_theta));
        const double ours  = law.friction_coefficient(p, alpha, V);
        max_rel            = std::max(max_rel, std::abs(ours - plain) / plain);
      }
  dealii::deallog << "max relative difference to plain asinh < 1e-12: "
                  << (max_rel < 1e-12 ? "yes" : "no") << std::endl;

  dealii::deallog << "mu(V*, alpha=0) - mu* = "
                  << law.friction_coefficient(p, 0., p.v_star) - p.mu_star
                  << std::endl;
  for (const double V : {1e-9, 1e-6, 50e-6, 1e-3, 1e-1})
    dealii::deallog << "V = " << V << ": mu_ss - (mu* + (a-b) log(V/V*)) = "
                    << law.steady_state_friction_coefficient(p, V) -
                         (p.mu_star + (p.a - p.b) * std::log(V / p.v_star))
                    << std::endl;

  // Extreme parameters.
  Parameters q = p;
  q.a          = 1e-3;
  q.b          = 0.016;
  q.mu_star    = 0.8;
  dealii::deallog << "extreme a = 1e-3, mu* = 0.8 (exp(mu*/a) = "
                  << std::exp(q.mu_star / q.a) << ")" << std::endl;
  for (const double alpha : {-5., 0., 10.})
    {
      double previous = -1;
      bool   monotone = true, finite = true;
      for (const double V : {0., 1e-300, 1e-200, 1e-12, 1e-6, 1., 10.})
        {
          const double mu  = law.friction_coefficient(q, alpha, V);
          const double dmu = law.friction_coefficient_derivative(q, alpha, V);
          finite = finite && std::isfinite(mu) && std::isfinite(dmu) && dmu > 0;
          monotone = monotone && mu >= previous;
          previous = mu;
        }
      dealii::deallog << "alpha = " << alpha
                      << ": mu(0) = " << law.friction_coefficient(q, alpha, 0.)
                      << ", mu(10 m/s) = "
                      << law.friction_coefficient(q, alpha, 10.)
                      << ", mu'(0) = "
                      << law.friction_coefficient_derivative(q, alpha, 0.)
                      << ", finite: " << (finite ? "yes" : "no")
                      << ", monotone: " << (monotone ? "yes" : "no")
                      << std::endl;
    }
  // At 10 m/s the classical law is accurate: mu = mu* + a log(V/V*) + b alpha
  dealii::deallog << "mu(10 m/s, alpha = 0) - classical = "
                  << law.friction_coefficient(q, 0., 10.) -
                       (q.mu_star + q.a * std::log(10. / q.v_star))
                  << std::endl;

  // Derivative against a difference quotient (relative error).
  double max_derivative_error = 0;
  for (const double V : {1e-154, 1e-152, 1e-9, 50e-6, 1.})
    {
      const double h  = 1e-6 * V;
      const double fd = (law.friction_coefficient(p, 0., V + h) -
                         law.friction_coefficient(p, 0., V - h)) /
                        (2 * h);
      const double exact = law.friction_coefficient_derivative(p, 0., V);
      max_derivative_error =
        std::max(max_derivative_error, std::abs(fd - exact) / exact);
    }
  dealii::deallog << "derivative matches difference quotient to 1e-6: "
                  << (max_derivative_error < 1e-6 ? "yes" : "no") << std::endl;
}
