// SPDX-License-Identifier: LGPL-2.1-or-later
// The fault's Green's functions from the assembled stiffness
// (physics/green_operator.h, doc/model.md §8.1).
#include <algorithm>
#include <boost/crc.hpp>
#include <cmath>
#include <rsfcycle/physics/green_operator.h>
#include <rsfcycle/physics/interior_solver.h>
#include <stdexcept>

namespace rsfcycle
{
  namespace physics
  {
    GreenOperator
    compute_green_operator(const GlobalSystem &K,
                           const MPI_Comm      communicator,
                           const unsigned int  block_size)
    {
      const std::vector<bool> &fixed = K.fixed;
      const unsigned int       n     = K.n();
      const unsigned int       n_c   = K.contact_dofs.size();
      const unsigned int       n_o   = K.observations.size();
      // the observation rows, then the normal rows (as many as contact
      // dofs, or none): computed alike
      const unsigned int n_rows = n_o + K.normal_rows.size();
      const auto         row_of =
        [&K, n_o](const unsigned int p) -> const ObservationRow & {
        return p < n_o ? K.observations[p] : K.normal_rows[p - n_o];
      };
      const unsigned int rank  = Utilities::MPI::this_mpi_process(communicator);
      const unsigned int first = K.rank_offsets[rank];
      const unsigned int n_own = K.rank_offsets[rank + 1] - first;
      const auto        &contact_dofs = K.contact_dofs;

      // the contact's dofs (c); the unknowns besides them and the fixed
      // ones (I) and the Cholesky factor of K_II
      std::vector<int> contact_index(n, -1);
      for (unsigned int k = 0; k < n_c; ++k)
        contact_index[contact_dofs[k]] = k;
      const InteriorSolver interior(K, communicator);
      const unsigned int   n_I            = interior.n_interior();
      const auto           interior_index = [&interior](const unsigned int i) {
        return interior.interior_index(i);
      };

      GreenOperator op;
      op.n_interior       = n_I;
      op.factor_megabytes = 1e-6 * interior.factor_bytes();
      op.n_nodes          = n_c;
      op.first_row        = first;

      // The loads: the force f (body force and shear prestress) and the
      // prescribed velocity v_b of the fixed dofs (zero but on loads).
      const auto &f   = K.force;
      const auto &v_b = K.fixed_velocity;
      // sum over the fixed columns j of row i of K: K_ij v_b,j
      const auto K_fixed_v = [&](const unsigned int i) {
        double sum = 0;
        for (auto e = K.row_begin(i); e < K.row_end(i); ++e)
          if (fixed[K.columns[e]])
            sum += K.values[e] * v_b[K.columns[e]];
        return sum;
      };

      // Z = K_II^-1 [f_I, -K_Ib v_b]
      {
        dealii::FullMatrix<double> B(n_I, 2), Z;
        for (unsigned int k = 0; k < n_I; ++k)
          {
            B(k, 0) = f[interior.interior_dof(k)];
            B(k, 1) = -K_fixed_v(interior.interior_dof(k));
          }
        interior.solve(B, Z);
        ++op.n_blocks;
        op.g0.reinit(n_own);
        op.g1.reinit(n_own);
        for (unsigned int r = 0; r < n_own; ++r)
          {
            const unsigned int row = contact_dofs[first + r];
            op.g0[r]               = f[row];
            op.g1[r]               = -K_fixed_v(row);
            for (auto e = K.row_begin(row); e < K.row_end(row); ++e)
              if (const int i = interior_index(K.columns[e]); i >= 0)
                {
                  op.g0[r] -= K.values[e] * Z(i, 0);
                  op.g1[r] -= K.values[e] * Z(i, 1);
                }
          }
        dealii::Vector<double> o0(n_rows), o1(n_rows);
        for (unsigned int p = 0; p < n_rows; ++p)
          for (const auto &[j, w] : row_of(p))
            if (const int i = interior_index(j); i >= 0)
              {
                o0[p] += w * Z(i, 0);
                o1[p] += w * Z(i, 1);
              }
            else if (fixed[j])
              o1[p] += w * v_b[j];
        op.o0.reinit(n_o);
        op.o1.reinit(n_o);
        op.n0.reinit(K.normal_rows.empty() ? 0 : n_own);
        op.n1.reinit(op.n0.size());
        for (unsigned int p = 0; p < n_o; ++p)
          {
            op.o0[p] = o0[p];
            op.o1[p] = o1[p];
          }
        for (unsigned int r = 0; r < op.n0.size(); ++r)
          {
            op.n0[r] = o0[n_o + first + r];
            op.n1[r] = o1[n_o + first + r];
          }
      }

      // This rank's rows of S (S symmetric: the columns of its nodes) and
      // its columns of O, block_size at a time: X = K_II^-1 K_Ic
      op.S.reinit(n_own, n_c);
      dealii::FullMatrix<double> O(n_rows, n_c);
      for (unsigned int b0 = first; b0 < first + n_own; b0 += block_size)
        {
          const unsigned int nb = std::min(block_size, first + n_own - b0);
          dealii::FullMatrix<double> B(n_I, nb), X;
          // K symmetric: column j of K_Ic is row c_j restricted to I
          for (unsigned int jj = 0; jj < nb; ++jj)
            {
              const unsigned int row = contact_dofs[b0 + jj];
              for (auto e = K.row_begin(row); e < K.row_end(row); ++e)
                if (const int i = interior_index(K.columns[e]); i >= 0)
                  B(i, jj) = K.values[e];
            }
          interior.solve(B, X);
          ++op.n_blocks;
          for (unsigned int r = 0; r < n_c; ++r)
            {
              const unsigned int row = contact_dofs[r];
              for (auto e = K.row_begin(row); e < K.row_end(row); ++e)
                {
                  const unsigned int col = K.columns[e];
                  if (const int i = interior_index(col); i >= 0)
                    for (unsigned int jj = 0; jj < nb; ++jj)
                      op.S(b0 + jj - first, r) -= K.values[e] * X(i, jj);
                  else if (const int q = contact_index[col];
                           q >= static_cast<int>(b0) &&
                           q < static_cast<int>(b0 + nb))
                    op.S(q - first, r) += K.values[e];
                }
            }
          for (unsigned int p = 0; p < n_rows; ++p)
            for (const auto &[j, w] : row_of(p))
              if (const int i = interior_index(j); i >= 0)
                for (unsigned int jj = 0; jj < nb; ++jj)
                  O(p, b0 + jj) -= w * X(i, jj);
              else if (const int q = contact_index[j];
                       q >= static_cast<int>(b0) &&
                       q < static_cast<int>(b0 + nb))
                O(p, q) += w;
        }
      // every rank filled its nodes' columns of O (and N)
      dealii::FullMatrix<double> sum(n_rows, n_c);
      Utilities::MPI::sum(O, communicator, sum);
      op.O.reinit(n_o, n_c);
      op.O.fill(sum, 0, 0, 0, 0);
      op.normal_coupling = !K.normal_rows.empty();
      if (op.normal_coupling)
        {
          op.N.reinit(n_own, n_c);
          op.N.fill(sum, 0, 0, n_o + first, 0);
        }
      return op;
    }


    void
    GreenOperator::apply(const double *slip, double *force) const
    {
      if (is_compressed())
        {
          // this rank's part of the triangle: S(P, P) x_P and S(P, L) x_L
          // on the rows P, S(P, L)^T x_P on the rows L left of them (on
          // one rank straight into force, which then holds every row)
          const bool one_rank = row_counts.size() == 1;
          if (!one_rank)
            product_work.resize(n_nodes);
          double *z = one_rank ? force : product_work.data();
          std::fill(z, z + n_nodes, 0.);
          if (compressed)
            compressed->vmult(slip + product_begin, z + product_begin);
          if (compressed_left)
            {
              compressed_left->vmult(slip, z + product_begin, true);
              compressed_left->Tvmult(slip + product_begin, z, true);
            }
          if (!one_rank && MPI_Reduce_scatter(z,
                                              force,
                                              row_counts.data(),
                                              MPI_DOUBLE,
                                              MPI_SUM,
                                              communicator) != MPI_SUCCESS)
            throw std::runtime_error("the product with S: MPI failed");
          return;
        }
      const unsigned int n = S.n();
      for (unsigned int r = 0; r < S.m(); ++r)
        {
          const double *row = &S(r, 0);
          double        sum = 0;
#pragma omp simd reduction(+ : sum)
          for (unsigned int j = 0; j < n; ++j)
            sum += row[j] * slip[j];
          force[r] = sum;
        }
    }


    void
    GreenOperator::apply_normal(const double *slip,
                                const double  t,
                                double       *force) const
    {
      if (normal_negligible)
        std::fill(force, force + n0.size(), 0.);
      else if (compressed_normal)
        compressed_normal->vmult(slip, force);
      else
        {
          const unsigned int n = N.n();
          for (unsigned int r = 0; r < N.m(); ++r)
            {
              const double *row = &N(r, 0);
              double        sum = 0;
#pragma omp simd reduction(+ : sum)
              for (unsigned int j = 0; j < n; ++j)
                sum += row[j] * slip[j];
              force[r] = sum;
            }
        }
      for (unsigned int r = 0; r < n0.size(); ++r)
        force[r] += n0[r] + t * n1[r];
    }


    std::size_t
    GreenOperator::stored_entries() const
    {
      return (compressed ? compressed->stored_entries() : 0) +
             (compressed_left ? compressed_left->stored_entries() : 0);
    }


    std::size_t
    GreenOperator::n_low_rank_blocks() const
    {
      return (compressed ? compressed->n_low_rank_blocks() : 0) +
             (compressed_left ? compressed_left->n_low_rank_blocks() : 0);
    }


    std::size_t
    GreenOperator::memory_consumption() const
    {
      return (compressed ? compressed->memory_consumption() : 0) +
             (compressed_left ? compressed_left->memory_consumption() : 0);
    }


    std::size_t
    GreenOperator::n_dense_blocks() const
    {
      return (compressed ? compressed->n_dense_blocks() : 0) +
             (compressed_left ? compressed_left->n_dense_blocks() : 0);
    }


    double
    GreenOperator::compress(
      const std::vector<double>                   &points,
      const unsigned int                           dim,
      const double                                 tolerance,
      const MPI_Comm                               mpi_communicator,
      const solvers::HierarchicalMatrix::Precision precision)
    {
      communicator = mpi_communicator;
      // (n_nodes, not S.n(): a rank without contact nodes has an empty S,
      // which deal.II gives no columns either)
      const unsigned int m = S.m(), n = n_nodes;
      const unsigned int rank  = Utilities::MPI::this_mpi_process(communicator);
      const unsigned int ranks = Utilities::MPI::n_mpi_processes(communicator);
      const std::vector<unsigned int> counts =
        Utilities::MPI::all_gather(communicator, m);
      row_counts.assign(counts.begin(), counts.end());
      std::vector<unsigned int> own_offsets(ranks + 1, 0);
      for (unsigned int r = 0; r < ranks; ++r)
        own_offsets[r + 1] = own_offsets[r] + counts[r];

      const unsigned int own_begin = own_offsets[rank];
      const auto         owns_row  = [&](const unsigned int i) {
        return i >= own_begin && i < own_begin + m;
      };
      const auto points_of = [&](const unsigned int begin,
                                 const unsigned int end) {
        return std::vector<double>(points.begin() + dim * begin,
                                   points.begin() + dim * end);
      };

      // Compress this rank's part of the triangle for the product rows
      // `offsets` (rank r's rows offsets[r] ... offsets[r + 1] - 1)
      const auto compress_split = [&](
                                    const std::vector<unsigned int> &offsets) {
        product_begin                = offsets[rank];
        product_end                  = offsets[rank + 1];
        const unsigned int n_product = product_end - product_begin;

        // the rows of P that other ranks own, their columns 0 ...
        // product_end - 1, sent by their owners (row by row, in order)
        std::vector<int>         foreign_row(n_product, -1);
        std::vector<MPI_Request> requests;
        for (unsigned int i = product_begin; i < product_end; ++i)
          if (!owns_row(i))
            {
              foreign_row[i - product_begin] = requests.size();
              requests.emplace_back();
            }
        std::vector<double> foreign(requests.size() * std::size_t(product_end));
        for (unsigned int i = product_begin, k = 0; i < product_end; ++i)
          if (!owns_row(i))
            {
              const unsigned int owner =
                std::upper_bound(own_offsets.begin(), own_offsets.end(), i) -
                own_offsets.begin() - 1;
              MPI_Irecv(foreign.data() + std::size_t(k) * product_end,
                        product_end,
                        MPI_DOUBLE,
                        owner,
                        0,
                        communicator,
                        &requests[k]);
              ++k;
            }
        for (unsigned int r = 0; r < ranks; ++r)
          if (r != rank)
            for (unsigned int i = std::max(own_begin, offsets[r]);
                 i < std::min(own_begin + m, offsets[r + 1]);
                 ++i)
              {
                requests.emplace_back();
                MPI_Isend(&S(i - own_begin, 0),
                          offsets[r + 1],
                          MPI_DOUBLE,
                          r,
                          0,
                          communicator,
                          &requests.back());
              }
        if (MPI_Waitall(requests.size(),
                        requests.data(),
                        MPI_STATUSES_IGNORE) != MPI_SUCCESS)
          throw std::runtime_error("compressing S: MPI failed");
        const auto entry = [&](const unsigned int i, const unsigned int j) {
          return owns_row(i) ?
                   S(i - own_begin, j) :
                   foreign[std::size_t(foreign_row[i - product_begin]) *
                             product_end +
                           j];
        };

        const std::vector<double> product_points =
          points_of(product_begin, product_end);
        compressed.reset();
        compressed_left.reset();
        if (n_product > 0)
          compressed = std::make_shared<const solvers::HierarchicalMatrix>(
            n_product,
            n_product,
            [&](const unsigned int i, const unsigned int j) {
              return entry(product_begin + i, product_begin + j);
            },
            product_points,
            product_points,
            dim,
            tolerance,
            true,
            precision);
        if (n_product > 0 && product_begin > 0)
          compressed_left = std::make_shared<const solvers::HierarchicalMatrix>(
            n_product,
            product_begin,
            [&](const unsigned int i, const unsigned int j) {
              return entry(product_begin + i, j);
            },
            product_points,
            points_of(0, product_begin),
            dim,
            tolerance,
            false,
            precision);
      };

      // The product rows, so that the ranks hold equal shares of the
      // compressed triangle. First a model: the triangle of the rows 0 ...
      // k - 1 of an H-matrix of a kernel that decays with distance holds
      // about k log k numbers (a dense one k^2 / 2, whose split would put
      // 71 % of the rows on the first of two ranks, and there 64 % of the
      // compressed numbers at BP5's 1 km), so rank r's rows end at p with
      // p log p = ((r + 1) / ranks) n log n. Then, on more than one rank,
      // once more at the shares the first split measured, each rank's
      // numbers spread evenly over its rows (BP5 at 1 km on 2 ranks: 57 %
      // of the numbers on the first rank after the model, 50.6 % after the
      // correction).
      const auto cost = [](const double k) { return k * std::log(k + 2.); };
      std::vector<unsigned int> offsets(ranks + 1, n);
      for (unsigned int r = 0; r < ranks; ++r)
        {
          const double target = cost(n) * r / ranks;
          unsigned int low = 0, high = n;
          while (low < high)
            {
              const unsigned int middle = (low + high) / 2;
              if (cost(middle) < target)
                low = middle + 1;
              else
                high = middle;
            }
          offsets[r] = low;
        }
      compress_split(offsets);
      if (ranks > 1)
        {
          const std::vector<double> shares =
            Utilities::MPI::all_gather(communicator, double(stored_entries()));
          std::vector<double> cumulative(ranks + 1, 0.);
          for (unsigned int r = 0; r < ranks; ++r)
            cumulative[r + 1] = cumulative[r] + shares[r];
          std::vector<unsigned int> balanced(offsets);
          for (unsigned int r = 1, q = 0; r < ranks; ++r)
            {
              const double target = cumulative[ranks] * r / ranks;
              while (q + 1 < ranks && cumulative[q + 1] < target)
                ++q;
              const double fraction =
                shares[q] > 0 ? (target - cumulative[q]) / shares[q] : 0.;
              balanced[r] =
                offsets[q] + static_cast<unsigned int>(std::lround(
                               fraction * (offsets[q + 1] - offsets[q])));
            }
          if (balanced != offsets)
            compress_split(balanced);
        }

      const std::vector<double> rows = points_of(own_begin, own_begin + m);
      normal_negligible =
        normal_coupling && N.frobenius_norm() <= 1e-10 * S.frobenius_norm();
      if (normal_coupling && !normal_negligible)
        compressed_normal = std::make_shared<const solvers::HierarchicalMatrix>(
          N, rows, points, dim, tolerance, false, precision);
      std::vector<double> x(n), dense(m), h(m);
      double              error = 0;
      // (the product with S is collective: every rank runs both tests)
      for (const auto &[A, H] :
           {std::make_pair(&S, true),
            std::make_pair(&N, compressed_normal != nullptr)})
        for (unsigned int test = 0; H && test < 2; ++test)
          {
            // a uniform slip; a reproducible pseudo-random one in [-1, 1]
            std::uint32_t seed = 12345;
            for (auto &xi : x)
              {
                seed = 1664525u * seed + 1013904223u;
                xi   = test == 0 ? 1. : seed / 2147483648. - 1.;
              }
            for (unsigned int r = 0; r < m; ++r)
              {
                dense[r] = 0;
                for (unsigned int j = 0; j < n; ++j)
                  dense[r] += (*A)(r, j) * x[j];
              }
            if (A == &S)
              apply(x.data(), h.data());
            else
              compressed_normal->vmult(x.data(), h.data());
            double diff = 0, norm = 0;
            for (unsigned int r = 0; r < m; ++r)
              {
                diff += (h[r] - dense[r]) * (h[r] - dense[r]);
                norm += dense[r] * dense[r];
              }
            error = std::max(error, norm > 0 ? std::sqrt(diff / norm) : 0.);
          }
      return error;
    }


    void
    GreenOperator::release_dense()
    {
      if (!is_compressed())
        throw std::logic_error("release_dense() before compress()");
      S = dealii::FullMatrix<double>();
      if (compressed_normal || normal_negligible)
        N = dealii::FullMatrix<double>();
    }


    std::uint32_t
    operator_fingerprint(const GlobalSystem &K)
    {
      boost::crc_32_type crc;
      const auto add = [&](const auto x) { crc.process_bytes(&x, sizeof x); };
      add(static_cast<std::uint64_t>(K.n()));
      for (unsigned int i = 0; i < K.n(); ++i)
        {
          add(static_cast<std::uint8_t>(K.fixed[i]));
          add(K.force[i]);
          add(K.fixed_velocity[i]);
          for (auto e = K.row_begin(i); e < K.row_end(i); ++e)
            {
              add(static_cast<std::uint32_t>(K.columns[e]));
              add(K.values[e]);
            }
        }
      for (const unsigned int dof : K.contact_dofs)
        add(static_cast<std::uint32_t>(dof));
      for (const unsigned int offset : K.rank_offsets)
        add(static_cast<std::uint32_t>(offset));
      for (const auto *list : {&K.observations, &K.normal_rows})
        for (const auto &row : *list)
          {
            add(static_cast<std::uint64_t>(row.size()));
            for (const auto &[j, w] : row)
              {
                add(static_cast<std::uint64_t>(j));
                add(w);
              }
          }
      return crc.checksum();
    }


  } // namespace physics
} // namespace rsfcycle
