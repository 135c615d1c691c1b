// Checks the implicit Newmark step (15) (trapezoidal rule, beta = 1/4,
// gamma = 1/2) on a frictionless, inviscid elastic block that vibrates
// freely: a 1 m x 0.25 m plane-strain block on a base with zero friction
// (mu* = 0, cohesion 0, no gravity, so every normal force vanishes), fixed at
// the backstop x = 1, started with the velocity field v_x = v (1 - x).
//  - The trapezoidal rule conserves the discrete energy 1/2 v'Mv + 1/2 u'Ku
//    exactly for a linear undamped system: the relative drift over 200 steps
//    is printed (round-off / solver tolerance level: < 1e-8).
//  - Second-order convergence in time: the error of u(T) against a run with
//    tau = T/12800 falls by a factor ~4 per halving of tau from T/100 (printed:
//    the observed orders, expected 2 within 0.1).
#include "tests.h"

#include <cmath>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/numerics/vector_tools.h>
#include <rsfcycle/ids.h>
#include <rsfcycle/problem_base.h>

using namespace dealii;
using namespace rsfcycle;

class Block : public scenes::Scene<2>
{
public:
  void
  create_coarse_mesh(Triangulation<2> &tria) const override
  {
    GridGenerator::subdivided_hyper_rectangle(tria,
                                              {4, 1},
                                              Point<2>(0, 0),
                                              Point<2>(1, 0.25));
    for (const auto &face : tria.active_face_iterators())
      if (face->at_boundary())
        {
          const Point<2> c = face->center();
          face->set_boundary_id(std::abs(c[1]) < 1e-12 ? boundary_id::contact :
                                std::abs(c[0] - 1) < 1e-12 ?
                                                         boundary_id::backstop :
                                                         boundary_id::surface);
        }
  }
  double
  distance_to_patch(const BoundingBox<2> &box, double margin) const override
  {
    return std::max(0., box.get_boundary_points().first.norm() - margin);
  }
  types::material_id
  material_id(const Point<2> &, types::material_id) const override
  {
    return 0;
  }
  scenes::Material
  material(types::material_id) const override
  {
    scenes::Material m;
    m.density         = 1000;
    m.bulk_modulus    = 1e6;
    m.poisson_ratio   = 0.25;
    m.shear_viscosity = 0;
    m.bulk_viscosity  = 0;
    return m;
  }
  Tensor<1, 2>
  gravity() const override
  {
    return Tensor<1, 2>();
  }
  Tensor<1, 2>
  vertical() const override
  {
    return Tensor<1, 2>({0., 1.});
  }
  Tensor<1, 2>
  backstop_velocity(double) const override
  {
    return Tensor<1, 2>();
  }
  friction::Parameters
  friction_parameters(const Point<2> &) const override
  {
    friction::Parameters p;
    p.mu_star = 0;
    p.b       = 0;
    return p;
  }
  double
  convergence_rate() const override
  {
    return 1e-3;
  }
  std::vector<std::pair<std::string, Point<2>>>
  observation_points() const override
  {
    return {{"top", Point<2>(0.5, 0.25)}};
  }
};

class InitialVelocity : public Function<2>
{
public:
  InitialVelocity()
    : Function<2>(2)
  {}
  double
  value(const Point<2> &p, const unsigned int component) const override
  {
    return component == 0 ? 1e-3 * (1 - p[0]) : 0.;
  }
};

int
main(int argc, char **argv)
{
  // the mesh is a parallel::distributed::Triangulation: MPI, one process
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(6);
  Parameters parameters;
  parameters.mesh.global_refinements = 2;
  parameters.mesh.local_refinements  = 0;
  parameters.solver.tnnmg_tolerance  = 1e-13;
  // every velocity solve to 1e-13 (no inexact early fixed-point iterations):
  // the energy check is at round-off level
  parameters.solver.inner_tolerance_factor = 0;
  Block              scene;
  std::ostringstream log;
  ProblemBase<2>     problem(parameters, scene, log);
  problem.setup();

  BodyState start = problem.initial_state();
  VectorTools::interpolate(problem.dofs(), InitialVelocity(), start.v);
  const double T = 0.02; // about one period of the lowest mode

  const auto run = [&](const unsigned int n_steps) {
    BodyState    state     = start;
    const double tau       = T / n_steps;
    double       max_drift = 0;
    const double e0        = problem.energy(state);
    for (unsigned int n = 0; n < n_steps; ++n)
      {
        auto next = problem.newmark_step(state, n * tau, tau);
        if (!next)
          throw std::runtime_error("step failed");
        state = std::move(*next);
        max_drift =
          std::max(max_drift, std::abs(problem.energy(state) - e0) / e0);
      }
    return std::make_pair(state.u, max_drift);
  };

  const auto reference = run(12800);
  dealii::deallog << "energy drift over " << 12800 << " steps < 1e-8: "
                  << (reference.second < 1e-8 ? "yes" : "no") << std::endl;
  double previous = 0;
  for (const unsigned int n : {100, 200, 400, 800})
    {
      const auto result = run(n);
      la::Vector diff   = result.first;
      diff -= reference.first;
      const double error = diff.l2_norm() / reference.first.l2_norm();
      dealii::deallog << "steps " << n << ": relative error of u(T) " << error;
      if (previous > 0)
        {
          const double order = std::log2(previous / error);
          dealii::deallog << ", order " << order << " (2 within 0.1: "
                          << (std::abs(order - 2) < 0.1 ? "yes" : "no") << ")";
        }
      dealii::deallog << std::endl;
      previous = error;
    }
}
