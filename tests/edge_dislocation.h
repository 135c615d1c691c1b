// SPDX-License-Identifier: LGPL-2.1-or-later
// The closed form of an edge dislocation on a dipping fault through a
// half-space's surface (Segall, Earthquake and Volcano Deformation, 2010,
// ch. 3), for tests/green_operator_split_normal.cc and
// benchmarks/seas-bp3/operator_loading.cc. For a dislocation at down-dip
// distance z on a fault of dip delta that reaches the surface, observed on
// the fault at down-dip distance t, with D = t^2 + z^2 - 2 t z cos(2 delta)
// (the squared distance from the dislocation's image above the surface),
// the shear and normal (compression positive) stresses on the fault per
// unit thrust slip are (the full-space edge dislocation's
// mu / (2 pi (1 - nu) (t - z)) as t -> z)
//   T_s = 2 mu z (t + z) sin^2(delta) [P1 + P2 cos 2 delta + t^2 z^2 cos 4
//         delta] / (pi (1 - nu) (t - z) D^3),
//     P1 = t^4 - 3 t^3 z + 7 t^2 z^2 - 3 t z^3 + z^4,
//     P2 = t^4 - 5 t^3 z + 4 t^2 z^2 - 5 t z^3 + z^4,
//   T_n = -4 mu z^2 cos(delta) sin^3(delta) (z^3 - 3 t^2 z + 2 t^3 cos 2
//         delta) / (pi (1 - nu) D^3),
// and a unit thrust slip on a < x_d < b makes T(t, b) - T(t, a). (T_n
// vanishes at delta = 90 degrees: the vertical fault's normal stress does
// not change.)
#ifndef rsfcycle_tests_edge_dislocation_h
#define rsfcycle_tests_edge_dislocation_h

#include <array>
#include <cmath>

/** {T_s, T_n} at t of a unit thrust edge dislocation at z (see above). */
inline std::array<double, 2>
edge_dislocation(const double t,
                 const double z,
                 const double delta,
                 const double mu,
                 const double nu)
{
  const double c2 = std::cos(2 * delta), sd = std::sin(delta);
  const double D = t * t + z * z - 2 * t * z * c2, D3 = D * D * D;
  const double t2 = t * t, z2 = z * z;
  const double P1 =
    t2 * t2 - 3 * t2 * t * z + 7 * t2 * z2 - 3 * t * z2 * z + z2 * z2;
  const double P2 =
    t2 * t2 - 5 * t2 * t * z + 4 * t2 * z2 - 5 * t * z2 * z + z2 * z2;
  const double shear = 2 * mu * z * (t + z) * sd * sd *
                       (P1 + P2 * c2 + t2 * z2 * std::cos(4 * delta)) /
                       (M_PI * (1 - nu) * (t - z) * D3);
  const double normal = -4 * mu * z2 * std::cos(delta) * sd * sd * sd *
                        (z2 * z - 3 * t2 * z + 2 * t2 * t * c2) /
                        (M_PI * (1 - nu) * D3);
  return {{shear, normal}};
}

#endif
