// SPDX-License-Identifier: LGPL-2.1-or-later
// The exact linear correction of TNNMG (solvers/direct_correction.h):
// CHOLMOD on the free non-contact unknowns and a dense Schur complement on
// the contact dofs.
#include <cmath>
#include <deal.II/lac/lapack_full_matrix.h>
#include <rsfcycle/solvers/direct_correction.h>
#include <rsfcycle/solvers/sparse_cholesky.h>

namespace rsfcycle
{
  namespace solvers
  {
    using dealii::Vector;

    struct DirectCorrection::Factorization
    {
      double                           key = 0;
      SparseCholesky                   cholesky; // of A_II
      dealii::LAPACKFullMatrix<double> schur;    // n_c x n_c
    };


    DirectCorrection::DirectCorrection()  = default;
    DirectCorrection::~DirectCorrection() = default;


    const DirectCorrection::Factorization &
    DirectCorrection::factorization(const TruncatedNewtonSystem &system)
    {
      for (const auto &f : cache)
        if (f->key == system.matrix_key)
          return *f;

      // one rank: local indices are the global ones
      const la::LocalMatrix &A       = *system.local_A;
      const ContactSet      &contact = *system.contact;
      const unsigned int     n       = A.m();
      if (interior_index.size() != n)
        {
          // Interior: free dofs without friction (fixed ones are truncated
          // and not contact dofs).
          interior.clear();
          contact_dofs.clear();
          interior_index.assign(n, -1);
          contact_index.assign(n, -1);
          for (unsigned int i = 0; i < n; ++i)
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

      if (cache.size() >= 8)
        cache.erase(cache.begin());
      auto f = std::make_unique<Factorization>();
      f->key = system.matrix_key;

      // M = [A_II A_Ic; A_cI A_cc], the interior first, its upper triangle
      // in compressed columns (A symmetric: column J is row J restricted to
      // the rows up to J); its leading columns are A_II's
      const unsigned int n_I = interior.size(), n_c = contact_dofs.size();
      const auto         index = [&](const global_dof_index dof) {
        return interior_index[dof] >= 0 ?
                         interior_index[dof] :
                         (contact_index[dof] >= 0 ? int(n_I) + contact_index[dof] : -1);
      };
      std::vector<int>    p(1, 0), i;
      std::vector<double> x;
      for (unsigned int J = 0; J < n_I + n_c; ++J)
        {
          const global_dof_index row =
            J < n_I ? interior[J] : contact_dofs[J - n_I];
          for (unsigned int e = A.row_begin(row); e < A.row_end(row); ++e)
            {
              const int I = index(A.column(e));
              if (I >= 0 && I <= int(J))
                {
                  i.push_back(I);
                  x.push_back(A.value(e));
                }
            }
          p.push_back(i.size());
        }
      // A_II's own factor for the solves: M's (below) also holds the dense
      // L_cc, which every back-substitution would have to pass
      f->cholesky.factorize(std::vector<int>(p.begin(), p.begin() + n_I + 1),
                            std::vector<int>(i.begin(), i.begin() + p[n_I]),
                            std::vector<double>(x.begin(), x.begin() + p[n_I]));
      // S = A_cc - A_cI A_II^{-1} A_Ic from M's factor in A_II's order with
      // the contact dofs last (one solve per contact dof took 11 minutes
      // and 16 GB for SEAS BP3-FD's 3,200 contact dofs at 25 m)
      if (n_c > 0)
        f->cholesky.schur_complement(p, i, x, f->schur);
      cache.push_back(std::move(f));
      return *cache.back();
    }


    void
    DirectCorrection::contact_matrix(const Factorization             &f,
                                     const TruncatedNewtonSystem     &system,
                                     const std::vector<unsigned int> &active,
                                     const std::vector<int> &active_position,
                                     dealii::LAPACKFullMatrix<double> &S) const
    {
      const ContactSet  &contact = *system.contact;
      const unsigned int n_a     = active.size();
      if (n_a == contact_dofs.size())
        S = f.schur; // all active: one copy
      else
        {
          S.reinit(n_a, n_a);
          for (unsigned int p = 0; p < n_a; ++p)
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
                  S(pi, pj) += (*system.node_hessians)[k][node.n_dofs * i + j];
              }
        }
    }


    unsigned int
    DirectCorrection::solve(const TruncatedNewtonSystem &system,
                            const la::Vector            &rhs,
                            la::Vector                  &c)
    {
      const Factorization     &f         = factorization(system);
      const la::LocalMatrix   &A         = *system.local_A;
      const std::vector<bool> &truncated = *system.truncated;
      const unsigned int       n_I       = interior.size();

      // Active contact dofs and their position in contact_dofs.
      std::vector<unsigned int> active;
      for (unsigned int j = 0; j < contact_dofs.size(); ++j)
        if (!truncated[contact_dofs[j]])
          active.push_back(j);
      const unsigned int n_a = active.size();

      // y = A_II^{-1} b_I
      b_I.reinit(n_I, true);
      // one rank: local entries are the global ones
      const double *b = rhs.begin();
      double       *x = c.begin();
      for (unsigned int k = 0; k < n_I; ++k)
        b_I[k] = b[interior[k]];
      f.cholesky.solve(b_I, y);

      c = 0;
      if (n_a > 0)
        {
          // (S_aa + H_aa) x_a = b_a - A_aI y, with S_aa + H_aa formed
          // directly in the LAPACK matrix (n_a is small: contact dofs only)
          dealii::Vector<double> x_a(n_a);
          std::vector<int>       active_position(contact_dofs.size(), -1);
          for (unsigned int p = 0; p < n_a; ++p)
            {
              active_position[active[p]] = p;
              const global_dof_index row = contact_dofs[active[p]];
              x_a[p]                     = b[row];
              for (unsigned int e = A.row_begin(row); e < A.row_end(row); ++e)
                if (interior_index[A.column(e)] >= 0)
                  x_a[p] -= A.value(e) * y[interior_index[A.column(e)]];
            }
          // S_aa is positive definite and the friction's Hessian (convex)
          // positive semidefinite: Cholesky, half LU's work; LU should
          // rounding make it fail
          // (the work matrix keeps its memory from one iteration to the
          // next: n_a^2 doubles, 80 MB for BP3-FD at 25 m)
          dealii::LAPACKFullMatrix<double> &S = contact_work;
          contact_matrix(f, system, active, active_position, S);
          S.set_property(dealii::LAPACKSupport::symmetric);
          try
            {
              S.compute_cholesky_factorization();
            }
          catch (const std::exception &)
            {
              contact_matrix(f, system, active, active_position, S);
              S.set_property(dealii::LAPACKSupport::general);
              S.compute_lu_factorization();
            }
          S.solve(x_a);
          for (unsigned int p = 0; p < n_a; ++p)
            x[contact_dofs[active[p]]] = x_a[p];

          // x_I = A_II^{-1} (b_I - A_Ia x_a): a second sparse solve, not
          // y - Z_a x_a with the dense n_I x n_c Z (its product took half of
          // an inertial BP3 step at 200 m, and Z is not kept: 640 MB per
          // step size at 50 m); A symmetric: A_Ia's column p is row
          // contact_dofs[active[p]] restricted to I
          for (unsigned int k = 0; k < n_I; ++k)
            b_I[k] = b[interior[k]];
          for (unsigned int p = 0; p < n_a; ++p)
            {
              const global_dof_index row = contact_dofs[active[p]];
              for (unsigned int e = A.row_begin(row); e < A.row_end(row); ++e)
                if (interior_index[A.column(e)] >= 0)
                  b_I[interior_index[A.column(e)]] -= A.value(e) * x_a[p];
            }
          f.cholesky.solve(b_I, y);
        }
      for (unsigned int k = 0; k < n_I; ++k)
        x[interior[k]] = y[k];
      return 1;
    }
  } // namespace solvers
} // namespace rsfcycle
