// SPDX-License-Identifier: LGPL-2.1-or-later
// Checks the generalized-alpha step (`Solver/Time scheme =
// generalized-alpha`, time/generalized_alpha_scheme.h, doc/model.md §8.3):
//  1. The scheme's coefficients on the oscillator u'' + Omega^2 u = 0 (one
//     step of tau = 1 through the same formulas as ImplicitStep: the step
//     matrix, the known parts, the new velocity, acceleration and
//     displacement): the spectral radius of the amplification matrix of
//     (u, tau v, tau^2 a) at Omega tau = 1e8 equals rho_inf (to 1e-5; the
//     closed form of Chung and Hulbert 1993), at Omega tau = 0.01 it is 1
//     within 1e-6 (the low modes keep their energy), and for rho_inf = 1 it
//     is 1 at every Omega tau (to 1e-12: the trapezoidal rule).
//  2. On the frictionless elastic block of newmark_oscillator (inertial,
//     inviscid, started with v_x = v (1 - x)): second order in time (the
//     error of u(T) against a trapezoidal run of 12800 steps falls by ~4 per
//     halving of tau: the order between T/400 and T/800 is 2 within 0.1;
//     the coarser pairs are printed, pre-asymptotic for small rho_inf,
//     whose dissipation of the mesh's stiff modes is then still first
//     order in the error) for rho_inf = 1, 0.8, 0.5 and 0; rho_inf = 1
//     conserves the energy (drift below 1e-8 over 800 steps), and rho_inf < 1
//     never adds energy (the energy after every step at most the initial one,
//     to 1e-10) and dissipates some over 800 steps of T/800 (the stiffest mesh
//     modes).
//  3. The refusal of a run without inertia, in one line.
//  4. Kelvin-Voigt relaxation with inertia, on one mode of a body whose
//     viscosity is T times its stiffness (C = T K, as newmark_oscillator's
//     quasi-static relaxation): u'' + c u' + k u = 0 with c = T k, T = 1,
//     k = 1e4, so the inertial time 1/(T k) = 1e-4 T and the motion is
//     nearly quasi-static. Its closed form: u = A exp(s1 t) + B exp(s2 t),
//     s1,2 = (-c -+ sqrt(c^2 - 4k))/2 (s1 = -1.0001/T, the relaxation;
//     s2 = -9999/T, the inertia). Checked for rho_inf = 0, 0.5, 0.8, 1:
//     - the step is stable with the damping: the spectral radius is at most
//       1 for tau/T from 1e-4 to 1e8;
//     - the relaxation is kept: at tau = 0.01 T an eigenvalue of the step's
//       amplification is exp(s1 tau) to 1e-6;
//     - the stiff relaxing mode decays by rho_inf per step: the radius at
//       tau = 1e6 T is rho_inf to 1e-3 (theta = 1/2 keeps it at -0.96 a step
//       at tau = 100 T, newmark_oscillator; here rho_inf = 1 does the same,
//       radius 1);
//     - second order: the error of u(T) from rest (u = 1, v = 0) against
//       the closed form falls by ~4 per halving of tau; the order between
//       T/400 and T/800 is 2 within 0.1.
#include "block_scene.h"
#include "tests.h"

#include <cmath>
#include <complex>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/numerics/vector_tools.h>
#include <rsfcycle/models/problem_base.h>
#include <rsfcycle/time/generalized_alpha_scheme.h>
#include <rsfcycle/time/schemes.h>
#include <vector>

using namespace dealii;
using namespace rsfcycle;

/** u, v and a of one degree of freedom. */
struct Mode
{
  double u, v, a;
};

/**
 * One step of `scheme` on u'' + c u' + k u = 0 (unit mass), through the
 * same formulas as ImplicitStep: the step matrix, the known parts, the new
 * velocity, acceleration and displacement.
 */
Mode
one_step(const time::TimeScheme &scheme,
         const double            tau,
         const double            k,
         const double            damping,
         const Mode             &x)
{
  const auto   c = scheme.step_coefficients(tau);
  const auto   d = scheme.known_displacement();
  const auto   m = scheme.known_inertia(tau);
  const double w = (-k * (x.u + tau * (d[0] * x.v + tau * d[1] * x.a)) +
                    m[0] * x.v + m[1] * x.a) /
                   (c[0] + c[1] * damping + c[2] * k);
  const auto   e  = scheme.new_velocity();
  const auto   g  = scheme.new_acceleration(tau);
  const auto   h  = scheme.new_displacement();
  const double v1 = e[0] * w + e[1] * x.v;
  const double a1 = g[0] * (v1 - x.v) + g[1] * x.a;
  const double u1 =
    x.u + tau * (h[0] * x.v + h[1] * v1) + tau * tau * (h[2] * x.a + h[3] * a1);
  return {u1, v1, a1};
}

/**
 * The eigenvalues of the amplification matrix of (u, tau v, tau^2 a) of one
 * step of `scheme` on u'' + c u' + k u = 0.
 */
std::vector<std::complex<double>>
amplification_eigenvalues(const time::TimeScheme &scheme,
                          const double            tau,
                          const double            k,
                          const double            damping)
{
  LAPACKFullMatrix<double> amplification(3, 3);
  for (unsigned int j = 0; j < 3; ++j)
    {
      const Mode x1       = one_step(scheme,
                               tau,
                               k,
                               damping,
                               {1. * (j == 0),
                                      1. * (j == 1) / tau,
                                      1. * (j == 2) / (tau * tau)});
      amplification(0, j) = x1.u;
      amplification(1, j) = tau * x1.v;
      amplification(2, j) = tau * tau * x1.a;
    }
  amplification.compute_eigenvalues();
  std::vector<std::complex<double>> eigenvalues;
  for (unsigned int i = 0; i < 3; ++i)
    eigenvalues.push_back(amplification.eigenvalue(i));
  return eigenvalues;
}

/** The largest modulus of those eigenvalues. */
double
spectral_radius(const time::TimeScheme &scheme,
                const double            tau,
                const double            k,
                const double            damping)
{
  double radius = 0;
  for (const auto lambda : amplification_eigenvalues(scheme, tau, k, damping))
    radius = std::max(radius, std::abs(lambda));
  return radius;
}

/** The undamped oscillator u'' + Omega^2 u = 0, one step of tau = 1. */
double
spectral_radius(const time::TimeScheme &scheme, const double Omega)
{
  return spectral_radius(scheme, 1., Omega * Omega, 0.);
}

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

Parameters
test_parameters(const std::string &scheme, const double rho_infinity)
{
  Parameters parameters;
  parameters.mesh.global_refinements       = 2;
  parameters.mesh.local_refinements        = 0;
  parameters.solver.tnnmg_tolerance        = 1e-13;
  parameters.solver.inner_tolerance_factor = 0;
  parameters.solver.time_scheme            = scheme;
  parameters.solver.spectral_radius        = rho_infinity;
  parameters.solver.dynamics = SolverParameters::Dynamics::dynamic;
  return parameters;
}

const char *
yes_no(const bool b)
{
  return b ? "yes" : "no";
}

/**
 * After the error with n steps, the observed order against the error with
 * n/2 (`previous`, 0 for the first); with 800 steps whether it is 2 within
 * 0.1.
 */
void
log_order(const double previous, const double error, const unsigned int n)
{
  if (previous > 0)
    {
      const double order = std::log2(previous / error);
      deallog << ", order " << order;
      if (n == 800)
        deallog << " (2 within 0.1: " << yes_no(std::abs(order - 2) < 0.1)
                << ")";
    }
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(6);

  // 1. the amplification of the scheme
  for (const double rho : {0., 0.5, 0.8, 1.})
    {
      const time::GeneralizedAlphaScheme scheme(rho);
      const double                       high = spectral_radius(scheme, 1e8);
      const double                       low  = spectral_radius(scheme, 0.01);
      deallog << "rho_inf " << rho << ": spectral radius at Omega tau 1e8 "
              << high
              << " (rho_inf to 1e-5: " << yes_no(std::abs(high - rho) < 1e-5)
              << "), at 0.01 equal to 1 within 1e-6: "
              << yes_no(std::abs(low - 1) < 1e-6);
      if (rho == 1)
        {
          double worst = 0;
          for (const double Omega : {0.01, 0.1, 1., 10., 100., 1e6})
            worst =
              std::max(worst, std::abs(spectral_radius(scheme, Omega) - 1));
          deallog << ", 1 at every Omega tau to 1e-12: "
                  << yes_no(worst < 1e-12);
        }
      deallog << std::endl;
    }

  // 2. the elastic block
  Block        scene;
  const double T = 0.02;
  const auto   run =
    [&](const std::string &name, const double rho, const unsigned int n_steps) {
      const Parameters   parameters = test_parameters(name, rho);
      std::ostringstream log;
      ProblemBase<2>     problem(parameters, scene, log);
      problem.setup();
      BodyState state = problem.initial_state();
      VectorTools::interpolate(problem.dofs(), InitialVelocity(), state.v);
      const double tau      = T / n_steps;
      const double e0       = problem.energy(state);
      double       max_gain = 0, e = e0;
      for (unsigned int n = 0; n < n_steps; ++n)
        {
          auto next = problem.step(state, n * tau, tau);
          if (!next)
            throw std::runtime_error("step failed");
          state    = std::move(*next);
          e        = problem.energy(state);
          max_gain = std::max(max_gain, (e - e0) / e0);
        }
      return std::make_tuple(state.u, max_gain, (e0 - e) / e0);
    };
  const auto reference = run("theta", 0, 12800);
  for (const double rho : {1., 0.8, 0.5, 0.})
    {
      double previous = 0;
      for (const unsigned int n : {100, 200, 400, 800})
        {
          const auto [u, max_gain, loss] = run("generalized-alpha", rho, n);
          la::Vector diff                = u;
          diff -= std::get<0>(reference);
          const double error =
            diff.l2_norm() / std::get<0>(reference).l2_norm();
          deallog << "rho_inf " << rho << ", steps " << n
                  << ": relative error of u(T) " << error;
          log_order(previous, error, n);
          if (n == 800 && rho == 1)
            deallog << ", energy conserved to 1e-8: "
                    << yes_no(std::abs(loss) < 1e-8 && max_gain < 1e-8);
          if (n == 800 && rho < 1)
            deallog << ", energy never above the initial: "
                    << yes_no(max_gain < 1e-10)
                    << ", some dissipated: " << yes_no(loss > 1e-10);
          deallog << std::endl;
          previous = error;
        }
    }

  // 3. no inertia: refused
  Parameters parameters      = test_parameters("generalized-alpha", 0.5);
  parameters.solver.dynamics = SolverParameters::Dynamics::quasi_static;
  try
    {
      time::make_scheme(parameters.solver, false);
      deallog << "quasi-static run accepted" << std::endl;
    }
  catch (const std::invalid_argument &error)
    {
      deallog << "quasi-static: " << error.what() << std::endl;
    }
  // 4. Kelvin-Voigt relaxation with inertia: u'' + c u' + k u = 0, c = T k
  {
    const double               k = 1e4, damping = 1. * k; // T = 1
    const std::complex<double> root =
      std::sqrt(std::complex<double>(damping * damping - 4 * k));
    const std::complex<double> s1 = (-damping + root) / 2.,
                               s2 = (-damping - root) / 2.;
    // from rest at u = 1: A + B = 1, s1 A + s2 B = 0
    const std::complex<double> B = -s1 / (s2 - s1), A = 1. - B;
    const double exact = (A * std::exp(s1) + B * std::exp(s2)).real();
    for (const double rho : {0., 0.5, 0.8, 1.})
      {
        const time::GeneralizedAlphaScheme scheme(rho);
        double                             largest = 0;
        for (const double z :
             {1e-4, 1e-3, 1e-2, 0.1, 1., 10., 100., 1e4, 1e6, 1e8})
          largest = std::max(largest, spectral_radius(scheme, z, k, damping));
        // the eigenvalue of the relaxing mode: the one nearest exp(s1 tau)
        const double         kept = std::exp(0.01 * s1.real());
        std::complex<double> slow = 0;
        for (const auto lambda :
             amplification_eigenvalues(scheme, 0.01, k, damping))
          if (std::abs(lambda - kept) < std::abs(slow - kept))
            slow = lambda;
        const double stiff = spectral_radius(scheme, 1e6, k, damping);
        deallog << "Kelvin-Voigt, rho_inf " << rho
                << ": largest spectral radius " << largest
                << " (at most 1: " << yes_no(largest <= 1 + 1e-12)
                << "), its eigenvalue nearest exp(s1 tau) at tau = 0.01 T "
                << slow.real() << " (exp(s1 tau) to 1e-6: "
                << yes_no(std::abs(slow - kept) < 1e-6) << "), at tau = 1e6 T "
                << stiff
                << " (rho_inf to 1e-3: " << yes_no(std::abs(stiff - rho) < 1e-3)
                << ")" << std::endl;
        double previous = 0;
        for (const unsigned int n : {100, 200, 400, 800})
          {
            const double tau = 1. / n;
            Mode         x{1., 0., -k};
            for (unsigned int i = 0; i < n; ++i)
              x = one_step(scheme, tau, k, damping, x);
            const double error = std::abs(x.u - exact) / std::abs(exact);
            deallog << "Kelvin-Voigt, rho_inf " << rho << ", steps " << n
                    << ": relative error of u(T) " << error;
            log_order(previous, error, n);
            deallog << std::endl;
            previous = error;
          }
      }
  }
}
