// SPDX-License-Identifier: LGPL-2.1-or-later
// The whole body of the Green's-function method (GreenFault::body(), what
// its VTU snapshots show): on SEAS BP1-QD's mesh at 200 m (antiplane,
// prm/seas-bp1-qd.prm), a fault state with a smooth slip and slip rate
// (s(d) = 2 m exp(-((d - 10 km) / 5 km)^2), V = 1e-9 m/s (1 + d / 40 km),
// t = 30 years) is turned into the displacement and velocity of the body by
// one static solve each (the contact held at s and V, the load boundaries
// at V_p t and V_p, CG with algebraic multigrid to 1e-12). Checked against
// the operator, which computes the same quantities independently (one
// Cholesky factor, physics/green_operator): the surface observation points'
// displacement o0 + t o1 + O s and velocity o1 + O V equal the body's
// interpolated at the points to 1e-7 of their size (yes/no); the body
// holds the slip on the contact and V_p t on the load boundary exactly.
#include "green_body_stations.h"
#include "tests.h"

#include <cmath>
#include <deal.II/base/mpi.h>
#include <rsfcycle/app/simulation.h>
#include <rsfcycle/models/green_fault.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/physics/global_system.h>
#include <rsfcycle/scenes/scenes.h>
#include <sstream>

using namespace rsfcycle;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(6);
  const std::string        source = SOURCE_DIR;
  dealii::ParameterHandler prm;
  app::declare_parameters(prm);
  app::parse_parameter_file(prm, source + "/../prm/seas-bp1-qd.prm");
  prm.parse_input_from_string("set Output directory = output-body\n"
                              "subsection Mesh\n"
                              "  set Local refinements = 3\n"
                              "end\n");
  Parameters parameters;
  parameters.parse_parameters(prm);
  const auto            scene = scenes::make_scene<2>("mesh-file", prm);
  std::ostringstream    log;
  models::GreenFault<2> fault(parameters, *scene, log);
  fault.setup();

  // a smooth slip and slip rate of depth d, every node
  const auto        &contact = fault.contact_quadrature();
  models::FaultState state   = fault.initial_state();
  state.t                    = 30 * 3.15576e7;
  const auto layout          = fault.layout();
  for (unsigned int k = 0; k < state.slip.size(); ++k)
    {
      const double d = layout.positions[k];
      state.slip[k]  = 2 * std::exp(-std::pow((d - 10e3) / 5e3, 2));
      state.rate[k]  = 1e-9 * (1 + d / 40e3);
    }
  const BodyState body = fault.body(state);
  body.u.update_ghost_values();
  body.v.update_ghost_values();

  const auto &op = fault.green_operator();
  const auto  rows =
    physics::observation_rows(fault.body_discretisation(), *scene, true);
  dealii::deallog << rows.size() << " surface points: displacement and "
                  << "velocity as the operator's to 1e-7: "
                  << (stations_as_operator(op, rows, state, body) ? "yes" :
                                                                    "no")
                  << std::endl;

  // the contact at the slip, the load boundary at V_p t
  const auto &nodes = contact.contact_set().nodes;
  double      held  = 0;
  for (unsigned int k = 0; k < nodes.size(); ++k)
    held = std::max(held,
                    std::abs(body.u.local_element(nodes[k].dofs[0]) -
                             state.slip[k]));
  const auto &discretisation = fault.body_discretisation();
  for (const auto &[i, component, sign] : discretisation.backstop_dofs)
    held =
      std::max(held, std::abs(body.u.local_element(i) - sign * 1e-9 * state.t));
  dealii::deallog << "contact at the slip, load at V_p t: "
                  << (held < 1e-12 ? "yes" : "no") << std::endl;
  return 0;
}
