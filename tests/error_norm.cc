// SPDX-License-Identifier: LGPL-2.1-or-later
// Checks `Time stepping/Error norm`, the distance of two states in the
// step-doubling error estimate (ProblemBase::error_distance), on the block
// of block_scene.h (refined twice globally and twice toward the origin:
// 20 contact nodes, weights w_k of 1/64 to 1/32 m, summing to the base
// length less the half cell at the backstop vertex, 0.96875 m = A). Two
// states differ by 1 at one contact node k (the last, w_k = 1/64 m) and
// agree elsewhere:
//  - L2 (the default, the distance (14)): sqrt(w_k / A) = 0.127;
//  - max: 1 (the largest difference, whatever its weight);
// and with the difference 0.5 at every node both give 0.5. The distance
// (14) of the fixed-point iteration (state_distance) is L2 either way.
// Printed: the values and yes/no against those closed forms (1e-12).
#include "block_scene.h"
#include "tests.h"

#include <deal.II/base/mpi.h>
#include <rsfcycle/models/problem_base.h>

void
check(const std::string &norm)
{
  Parameters parameters;
  parameters.mesh.global_refinements = 2;
  parameters.mesh.local_refinements  = 2;
  parameters.time_stepping.error_norm =
    norm == "max" ? TimeSteppingParameters::ErrorNorm::max :
                    TimeSteppingParameters::ErrorNorm::l2;
  Block              scene;
  std::ostringstream log;
  ProblemBase<2>     problem(parameters, scene, log);
  problem.setup();

  const auto         &nodes = problem.contact_nodes();
  const unsigned int  n     = nodes.size();
  std::vector<double> a(n, 0.), b(n, 0.), c(n, 0.5);
  b[n - 1]            = 1;
  double total_weight = 0;
  for (const auto &node : nodes)
    total_weight += node.weight;
  const double one      = problem.error_distance(a, b);
  const double all      = problem.error_distance(a, c);
  const double l2_one   = std::sqrt(nodes[n - 1].weight / total_weight);
  const double expected = norm == "max" ? 1. : l2_one;
  dealii::deallog << norm << ": " << n << " contact nodes, weights sum "
                  << total_weight << " m; one node (w = " << nodes[n - 1].weight
                  << " m) off by 1: " << one << ", expected " << expected
                  << ": " << (std::abs(one - expected) < 1e-12 ? "yes" : "no")
                  << "; all off by 0.5: " << all << ": "
                  << (std::abs(all - 0.5) < 1e-12 ? "yes" : "no")
                  << "; fixed-point distance stays (14): "
                  << (std::abs(problem.state_distance(a, b) - l2_one) < 1e-12 ?
                        "yes" :
                        "no")
                  << std::endl;
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(6);
  check("L2");
  check("max");
}
