// SPDX-License-Identifier: LGPL-2.1-or-later
// The whole body of a split fault in the Green's-function method
// (GreenFault::body(), what its VTU snapshots show): SEAS BP3-QD's 60°
// thrust fault between two deformable sides (prm/seas-bp3-qd.prm) on 200 m
// fault cells, a fault state with a smooth slip and slip rate of the
// down-dip distance d (s = 2 m exp(-((d - 10 km) / 5 km)^2), V = 1e-9 m/s
// (1 + d / 40 km), t = 30 years) turned into the displacement and velocity
// of both sides by one solve each of the tied system's interior (a
// Cholesky factor, physics::InteriorSolver) and untied. Checked:
//  - the jump: at every pair of fault nodes, the + side's tangential
//    displacement minus the - side's is the slip, and the normal ones are
//    equal (no opening), to 1e-9 m (yes/no; the number of pairs printed);
//  - equilibrium: the untied stiffness's nodal force K u vanishes at the
//    dofs off the fault that are neither loaded nor hanging, and the two
//    sides' forces at a fault pair cancel (the fault's traction acts on
//    both, opposite), each to 1e-8 of the largest nodal force (yes/no);
//  - the load boundaries off the fault at their velocity times t,
//    exactly (yes/no);
//  - the 8 surface stations' two components against the operator, which
//    computes them independently (the tied rows, the set-up's factor):
//    o0 + t o1 + O s and o1 + O V equal the body's interpolated at the
//    points to 1e-7 of their size (yes/no);
//  - the normal stress and the shear traction of the body's fault nodes:
//    the normal stress the prescribed 50 MPa plus the operator's change at
//    the slip (GreenFault::normal_forces), its largest change printed in
//    MPa to 0.01 (a 2 m slip on a 60° thrust changes it by MPa).
#include "green_body_stations.h"
#include "tests.h"

#include <cmath>
#include <deal.II/base/mpi.h>
#include <rsfcycle/app/simulation.h>
#include <rsfcycle/models/green_fault.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/physics/global_system.h>
#include <rsfcycle/physics/split_fault.h>
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
  app::parse_parameter_file(prm, source + "/../prm/seas-bp3-qd.prm");
  prm.parse_input_from_string(
    "set Output directory = output-split-body\n"
    "subsection Mesh\n"
    "  set Global refinements = 0\n"
    "  set Local refinements = 2\n"
    "end\n"
    "subsection Output\n"
    "  set Writers = time series, base profile, events, seas, vtu\n"
    "end\n");
  Parameters parameters;
  parameters.parse_parameters(prm);
  const auto            scene = scenes::make_scene<2>("mesh-file", prm);
  std::ostringstream    log;
  models::GreenFault<2> fault(parameters, *scene, log);
  fault.setup();

  models::FaultState state = fault.initial_state();
  state.t                  = 30 * 3.15576e7;
  const auto layout        = fault.layout();
  for (unsigned int k = 0; k < state.slip.size(); ++k)
    {
      const double d = layout.positions[k];
      state.slip[k]  = 2 * std::exp(-std::pow((d - 10e3) / 5e3, 2));
      state.rate[k]  = 1e-9 * (1 + d / 40e3);
    }
  const BodyState body    = fault.body(state);
  const auto     &disc    = fault.body_discretisation();
  const auto     &contact = fault.contact_quadrature();
  const auto     &nodes   = contact.contact_set().nodes;

  // the untied system (K u, the fixed dofs and their velocity) and the
  // tie's pairs
  auto system = physics::gather_system(disc,
                                       contact.contact_set(),
                                       std::vector<physics::ObservationRow>{});
  auto tied   = system;
  physics::tie_split_fault(disc, tied);
  const unsigned int  n = system.n();
  std::vector<double> u(n), Ku(n, 0.);
  for (unsigned int i = 0; i < n; ++i)
    u[i] = body.u(i);
  for (unsigned int i = 0; i < n; ++i)
    for (auto e = system.row_begin(i); e < system.row_end(i); ++e)
      Ku[i] += system.values[e] * u[system.columns[e]];

  // the jump and the pairs' forces
  unsigned int pairs = 0;
  double       jump = 0, opening = 0, scale = 0;
  for (unsigned int i = 0; i < n; ++i)
    scale = std::max(scale, std::abs(Ku[i]));
  double pair_force = 0;
  for (unsigned int k = 0; k < nodes.size(); ++k)
    {
      const unsigned int a = nodes[k].dofs[0];
      const unsigned int b = tied.tie_partner[a];
      if (tied.tie_kind[a] != physics::tie_slip)
        continue;
      ++pairs;
      jump       = std::max(jump, std::abs(u[a] - u[b] - state.slip[k]));
      pair_force = std::max(pair_force, std::abs(Ku[a] + Ku[b]));
    }
  double off_fault = 0;
  for (unsigned int i = 0; i < n; ++i)
    {
      const auto kind = tied.tie_kind[i];
      if (kind == physics::tie_normal)
        {
          const unsigned int d = tied.tie_partner[i];
          opening              = std::max(opening, std::abs(u[i] - u[d]));
          pair_force           = std::max(pair_force, std::abs(Ku[i] + Ku[d]));
        }
      else if (kind == physics::tie_none && !system.fixed[i])
        off_fault = std::max(off_fault, std::abs(Ku[i]));
    }
  dealii::deallog << pairs << " fault pairs: the jump is the slip, "
                  << "no opening: "
                  << (jump < 1e-9 && opening < 1e-9 ? "yes" : "no")
                  << std::endl;
  dealii::deallog << "equilibrium off the fault and across it: "
                  << (off_fault < 1e-8 * scale && pair_force < 1e-8 * scale ?
                        "yes" :
                        "no")
                  << std::endl;

  // the load boundaries (fixed, not hanging, off the fault: the creeping
  // extension's dofs prescribe the slip, not each side) at t v_b
  double held = 0;
  for (unsigned int i = 0; i < n; ++i)
    if (system.fixed[i] && !disc.hanging_constraints.is_constrained(i) &&
        tied.tie_kind[i] == physics::tie_none)
      held =
        std::max(held, std::abs(u[i] - state.t * system.fixed_velocity[i]));
  dealii::deallog << "load boundaries at t v_b: " << (held == 0 ? "yes" : "no")
                  << std::endl;

  // the stations against the operator
  const auto &op   = fault.green_operator();
  const auto  rows = physics::observation_rows(disc, *scene, false);
  dealii::deallog << rows.size() << " station components: displacement and "
                  << "velocity as the operator's to 1e-7: "
                  << (stations_as_operator(op, rows, state, body) ? "yes" :
                                                                    "no")
                  << std::endl;

  // the fault's normal stress: 50 MPa plus the slip's change
  const auto &N        = fault.normal_forces(state.slip.data(), state.t);
  double      mismatch = 0, change = 0;
  for (unsigned int k = 0; k < nodes.size(); ++k)
    {
      const double w = contact.nodes()[k].weight;
      mismatch = std::max(mismatch, std::abs(body.normal_stress[k] - N[k] / w));
      change   = std::max(change, std::abs(body.normal_stress[k] - 50e6));
    }
  dealii::deallog << "normal stress as the operator's: "
                  << (mismatch == 0 &&
                          body.normal_stress.size() == nodes.size() ?
                        "yes" :
                        "no")
                  << ", largest change " << std::fixed << std::setprecision(2)
                  << change / 1e6 << " MPa" << std::endl;
  return 0;
}
