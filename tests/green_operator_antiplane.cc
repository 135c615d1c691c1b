// SPDX-License-Identifier: LGPL-2.1-or-later
// Checks the Green's-function operator of `Solver/Bulk = green-function`
// (physics::GreenOperator, doc/model.md §8.1) against the antiplane closed
// form: uniform slip D on the depth interval d1 < z < d2 of the vertical
// fault of a half-space with a free surface (a pair of screw dislocations
// and their images). In the full space with shear modulus mu the shear
// stress on the fault is
//   tau(z) = mu D / (2 pi) [1/(z - d2) - 1/(z - d1) + 1/(z + d1) - 1/(z + d2)]
// and the surface displacement on the side x > 0 is
//   u(x) = D / pi [atan(d2 / x) - atan(d1 / x)];
// the one-sided model of prm/seas-bp1-qd.prm (mu' = mu / 2, a rigid mirror
// at x = 0, the slip the displacement relative to it) has the same stress
// and twice that displacement.
// Positions in the scene's rotated frame: the depth is the along-base
// coordinate, the distance from the fault the height above the base.
// The mesh is seas-bp1's (400 km, the fault below 40 km and the remote side
// held) refined to 100 m on the fault (4 local refinements); slip 1 m on the
// contact nodes with 10 km < z < 20 km. Compared, with yes/no lines:
//  - the traction -(S s)_k / w_k at the contact nodes more than 2 km from
//    the interval's ends (inside and outside) and from 1 km to 38 km deep,
//    as the largest error relative to the stress drop at the interval's
//    centre (within 1 %; the node at the free surface, whose lumped weight
//    is half a cell, is 3 % off and left out);
//  - the displacement o0 + O s at the surface stations (no load: t = 0,
//    and g0, o0 vanish without prestress) against 2 u(x) (within 1 %);
//  - S symmetric (to 1e-8 of its largest entry);
//  - the loading: g1, the plate rate on the remote side and the fault
//    below 40 km with no slip, loads the whole fault (g1 > 0); g0 is the
//    shear prestress tau_0 w_k alone (the antiplane model has no body
//    force);
//  - S compressed as an H-matrix (hmat-oss, Green compression tolerance
//    1e-6): fewer than half the dense numbers, and its product for the
//    interval's slip within 1e-5 of the largest |S s| of the dense one
//    (ACA+ bounds each block's error by the tolerance relative to the
//    block), as is the error that compress() reports for its test slips.
#include "tests.h"

#include <cmath>
#include <deal.II/base/mpi.h>
#include <rsfcycle/app/simulation.h>
#include <rsfcycle/models/green_fault.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/scenes/scenes.h>

using namespace rsfcycle;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(6);
  const std::string source = SOURCE_DIR;

  dealii::ParameterHandler prm;
  app::declare_parameters(prm);
  prm.parse_input(source + "/../prm/seas-bp1-qd.prm");
  prm.parse_input_from_string("set Output directory = output-run\n"
                              "subsection Mesh file\n"
                              "  set File = " +
                              source +
                              "/../prm/meshes/seas-bp1.msh\n"
                              "end\n"
                              "subsection Mesh\n"
                              "  set Local refinements = 4\n"
                              "end\n"
                              "subsection Time stepping\n"
                              "  set Integrator = runge-kutta\n"
                              "end\n"
                              "subsection Solver\n"
                              "  set Bulk = green-function\n"
                              "end\n");
  Parameters parameters;
  parameters.parse_parameters(prm);
  const auto scene = scenes::make_scene<2>("mesh-file", prm);

  std::ostringstream    log;
  models::GreenFault<2> fault(parameters, *scene, log);
  fault.setup();
  const auto        &op    = fault.green_operator();
  const auto        &nodes = fault.contact_quadrature().nodes();
  const unsigned int n     = nodes.size();
  dealii::deallog << "contact nodes: " << n << ", S " << op.S.m() << " x "
                  << op.S.n() << ", observation rows " << op.O.m() << std::endl;

  const double mu = 2 * 16.019e9; // the full material of the benchmark
  const double d1 = 10e3, d2 = 20e3;
  double       e1 = d1, e2 = d2; // the ends of the closed form, below
  const auto   tau_exact = [&](const double z) {
    return mu / (2 * M_PI) *
           (1 / (z - e2) - 1 / (z - e1) + 1 / (z + e1) - 1 / (z + e2));
  };
  dealii::Vector<double> s(n), Ss(n);
  for (unsigned int k = 0; k < n; ++k)
    {
      const double z = scene->along_base_coordinate(nodes[k].position);
      s[k]           = (z > d1 && z < d2) ? 1. : 0.;
    }
  op.S.vmult(Ss, s);
  // The discrete slip ramps linearly over the cell at each end: the
  // closed form takes the ends at the ramps' midpoints (its far field is
  // that of the step there, to O(h^2 / r^2)).
  double in_lo = 1e300, in_hi = -1e300, out_lo = -1e300, out_hi = 1e300;
  for (unsigned int k = 0; k < n; ++k)
    if (s[k] == 1)
      {
        const double z = scene->along_base_coordinate(nodes[k].position);
        in_lo          = std::min(in_lo, z);
        in_hi          = std::max(in_hi, z);
      }
  for (unsigned int k = 0; k < n; ++k)
    {
      const double z = scene->along_base_coordinate(nodes[k].position);
      if (z < in_lo)
        out_lo = std::max(out_lo, z);
      if (z > in_hi)
        out_hi = std::min(out_hi, z);
    }
  e1 = 0.5 * (out_lo + in_lo);
  e2 = 0.5 * (in_hi + out_hi);
  dealii::deallog << "slip 1 m on " << in_lo << " m ... " << in_hi
                  << " m, the closed form's ends at " << e1 << " m and " << e2
                  << " m" << std::endl;
  const double scale = std::abs(tau_exact(0.5 * (d1 + d2)));
  double       error = 0, z_worst = 0;
  unsigned int checked = 0;
  for (unsigned int k = 0; k < n; ++k)
    {
      const double z = scene->along_base_coordinate(nodes[k].position);
      if (std::abs(z - d1) < 2e3 || std::abs(z - d2) < 2e3 || z < 1e3 ||
          z > 38e3)
        continue;
      const double tau = -Ss[k] / nodes[k].weight;
      if (std::abs(tau - tau_exact(z)) > error)
        {
          error   = std::abs(tau - tau_exact(z));
          z_worst = z;
        }
      if (std::abs(z - 0.5 * (d1 + d2)) < 60)
        dealii::deallog << "traction at z = " << z << " m: " << tau / 1e6
                        << " MPa, closed form " << tau_exact(z) / 1e6 << " MPa"
                        << std::endl;
      ++checked;
    }
  dealii::deallog << "nodes compared: " << checked
                  << ", largest error at z = " << z_worst << " m" << std::endl;
  dealii::deallog << "largest traction error / stress drop at the centre: "
                  << error / scale << " ("
                  << (error / scale < 1e-2 ? "within 1 %: yes" : "no") << ")"
                  << std::endl;

  // the surface stations fn+02 ... fn+32 (fn+00 lies on the fault)
  const auto points  = scene->observation_points();
  double     u_error = 0, u_scale = 0;
  for (unsigned int p = 0; p < points.size(); ++p)
    {
      const double x = points[p].second[1];
      double       u = op.o0[p];
      for (unsigned int k = 0; k < n; ++k)
        u += op.O(p, k) * s[k];
      const double exact =
        x > 0 ? 2 / M_PI * (std::atan(e2 / x) - std::atan(e1 / x)) : 0.;
      dealii::deallog << points[p].first << ": u = " << u << " m, closed form "
                      << exact << " m" << std::endl;
      u_error = std::max(u_error, std::abs(u - exact));
      u_scale = std::max(u_scale, std::abs(exact));
    }
  dealii::deallog << "surface displacement within 1 % of the largest: "
                  << (u_error < 1e-2 * u_scale ? "yes" : "no") << std::endl;

  double asymmetry = 0, entry = 0;
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < n; ++j)
      {
        asymmetry = std::max(asymmetry, std::abs(op.S(i, j) - op.S(j, i)));
        entry     = std::max(entry, std::abs(op.S(i, j)));
      }
  dealii::deallog << "S symmetric: "
                  << (asymmetry < 1e-8 * entry ? "yes" : "no") << std::endl;

  // tau_0 of prm/seas-bp1-qd.prm (Shear prestress)
  const double tau0 =
    50e6 * 0.025 *
      std::asinh(1e-9 / 2e-6 *
                 std::exp((0.6 + 0.015 * std::log(1e-6 / 1e-9)) / 0.025)) +
    4.62444e6 * 1e-9;
  bool loading = true, prestress = true;
  for (unsigned int k = 0; k < n; ++k)
    {
      loading = loading && op.g1[k] > 0;
      prestress =
        prestress && std::abs(op.g0[k] / nodes[k].weight - tau0) < 1e-9 * tau0;
    }
  dealii::deallog << "loading rate g1 > 0 on every node: "
                  << (loading ? "yes" : "no") << std::endl;
  dealii::deallog << "g0 / w = tau_0 = " << tau0 / 1e6
                  << " MPa on every node (no body force): "
                  << (prestress ? "yes" : "no") << std::endl;

  physics::GreenOperator compressed = op;
  std::vector<double>    xy;
  for (const auto &node : nodes)
    xy.insert(xy.end(), {node.position[0], node.position[1]});
  const double reported = compressed.compress(xy, 2, 1e-6, MPI_COMM_SELF);
  dealii::Vector<double> Hs(n);
  compressed.compressed->vmult(s.data(), Hs.data());
  Hs -= Ss;
  const double fraction =
    compressed.compressed->stored_entries() / (double(n) * n);
  dealii::deallog << "H-matrix: stored fraction below one half: "
                  << (fraction < 0.5 ? "yes" : "no")
                  << "; product error below 1e-5: "
                  << (Hs.linfty_norm() < 1e-5 * Ss.linfty_norm() ? "yes" : "no")
                  << "; reported error below 1e-5: "
                  << (reported < 1e-5 ? "yes" : "no") << std::endl;
  return 0;
}
