#include <cmath>
#include <cstdlib>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <iostream>
#include <rsfcycle/solvers/sparse_cholesky.h>
#include <rsfcycle/solvers/tnnmg.h>

namespace rsfcycle
{
  namespace solvers
  {
    using dealii::SparseMatrix;
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
        const double g  = phi.derivative(s);
        const double gp = phi.second_derivative(s);
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


    TNNMG::TNNMG(LinearCorrection &correction, const TNNMGControl &control)
      : correction(correction)
      , control(control)
    {}


    void
    TNNMG::gauss_seidel_sweep(const SpatialProblem &problem, Vector<double> &v)
    {
      const SparseMatrix<double> &A       = *problem.A;
      const Vector<double>       &r       = *problem.rhs;
      const std::vector<bool>    &fixed   = *problem.fixed;
      const ContactSet           &contact = *problem.contact;

      for (global_dof_index i = 0; i < v.size(); ++i)
        {
          if (fixed[i])
            continue;
          const int node_index = contact.dof_to_node[i];
          if (node_index < 0)
            {
              // Linear Gauss-Seidel update of a dof without friction.
              double sum = r[i], diagonal = 0;
              for (auto it = A.begin(i); it != A.end(i); ++it)
                if (it->column() == i)
                  diagonal = it->value();
                else
                  sum -= it->value() * v[it->column()];
              v[i] = sum / diagonal;
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
              for (auto it = A.begin(row); it != A.end(row); ++it)
                {
                  const global_dof_index col      = it->column();
                  bool                   in_block = false;
                  for (unsigned int l = 0; l < d; ++l)
                    if (col == node.dofs[l])
                      {
                        A_TT[d * k + l] = it->value();
                        in_block        = true;
                      }
                  if (!in_block)
                    rho[k] -= it->value() * v[col];
                }
            }

          const friction::NodePotential &phi =
            (*problem.potentials)[node_index];
          if (d == 1)
            {
              const auto sol =
                friction::solve_local_problem<1>({{A_TT[0]}}, {{rho[0]}}, phi);
              v[node.dofs[0]] = sol.x[0];
            }
          else
            {
              const auto sol = friction::solve_local_problem<2>(A_TT, rho, phi);
              v[node.dofs[0]] = sol.x[0];
              v[node.dofs[1]] = sol.x[1];
            }
        }
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
                       const Vector<double> &v,
                       const Vector<double> &c)
    {
      const double c_residual = -(c * residual); // residual = r - A v
      problem.A->vmult(Ac, c);
      const double      cAc     = c * Ac;
      const ContactSet &contact = *problem.contact;

      // D(t) and, where every node moves off 0, D'(t) (else NaN)
      const auto derivatives = [&](const double t) {
        std::array<double, 2> value = {{c_residual + t * cAc, cAc}};
        for (unsigned int n = 0; n < contact.nodes.size(); ++n)
          {
            const ContactNode    &node = contact.nodes[n];
            std::array<double, 2> y{}, cn{};
            for (unsigned int k = 0; k < node.n_dofs; ++k)
              {
                cn[k] = c[node.dofs[k]];
                y[k]  = v[node.dofs[k]] + t * cn[k];
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
                                  const Vector<double> &v)
    {
      const SparseMatrix<double> &A       = *problem.A;
      const std::vector<bool>    &fixed   = *problem.fixed;
      const ContactSet           &contact = *problem.contact;
      const auto                 &phis    = *problem.potentials;
      const global_dof_index      n       = v.size();
      A.residual(residual, v, *problem.rhs); // r - A v
      for (global_dof_index i = 0; i < n; ++i)
        truncated[i] = fixed[i];
      newton_rhs = residual;
      for (unsigned int k = 0; k < contact.nodes.size(); ++k)
        {
          const ContactNode    &node = contact.nodes[k];
          std::array<double, 2> y{}, grad{};
          for (unsigned int l = 0; l < node.n_dofs; ++l)
            y[l] = v[node.dofs[l]];
          friction_gradient_and_hessian(
            phis[k], y, node.n_dofs, grad, hessians[k]);
          double max_hessian = 0, max_diagonal = 0;
          for (unsigned int l = 0; l < node.n_dofs; ++l)
            {
              max_hessian =
                std::max(max_hessian, hessians[k][node.n_dofs * l + l]);
              max_diagonal =
                std::max(max_diagonal, A.diag_element(node.dofs[l]));
            }
          const bool stuck =
            (y[0] == 0 && y[1] == 0) ||
            !(max_hessian <= control.truncation_ratio * max_diagonal);
          for (unsigned int l = 0; l < node.n_dofs; ++l)
            {
              truncated[node.dofs[l]] = stuck;
              newton_rhs[node.dofs[l]] -= grad[l];
            }
          if (stuck)
            hessians[k] = {{0., 0., 0., 0.}};
        }
      for (global_dof_index i = 0; i < n; ++i)
        if (truncated[i])
          newton_rhs[i] = 0;
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
                 Vector<double>       &v,
                 const double          tolerance)
    {
      const SparseMatrix<double> &A       = *problem.A;
      const ContactSet           &contact = *problem.contact;
      const global_dof_index      n       = v.size();

      residual.reinit(n);
      newton_rhs.reinit(n);
      correction_vector.reinit(n);
      v_old.reinit(n);
      increment.reinit(n);
      Ac.reinit(n);
      Av_old.reinit(n);
      // A v is carried from iteration to iteration (the residual of step 2
      // and A c of the line search give it), so that the stopping test
      // costs no matrix product
      Av.reinit(n);
      A.vmult(Av, v);
      truncated.assign(n, false);
      hessians.assign(contact.nodes.size(), {{0., 0., 0., 0.}});

      TNNMGStatistics stats;
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
          auto                  scope = section("TNNMG: linear correction");
          TruncatedNewtonSystem system;
          system.A             = &A;
          system.contact       = &contact;
          system.node_hessians = &hessians;
          system.truncated     = &truncated;
          system.matrix_key    = problem.matrix_key;
          correction_vector    = 0;
          stats.linear_iterations +=
            correction.solve(system, newton_rhs, correction_vector);
          for (global_dof_index i = 0; i < n; ++i)
            if (truncated[i])
              correction_vector[i] = 0;

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
              return stats;
            }
          if (stats.relative_change <= tolerance)
            {
              stats.converged = true;
              return stats;
            }
        }
      return stats;
    }


    struct DirectCorrection::Factorization
    {
      double                       key = 0;
      dealii::SparsityPattern      pattern;
      dealii::SparseMatrix<double> A_II;
      SparseCholesky               lu;
      dealii::FullMatrix<double>   schur; // n_c x n_c
      dealii::FullMatrix<double>   Z;     // A_II^{-1} A_Ic
    };


    DirectCorrection::DirectCorrection()  = default;
    DirectCorrection::~DirectCorrection() = default;


    const DirectCorrection::Factorization &
    DirectCorrection::factorization(const TruncatedNewtonSystem &system)
    {
      for (const auto &f : cache)
        if (f->key == system.matrix_key)
          return *f;

      const SparseMatrix<double> &A       = *system.A;
      const ContactSet           &contact = *system.contact;
      const global_dof_index      n       = A.m();
      if (interior_index.size() != n)
        {
          // Interior: free dofs without friction (fixed ones are truncated
          // and not contact dofs).
          interior.clear();
          contact_dofs.clear();
          interior_index.assign(n, -1);
          contact_index.assign(n, -1);
          for (global_dof_index i = 0; i < n; ++i)
            if (contact.dof_to_node[i] >= 0)
              {
                contact_index[i] = contact_dofs.size();
                contact_dofs.push_back(i);
              }
            else if (!(*system.truncated)[i])
              {
                interior_index[i] = interior.size();
                interior.push_back(i);
              }
        }

      static int n_setups = 0;
      if (std::getenv("RSF_DEBUG"))
        std::cerr << "setup " << ++n_setups << " key " << system.matrix_key
                  << "\n";
      if (cache.size() >= 8)
        cache.erase(cache.begin());
      auto f = std::make_unique<Factorization>();
      f->key = system.matrix_key;

      const unsigned int             n_I = interior.size();
      dealii::DynamicSparsityPattern dsp(n_I, n_I);
      for (unsigned int k = 0; k < n_I; ++k)
        for (auto it = A.begin(interior[k]); it != A.end(interior[k]); ++it)
          if (interior_index[it->column()] >= 0)
            dsp.add(k, interior_index[it->column()]);
      f->pattern.copy_from(dsp);
      f->A_II.reinit(f->pattern);
      for (unsigned int k = 0; k < n_I; ++k)
        for (auto it = A.begin(interior[k]); it != A.end(interior[k]); ++it)
          if (interior_index[it->column()] >= 0)
            f->A_II.set(k, interior_index[it->column()], it->value());
      f->lu.factorize(f->A_II);

      const unsigned int n_c = contact_dofs.size();
      f->schur.reinit(n_c, n_c);
      // A symmetric: column j of A_Ic is row contact_dofs[j] restricted to I.
      dealii::FullMatrix<double> A_Ic(n_I, n_c);
      for (unsigned int j = 0; j < n_c; ++j)
        for (auto it = A.begin(contact_dofs[j]); it != A.end(contact_dofs[j]);
             ++it)
          {
            if (interior_index[it->column()] >= 0)
              A_Ic(interior_index[it->column()], j) = it->value();
            else if (contact_index[it->column()] >= 0)
              f->schur(contact_index[it->column()], j) += it->value();
          }
      f->lu.solve(A_Ic, f->Z);
      // S = A_cc - A_Ic^T Z
      dealii::FullMatrix<double> product(n_c, n_c);
      A_Ic.Tmmult(product, f->Z);
      f->schur.add(-1., product);
      cache.push_back(std::move(f));
      return *cache.back();
    }


    unsigned int
    DirectCorrection::solve(const TruncatedNewtonSystem &system,
                            const Vector<double>        &rhs,
                            Vector<double>              &c)
    {
      const Factorization        &f         = factorization(system);
      const SparseMatrix<double> &A         = *system.A;
      const ContactSet           &contact   = *system.contact;
      const std::vector<bool>    &truncated = *system.truncated;
      const unsigned int          n_I       = interior.size();

      // Active contact dofs and their position in contact_dofs.
      std::vector<unsigned int> active;
      for (unsigned int j = 0; j < contact_dofs.size(); ++j)
        if (!truncated[contact_dofs[j]])
          active.push_back(j);
      const unsigned int n_a = active.size();

      // y = A_II^{-1} b_I
      b_I.reinit(n_I, true);
      for (unsigned int k = 0; k < n_I; ++k)
        b_I[k] = rhs[interior[k]];
      f.lu.solve(b_I, y);

      c = 0;
      if (n_a > 0)
        {
          // (S_aa + H_aa) x_a = b_a - A_aI y, with S_aa + H_aa formed
          // directly in the LAPACK matrix (n_a is small: contact dofs only)
          dealii::LAPACKFullMatrix<double> S(n_a, n_a);
          Vector<double>                   x_a(n_a);
          std::vector<int> active_position(contact_dofs.size(), -1);
          for (unsigned int p = 0; p < n_a; ++p)
            {
              active_position[active[p]] = p;
              const global_dof_index row = contact_dofs[active[p]];
              x_a[p]                     = rhs[row];
              for (auto it = A.begin(row); it != A.end(row); ++it)
                if (interior_index[it->column()] >= 0)
                  x_a[p] -= it->value() * y[interior_index[it->column()]];
              for (unsigned int q = 0; q < n_a; ++q)
                S(p, q) = f.schur(active[p], active[q]);
            }
          // Hessian blocks of the active nodes.
          for (unsigned int k = 0; k < contact.nodes.size(); ++k)
            {
              const ContactNode &node = contact.nodes[k];
              for (unsigned int i = 0; i < node.n_dofs; ++i)
                for (unsigned int j = 0; j < node.n_dofs; ++j)
                  {
                    const int pi = active_position[contact_index[node.dofs[i]]],
                              pj = active_position[contact_index[node.dofs[j]]];
                    if (pi >= 0 && pj >= 0)
                      S(pi, pj) +=
                        (*system.node_hessians)[k][node.n_dofs * i + j];
                  }
            }
          S.compute_lu_factorization();
          S.solve(x_a);
          for (unsigned int p = 0; p < n_a; ++p)
            c[contact_dofs[active[p]]] = x_a[p];

          // x_I = A_II^{-1} (b_I - A_Ia x_a) = y - Z_a x_a
          for (unsigned int k = 0; k < n_I; ++k)
            {
              double sum = 0;
              for (unsigned int p = 0; p < n_a; ++p)
                sum += f.Z(k, active[p]) * x_a[p];
              y[k] -= sum;
            }
        }
      for (unsigned int k = 0; k < n_I; ++k)
        c[interior[k]] = y[k];
      return 1;
    }


    std::string
    linear_correction_names()
    {
      return "multigrid|direct|amg";
    }
  } // namespace solvers
} // namespace rsfcycle
