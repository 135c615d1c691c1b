// SPDX-License-Identifier: LGPL-2.1-or-later
// Checks the radiation damping of `Solver/Dynamics = quasi-dynamic`: the
// dashpot eta V that Discretisation adds to C on the contact.
//  - On the block of block_scene.h (inviscid, so C is the dashpot alone),
//    refined twice globally and twice toward the origin (cells of two
//    sizes on the base): the row sums of C for a unit x velocity equal eta w_i
//    at every contact node, w_i the friction's lumped weights
//    (ContactQuadrature, through ProblemBase::contact_nodes()); they add up
//    to eta times the base length 1 m; C has nothing in y (the normal).
//  - The default eta is the shear impedance sqrt(G rho) of the material
//    (G = 0.6 MPa, rho = 1000 kg/m^3: 24494.9 Pa s/m); with G and rho
//    halved (the one-sided reduction of a fault between two equal
//    half-spaces, SEAS BP1) it is G / (2 c_s) of the full material,
//    c_s = sqrt(G / rho) (12247.4 Pa s/m).
// Printed: eta from the matrix, the expected value, and yes/no for the
// node-wise and total agreement to 1e-10 relative.
#include "block_scene.h"
#include "tests.h"

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/numerics/vector_tools.h>
#include <rsfcycle/models/problem_base.h>
#include <rsfcycle/physics/discretisation.h>

void
check(const double material_scale, const double expected_eta)
{
  Parameters parameters;
  parameters.mesh.global_refinements = 2;
  parameters.mesh.local_refinements  = 2;
  parameters.solver.dynamics = SolverParameters::Dynamics::quasi_dynamic;
  Block scene;
  scene.material_scale = material_scale;

  // the friction's weights w_i and positions
  std::ostringstream log;
  ProblemBase<2>     problem(parameters, scene, log);
  problem.setup();

  // the same mesh, its matrices with the dashpot
  physics::Discretisation<2> discretisation(parameters.mesh,
                                            scene,
                                            {false, true});
  discretisation.make_grid();
  discretisation.setup_system();
  discretisation.setup_boundary_conditions();
  discretisation.assemble_matrices();

  la::Vector ex, Cex;
  discretisation.reinit(ex);
  discretisation.reinit(Cex);
  VectorTools::interpolate(discretisation.dof_handler,
                           Functions::ConstantFunction<2>(
                             std::vector<double>{1., 0.}),
                           ex);
  discretisation.viscosity_local.vmult(Cex, ex);

  // row sums at the base vertices, by position
  std::map<std::pair<double, double>, double> row_sum;
  double                                      total = 0, normal = 0;
  for (const auto &cell : discretisation.dof_handler.active_cell_iterators())
    for (const unsigned int v : cell->vertex_indices())
      {
        const auto x_dof = cell->vertex_dof_index(v, 0);
        const auto y_dof = cell->vertex_dof_index(v, 1);
        normal           = std::max(normal, std::abs(Cex(y_dof)));
        if (std::abs(cell->vertex(v)[1]) < 1e-12)
          row_sum[{cell->vertex(v)[0], cell->vertex(v)[1]}] = Cex(x_dof);
      }
  for (const auto &[p, value] : row_sum)
    total += value;

  bool   nodes_agree = true;
  double eta         = 0;
  for (const auto &node : problem.contact_nodes())
    {
      const double value = row_sum.at({node.position[0], node.position[1]});
      nodes_agree =
        nodes_agree && std::abs(value - expected_eta * node.weight) <
                         1e-10 * expected_eta * node.weight;
      eta = std::max(eta, value / node.weight);
    }
  dealii::deallog
    << "scale " << material_scale << ": " << row_sum.size()
    << " base vertices, " << problem.contact_nodes().size()
    << " contact nodes; eta " << eta << " Pa s/m, expected " << expected_eta
    << "; C 1_x = eta w_i at every node: " << (nodes_agree ? "yes" : "no")
    << "; sum = eta x 1 m: "
    << (std::abs(total - expected_eta) < 1e-10 * expected_eta ? "yes" : "no")
    << "; nothing in y: " << (normal == 0 ? "yes" : "no") << std::endl;
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(6);
  const double G = 0.6e6, rho = 1000, c_s = std::sqrt(G / rho);
  check(1, std::sqrt(G * rho));
  check(0.5, G / (2 * c_s));
}
