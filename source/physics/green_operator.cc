// The fault's Green's functions from the assembled stiffness
// (physics/green_operator.h, MODEL.md §8.1).
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
      if (compressed)
        return compressed->vmult(slip, force);
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


    double
    GreenOperator::compress(const std::vector<double> &points,
                            const unsigned int         dim,
                            const double               tolerance)
    {
      const unsigned int        m = S.m(), n = S.n();
      const std::vector<double> rows(points.begin() + dim * first_row,
                                     points.begin() + dim * (first_row + m));
      // (S symmetric: on one rank its rows are all rows, and half is kept)
      compressed = std::make_shared<const solvers::HierarchicalMatrix>(
        S, rows, points, dim, tolerance, rows == points);
      normal_negligible =
        normal_coupling && N.frobenius_norm() <= 1e-10 * S.frobenius_norm();
      if (normal_coupling && !normal_negligible)
        compressed_normal = std::make_shared<const solvers::HierarchicalMatrix>(
          N, rows, points, dim, tolerance, false);
      std::vector<double> x(n), dense(m), h(m);
      double              error = 0;
      for (const auto &[A, H] : {std::make_pair(&S, compressed.get()),
                                 std::make_pair(&N, compressed_normal.get())})
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
            H->vmult(x.data(), h.data());
            double diff = 0, norm = 0;
            for (unsigned int r = 0; r < m; ++r)
              {
                diff += (h[r] - dense[r]) * (h[r] - dense[r]);
                norm += dense[r] * dense[r];
              }
            error = std::max(error, std::sqrt(diff / norm));
          }
      return error;
    }


    void
    GreenOperator::release_dense()
    {
      if (!compressed)
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
