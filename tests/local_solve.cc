// SPDX-License-Identifier: LGPL-2.1-or-later
// Checks the exact node-local friction solve of the nonlinear Gauss-Seidel
// sweep, min 1/2 x^T A x - rho^T x + phi(|x|) (doc/model.md §4.2 step 1):
//  - stick below cohesion: |rho| <= W gives x = 0 exactly;
//  - slip above: the optimality condition A x + phi'(|x|) x/|x| = rho holds
//    to a relative residual < 1e-10, for 1 (2D) and 2 (3D) components;
//  - 3D with an anisotropic 2x2 block: x is not parallel to rho (the
//    angle is printed) and the residual is still at round-off;
//  - a nearly stuck node of the paper's unstable patch (slip rate around
//    1e-150 m/s, where phi'' exceeds A by ~150 orders of magnitude), and a
//    fast one (|x| ~ 1 m/s): finite, positive, residual at round-off.
// The printed log10|x| values were checked against the scalar equation
// a s + N mu(s) + W = |rho| solved by hand for the 1-component cases.
#include "tests.h"

#include <algorithm>
#include <cmath>
#include <rsfcycle/friction/ageing_law.h>
#include <rsfcycle/friction/local_solve.h>

using namespace rsfcycle::friction;

template <int d>
void
check(const std::string               &name,
      const std::array<double, d * d> &A,
      const std::array<double, d>     &rho,
      const NodePotential             &phi)
{
  const auto   sol = solve_local_problem<d>(A, rho, phi);
  const double s =
    (d == 1) ? std::abs(sol.x[0]) : std::hypot(sol.x[0], sol.x[d - 1]);
  dealii::deallog << name << ": ";
  if (s == 0)
    {
      dealii::deallog << "stuck (x = 0)" << std::endl;
      return;
    }
  double res2 = 0, rho2 = 0;
  for (unsigned int i = 0; i < d; ++i)
    {
      double r = -rho[i] + phi.derivative(s) * sol.x[i] / s;
      for (unsigned int j = 0; j < d; ++j)
        r += A[d * i + j] * sol.x[j];
      res2 += r * r;
      rho2 += rho[i] * rho[i];
    }
  dealii::deallog << "log10|x| = " << std::log10(s) << ", relative residual < "
                  << "1e-10: "
                  << (std::sqrt(res2 / rho2) < 1e-10 ? "yes" : "no");
  if (d == 2)
    dealii::deallog << ", angle(x, rho) = "
                    << std::acos(std::min(1.,
                                          ((sol.x[0] / s) * rho[0] +
                                           (sol.x[d - 1] / s) * rho[d - 1]) /
                                            std::sqrt(rho2)))
                    << " rad";
  dealii::deallog << std::endl;
}

int
main()
{
  initlog(8);

  const AgeingLaw ageing;
  NodePotential   stable; // rate strengthening, Table 1
  stable.law            = &ageing;
  stable.params.a       = 0.02;
  stable.params.b       = 0.005;
  stable.normal_force   = 3.0;  // N/m
  stable.cohesion_force = 0.05; // N/m
  stable.set_state(0);

  NodePotential unstable = stable; // the patch, Table 1
  unstable.params.a      = 0.002;
  unstable.params.b      = 0.017;
  unstable.set_state(0);

  // 2D: one tangential component.
  check<1>("2D stick", {{1e4}}, {{0.049}}, stable);
  check<1>("2D stick negative", {{1e4}}, {{-0.05}}, stable);
  check<1>("2D slip", {{1e4}}, {{2.5}}, stable);
  check<1>("2D slip negative", {{1e4}}, {{-2.5}}, stable);
  check<1>("2D fast", {{1.}}, {{3.0}}, stable);
  // mu at V ~ 1e-150 is ~ a asinh(1) on the patch: rho slightly above W
  check<1>("2D nearly stuck patch", {{1e4}}, {{0.0501}}, unstable);
  check<1>("2D patch at mu*", {{1e4}}, {{2.15}}, unstable);

  // 3D: two tangential components.
  check<2>("3D stick", {{1e4, 0, 0, 1e4}}, {{0.03, 0.03}}, stable);
  check<2>("3D slip isotropic", {{1e4, 0, 0, 1e4}}, {{1.5, 2.0}}, stable);
  check<2>("3D slip anisotropic", {{1e4, 3e3, 3e3, 2e4}}, {{1.5, 2.0}}, stable);
  check<2>("3D fast anisotropic", {{1., 0.3, 0.3, 2.}}, {{2.0, 2.5}}, stable);
  check<2>("3D nearly stuck patch",
           {{1e4, 3e3, 3e3, 2e4}},
           {{0.04, 0.031}},
           unstable);
}
