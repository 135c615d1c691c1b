// SPDX-License-Identifier: LGPL-2.1-or-later
// Checks the normal coupling of a split fault in the Green's-function
// method (physics::GreenOperator::N, physics/split_fault.h): the normal
// stress change that slip on a dipping fault makes through the free
// surface (SEAS BP3's Delta sigma_n), against the closed form of an edge
// dislocation in a half-space (Segall 2010: T_s and T_n of a unit thrust
// slip, tests/edge_dislocation.h; a unit thrust slip on a < x_d < b makes
// T(t, b) - T(t, a); T_n vanishes at 90 degrees, as green_function_split's
// mirror models need). The mesh:
// tests/meshes/dipping-split-2d.msh (BP3's 60-degree fault, the hanging
// wall x > fault the + side, the footwall the - side, meshed apart),
// refined to 63 m next to the fault; mu = 32.04 GPa, nu = 1/4;
// a = 10 km, b = 20 km. The rotated frame's x is down dip (y into the
// hanging wall), so the slip s = u+ - u- > 0 is normal faulting: the
// thrust slip is -s. Compared (yes/no lines), at the nodes more than 3 km
// from the ends of the slipping interval and less than 38 km down dip:
//  - the shear stress change -(S s)_k / w_k against T_s within 2 % of the
//    stress drop at the interval's centre;
//  - the normal stress change (N s)_k / w_k against T_n (of -s) within
//    2 % of its largest value (at the surface) below 1 km down dip (1.7 %
//    at 16.9 km, where the unstructured cells change size; under 1 %
//    elsewhere), within 3 % above (2.5 %: the corner of the free surface
//    and the fault, 63 m cells), and its sign at the largest;
//  - the whole fault sliding with the plates (both sides move rigidly):
//    the rate of the normal forces n1 + N s' (s' the plates' relative
//    velocity, -1e-9 m/s along the frame's x) vanishes, within 1e-7 of
//    the locked fault's n1 (rounding: 3e-9).
#include "edge_dislocation.h"
#include "tests.h"

#include <cmath>
#include <deal.II/base/mpi.h>
#include <rsfcycle/app/simulation.h>
#include <rsfcycle/models/green_fault.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/scenes/scenes.h>

using namespace rsfcycle;

namespace
{
  const double mu = 32.04e9, nu = 0.25, delta = M_PI / 3, a = 10e3, b = 20e3;

  /** Shear and normal stress of a unit thrust edge dislocation at z. */
  std::array<double, 2>
  dislocation(const double t, const double z)
  {
    return edge_dislocation(t, z, delta, mu, nu);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(6);
  const std::string        source = SOURCE_DIR;
  dealii::ParameterHandler prm;
  app::declare_parameters(prm);
  prm.parse_input_from_string(
    "set Dimension = 2\n"
    "set Scene = mesh-file\n"
    "set Output directory = output\n"
    "set Displacement = vector\n"
    "subsection Mesh file\n"
    "  set File = " +
    source +
    "/meshes/dipping-split-2d.msh\n"
    "  set Boundary roles = 1: contact, 2: creep, 3: free, 4: free, 5: load, "
    "11: fault-opposite, 12: fault-opposite, 15: load-opposite\n"
    "  set Materials = 10: density 2670, bulk modulus 5.34e10, Poisson ratio "
    "0.25, shear viscosity 0, bulk viscosity 0; 20: density 2670, bulk "
    "modulus 5.34e10, Poisson ratio 0.25, shear viscosity 0, bulk viscosity "
    "0\n"
    "  set Gravity = 0, 0\n"
    "  set Load velocity = -2.5e-10, 4.330127e-10\n"
    "  set Ramp time = 0\n"
    "  set Refine where = 1\n"
    "  subsection Friction\n"
    "    set a = 0.01\n"
    "    set b - a = 0.005\n"
    "    set Normal stress = 50e6\n"
    "    set Cohesion = 0\n"
    "  end\n"
    "end\n"
    "subsection Mesh\n"
    "  set Global refinements = 0\n"
    "  set Local refinements = 4\n"
    "  set Refinement distance = 1\n"
    "end\n"
    "subsection Time stepping\n"
    "  set Integrator = runge-kutta\n"
    "end\n"
    "subsection Output\n"
    "  set Writers = time series, base profile, events\n"
    "end\n"
    "subsection Solver\n"
    "  set Dynamics = quasi-dynamic\n"
    "  set Bulk = green-function\n"
    "end\n");
  Parameters parameters;
  parameters.parse_parameters(prm);
  const auto            scene = scenes::make_scene<2>("mesh-file", prm);
  std::ostringstream    log;
  models::GreenFault<2> fault(parameters, *scene, log);
  fault.setup();
  const auto        &op    = fault.green_operator();
  const auto        &nodes = fault.contact_quadrature().nodes();
  const unsigned int n     = nodes.size();

  // down-dip distances (the contact starts at the surface)
  std::vector<double> x(n);
  double              lo = 1e300, hi = -1e300;
  for (unsigned int k = 0; k < n; ++k)
    {
      x[k] = scene->along_base_coordinate(nodes[k].position);
      lo   = std::min(lo, x[k]);
      hi   = std::max(hi, x[k]);
    }
  for (auto &xk : x)
    xk -= lo;
  double h = hi - lo;
  for (unsigned int k = 0; k + 1 < n; ++k)
    for (unsigned int j = 0; j < n; ++j)
      if (x[j] > x[k])
        h = std::min(h, x[j] - x[k]);
  dealii::deallog << "normal coupling: " << (op.normal_coupling ? "yes" : "no")
                  << "; " << n << " contact nodes from 0 to "
                  << std::round((hi - lo) / 100) / 10
                  << " km down dip, spacing " << std::round(h) << " m"
                  << std::endl;

  // a unit slip s = 1 on a < x_d < b (normal faulting in this frame); the
  // closed form's ends at the ramps' midpoints (green_operator_normal)
  dealii::Vector<double> s(n), Ss(n), Ns(n);
  for (unsigned int k = 0; k < n; ++k)
    s[k] = (x[k] > a && x[k] < b) ? 1. : 0.;
  double a_in = 1e300, b_in = 0, a_out = 0, b_out = 1e300;
  for (unsigned int k = 0; k < n; ++k)
    if (s[k] == 1)
      {
        a_in = std::min(a_in, x[k]);
        b_in = std::max(b_in, x[k]);
      }
    else if (x[k] < a)
      a_out = std::max(a_out, x[k]);
    else
      b_out = std::min(b_out, x[k]);
  const double a_e = 0.5 * (a_in + a_out), b_e = 0.5 * (b_in + b_out);
  op.S.vmult(Ss, s);
  op.N.vmult(Ns, s);
  const auto exact = [&](const double t) {
    // the thrust slip is -s: minus the thrust interval's stresses; the
    // shear stress in s's direction is the same quadratic form either way
    const auto A = dislocation(t, a_e), B = dislocation(t, b_e);
    return std::array<double, 2>{{B[0] - A[0], -(B[1] - A[1])}};
  };
  const double drop  = std::abs(exact(0.5 * (a_e + b_e))[0]);
  double shear_error = 0, normal_error = 0, surface_error = 0, largest = 0,
         at            = 0;
  double largest_exact = 0;
  for (unsigned int k = 0; k < n; ++k)
    {
      const auto e = exact(x[k]);
      if (std::abs(e[1]) > std::abs(largest_exact))
        {
          largest_exact = e[1];
          at            = x[k];
        }
    }
  for (unsigned int k = 0; k < n; ++k)
    {
      const double tau   = -Ss[k] / nodes[k].weight,
                   sigma = Ns[k] / nodes[k].weight;
      if (x[k] == at)
        largest = sigma;
      if (std::abs(x[k] - a) < 3e3 || std::abs(x[k] - b) < 3e3 || x[k] > 38e3)
        continue;
      const auto e = exact(x[k]);
      shear_error  = std::max(shear_error, std::abs(tau - e[0]));
      (x[k] < 1e3 ? surface_error : normal_error) =
        std::max(x[k] < 1e3 ? surface_error : normal_error,
                 std::abs(sigma - e[1]));
    }
  dealii::deallog << "shear stress change: drop at the centre "
                  << std::round(drop / 1e4) / 1e2
                  << " MPa; largest error relative to it within 2 %: "
                  << (shear_error / drop < 0.02 ? "yes" : "no") << std::endl;
  dealii::deallog
    << "normal stress change: largest " << std::round(largest / 1e4) / 1e2
    << " MPa at " << std::round(at / 100) / 10 << " km down dip, closed form "
    << std::round(largest_exact / 1e4) / 1e2
    << " MPa; largest error relative to it within 2 % "
       "below 1 km down dip: "
    << (normal_error / std::abs(largest_exact) < 0.02 ? "yes" : "no")
    << ", within 3 % above: "
    << (surface_error / std::abs(largest_exact) < 0.03 ? "yes" : "no")
    << "; the same sign: " << (largest * largest_exact > 0 ? "yes" : "no")
    << std::endl;
  // the whole fault sliding with the plates (s' = 2 (Vp/2) along x, the
  // load's -5e-10 along the frame's x per side): both sides move rigidly,
  // so n1 + N s' vanishes (to rounding)
  dealii::Vector<double> ones(n), N1(n);
  ones = 1.;
  op.N.vmult(N1, ones);
  double rigid = 0, scale = 0;
  for (unsigned int k = 0; k < n; ++k)
    {
      rigid = std::max(rigid, std::abs(op.n1[k] - 1e-9 * N1[k]));
      scale = std::max(scale, std::abs(op.n1[k]));
    }
  dealii::deallog << "the fault sliding with the plates: the normal force's "
                     "rate within 1e-7 of the locked fault's: "
                  << (rigid < 1e-7 * scale ? "yes" : "no") << std::endl;
  return 0;
}
