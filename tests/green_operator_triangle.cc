// SPDX-License-Identifier: LGPL-2.1-or-later
// physics::GreenOperator::compress() and apply() on N ranks: the symmetric
// operator S stored as its lower triangle, split among the ranks by product
// rows that are not the ranks' own rows, the transposed blocks' sums
// reduced onto the own rows. Run on 1, 2 and 3 ranks (the same output); on
// 2 ranks the own rows are split 500 / 1100 (uneven), on 3 ranks 700 / 0 /
// 900 (the middle rank owns no row). S is the kernel 1 / (1 + r) of the
// nodes of a 40 x 40 grid (spacing 1), symmetric, compressed to 1e-8.
// Checked (yes/no lines, the AND over the ranks):
//  - apply() equals the dense product S x on the own rows to 1e-6 (the
//    2-norm over all rows relative to that of S x) for two slips, a
//    uniform one and an oscillating one: the triangle's diagonal and left
//    blocks, the left blocks' transposes and the reduce-scatter add up to
//    S;
//  - compress() reports a product error below 1e-6 on every rank;
//  - the product rows cover rows 0 ... n - 1, rank by rank, without gap
//    or overlap;
//  - the ranks' shares of the stored numbers are balanced: the largest at
//    most 1.3 times the mean (the split's correction, on one rank 1);
//  - all ranks together store less than the dense triangle n (n + 1) / 2;
//  - solvers::HierarchicalMatrix's transposed product (Tvmult) of a
//    non-symmetric 300 x 500 block equals the dense A^T x to 1e-6, and
//    vmult and Tvmult with `add` add to what y held;
//  - in single precision (tolerance 1e-5): apply() equals the dense S x to
//    3e-5 (the tolerance and float rounding), the reported error is below
//    3e-5, and the ranks store the same numbers as in double precision
//    compressed to 1e-5 in half the bytes (the blocks are compressed in
//    double either way).
#include "tests.h"

#include <cmath>
#include <rsfcycle/physics/green_operator.h>
#include <rsfcycle/solvers/hierarchical_matrix.h>

using namespace dealii;
using namespace rsfcycle;

namespace
{
  constexpr unsigned int grid = 40, n = grid * grid;

  double
  kernel(const std::vector<double> &p,
         const unsigned int         i,
         const std::vector<double> &q,
         const unsigned int         j)
  {
    return 1. /
           (1. + std::hypot(p[2 * i] - q[2 * j], p[2 * i + 1] - q[2 * j + 1]));
  }

  std::string
  yes(const bool ok)
  {
    return Utilities::MPI::min(ok ? 1 : 0, MPI_COMM_WORLD) == 1 ? "yes" : "no";
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int rank  = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const unsigned int ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  if (rank == 0)
    initlog();
  else
    deallog.depth_console(0);
  if (ranks > 3)
    throw std::runtime_error("this test runs on 1, 2 or 3 ranks");

  std::vector<double> points;
  for (unsigned int a = 0; a < grid; ++a)
    for (unsigned int b = 0; b < grid; ++b)
      points.insert(points.end(), {double(a), double(b)});

  // the own rows: uneven, and on 3 ranks the middle one owns none
  const std::vector<std::vector<unsigned int>> splits = {{0, n},
                                                         {0, 500, n},
                                                         {0, 700, 700, n}};
  const unsigned int                           first  = splits[ranks - 1][rank],
                     m = splits[ranks - 1][rank + 1] - first;

  // this rank's rows of S, compressed; and apply() against the dense
  // rows for two slips (the 2-norm over all ranks relative to that of S x)
  dealii::FullMatrix<double> dense(m, n);
  for (unsigned int i = 0; i < m; ++i)
    for (unsigned int j = 0; j < n; ++j)
      dense(i, j) = kernel(points, first + i, points, j);
  using Precision  = solvers::HierarchicalMatrix::Precision;
  const auto setup = [&](physics::GreenOperator &op,
                         const double            tolerance,
                         const Precision         precision) {
    op.S = dense;
    op.g0.reinit(m);
    op.g1.reinit(m);
    op.n_nodes   = n;
    op.first_row = first;
    return op.compress(points, 2, tolerance, MPI_COMM_WORLD, precision);
  };
  const auto products_within = [&](const physics::GreenOperator &op,
                                   const double                  bound) {
    bool within = true;
    for (unsigned int test = 0; test < 2; ++test)
      {
        std::vector<double> x(n), y(m);
        for (unsigned int j = 0; j < n; ++j)
          x[j] = test == 0 ? 1. : std::sin(0.37 * j) + std::cos(0.011 * j);
        op.apply(x.data(), y.data());
        double difference = 0, norm = 0;
        for (unsigned int i = 0; i < m; ++i)
          {
            double exact = 0;
            for (unsigned int j = 0; j < n; ++j)
              exact += dense(i, j) * x[j];
            difference += (y[i] - exact) * (y[i] - exact);
            norm += exact * exact;
          }
        difference = Utilities::MPI::sum(difference, MPI_COMM_WORLD);
        norm       = Utilities::MPI::sum(norm, MPI_COMM_WORLD);
        within     = within && std::sqrt(difference) <= bound * std::sqrt(norm);
      }
    return within;
  };

  physics::GreenOperator op;
  const double reported = setup(op, 1e-8, Precision::double_precision);
  deallog << "apply() equals the dense S x on the own rows to 1e-6 (two "
             "slips): "
          << yes(products_within(op, 1e-6)) << std::endl;
  deallog << "reported product error below 1e-6: " << yes(reported < 1e-6)
          << std::endl;

  const std::vector<unsigned int> begins =
    Utilities::MPI::all_gather(MPI_COMM_WORLD, op.product_begin);
  const std::vector<unsigned int> ends =
    Utilities::MPI::all_gather(MPI_COMM_WORLD, op.product_end);
  bool cover = begins.front() == 0 && ends.back() == n;
  for (unsigned int r = 0; r + 1 < ranks; ++r)
    cover = cover && ends[r] == begins[r + 1] && begins[r] <= ends[r];
  deallog << "the product rows cover 0 ... n - 1 rank by rank: " << yes(cover)
          << std::endl;

  const double stored = op.stored_entries();
  const double total  = Utilities::MPI::sum(stored, MPI_COMM_WORLD);
  deallog << "the largest share of the stored numbers at most 1.3 times the "
             "mean: "
          << yes(Utilities::MPI::max(stored, MPI_COMM_WORLD) <=
                 1.3 * total / ranks)
          << std::endl;
  deallog << "all ranks together store less than the dense triangle: "
          << yes(total < 0.5 * n * (n + 1.)) << std::endl;

  // a non-symmetric block: rows 300 nodes, columns 500 others
  {
    const unsigned int  rows = 300, columns = 500;
    std::vector<double> p(points.begin(), points.begin() + 2 * rows),
      q(points.begin() + 2 * 1000, points.begin() + 2 * (1000 + columns));
    const auto entry = [&](const unsigned int i, const unsigned int j) {
      return kernel(p, i, q, j) * (1. + 0.1 * i / rows);
    };
    const solvers::HierarchicalMatrix H(
      rows, columns, entry, p, q, 2, 1e-8, false);
    std::vector<double> x(rows), y(columns, 1.), exact(columns, 1.);
    for (unsigned int i = 0; i < rows; ++i)
      x[i] = std::cos(0.3 * i);
    for (unsigned int j = 0; j < columns; ++j)
      for (unsigned int i = 0; i < rows; ++i)
        exact[j] += entry(i, j) * x[i];
    H.Tvmult(x.data(), y.data(), true);
    double difference = 0, norm = 0;
    for (unsigned int j = 0; j < columns; ++j)
      {
        difference += (y[j] - exact[j]) * (y[j] - exact[j]);
        norm += exact[j] * exact[j];
      }
    bool transposed = std::sqrt(difference) <= 1e-6 * std::sqrt(norm);

    // vmult with add: y = 2 + A z for z = 1
    std::vector<double> z(columns, 1.), w(rows, 2.);
    H.vmult(z.data(), w.data(), true);
    for (unsigned int i = 0; i < rows; ++i)
      {
        double row = 2.;
        for (unsigned int j = 0; j < columns; ++j)
          row += entry(i, j);
        transposed = transposed && std::abs(w[i] - row) <= 1e-6 * row;
      }
    deallog << "the transposed product of a 300 x 500 block equals A^T x, "
               "and add adds: "
            << yes(transposed) << std::endl;
  }

  // single precision against double, both at 1e-5
  {
    physics::GreenOperator single, twin;
    const double           reported_single =
      setup(single, 1e-5, Precision::single_precision);
    setup(twin, 1e-5, Precision::double_precision);
    deallog << "single precision: apply() equals the dense S x to 3e-5: "
            << yes(products_within(single, 3e-5))
            << ", reported error below 3e-5: " << yes(reported_single < 3e-5)
            << ", the same numbers as double in half the bytes: "
            << yes(single.stored_entries() == twin.stored_entries() &&
                   2 * single.memory_consumption() == twin.memory_consumption())
            << std::endl;
  }
  return 0;
}
