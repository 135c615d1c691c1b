// SPDX-License-Identifier: LGPL-2.1-or-later
// Checks the implicit time step (15) and its theta scheme (`Solver/Theta`,
// time/theta_scheme.h) on a frictionless elastic block: a 1 m x 0.25 m
// plane-strain block on a base with zero friction (mu* = 0, cohesion 0, no
// gravity, so every normal force vanishes), fixed at the backstop x = 1.
// Inviscid, with inertia, started with the velocity field v_x = v (1 - x):
//  - The trapezoidal rule (theta = 1/2: Newmark beta = 1/4, gamma = 1/2)
//    conserves the discrete energy 1/2 v'Mv + 1/2 u'Ku exactly for a linear
//    undamped system: the relative drift over 12800 steps is printed
//    (round-off / solver tolerance level: < 1e-8).
//  - Second-order convergence in time: the error of u(T) against a run with
//    tau = T/12800 falls by a factor ~4 per halving of tau from T/100 (printed:
//    the observed orders, expected 2 within 0.1).
//  - Backward Euler (theta = 1): first order (the error against the same
//    reference halves per halving of tau: orders 1 within 0.1) and
//    dissipative (the energy decreases in every step).
// Quasi-static Kelvin-Voigt relaxation: viscosities proportional to the
// moduli (eta_s = T G, eta_b = T K), so C = T K, and the state u_0 = (1 -
// x)(1, y) mm, v_0 = -u_0 / T solves C v + K u = 0; every mode decays as
// exp(-t/T), and one step of tau = z T multiplies u by the theta scheme's
// amplification R(z) = (1 - (1 - theta) z) / (1 + theta z). Printed: the
// measured factor ||u_1|| / ||u_0|| (signed by u_1 . u_0) and whether it is
// R(z) to 1e-8, for theta = 1/2, 3/4, 1 and z = 0.1, 1, 100: the
// trapezoidal factor at z = 100 is -0.96 (the stiff mode flips sign and
// hardly decays), backward Euler's 1/101.
#include "block_scene.h"
#include "tests.h"

#include <cmath>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/numerics/vector_tools.h>
#include <rsfcycle/ids.h>
#include <rsfcycle/models/problem_base.h>

using namespace dealii;
using namespace rsfcycle;

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

/** (1 - x)(1, y) mm: zero at the backstop, tangential on the base. */
class InitialDisplacement : public Function<2>
{
public:
  InitialDisplacement()
    : Function<2>(2)
  {}
  double
  value(const Point<2> &p, const unsigned int component) const override
  {
    return 1e-3 * (1 - p[0]) * (component == 0 ? 1. : p[1]);
  }
};

Parameters
test_parameters(const double theta, const SolverParameters::Dynamics dynamics)
{
  Parameters parameters;
  parameters.mesh.global_refinements = 2;
  parameters.mesh.local_refinements  = 0;
  parameters.solver.tnnmg_tolerance  = 1e-13;
  // every velocity solve to 1e-13 (no inexact early fixed-point iterations):
  // the energy check is at round-off level
  parameters.solver.inner_tolerance_factor = 0;
  parameters.solver.theta                  = theta;
  parameters.solver.dynamics               = dynamics;
  return parameters;
}

void
check_relaxation()
{
  Block scene;
  scene.relaxation_time = 0.01;
  for (const double theta : {0.5, 0.75, 1.})
    {
      const Parameters parameters =
        test_parameters(theta, SolverParameters::Dynamics::quasi_static);
      std::ostringstream log;
      ProblemBase<2>     problem(parameters, scene, log);
      problem.setup();
      BodyState start = problem.initial_state();
      VectorTools::interpolate(problem.dofs(), InitialDisplacement(), start.u);
      start.v = start.u;
      start.v *= -1 / scene.relaxation_time;
      for (const double z : {0.1, 1., 100.})
        {
          const auto next = problem.step(start, 0, z * scene.relaxation_time);
          if (!next)
            throw std::runtime_error("step failed");
          const double sign  = next->u * start.u >= 0 ? 1. : -1.;
          const double R     = sign * next->u.l2_norm() / start.u.l2_norm();
          const double exact = (1 - (1 - theta) * z) / (1 + theta * z);
          dealii::deallog << "quasi-static theta " << theta << ", tau/T " << z
                          << ": u_1/u_0 " << R << ", R(z) " << exact
                          << " (equal to 1e-8: "
                          << (std::abs(R - exact) < 1e-8 ? "yes" : "no") << ")"
                          << std::endl;
        }
    }
}

int
main(int argc, char **argv)
{
  // the mesh is a parallel::distributed::Triangulation: MPI, one process
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(6);
  Block        scene;
  const double T = 0.02; // about one period of the lowest mode

  // the free vibration with n steps of theta: u(T) and the largest relative
  // energy drift; `decreasing` is false if the energy ever grew
  const auto run = [&](const double theta, const unsigned int n_steps) {
    const Parameters parameters =
      test_parameters(theta, SolverParameters::Dynamics::dynamic);
    std::ostringstream log;
    ProblemBase<2>     problem(parameters, scene, log);
    problem.setup();
    BodyState start = problem.initial_state();
    VectorTools::interpolate(problem.dofs(), InitialVelocity(), start.v);
    BodyState    state      = start;
    const double tau        = T / n_steps;
    double       max_drift  = 0;
    bool         decreasing = true;
    const double e0         = problem.energy(state);
    double       e          = e0;
    for (unsigned int n = 0; n < n_steps; ++n)
      {
        auto next = problem.step(state, n * tau, tau);
        if (!next)
          throw std::runtime_error("step failed");
        state              = std::move(*next);
        const double e_new = problem.energy(state);
        decreasing         = decreasing && e_new < e;
        e                  = e_new;
        max_drift          = std::max(max_drift, std::abs(e - e0) / e0);
      }
    return std::make_tuple(state.u, max_drift, decreasing);
  };

  const auto reference = run(0.5, 12800);
  dealii::deallog << "energy drift over " << 12800 << " steps < 1e-8: "
                  << (std::get<1>(reference) < 1e-8 ? "yes" : "no")
                  << std::endl;
  for (const double theta : {0.5, 1.})
    {
      double previous = 0;
      for (const unsigned int n : {100, 200, 400, 800})
        {
          const auto result = run(theta, n);
          la::Vector diff   = std::get<0>(result);
          diff -= std::get<0>(reference);
          const double error =
            diff.l2_norm() / std::get<0>(reference).l2_norm();
          if (theta != 0.5)
            dealii::deallog << "theta " << theta << ", ";
          dealii::deallog << "steps " << n << ": relative error of u(T) "
                          << error;
          const unsigned int expected = theta == 0.5 ? 2 : 1;
          if (previous > 0)
            {
              const double order = std::log2(previous / error);
              dealii::deallog
                << ", order " << order << " (" << expected << " within 0.1: "
                << (std::abs(order - expected) < 0.1 ? "yes" : "no") << ")";
            }
          if (theta != 0.5)
            dealii::deallog << ", energy decreasing in every step: "
                            << (std::get<2>(result) ? "yes" : "no");
          dealii::deallog << std::endl;
          previous = error;
        }
    }
  check_relaxation();
}
