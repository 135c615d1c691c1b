// SPDX-License-Identifier: LGPL-2.1-or-later
// Checks that the Green's-function operator of `Solver/Bulk =
// green-function` (physics::GreenOperator, doc/model.md §8.1) converges under
// mesh refinement in plane strain, where no closed form is at hand: the
// mesh of prm/seas-bp1-qd.prm with `Displacement = vector` (the vertical
// fault as a dip-slip contact, its normal held, the same material), at 3,
// 4 and 5 local refinements (200 m, 100 m, 50 m on the fault). For a
// smooth slip, s = 1 m above 10 km and cos^2 down to 0 at 20 km, the
// traction -(S s)_k / w_k is compared at the nodes of the coarsest mesh
// (which every finer mesh has) from 1 km to 38 km deep. Checked (yes/no
// lines): the difference between successive meshes falls by more than 2
// (the operator converges at least at first order; second order gives 4),
// and the finest difference is below 1 % of the stress drop at 5 km; S is
// symmetric with a positive diagonal on every mesh; and the plane-strain
// stress drop at 5 km exceeds the antiplane one on the same mesh (by
// 1 / (1 - nu) = 4/3 for a long dislocation in a full space: printed,
// within 10 %). The traction at 5 km and the factor by which the
// differences fall (2.6: the maximum over the nodes, the taper's ends
// included) are printed rounded.
#include "tests.h"

#include <cmath>
#include <deal.II/base/mpi.h>
#include <map>
#include <rsfcycle/app/simulation.h>
#include <rsfcycle/models/green_fault.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/scenes/scenes.h>

using namespace rsfcycle;

namespace
{
  // depth [m, rounded] -> traction [Pa] for the smooth slip
  std::map<long, double>
  tractions(const std::string &source,
            const unsigned int refinements,
            const bool         antiplane,
            bool              &symmetric)
  {
    dealii::ParameterHandler prm;
    app::declare_parameters(prm);
    prm.parse_input(source + "/../prm/seas-bp1-qd.prm");
    prm.parse_input_from_string(
      std::string("set Output directory = output-run\n") +
      "set Displacement = " + (antiplane ? "antiplane" : "vector") + "\n" +
      "subsection Mesh file\n  set File = " + source +
      "/../prm/meshes/seas-bp1.msh\n" +
      (antiplane ? "" : "  set Load velocity = 0, 1e-9\n") + "end\n" +
      "subsection Mesh\n  set Local refinements = " +
      std::to_string(refinements) + "\nend\n" +
      "subsection Solver\n  set Green operator storage = dense\nend\n");
    Parameters parameters;
    parameters.parse_parameters(prm);
    const auto scene = scenes::make_scene<2>("mesh-file", prm);

    std::ostringstream    log;
    models::GreenFault<2> fault(parameters, *scene, log);
    fault.setup();
    const auto            &op    = fault.green_operator();
    const auto            &nodes = fault.contact_quadrature().nodes();
    const unsigned int     n     = nodes.size();
    dealii::Vector<double> s(n), Ss(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        const double z = scene->along_base_coordinate(nodes[k].position);
        const double c = std::cos(0.5 * M_PI * (z - 10e3) / 10e3);
        s[k]           = z < 10e3 ? 1. : z < 20e3 ? c * c : 0.;
      }
    op.S.vmult(Ss, s);
    double asymmetry = 0, entry = 0;
    bool   diagonal = true;
    for (unsigned int i = 0; i < n; ++i)
      {
        diagonal = diagonal && op.S(i, i) > 0;
        for (unsigned int j = 0; j < n; ++j)
          {
            asymmetry = std::max(asymmetry, std::abs(op.S(i, j) - op.S(j, i)));
            entry     = std::max(entry, std::abs(op.S(i, j)));
          }
      }
    symmetric = symmetric && diagonal && asymmetry < 1e-8 * entry;
    std::map<long, double> tau;
    for (unsigned int k = 0; k < n; ++k)
      tau[std::lround(scene->along_base_coordinate(nodes[k].position))] =
        -Ss[k] / nodes[k].weight;
    return tau;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(6);
  const std::string source = SOURCE_DIR;

  bool                                symmetric = true;
  std::vector<std::map<long, double>> tau;
  for (const unsigned int r : {3u, 4u, 5u})
    tau.push_back(tractions(source, r, false, symmetric));
  const auto antiplane = tractions(source, 3, true, symmetric);

  const double        scale = std::abs(tau[2].at(5000));
  std::vector<double> difference(2, 0.);
  unsigned int        compared = 0;
  for (const auto &[z, t] : tau[0])
    {
      if (z < 1000 || z > 38000)
        continue;
      ++compared;
      for (unsigned int i = 0; i < 2; ++i)
        difference[i] =
          std::max(difference[i], std::abs(tau[i].at(z) - tau[i + 1].at(z)));
    }
  dealii::deallog << "nodes compared: " << compared << std::endl;
  dealii::deallog << "traction change at 5 km (50 m cells): "
                  << std::round(1e3 * tau[2].at(5000) / 1e6) / 1e3 << " MPa"
                  << std::endl;
  dealii::deallog << "successive differences fall by "
                  << std::round(10 * difference[0] / difference[1]) / 10
                  << std::endl;
  dealii::deallog << "difference 200/100 m over difference 100/50 m above 2: "
                  << (difference[0] > 2 * difference[1] ? "yes" : "no")
                  << std::endl;
  dealii::deallog << "difference 100/50 m below 1 % of the stress drop: "
                  << (difference[1] < 1e-2 * scale ? "yes" : "no") << std::endl;
  dealii::deallog << "S symmetric with a positive diagonal on every mesh: "
                  << (symmetric ? "yes" : "no") << std::endl;
  const double ratio = tau[0].at(5000) / antiplane.at(5000);
  dealii::deallog << "plane strain / antiplane at 5 km: "
                  << std::round(100 * ratio) / 100
                  << (std::abs(ratio - 4. / 3.) < 0.1 * 4. / 3. ?
                        " (4/3 within 10 %: yes)" :
                        " (4/3 within 10 %: no)")
                  << std::endl;
  return 0;
}
