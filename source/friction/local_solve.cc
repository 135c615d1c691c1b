// SPDX-License-Identifier: LGPL-2.1-or-later
#include <algorithm>
#include <cmath>
#include <rsfcycle/friction/local_solve.h>

namespace rsfcycle
{
  namespace friction
  {
    namespace
    {
      /**
       * x = (A + lambda I)^{-1} rho for d = 1, 2. For lambda > 1 it is
       * computed as (A/lambda + I)^{-1} rho / lambda, so that the
       * determinant cannot overflow for lambda up to 1e300.
       */
      template <int d>
      std::array<double, d>
      shifted_solve(const std::array<double, d * d> &A,
                    const std::array<double, d>     &rho,
                    const double                     lambda)
      {
        std::array<double, d> x;
        if constexpr (d == 1)
          x[0] = rho[0] / (A[0] + lambda);
        else
          {
            const double scale = (lambda > 1) ? 1. / lambda : 1.;
            const double shift = (lambda > 1) ? 1. : lambda;
            const double a00 = A[0] * scale + shift, a01 = A[1] * scale,
                         a10 = A[2] * scale, a11 = A[3] * scale + shift;
            const double det = a00 * a11 - a01 * a10;
            x[0]             = (a11 * rho[0] - a01 * rho[1]) / det * scale;
            x[1]             = (-a10 * rho[0] + a00 * rho[1]) / det * scale;
          }
        return x;
      }

      /** |x| without underflow of x^2 (slip rates may be ~1e-160 m/s). */
      template <int d>
      double
      norm(const std::array<double, d> &x)
      {
        if constexpr (d == 1)
          return std::abs(x[0]);
        else
          return std::hypot(x[0], x[1]);
      }
    } // namespace


    template <int d>
    LocalSolution<d>
    solve_local_problem(const std::array<double, d * d> &A,
                        const std::array<double, d>     &rho,
                        const NodePotential             &phi,
                        const std::array<double, d>     *guess)
    {
      LocalSolution<d> result;
      const double     rho_norm = norm<d>(rho);
      if (!(rho_norm > phi.cohesion_force))
        {
          result.stuck = true;
          return result;
        }

      // F(l) with lambda = exp(l); F is increasing in l.
      const auto F = [&](const double l, double &dF_dl) {
        const double lambda = std::exp(l);
        const auto   x      = shifted_solve<d>(A, rho, lambda);
        const double s      = norm<d>(x);
        // ds/dlambda = - x^T (A + lambda I)^{-1} x / s = -s e^T (A + lambda
        // I)^{-1} e with e = x/s (no underflow for tiny s and huge lambda)
        double ds = 0;
        if (s > 0)
          {
            std::array<double, d> e;
            for (unsigned int i = 0; i < d; ++i)
              e[i] = x[i] / s;
            const auto y  = shifted_solve<d>(A, e, lambda);
            double     ey = 0;
            for (unsigned int i = 0; i < d; ++i)
              ey += e[i] * y[i];
            ds = -s * ey;
          }
        const auto [d1, d2] = phi.derivatives(s);
        dF_dl               = lambda * (s + lambda * ds - d2 * ds);
        return lambda * s - d1;
      };

      // Safeguarded Newton in l, started where lambda = phi'(s)/s for the
      // guess s (its value at the solution), or else for s0 = |A^-1 rho| (an
      // upper bound of s). Until F has changed sign the iterates move toward
      // the root by at most 2.3 (a factor of 10 in lambda); after that they
      // stay inside the bracket [lo, hi] (bisection where Newton would leave
      // it).
      const double s_guess = guess ? norm<d>(*guess) : 0.;
      const double s_start =
        (s_guess > 0) ? s_guess : norm<d>(shifted_solve<d>(A, rho, 0.));
      constexpr double l_min = -690., l_max = 690., max_move = 2.3;
      double l = std::clamp(std::log(std::max(phi.derivative(s_start) / s_start,
                                              1e-300)),
                            l_min,
                            l_max);
      double lo = l_min, hi = l_max;
      bool   above = false, below = false; // F > 0 / F < 0 seen
      for (unsigned int it = 0; it < 200; ++it)
        {
          ++result.iterations;
          double       dF;
          const double f = F(l, dF);
          if (f == 0)
            break;
          if (f < 0)
            {
              if (l >= l_max)
                {
                  // s(lambda) < 1e-300 |rho|/|A|: the node does not move in
                  // double precision.
                  result.stuck = true;
                  return result;
                }
              lo    = l;
              below = true;
            }
          else
            {
              if (l <= l_min)
                break;
              hi    = l;
              above = true;
            }
          const double towards = (f < 0) ? max_move : -max_move;
          double       l_new   = (dF > 0) ? l - f / dF : l + towards;
          if (!(above && below))
            l_new = std::clamp(l_new, l - max_move, l + max_move);
          if (!(l_new > lo && l_new < hi))
            l_new = (above && below) ? 0.5 * (lo + hi) :
                                       std::clamp(l + towards, l_min, l_max);
          const double step = std::abs(l_new - l);
          l                 = l_new;
          if (step < 1e-14 * std::max(1., std::abs(l)) ||
              (above && below && hi - lo < 1e-14))
            break;
        }
      result.x = shifted_solve<d>(A, rho, std::exp(l));
      return result;
    }

    template LocalSolution<1>
    solve_local_problem<1>(const std::array<double, 1> &,
                           const std::array<double, 1> &,
                           const NodePotential &,
                           const std::array<double, 1> *);
    template LocalSolution<2>
    solve_local_problem<2>(const std::array<double, 4> &,
                           const std::array<double, 2> &,
                           const NodePotential &,
                           const std::array<double, 2> *);
  } // namespace friction
} // namespace rsfcycle
