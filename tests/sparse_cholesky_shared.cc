// SPDX-License-Identifier: LGPL-2.1-or-later
// solvers::SparseCholesky::factorize_shared(): the factor made once per
// node (by the node's first rank) and read by every rank of the node from
// an MPI shared-memory window, as the Green's-function operator uses it
// (physics::InteriorSolver). Run on 1 and on 2 ranks (the same output).
// Checked, on every rank (yes/no lines; the lines are the logical AND
// over the ranks):
//  - the solutions with the shared factor equal those of the rank's own
//    factor (factorize()) to the bit, one right-hand side and three at
//    once: the window holds the same factor;
//  - the residual |A x - b| / |b| is below 1e-12 (A: the 5-point Laplacian
//    of a 30 x 30 grid plus the identity, SPD);
//  - the factor's size (memory_bytes()) is the same on every rank and
//    equals the private factor's;
//  - a second factorize_shared() of another matrix (A + 2 I) frees the
//    first window and solves that matrix to 1e-12;
//  - a singular matrix (a zero row and column: a zero pivot) is refused
//    with std::runtime_error on every rank of the node, not only on the
//    one that factors it.
#include "tests.h"

#include <cmath>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <rsfcycle/solvers/sparse_cholesky.h>
#include <stdexcept>

using namespace dealii;
using rsfcycle::solvers::SparseCholesky;

namespace
{
  constexpr unsigned int grid = 30, n = grid * grid;

  /** The 5-point Laplacian of the grid plus `shift` times the identity. */
  void
  make_matrix(SparsityPattern &pattern, SparseMatrix<double> &A, double shift)
  {
    DynamicSparsityPattern dsp(n, n);
    const auto id = [](unsigned int i, unsigned int j) { return i * grid + j; };
    for (unsigned int i = 0; i < grid; ++i)
      for (unsigned int j = 0; j < grid; ++j)
        {
          dsp.add(id(i, j), id(i, j));
          if (i > 0)
            dsp.add(id(i, j), id(i - 1, j));
          if (i + 1 < grid)
            dsp.add(id(i, j), id(i + 1, j));
          if (j > 0)
            dsp.add(id(i, j), id(i, j - 1));
          if (j + 1 < grid)
            dsp.add(id(i, j), id(i, j + 1));
        }
    pattern.copy_from(dsp);
    A.reinit(pattern);
    for (unsigned int r = 0; r < n; ++r)
      for (auto e = pattern.begin(r); e != pattern.end(r); ++e)
        A.set(r, e->column(), e->column() == r ? 4. + shift : -1.);
  }

  double
  relative_residual(const SparseMatrix<double> &A,
                    const Vector<double>       &x,
                    const Vector<double>       &b)
  {
    Vector<double> r(n);
    A.vmult(r, x);
    r -= b;
    return r.l2_norm() / b.l2_norm();
  }

  /** true on every rank */
  bool
  all(const bool ok)
  {
    return Utilities::MPI::min(ok ? 1 : 0, MPI_COMM_WORLD) == 1;
  }

  std::string
  yes(const bool ok)
  {
    return all(ok) ? "yes" : "no";
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool first = SparseCholesky::first_on_node(MPI_COMM_WORLD);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    initlog();
  else
    deallog.depth_console(0);

  SparsityPattern      pattern;
  SparseMatrix<double> A;
  make_matrix(pattern, A, 1.);
  Vector<double>     b(n);
  FullMatrix<double> B(n, 3);
  for (unsigned int i = 0; i < n; ++i)
    {
      b[i] = std::sin(1. + i);
      for (unsigned int c = 0; c < 3; ++c)
        B(i, c) = std::cos(0.3 * i + c);
    }

  SparseCholesky own, shared;
  own.factorize(A);
  shared.factorize_shared(first ? &A : nullptr, MPI_COMM_WORLD);
  Vector<double>     x_own, x_shared;
  FullMatrix<double> X_own, X_shared;
  own.solve(b, x_own);
  shared.solve(b, x_shared);
  own.solve(B, X_own);
  shared.solve(B, X_shared);
  bool same = x_own.size() == n && x_shared.size() == n;
  for (unsigned int i = 0; same && i < n; ++i)
    {
      same = x_own[i] == x_shared[i];
      for (unsigned int c = 0; c < 3; ++c)
        same = same && X_own(i, c) == X_shared(i, c);
    }
  deallog << "shared factor's solutions equal the rank's own factor's to "
             "the bit (1 and 3 right-hand sides): "
          << yes(same) << std::endl;
  deallog << "residual below 1e-12: "
          << yes(relative_residual(A, x_shared, b) < 1e-12) << std::endl;
  const auto bytes = static_cast<double>(shared.memory_bytes());
  deallog << "factor's size the same on every rank and the private one's: "
          << yes(bytes > 0 &&
                 Utilities::MPI::max(bytes, MPI_COMM_WORLD) ==
                   Utilities::MPI::min(bytes, MPI_COMM_WORLD) &&
                 bytes == static_cast<double>(own.memory_bytes()))
          << std::endl;

  SparsityPattern      pattern2;
  SparseMatrix<double> A2;
  make_matrix(pattern2, A2, 3.);
  shared.factorize_shared(first ? &A2 : nullptr, MPI_COMM_WORLD);
  shared.solve(b, x_shared);
  deallog << "a second matrix factorised in place, residual below 1e-12: "
          << yes(relative_residual(A2, x_shared, b) < 1e-12) << std::endl;

  // row and column n/2 zero: a zero pivot, which CHOLMOD's simplicial
  // LDL^T (chosen for small matrices) detects as its supernodal LL^T does
  // (a negative diagonal it would not: LDL^T factors indefinite matrices)
  for (auto e = pattern2.begin(n / 2); e != pattern2.end(n / 2); ++e)
    {
      A2.set(n / 2, e->column(), 0.);
      A2.set(e->column(), n / 2, 0.);
    }
  bool refused = false;
  try
    {
      shared.factorize_shared(first ? &A2 : nullptr, MPI_COMM_WORLD);
    }
  catch (const std::runtime_error &)
    {
      refused = true;
    }
  deallog << "a singular matrix refused on every rank: " << yes(refused)
          << std::endl;
  return 0;
}
