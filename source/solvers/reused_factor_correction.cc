// SPDX-License-Identifier: LGPL-2.1-or-later
// The direct linear correction with reused factors
// (solvers/reused_factor_correction.h): CHOLMOD factors of the truncated
// Newton matrix on a pattern analysed once, reused as preconditioners.
#include <algorithm>
#include <cmath>
#include <rsfcycle/solvers/reused_factor_correction.h>

namespace rsfcycle
{
  namespace solvers
  {
    ReusedFactorCorrection::ReusedFactorCorrection(
      const LinearCorrectionControl &control)
      : control(control)
    {}


    ReusedFactorCorrection::~ReusedFactorCorrection() = default;


    void
    ReusedFactorCorrection::make_pattern(const TruncatedNewtonSystem &system)
    {
      const la::LocalMatrix &A       = *system.local_A;
      const ContactSet      &contact = *system.contact;
      const unsigned int     n       = A.m();

      // column j: the rows i <= j of row j of A, its diagonal, and the
      // contact node blocks (a node's dofs need not be coupled in A)
      std::vector<std::vector<int>> rows(n);
      for (unsigned int j = 0; j < n; ++j)
        {
          rows[j].push_back(j);
          for (unsigned int e = A.row_begin(j); e < A.row_end(j); ++e)
            if (A.column(e) <= j)
              rows[j].push_back(A.column(e));
        }
      for (const ContactNode &node : contact.nodes)
        for (unsigned int a = 0; a < node.n_dofs; ++a)
          for (unsigned int c = 0; c < node.n_dofs; ++c)
            if (node.dofs[a] <= node.dofs[c])
              rows[node.dofs[c]].push_back(node.dofs[a]);
      column_start.assign(1, 0);
      row_index.clear();
      for (auto &r : rows)
        {
          std::sort(r.begin(), r.end());
          r.erase(std::unique(r.begin(), r.end()), r.end());
          row_index.insert(row_index.end(), r.begin(), r.end());
          column_start.push_back(row_index.size());
        }
      values.assign(row_index.size(), 0.);

      const auto position = [&](const unsigned int i, const unsigned int j) {
        const auto begin = row_index.begin() + column_start[j],
                   end   = row_index.begin() + column_start[j + 1];
        return static_cast<int>(std::lower_bound(begin, end, int(i)) -
                                row_index.begin());
      };
      a_position.assign(A.row_begin(n), -1);
      diagonal.resize(n);
      for (unsigned int j = 0; j < n; ++j)
        {
          diagonal[j] = position(j, j);
          for (unsigned int e = A.row_begin(j); e < A.row_end(j); ++e)
            if (A.column(e) <= j)
              a_position[e] = position(A.column(e), j);
        }
      hessian_position.assign(contact.nodes.size(), {{-1, -1, -1, -1}});
      for (unsigned int k = 0; k < contact.nodes.size(); ++k)
        {
          const ContactNode &node = contact.nodes[k];
          for (unsigned int a = 0; a < node.n_dofs; ++a)
            for (unsigned int c = 0; c < node.n_dofs; ++c)
              if (node.dofs[a] <= node.dofs[c])
                hessian_position[k][node.n_dofs * a + c] =
                  position(node.dofs[a], node.dofs[c]);
        }
    }


    void
    ReusedFactorCorrection::fill_values(const TruncatedNewtonSystem &system)
    {
      const la::LocalMatrix   &A         = *system.local_A;
      const ContactSet        &contact   = *system.contact;
      const std::vector<bool> &truncated = *system.truncated;
      std::fill(values.begin(), values.end(), 0.);
      for (unsigned int j = 0; j < A.m(); ++j)
        if (truncated[j])
          values[diagonal[j]] = 1.;
        else
          for (unsigned int e = A.row_begin(j); e < A.row_end(j); ++e)
            if (a_position[e] >= 0 && !truncated[A.column(e)])
              values[a_position[e]] += A.value(e);
      for (unsigned int k = 0; k < contact.nodes.size(); ++k)
        {
          const ContactNode &node = contact.nodes[k];
          for (unsigned int a = 0; a < node.n_dofs; ++a)
            for (unsigned int d = 0; d < node.n_dofs; ++d)
              {
                const int p = hessian_position[k][node.n_dofs * a + d];
                if (p >= 0 && !truncated[node.dofs[a]] &&
                    !truncated[node.dofs[d]])
                  values[p] += (*system.node_hessians)[k][node.n_dofs * a + d];
              }
        }
    }


    unsigned int
    ReusedFactorCorrection::solve(const TruncatedNewtonSystem &system,
                                  const la::Vector            &rhs,
                                  la::Vector                  &c)
    {
      const std::vector<bool> &truncated = *system.truncated;
      const unsigned int       n         = system.local_A->m();
      if (diagonal.size() != n)
        make_pattern(system);
      b.reinit(n, true);
      x.reinit(n, true);
      // one rank: local entries are the global ones
      const auto apply =
        [&](const Factor &f, la::Vector &z, const la::Vector &r) {
          for (unsigned int i = 0; i < n; ++i)
            b[i] = truncated[i] ? 0. : r.local_element(i);
          f.cholesky.solve(b, x);
          for (unsigned int i = 0; i < n; ++i)
            z.local_element(i) = truncated[i] ? 0. : x[i];
        };

      // CG preconditioned with this step matrix's factor, if it has one
      // for the same truncated set
      Factor *factor = nullptr;
      for (auto &f : factors)
        if (f->key == system.matrix_key)
          factor = f.get();
      unsigned int solves = 0;
      if (factor != nullptr && factor->truncated == truncated &&
          control.tolerance > 0)
        {
          solves = cg.solve(
            system,
            rhs,
            c,
            [&](la::Vector &z, const la::Vector &r) { apply(*factor, z, r); },
            control);
          if (cg.relative_residual() <= control.tolerance)
            return solves;
        }

      // factorise the current matrix and solve with it
      if (factor == nullptr)
        {
          // a forgotten factor's object, a new one, or the oldest; moved
          // last (the newest)
          const auto free =
            std::find_if(factors.begin(), factors.end(), [](const auto &f) {
              return std::isnan(f->key);
            });
          if (free == factors.end() && factors.size() < 4)
            factors.push_back(std::make_unique<Factor>());
          else
            {
              const auto reused =
                free != factors.end() ? free : factors.begin();
              std::rotate(reused, reused + 1, factors.end());
            }
          factor      = factors.back().get();
          factor->key = system.matrix_key;
        }
      factor->truncated = truncated;
      fill_values(system);
      factor->cholesky.factorize(column_start, row_index, values);
      apply(*factor, c, rhs);
      return solves + 1;
    }
  } // namespace solvers
} // namespace rsfcycle
