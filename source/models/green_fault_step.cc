// SPDX-License-Identifier: LGPL-2.1-or-later
// The implicit step of the Green's-function method: the spatial problem on
// the fault's nodes only (models/green_fault.h, solvers/fault_solver.h).
#include <algorithm>
#include <cmath>
#include <rsfcycle/models/green_fault.h>
#include <rsfcycle/time/rate_state_coupling.h>

namespace rsfcycle
{
  namespace models
  {
    template <int dim>
    std::optional<FaultState>
    GreenFault<dim>::step(const State &old,
                          const double t,
                          const double tau,
                          const State *guess)
    {
      // (2D: one tangential dof per contact node, so dof j and node j
      // coincide; Parameters::validate refuses the implicit step in 3D)
      TimerOutput::Scope scope(timer, "Implicit fault step");
      const unsigned int n = old.slip.size(), first = op.first_row,
                         n_own = damping.size();
      const auto   c           = time::step_coefficients(*scheme, tau, false);
      const auto   d           = scheme->known_displacement();
      const double t_step      = t + scheme->load_fraction() * tau;
      const auto  &law         = *parameters.solver.law;

      // r = g0 + t* g1 + g(t*) P - S (s_n + tau d0 V_n) (P the shear
      // stress perturbation's forces), the damping c_C eta w, the friction
      // potentials at t*
      std::vector<double> known(n), rhs(n_own), D(n_own);
      for (unsigned int j = 0; j < n; ++j)
        known[j] = old.slip[j] + tau * d[0] * old.rate[j];
      op.apply(known.data(), rhs.data());
      const double                         g = perturbation_factor(t_step);
      std::vector<friction::NodePotential> potentials(n_own);
      bool                                 compressed = true;
      for (unsigned int k = 0; k < n_own; ++k)
        {
          rhs[k] =
            op.g0[k] + t_step * op.g1[k] + g * perturbation_forces[k] - rhs[k];
          D[k]                       = c[1] * damping[k];
          potentials[k].law          = &law;
          potentials[k].params       = contact.nodes()[k].params;
          potentials[k].normal_force = normal_force(k, t_step);
          compressed = compressed && potentials[k].normal_force > 0;
        }
      // (a pore pressure that leaves a node without compression: the same
      // one-line error as the Runge-Kutta's, on every rank)
      if (pore_pressure &&
          Utilities::MPI::min(compressed ? 1 : 0, communicator) == 0)
        check_compression(t_step);
      solvers::FaultProblem problem;
      problem.apply_S = [this](const double *x, double *y) { op.apply(x, y); };
      problem.gather  = [this](double *values) { gather_in_place(values); };
      problem.stiffness_factor = c[2];
      problem.S_diagonal       = &S_diagonal;
      problem.damping          = &D;
      problem.rhs              = &rhs;
      problem.potentials       = &potentials;
      problem.first            = first;
      problem.communicator     = communicator;

      std::vector<double> w     = guess ? guess->rate : old.rate;
      std::vector<double> alpha = guess ? guess->alpha : old.alpha;

      // A split fault's normal coupling: the normal forces at the slip of
      // the step's end for the rates w, updated with the state in the
      // fixed point (the spatial problem for fixed normal forces stays
      // convex); a node without compression fails the step.
      const auto e        = scheme->new_velocity();
      const auto h        = scheme->new_displacement();
      const auto new_slip = [&](const std::vector<double> &rates,
                                std::vector<double>       &slip) {
        slip.resize(n);
        for (unsigned int j = 0; j < n; ++j)
          slip[j] =
            old.slip[j] + tau * (h[0] * old.rate[j] +
                                 h[1] * (e[0] * rates[j] + e[1] * old.rate[j]));
      };
      std::vector<double> slip_end;
      const auto update_normal_forces = [&](const std::vector<double> &rates) {
        new_slip(rates, slip_end);
        const auto &N = normal_forces(slip_end.data(), t_step);
        for (unsigned int k = 0; k < n_own; ++k)
          potentials[k].normal_force = N[k];
        const bool positive =
          std::all_of(N.begin(), N.end(), [](double x) { return x > 0; });
        return Utilities::MPI::min(positive ? 1 : 0, communicator) == 1;
      };
      bool compressed_end = true;
      if (op.normal_coupling)
        compressed_end = update_normal_forces(w);
      const double            sigma = scheme->friction_state_weight();
      solvers::StepStatistics statistics;
      const auto              iterations = time::couple_rate_and_state(
        parameters.solver.coupling,
        parameters.solver.fixed_point_tolerance,
        parameters.solver.max_fixed_point_iterations,
        scheme->state_weight(),
        old.rate,
        w,
        alpha,
        [&](const std::vector<double> &a, std::vector<double> &v) {
          if (!compressed_end)
            return false;
          for (unsigned int k = 0; k < n_own; ++k)
            potentials[k].set_state((1 - sigma) * old.alpha[first + k] +
                                    sigma * a[first + k]);
          const auto solve =
            fault_solver.solve(problem, v, parameters.solver.tnnmg_tolerance);
          statistics.tnnmg_iterations += solve.iterations;
          statistics.linear_iterations += solve.linear_iterations;
          return solve.converged;
        },
        [&](const std::vector<double> &v_new,
            const double               weight_new,
            std::vector<double>       &a) {
          for (unsigned int k = 0; k < n_own; ++k)
            {
              const unsigned int j = first + k;
              const double       V = std::abs((1 - weight_new) * old.rate[j] +
                                        weight_new * v_new[j]);
              a[j] = law.update_state(contact.nodes()[k].params,
                                      old.alpha[j],
                                      V,
                                      tau);
            }
          gather_in_place(a.data(), true);
          if (op.normal_coupling)
            compressed_end = update_normal_forces(v_new);
        },
        [this](const std::vector<double> &a1, const std::vector<double> &a2) {
          return state_distance(a1, a2);
        });
      if (!iterations)
        return {};

      State next;
      next.t                                 = t + tau;
      next.statistics                        = statistics;
      next.statistics.fixed_point_iterations = *iterations;
      next.alpha                             = alpha;
      next.rate.resize(n);
      next.slip.resize(n);
      bool finite = true;
      new_slip(w, next.slip);
      for (unsigned int j = 0; j < n; ++j)
        {
          next.rate[j] = e[0] * w[j] + e[1] * old.rate[j];
          finite       = finite && std::isfinite(next.slip[j]) &&
                   std::isfinite(next.alpha[j]) && std::isfinite(next.rate[j]);
        }
      if (!finite)
        return {};
      return next;
    }


    template <int dim>
    double
    GreenFault<dim>::state_distance(const std::vector<double> &alpha1,
                                    const std::vector<double> &alpha2,
                                    const bool                 largest) const
    {
      // this rank's nodes, measured by the contact quadrature (over ranks)
      const auto own1 = alpha1.begin() + first_node,
                 own2 = alpha2.begin() + first_node;
      const std::vector<double> a1(own1, own1 + damping.size()),
        a2(own2, own2 + damping.size());
      return largest ? contact.state_max_distance(a1, a2) :
                       contact.state_distance(a1, a2);
    }


    template <int dim>
    double
    GreenFault<dim>::error_distance(const State &s1, const State &s2) const
    {
      return state_distance(s1.alpha,
                            s2.alpha,
                            parameters.time_stepping.error_norm ==
                              TimeSteppingParameters::ErrorNorm::max);
    }


    template <int dim>
    FaultState
    GreenFault<dim>::predict(const std::array<const State *, 3> &s,
                             const std::array<double, 3>        &w) const
    {
      State p;
      p.slip.assign(s[0]->slip.size(), 0.);
      p.alpha.assign(s[0]->alpha.size(), 0.);
      p.rate.assign(s[0]->rate.size(), 0.);
      for (unsigned int i = 0; i < 3; ++i)
        {
          p.t += w[i] * s[i]->t;
          for (unsigned int j = 0; j < p.slip.size(); ++j)
            {
              p.slip[j] += w[i] * s[i]->slip[j];
              p.rate[j] += w[i] * s[i]->rate[j];
            }
          for (unsigned int j = 0; j < p.alpha.size(); ++j)
            p.alpha[j] += w[i] * s[i]->alpha[j];
        }
      return p;
    }


    template class GreenFault<2>;
    template class GreenFault<3>;
  } // namespace models
} // namespace rsfcycle
