// SPDX-License-Identifier: LGPL-2.1-or-later
// solvers::SparseCholesky::schur_complement(): the Schur complement
// S = C - B^T A^{-1} B of a symmetric positive definite M = [A B; B^T C]
// from a second factorisation of M with the trailing rows last
// (S = L_cc L_cc^T), as the direct linear correction forms it on the
// contact dofs. Checked (yes/no lines):
//  - closed form: the 1D Laplacian tridiag(-1, 2, -1) of 2k + 1 nodes with
//    the middle node trailing: two chains of k nodes whose inverse has
//    (A^{-1})_kk = k / (k + 1) at the end next to it, so S = 2 - 2 k / (k + 1)
//    = 2 / (k + 1), to 1e-13 for k = 1, 10, 1000;
//  - the 5-point Laplacian of a 30 x 30 grid plus the identity, with two
//    grid lines (60 dofs, coupled among themselves and to the rest)
//    trailing: S against one solve per trailing column and the dense
//    product (SparseCholesky::solve of B, then C - B^T X) to 1e-12 of its
//    largest entry; S symmetric to 1e-13 of it, and positive definite
//    (its Cholesky factorisation succeeds);
//  - no trailing rows: an empty S;
//  - refused: a matrix that is not positive definite (runtime_error), and a
//    call before factorize() (logic_error).
#include "tests.h"

#include <cmath>
#include <deal.II/lac/lapack_full_matrix.h>
#include <rsfcycle/solvers/sparse_cholesky.h>
#include <stdexcept>
#include <vector>

using namespace dealii;
using rsfcycle::solvers::SparseCholesky;

namespace
{
  /**
   * The upper triangle in compressed columns of the symmetric matrix whose
   * entries (row <= column) `entry(i, j)` gives (0 where absent), n x n.
   */
  struct Upper
  {
    std::vector<int>    p{0}, i;
    std::vector<double> x;
  };

  template <typename Entry>
  Upper
  upper(const unsigned int n, const Entry &entry)
  {
    Upper u;
    for (unsigned int j = 0; j < n; ++j)
      {
        for (const auto &[row, value] : entry(j))
          if (row <= j)
            {
              u.i.push_back(row);
              u.x.push_back(value);
            }
        u.p.push_back(u.i.size());
      }
    return u;
  }

  /** The leading n_A columns of u (A's upper triangle). */
  Upper
  leading(const Upper &u, const unsigned int n_A)
  {
    Upper a;
    a.p.assign(u.p.begin(), u.p.begin() + n_A + 1);
    a.i.assign(u.i.begin(), u.i.begin() + u.p[n_A]);
    a.x.assign(u.x.begin(), u.x.begin() + u.p[n_A]);
    return a;
  }

  std::string
  yes(const bool ok)
  {
    return ok ? "yes" : "no";
  }
} // namespace


int
main()
{
  initlog();

  // 1D chain: nodes 0 .. k-1 and k+1 .. 2k in A, the middle node k last
  for (const unsigned int k : {1u, 10u, 1000u})
    {
      const unsigned int n = 2 * k + 1;
      // position -> node: the middle node at the end
      std::vector<unsigned int> node(n), position(n);
      for (unsigned int q = 0, r = 0; r < n; ++r)
        if (r != k)
          node[q++] = r;
      node[n - 1] = k;
      for (unsigned int q = 0; q < n; ++q)
        position[node[q]] = q;
      const Upper    M = upper(n, [&](const unsigned int j) {
        std::vector<std::pair<unsigned int, double>> column{{j, 2.}};
        const unsigned int                           r = node[j];
        if (r > 0)
          column.emplace_back(position[r - 1], -1.);
        if (r + 1 < n)
          column.emplace_back(position[r + 1], -1.);
        return column;
      });
      const Upper    A = leading(M, n - 1);
      SparseCholesky cholesky;
      cholesky.factorize(A.p, A.i, A.x);
      LAPACKFullMatrix<double> S;
      cholesky.schur_complement(M.p, M.i, M.x, S);
      deallog << "chain of 2 x " << k << " nodes: S = 2 / (k + 1) to 1e-13: "
              << yes(S.m() == 1 && std::abs(S(0, 0) - 2. / (k + 1)) < 1e-13)
              << std::endl;
    }

  // 30 x 30 grid, the lines i = 10 and i = 20 trailing
  constexpr unsigned int    grid = 30, n = grid * grid;
  std::vector<unsigned int> node, position(n);
  for (const bool trailing : {false, true})
    for (unsigned int i = 0; i < grid; ++i)
      for (unsigned int j = 0; j < grid; ++j)
        if ((i == 10 || i == 20) == trailing)
          node.push_back(i * grid + j);
  for (unsigned int q = 0; q < n; ++q)
    position[node[q]] = q;
  const unsigned int n_c = 2 * grid, n_A = n - n_c;
  const auto         column = [&](const unsigned int j, const double shift) {
    const unsigned int r = node[j], i = r / grid, l = r % grid;
    std::vector<std::pair<unsigned int, double>> c{{j, 4. + shift}};
    if (i > 0)
      c.emplace_back(position[r - grid], -1.);
    if (i + 1 < grid)
      c.emplace_back(position[r + grid], -1.);
    if (l > 0)
      c.emplace_back(position[r - 1], -1.);
    if (l + 1 < grid)
      c.emplace_back(position[r + 1], -1.);
    return c;
  };
  const Upper M = upper(n, [&](const unsigned int j) { return column(j, 1.); });
  const Upper A = leading(M, n_A);
  SparseCholesky cholesky;
  cholesky.factorize(A.p, A.i, A.x);
  LAPACKFullMatrix<double> S;
  cholesky.schur_complement(M.p, M.i, M.x, S);

  // reference: X = A^{-1} B by one solve per column, S = C - B^T X
  FullMatrix<double> B(n_A, n_c), C(n_c, n_c), X;
  for (unsigned int j = n_A; j < n; ++j)
    for (const auto &[row, value] : column(j, 1.))
      if (row < n_A)
        B(row, j - n_A) = value;
      else
        C(row - n_A, j - n_A) = value;
  cholesky.solve(B, X);
  FullMatrix<double> reference(n_c, n_c);
  B.Tmmult(reference, X);
  reference *= -1.;
  reference.add(1., C);
  double largest = 0, difference = 0, asymmetry = 0;
  for (unsigned int a = 0; a < n_c; ++a)
    for (unsigned int b = 0; b < n_c; ++b)
      {
        largest    = std::max(largest, std::abs(reference(a, b)));
        difference = std::max(difference, std::abs(S(a, b) - reference(a, b)));
        asymmetry  = std::max(asymmetry, std::abs(S(a, b) - S(b, a)));
      }
  bool positive = true;
  try
    {
      LAPACKFullMatrix<double> factor = S;
      factor.set_property(LAPACKSupport::symmetric);
      factor.compute_cholesky_factorization();
    }
  catch (...)
    {
      positive = false;
    }
  deallog << "grid 30 x 30, 60 trailing dofs: S against one solve per "
             "column to 1e-12: "
          << yes(S.m() == n_c && S.n() == n_c && difference < 1e-12 * largest)
          << ", symmetric to 1e-13: " << yes(asymmetry < 1e-13 * largest)
          << ", positive definite: " << yes(positive) << std::endl;

  // no trailing rows
  LAPACKFullMatrix<double> empty;
  cholesky.schur_complement(A.p, A.i, A.x, empty);
  deallog << "no trailing rows: S empty: " << yes(empty.m() == 0) << std::endl;

  // refusals
  const Upper indefinite =
    upper(n, [&](const unsigned int j) { return column(j, -6.); });
  bool refused = false;
  try
    {
      LAPACKFullMatrix<double> T;
      cholesky.schur_complement(indefinite.p, indefinite.i, indefinite.x, T);
    }
  catch (const std::runtime_error &)
    {
      refused = true;
    }
  deallog << "a matrix that is not positive definite refused: " << yes(refused)
          << std::endl;
  refused = false;
  try
    {
      SparseCholesky           none;
      LAPACKFullMatrix<double> T;
      none.schur_complement(M.p, M.i, M.x, T);
    }
  catch (const std::logic_error &)
    {
      refused = true;
    }
  deallog << "before factorize(): refused: " << yes(refused) << std::endl;
}
