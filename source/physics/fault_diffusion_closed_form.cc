// SPDX-License-Identifier: LGPL-2.1-or-later
// The closed form of a Gaussian source of constant rate in the infinite
// plane and line (include/rsfcycle/physics/fault_diffusion.h, doc/model.md
// §9). The Gaussian injected at time s has spread by t to a Gaussian of
// variance v = L_inj^2 + 2 alpha (t - s) per direction; integrating over s
// gives E1 in the plane and F (erfc) in the line.
#include <array>
#include <cmath>
#include <deal.II/base/numbers.h>
#include <rsfcycle/physics/fault_diffusion.h>

namespace rsfcycle
{
  namespace physics
  {
    namespace
    {
      constexpr double euler_gamma = 0.57721566490153286061;

      /** E1(u) = int_u^inf exp(-s) / s ds, u > 0. */
      double
      e1(const double u)
      {
        return -std::expint(-u);
      }

      /** Ein(u) = int_0^u (1 - exp(-s)) / s ds = E1(u) + gamma + ln u. */
      double
      ein(const double u)
      {
        if (u >= 2)
          return e1(u) + euler_gamma + std::log(u);
        // sum_n (-1)^(n+1) u^n / (n n!), terms below 2^n / n!
        double term = u, sum = u;
        for (unsigned int n = 2; n < 60 && std::abs(term) > 1e-18; ++n)
          {
            term *= -u / n;
            sum += term / n;
          }
        return sum;
      }

      /**
       * E1(r^2 / (2 v)) - E1(r^2 / (2 v0)) for v >= v0, finite at r = 0:
       * ln(v / v0) + Ein(r^2 / (2 v)) - Ein(r^2 / (2 v0)) near the
       * source, the difference of the E1 far from it.
       */
      double
      e1_difference(const double r2, const double v, const double v0)
      {
        const double a = r2 / (2 * v), b = r2 / (2 * v0);
        if (a < 1)
          return std::log(v / v0) + ein(a) - ein(b);
        return e1(a) - e1(b);
      }

      /** F(v) = sqrt(2 v / pi) exp(-x^2 / (2 v)) - |x| erfc(|x| / sqrt(2 v)).
       */
      double
      line_kernel(const double x, const double v)
      {
        const double a = std::abs(x);
        return std::sqrt(2 * v / numbers::PI) * std::exp(-x * x / (2 * v)) -
               a * std::erfc(a / std::sqrt(2 * v));
      }

      /**
       * The variances at t of the fluid injected from t = 0 and, after the
       * shut-in, of the fluid not injected from t_off (the superposed sink);
       * 0: none.
       */
      std::array<double, 2>
      variances(const FaultDiffusionParameters &p, const double t)
      {
        const double v0    = p.injection_width * p.injection_width;
        const double alpha = p.diffusivity();
        return {
          {t > 0 ? v0 + 2 * alpha * t : 0.,
           t > p.shut_in_time ? v0 + 2 * alpha * (t - p.shut_in_time) : 0.}};
      }
    } // namespace


    template <int plane_dim>
    double
    gaussian_injection_pressure(const FaultDiffusionParameters &p,
                                const Point<plane_dim>         &x,
                                const double                    t)
    {
      static_assert(plane_dim == 1 || plane_dim == 2, "a line or a plane");
      const double v0 = p.injection_width * p.injection_width;
      const double c =
        p.injection_rate * p.viscosity / (p.permeability * p.thickness);
      const double r2       = x.norm_square();
      double       pressure = 0;
      double       sign     = 1;
      for (const double v : variances(p, t))
        {
          if (v > 0)
            pressure +=
              sign * (plane_dim == 2 ?
                        c / (4 * numbers::PI) * e1_difference(r2, v, v0) :
                        c / 2 * (line_kernel(x[0], v) - line_kernel(x[0], v0)));
          sign = -1;
        }
      return pressure;
    }


    template <int plane_dim>
    Tensor<1, plane_dim>
    gaussian_injection_darcy_velocity(const FaultDiffusionParameters &p,
                                      const Point<plane_dim>         &x,
                                      const double                    t)
    {
      const double         v0   = p.injection_width * p.injection_width;
      const double         q0   = p.injection_rate / p.thickness;
      const double         r2   = x.norm_square();
      double               sign = 1;
      Tensor<1, plane_dim> q;
      if (r2 == 0)
        return q;
      for (const double v : variances(p, t))
        {
          if (v > 0)
            {
              if (plane_dim == 2)
                {
                  // Q0 / (2 pi L r^2) [exp(-r^2 / 2v) - exp(-r^2 / 2v0)] x
                  const double a = r2 / (2 * v), b = r2 / (2 * v0);
                  const double f = -std::exp(-a) * std::expm1(a - b) / r2;
                  q += sign * q0 / (2 * numbers::PI) * f * x;
                }
              else
                {
                  const double a = std::abs(x[0]);
                  const double f = std::erfc(a / std::sqrt(2 * v)) -
                                   std::erfc(a / std::sqrt(2 * v0));
                  q[0] += sign * q0 / 2 * f * (x[0] > 0 ? 1 : -1);
                }
            }
          sign = -1;
        }
      return q;
    }


    template double
    gaussian_injection_pressure<1>(const FaultDiffusionParameters &,
                                   const Point<1> &,
                                   double);
    template double
    gaussian_injection_pressure<2>(const FaultDiffusionParameters &,
                                   const Point<2> &,
                                   double);
    template Tensor<1, 1>
    gaussian_injection_darcy_velocity<1>(const FaultDiffusionParameters &,
                                         const Point<1> &,
                                         double);
    template Tensor<1, 2>
    gaussian_injection_darcy_velocity<2>(const FaultDiffusionParameters &,
                                         const Point<2> &,
                                         double);
  } // namespace physics
} // namespace rsfcycle
