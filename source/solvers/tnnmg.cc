// SPDX-License-Identifier: LGPL-2.1-or-later
#include <cmath>
#include <cstdlib>
#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>
#include <rsfcycle/solvers/tnnmg.h>

namespace rsfcycle
{
  namespace solvers
  {
    using dealii::Vector;

    namespace
    {
      /**
       * Gradient phi'(s) y/s and Hessian of phi(|y|) at y for one node
       * (d = 1 or 2): phi''(s) e e^T + phi'(s)/s (I - e e^T), e = y/s.
       */
      void
      friction_gradient_and_hessian(const friction::NodePotential &phi,
                                    const std::array<double, 2>   &y,
                                    const unsigned int             d,
                                    std::array<double, 2>         &grad,
                                    std::array<double, 4>         &hess)
      {
        const double s = (d == 1) ? std::abs(y[0]) : std::hypot(y[0], y[1]);
        grad           = {{0., 0.}};
        hess           = {{0., 0., 0., 0.}};
        if (!(s > 0))
          return;
        const auto [g, gp] = phi.derivatives(s);
        for (unsigned int k = 0; k < d; ++k)
          grad[k] = g * y[k] / s;
        if (d == 1)
          hess[0] = gp;
        else
          {
            const double e[2] = {y[0] / s, y[1] / s};
            for (unsigned int k = 0; k < 2; ++k)
              for (unsigned int l = 0; l < 2; ++l)
                hess[2 * k + l] =
                  gp * e[k] * e[l] + g / s * ((k == l ? 1. : 0.) - e[k] * e[l]);
          }
      }
    } // namespace


    TNNMG::TNNMG(LinearCorrection   &correction,
                 const TNNMGControl &control,
                 LinearCorrection   *fallback)
      : correction(correction)
      , fallback(fallback)
      , control(control)
    {}


    void
    TNNMG::gauss_seidel_sweep(const SpatialProblem &problem, la::Vector &v)
    {
      // rows and columns in the vectors' local numbering (the global one
      // on one rank)
      const la::LocalMatrix &A = *problem.local_A;
      const double          *r = problem.rhs->begin();
      // the other ranks' entries as of the last sweep (hybrid
      // Gauss-Seidel/Jacobi across ranks)
      double                  *x       = const_cast<double *>(A.ghosted(v));
      const std::vector<bool> &fixed   = *problem.fixed;
      const ContactSet        &contact = *problem.contact;

      for (unsigned int i = 0; i < A.m(); ++i)
        {
          if (fixed[i])
            continue;
          const int node_index = contact.dof_to_node[i];
          if (node_index < 0)
            {
              // Linear Gauss-Seidel update of a dof without friction.
              double sum = r[i], diagonal = 0;
              for (unsigned int j = A.row_begin(i); j < A.row_end(i); ++j)
                if (A.column(j) == i)
                  diagonal = A.value(j);
                else
                  sum -= A.value(j) * x[A.column(j)];
              x[i] = sum / diagonal;
              continue;
            }

          const ContactNode &node = contact.nodes[node_index];
          if (node.dofs[0] != i)
            continue; // handled with the node's first dof

          // Node-local problem: 1/2 x^T A_TT x - rho^T x + phi(|x|) with
          // rho = r_T - sum_{j not in T} A_Tj v_j.
          const unsigned int    d = node.n_dofs;
          std::array<double, 4> A_TT{};
          std::array<double, 2> rho{};
          for (unsigned int k = 0; k < d; ++k)
            {
              const global_dof_index row = node.dofs[k];
              rho[k]                     = r[row];
              for (unsigned int j = A.row_begin(row); j < A.row_end(row); ++j)
                {
                  const unsigned int col      = A.column(j);
                  bool               in_block = false;
                  for (unsigned int l = 0; l < d; ++l)
                    if (col == node.dofs[l])
                      {
                        A_TT[d * k + l] = A.value(j);
                        in_block        = true;
                      }
                  if (!in_block)
                    rho[k] -= A.value(j) * x[col];
                }
            }

          const friction::NodePotential &phi =
            (*problem.potentials)[node_index];
          // the node's current value is the guess of the local solve
          if (d == 1)
            {
              const std::array<double, 1> guess = {{x[node.dofs[0]]}};
              const auto sol  = friction::solve_local_problem<1>({{A_TT[0]}},
                                                                {{rho[0]}},
                                                                phi,
                                                                &guess);
              x[node.dofs[0]] = sol.x[0];
            }
          else
            {
              const std::array<double, 2> guess = {
                {x[node.dofs[0]], x[node.dofs[1]]}};
              const auto sol =
                friction::solve_local_problem<2>(A_TT, rho, phi, &guess);
              x[node.dofs[0]] = sol.x[0];
              x[node.dofs[1]] = sol.x[1];
            }
        }
      A.release(v);
    }


    /**
     * The exact minimiser of the convex function t -> J(v + t c), the root
     * of its derivative
     *   D(t) = c^T(A v - r) + t c^T A c + sum_i phi_i'(|y_i|) y_i.c_i/|y_i|,
     * y_i = v_i + t c_i: along c the quadratic part is a parabola, so only
     * the contact nodes are evaluated per trial point. The root is
     * bracketed (D(0) < 0, doubling from t = 1), then found by Newton's
     * method on D (D' = c^T A c + sum_i c_i^T H_i(y_i) c_i with the friction
     * Hessians) inside the bracket, bisecting where a Newton step leaves it
     * or a node passes through 0 (where phi(|y|) has its kink), to the
     * relative width 1e-12 of the bisection alone. Also returns A c.
     */
    double
    TNNMG::line_search(const SpatialProblem &problem,
                       const la::Vector     &v,
                       const la::Vector     &c)
    {
      const double c_residual = -(c * residual); // residual = r - A v
      problem.local_A->vmult(Ac, c);
      const double      cAc     = c * Ac;
      const ContactSet &contact = *problem.contact;
      const MPI_Comm    comm    = v.get_partitioner()->get_mpi_communicator();
      const bool distributed    = v.get_partitioner()->n_mpi_processes() > 1;

      // D(t) and, where every node moves off 0, D'(t) (else NaN); the
      // friction part summed over the nodes of all ranks
      const auto derivatives = [&](const double t) {
        std::array<double, 2> value = {{0., 0.}};
        for (unsigned int n = 0; n < contact.nodes.size(); ++n)
          {
            const ContactNode    &node = contact.nodes[n];
            std::array<double, 2> y{}, cn{};
            for (unsigned int k = 0; k < node.n_dofs; ++k)
              {
                cn[k] = c.local_element(node.dofs[k]);
                y[k]  = v.local_element(node.dofs[k]) + t * cn[k];
              }
            const double c_norm = std::hypot(cn[0], cn[1]);
            if (c_norm == 0)
              continue;
            const double                   s   = std::hypot(y[0], y[1]);
            const friction::NodePotential &phi = (*problem.potentials)[n];
            if (!(s > 0))
              {
                value[0] += phi.cohesion_force * c_norm; // right derivative
                value[1] = std::nan("");
                continue;
              }
            std::array<double, 2> grad;
            std::array<double, 4> hess;
            friction_gradient_and_hessian(phi, y, node.n_dofs, grad, hess);
            value[0] += grad[0] * cn[0] + grad[1] * cn[1];
            value[1] += cn[0] * (hess[0] * cn[0] + hess[1] * cn[1]) +
                        cn[1] * (hess[2] * cn[0] + hess[3] * cn[1]);
          }
        if (distributed)
          dealii::Utilities::MPI::sum(
            dealii::ArrayView<const double>(value.data(), 2),
            comm,
            dealii::ArrayView<double>(value.data(), 2));
        value[0] += c_residual + t * cAc;
        value[1] += cAc;
        return value;
      };

      if (!(derivatives(0.)[0] < 0))
        return 0.;
      double lo = 0, hi = 1;
      auto   at_hi = derivatives(hi);
      while (at_hi[0] < 0 && hi < 1e9)
        {
          lo    = hi;
          hi    = 2 * hi;
          at_hi = derivatives(hi);
        }
      // Newton from the upper end of the bracket, bisection as safeguard
      double t = hi, D = at_hi[0], dD = at_hi[1];
      for (unsigned int it = 0; it < 100 && hi - lo > 1e-12 * hi; ++it)
        {
          double next = t - D / dD;
          if (!(next > lo && next < hi))
            next = 0.5 * (lo + hi);
          if (std::abs(next - t) <= 1e-12 * hi)
            return next;
          t                 = next;
          const auto at_t   = derivatives(t);
          D                 = at_t[0];
          dD                = at_t[1];
          (D < 0 ? lo : hi) = t;
          if (D == 0)
            return t;
        }
      return 0.5 * (lo + hi);
    }


    void
    TNNMG::truncate_and_linearise(const SpatialProblem &problem,
                                  const la::Vector     &v)
    {
      const la::LocalMatrix   &A       = *problem.local_A;
      const std::vector<bool> &fixed   = *problem.fixed;
      const ContactSet        &contact = *problem.contact;
      const auto              &phis    = *problem.potentials;
      problem.local_A->residual(residual, v, *problem.rhs); // r - A v
      truncated  = fixed;
      newton_rhs = residual;
      for (unsigned int k = 0; k < contact.nodes.size(); ++k)
        {
          const ContactNode    &node = contact.nodes[k];
          std::array<double, 2> y{}, grad{};
          for (unsigned int l = 0; l < node.n_dofs; ++l)
            y[l] = v.local_element(node.dofs[l]);
          friction_gradient_and_hessian(
            phis[k], y, node.n_dofs, grad, hessians[k]);
          double max_hessian = 0, max_diagonal = 0;
          for (unsigned int l = 0; l < node.n_dofs; ++l)
            {
              max_hessian =
                std::max(max_hessian, hessians[k][node.n_dofs * l + l]);
              max_diagonal = std::max(max_diagonal, A.diagonal(node.dofs[l]));
            }
          const bool stuck =
            (y[0] == 0 && y[1] == 0) ||
            !(max_hessian <= control.truncation_ratio * max_diagonal);
          for (unsigned int l = 0; l < node.n_dofs; ++l)
            {
              truncated[node.dofs[l]] = stuck;
              newton_rhs.local_element(node.dofs[l]) -= grad[l];
            }
          if (stuck)
            hessians[k] = {{0., 0., 0., 0.}};
        }
      for (unsigned int i = 0; i < newton_rhs.locally_owned_size(); ++i)
        if (truncated[i])
          newton_rhs.local_element(i) = 0;
    }


    void
    TNNMG::set_timer(dealii::TimerOutput *new_timer)
    {
      timer = new_timer;
    }


    std::optional<dealii::TimerOutput::Scope>
    TNNMG::section(const char *name) const
    {
      if (timer == nullptr)
        return std::nullopt;
      return std::optional<dealii::TimerOutput::Scope>(std::in_place,
                                                       *timer,
                                                       name);
    }


    TNNMGStatistics
    TNNMG::solve(const SpatialProblem &problem,
                 la::Vector           &v,
                 const double          tolerance)
    {
      const ContactSet &contact = *problem.contact;

      residual.reinit(v);
      newton_rhs.reinit(v);
      correction_vector.reinit(v);
      v_old.reinit(v);
      increment.reinit(v);
      Ac.reinit(v);
      Av_old.reinit(v);
      // A v is carried from iteration to iteration (the residual of step 2
      // and A c of the line search give it), so that the stopping test
      // costs no matrix product
      Av.reinit(v);
      problem.local_A->vmult(Av, v);
      truncated.assign(problem.fixed->size(), false);
      hessians.assign(contact.nodes.size(), {{0., 0., 0., 0.}});

      TNNMGStatistics stats;
      iterate(
        problem, v, tolerance, correction, "TNNMG: linear correction", stats);
      if (!stats.converged && fallback != nullptr &&
          std::isfinite(stats.relative_change))
        iterate(problem,
                v,
                tolerance,
                *fallback,
                "TNNMG: fallback correction",
                stats);
      return stats;
    }


    void
    TNNMG::iterate(const SpatialProblem &problem,
                   la::Vector           &v,
                   const double          tolerance,
                   LinearCorrection     &linear,
                   const char           *section_name,
                   TNNMGStatistics      &stats)
    {
      const ContactSet &contact = *problem.contact;
      for (unsigned int iteration = 0; iteration < control.max_iterations;
           ++iteration)
        {
          ++stats.iterations;
          v_old  = v;
          Av_old = Av;

          // 1. Nonlinear block Gauss-Seidel.
          {
            const auto scope = section("TNNMG: nonlinear smoother");
            gauss_seidel_sweep(problem, v);
          }

          // 2. Truncation and the Newton system at the smoothed iterate.
          {
            const auto scope = section("TNNMG: truncation");
            truncate_and_linearise(problem, v);
          }

          // 3. Linear correction.
          auto                  scope = section(section_name);
          TruncatedNewtonSystem system;
          system.assembled_A   = problem.assembled_A;
          system.local_A       = problem.local_A;
          system.contact       = &contact;
          system.node_hessians = &hessians;
          system.truncated     = &truncated;
          system.matrix_key    = problem.matrix_key;
          correction_vector    = 0;
          stats.linear_iterations +=
            linear.solve(system, newton_rhs, correction_vector);
          for (unsigned int i = 0; i < correction_vector.locally_owned_size();
               ++i)
            if (truncated[i])
              correction_vector.local_element(i) = 0;

          // 4. Line search.
          scope.reset();
          if (timer != nullptr)
            scope.emplace(*timer, "TNNMG: line search");
          Av = *problem.rhs;
          Av -= residual; // A v at the smoothed iterate
          if (std::isfinite(correction_vector.l2_norm()))
            {
              const double step = line_search(problem, v, correction_vector);
              v.add(step, correction_vector);
              Av.add(step, Ac);
            }

          // ||v - v_old||_A and ||v||_A from the carried products
          increment = v;
          increment -= v_old;
          Av_old.sadd(-1., 1., Av); // A (v - v_old)
          // (round-off may make a tiny square negative; NaN stays NaN)
          const auto root = [](const double x) {
            return x < 0 ? 0. : std::sqrt(x);
          };
          const double change   = root(increment * Av_old);
          const double size     = root(v * Av);
          stats.relative_change = (size > 0) ? change / size : change;
          if (!std::isfinite(stats.relative_change))
            {
              stats.converged = false;
              return;
            }
          if (stats.relative_change <= tolerance)
            {
              stats.converged = true;
              return;
            }
        }
    }

  } // namespace solvers
} // namespace rsfcycle
