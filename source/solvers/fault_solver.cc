// SPDX-License-Identifier: LGPL-2.1-or-later
// The fault-only spatial problem of the Green's-function method's implicit
// step (solvers/fault_solver.h).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <rsfcycle/solvers/fault_solver.h>
#include <utility>

namespace rsfcycle
{
  namespace solvers
  {
    namespace
    {
      /** The sum over the ranks of values summed over own rows. */
      template <std::size_t n>
      std::array<double, n>
      sum_over_ranks(std::array<double, n> values, const MPI_Comm comm)
      {
        MPI_Allreduce(
          MPI_IN_PLACE, values.data(), n, MPI_DOUBLE, MPI_SUM, comm);
        return values;
      }

      /** phi'(|x|) sign x, and phi''(|x|). */
      std::pair<double, double>
      signed_derivatives(const friction::NodePotential &phi, const double x)
      {
        const auto d = phi.derivatives(std::abs(x));
        return {x < 0 ? -d.first : d.first, d.second};
      }


      /**
       * The problem's pieces on this rank: A x on the own rows from an
       * all-node x, and the line search of J along a direction.
       */
      class Kernels
      {
      public:
        explicit Kernels(const FaultProblem &p)
          : p(p)
          , n_own(p.rhs->size())
        {
          diagonal.resize(n_own);
          for (unsigned int k = 0; k < n_own; ++k)
            diagonal[k] =
              p.stiffness_factor * (*p.S_diagonal)[k] + (*p.damping)[k];
        }

        /** y = A x on the own rows. */
        void
        product(const std::vector<double> &x, std::vector<double> &y) const
        {
          y.resize(n_own);
          p.apply_S(x.data(), y.data());
          for (unsigned int k = 0; k < n_own; ++k)
            y[k] = p.stiffness_factor * y[k] + (*p.damping)[k] * x[p.first + k];
        }

        /**
         * The minimiser lambda >= 0 of J(w + lambda d), with Aw and Ad on
         * the own rows: f'(lambda) = d.(Aw - r) + lambda d.Ad + sum d_k
         * phi_k'(w_k + lambda d_k) is increasing; bracketed by doubling,
         * then Newton kept in the bracket (bisection where it leaves it).
         */
        double
        line_search(const std::vector<double> &w,
                    const std::vector<double> &d,
                    const std::vector<double> &Aw,
                    const std::vector<double> &Ad) const
        {
          std::array<double, 2> a = {{0., 0.}};
          for (unsigned int k = 0; k < n_own; ++k)
            {
              const double dk = d[p.first + k];
              a[0] += dk * (Aw[k] - (*p.rhs)[k]);
              a[1] += dk * Ad[k];
            }
          a                = sum_over_ranks(a, p.communicator);
          const auto slope = [&](const double lambda) {
            std::array<double, 2> f = {{0., 0.}};
            for (unsigned int k = 0; k < n_own; ++k)
              {
                const double dk = d[p.first + k];
                if (dk == 0)
                  continue;
                const auto phi =
                  signed_derivatives((*p.potentials)[k],
                                     w[p.first + k] + lambda * dk);
                f[0] += dk * phi.first;
                f[1] += dk * dk * phi.second;
              }
            f = sum_over_ranks(f, p.communicator);
            return std::array<double, 2>{
              {a[0] + lambda * a[1] + f[0], a[1] + f[1]}};
          };
          if (!(slope(0.)[0] < 0))
            return 0;
          double lo = 0, hi = 1;
          for (unsigned int i = 0; i < 60; ++i)
            {
              const double f = slope(hi)[0];
              if (!std::isfinite(f))
                return std::numeric_limits<double>::quiet_NaN();
              if (f >= 0)
                break;
              lo = hi;
              hi *= 2;
            }
          double lambda = hi;
          for (unsigned int i = 0; i < 100 && hi - lo > 1e-12 * hi; ++i)
            {
              const auto f = slope(lambda);
              if (!std::isfinite(f[0]))
                return std::numeric_limits<double>::quiet_NaN();
              if (f[0] == 0)
                return lambda;
              (f[0] > 0 ? hi : lo) = lambda;
              double next          = lambda - f[0] / f[1];
              if (!(next > lo && next < hi))
                next = 0.5 * (lo + hi);
              if (std::abs(next - lambda) <= 1e-12 * hi)
                return next;
              lambda = next;
            }
          return lambda;
        }

        const FaultProblem &p;
        const unsigned int  n_own;
        std::vector<double> diagonal; // A_kk
      };
    } // namespace


    FaultSolver::FaultSolver(const unsigned int max_iterations,
                             const double       truncation_ratio)
      : max_iterations(max_iterations)
      , truncation_ratio(truncation_ratio)
    {}


    FaultSolverStatistics
    FaultSolver::solve(const FaultProblem  &p,
                       std::vector<double> &w,
                       const double         tolerance) const
    {
      const Kernels         kernels(p);
      const unsigned int    n_own = kernels.n_own, first = p.first;
      const auto           &A_kk = kernels.diagonal;
      const auto           &phi  = *p.potentials;
      std::vector<double>   Aw, Ad, d(w.size());
      FaultSolverStatistics statistics;
      kernels.product(w, Aw);

      // w += lambda d along the all-node direction d, Aw with it; the
      // change's A-norm squared
      const auto advance = [&](const double lambda) {
        double change = 0;
        for (unsigned int k = 0; k < n_own; ++k)
          {
            Aw[k] += lambda * Ad[k];
            change += lambda * lambda * d[first + k] * Ad[k];
          }
        for (unsigned int j = 0; j < w.size(); ++j)
          w[j] += lambda * d[j];
        return change;
      };

      std::vector<double> h(n_own), z(n_own), q, residual(n_own), c(n_own),
        direction(w.size());
      std::vector<bool> held(n_own);
      for (unsigned int it = 1; it <= max_iterations; ++it)
        {
          statistics.iterations = it;
          // 1. nonlinear Jacobi: every node's exact local solve against
          //    the residual of w, then the line search along the change
          std::fill(d.begin(), d.end(), 0.);
          for (unsigned int k = 0; k < n_own; ++k)
            {
              const double rho = (*p.rhs)[k] - Aw[k] + A_kk[k] * w[first + k];
              const std::array<double, 1> guess = {{w[first + k]}};
              d[first + k] = friction::solve_local_problem<1>({{A_kk[k]}},
                                                              {{rho}},
                                                              phi[k],
                                                              &guess)
                               .x[0] -
                             w[first + k];
            }
          p.gather(d.data());
          kernels.product(d, Ad);
          const double lambda_j = kernels.line_search(w, d, Aw, Ad);
          if (!std::isfinite(lambda_j))
            return statistics;
          double change = advance(lambda_j);

          // 2. truncated Newton: (A + H) c = -grad J on the nodes not held
          //    (preconditioned CG to 1e-3 of the residual), then the line
          //    search along c
          for (unsigned int k = 0; k < n_own; ++k)
            {
              const auto f = signed_derivatives(phi[k], w[first + k]);
              h[k]         = f.second;
              held[k]      = !(h[k] <= truncation_ratio * A_kk[k]);
              residual[k]  = held[k] ? 0. : (*p.rhs)[k] - Aw[k] - f.first;
            }
          std::fill(d.begin(), d.end(), 0.);
          std::fill(c.begin(), c.end(), 0.);
          std::fill(direction.begin(), direction.end(), 0.);
          const auto precondition = [&]() {
            double rz = 0;
            for (unsigned int k = 0; k < n_own; ++k)
              {
                z[k] = held[k] ? 0. : residual[k] / (A_kk[k] + h[k]);
                rz += residual[k] * z[k];
              }
            return sum_over_ranks(std::array<double, 1>{{rz}},
                                  p.communicator)[0];
          };
          double       rz  = precondition();
          const double rz0 = rz;
          for (unsigned int k = 0; k < n_own; ++k)
            direction[first + k] = z[k];
          for (unsigned int cg = 0; cg < 200 && rz > 1e-6 * rz0 && rz > 0; ++cg)
            {
              p.gather(direction.data());
              kernels.product(direction, q);
              double pq = 0;
              for (unsigned int k = 0; k < n_own; ++k)
                {
                  const double pk = direction[first + k];
                  q[k]            = held[k] ? 0. : q[k] + h[k] * pk;
                  pq += pk * q[k];
                }
              pq =
                sum_over_ranks(std::array<double, 1>{{pq}}, p.communicator)[0];
              ++statistics.linear_iterations;
              if (!(pq > 0))
                break;
              const double alpha = rz / pq;
              for (unsigned int k = 0; k < n_own; ++k)
                {
                  c[k] += alpha * direction[first + k];
                  residual[k] -= alpha * q[k];
                }
              const double rz_new = precondition();
              for (unsigned int k = 0; k < n_own; ++k)
                direction[first + k] =
                  z[k] + rz_new / rz * direction[first + k];
              rz = rz_new;
            }
          for (unsigned int k = 0; k < n_own; ++k)
            d[first + k] = c[k];
          p.gather(d.data());
          kernels.product(d, Ad);
          const double lambda_n = kernels.line_search(w, d, Aw, Ad);
          if (!std::isfinite(lambda_n))
            return statistics;
          change += advance(lambda_n);

          double norm = 0;
          for (unsigned int k = 0; k < n_own; ++k)
            norm += w[first + k] * Aw[k];
          const auto sums =
            sum_over_ranks(std::array<double, 2>{{change, norm}},
                           p.communicator);
          if (!std::isfinite(sums[0]) || !std::isfinite(sums[1]))
            return statistics;
          if (std::sqrt(sums[0]) <= tolerance * std::sqrt(sums[1]))
            {
              statistics.converged = true;
              return statistics;
            }
        }
      return statistics;
    }
  } // namespace solvers
} // namespace rsfcycle
