// SPDX-License-Identifier: LGPL-2.1-or-later
#include <algorithm>
#include <array>
#include <cholmod.h>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <rsfcycle/solvers/sparse_cholesky.h>
#ifdef RSFCYCLE_WITH_OPENMP
#  include <omp.h>
#endif
#include <stdexcept>
#include <vector>

namespace rsfcycle
{
  namespace solvers
  {
    namespace
    {
      /**
       * CHOLMOD runs parts of its supernodal factorisation in OpenMP
       * regions of a fixed 4 threads (CHOLMOD_OMP_NUM_THREADS), whatever
       * OMP_NUM_THREADS says. MPI ranks are rsfcycle's parallelism, so
       * those threads only compete with the ranks for the cores (and spin
       * while they wait): a small factor solved at every step ran 2.6 times
       * slower with them on an otherwise idle machine. Unless the user
       * configures OpenMP (OMP_NUM_THREADS, OMP_THREAD_LIMIT or
       * OMP_MAX_ACTIVE_LEVELS in the environment), every OpenMP region runs
       * on the calling thread (no active parallel levels).
       */
      void
      keep_openmp_on_one_thread()
      {
#ifdef RSFCYCLE_WITH_OPENMP
        static std::once_flag once;
        std::call_once(once, [] {
          if (std::getenv("OMP_NUM_THREADS") == nullptr &&
              std::getenv("OMP_THREAD_LIMIT") == nullptr &&
              std::getenv("OMP_MAX_ACTIVE_LEVELS") == nullptr)
            omp_set_max_active_levels(0);
        });
#endif
      }
    } // namespace


    struct SparseCholesky::Data
    {
      cholmod_common  common;
      cholmod_factor *factor = nullptr;
      std::size_t     n      = 0;
      // the upper triangle's pattern (column starts, row indices) that
      // `factor` was analysed for: a matrix of the same pattern is only
      // factorised numerically (the fill-reducing ordering and the
      // supernodal structure are kept)
      std::vector<int> analysed_p, analysed_i;
      // a factor shared by the ranks of a node (factorize_shared()): its
      // arrays in the MPI window, `factor` points to `view`
      MPI_Win        window = MPI_WIN_NULL;
      MPI_Comm       node   = MPI_COMM_NULL;
      cholmod_factor view;

      Data()
      {
        keep_openmp_on_one_thread();
        cholmod_start(&common);
        common.print = 0;
      }
      ~Data()
      {
        release();
        cholmod_finish(&common);
      }

      /** Free the factor (collective on the node if it is shared). */
      void
      release()
      {
        if (window != MPI_WIN_NULL)
          {
            MPI_Win_free(&window);
            MPI_Comm_free(&node);
            factor = nullptr;
          }
        if (factor != nullptr)
          cholmod_free_factor(&factor, &common);
      }

      cholmod_dense *
      solve(const double *b, const std::size_t n_rhs)
      {
        cholmod_dense *B =
          cholmod_allocate_dense(n, n_rhs, n, CHOLMOD_REAL, &common);
        std::copy(b, b + n * n_rhs, static_cast<double *>(B->x));
        cholmod_dense *X = cholmod_solve(CHOLMOD_A, factor, B, &common);
        cholmod_free_dense(&B, &common);
        if (X == nullptr)
          throw std::runtime_error("CHOLMOD solve failed");
        return X;
      }
    };


    namespace
    {
      /** A CHOLMOD copy of the upper triangle in compressed columns. */
      cholmod_sparse *
      upper_triangle(const std::vector<int>    &p,
                     const std::vector<int>    &i,
                     const std::vector<double> &x,
                     cholmod_common            &common)
      {
        const std::size_t n = p.size() - 1;
        cholmod_sparse   *S = cholmod_allocate_sparse(n,
                                                    n,
                                                    x.size(),
                                                    /*sorted*/ 0,
                                                    /*packed*/ 1,
                                                    /*stype*/ 1,
                                                    CHOLMOD_REAL,
                                                    &common);
        std::copy(p.begin(), p.end(), static_cast<int *>(S->p));
        std::copy(i.begin(), i.end(), static_cast<int *>(S->i));
        std::copy(x.begin(), x.end(), static_cast<double *>(S->x));
        return S;
      }
    } // namespace


    SparseCholesky::SparseCholesky()
      : data(std::make_unique<Data>())
    {}


    SparseCholesky::~SparseCholesky() = default;


    void
    SparseCholesky::factorize(const dealii::SparseMatrix<double> &A)
    {
      // Upper triangle in compressed-column form: for a symmetric matrix,
      // column j holds the entries of row j with column index <= j.
      std::vector<int>    p(1, 0), i;
      std::vector<double> x;
      for (std::size_t j = 0; j < A.m(); ++j)
        {
          for (auto it = A.begin(j); it != A.end(j); ++it)
            if (it->column() <= j)
              {
                i.push_back(it->column());
                x.push_back(it->value());
              }
          p.push_back(i.size());
        }
      factorize(p, i, x);
    }


    void
    SparseCholesky::factorize(const std::vector<int>    &p,
                              const std::vector<int>    &i,
                              const std::vector<double> &x)
    {
      const std::size_t n = p.size() - 1;
      cholmod_sparse   *S = upper_triangle(p, i, x, data->common);

      const bool same_pattern = data->factor != nullptr &&
                                p == data->analysed_p && i == data->analysed_i;
      if (!same_pattern)
        {
          data->release();
          data->factor     = cholmod_analyze(S, &data->common);
          data->analysed_p = p;
          data->analysed_i = i;
        }
      cholmod_factorize(S, data->factor, &data->common);
      const int status = data->common.status;
      cholmod_free_sparse(&S, &data->common);
      if (status != CHOLMOD_OK || data->factor->minor < n)
        throw std::runtime_error(
          "CHOLMOD: the matrix is not positive definite");
      data->n = n;
    }


    namespace
    {
      /**
       * The arrays of a CHOLMOD factor (simplicial or supernodal, integer
       * indices): each field's address, its length and its entry's size.
       */
      std::array<std::tuple<void **, std::size_t, std::size_t>, 12>
      factor_arrays(cholmod_factor &L)
      {
        const std::size_t i = sizeof(int), d = sizeof(double);
        return {{{&L.Perm, L.n, i},
                 {&L.ColCount, L.n, i},
                 {&L.p, L.n + 1, i},
                 {&L.i, L.nzmax, i},
                 {&L.x, L.is_super ? L.xsize : L.nzmax, d},
                 {&L.nz, L.n, i},
                 {&L.next, L.n + 2, i},
                 {&L.prev, L.n + 2, i},
                 {&L.super, L.nsuper + 1, i},
                 {&L.pi, L.nsuper + 1, i},
                 {&L.px, L.nsuper + 1, i},
                 {&L.s, L.ssize, i}}};
      }
    } // namespace


    bool
    SparseCholesky::first_on_node(const MPI_Comm communicator)
    {
      MPI_Comm node;
      MPI_Comm_split_type(
        communicator, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
      int node_rank = 0;
      MPI_Comm_rank(node, &node_rank);
      MPI_Comm_free(&node);
      return node_rank == 0;
    }


    void
    SparseCholesky::factorize_shared(const dealii::SparseMatrix<double> *A,
                                     const MPI_Comm communicator)
    {
      data->release();
      data->analysed_p.clear();
      data->analysed_i.clear();
      MPI_Comm &node = data->node;
      MPI_Comm_split_type(
        communicator, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
      int node_rank = 0;
      MPI_Comm_rank(node, &node_rank);
      if ((node_rank == 0) != (A != nullptr))
        throw std::logic_error(
          "SparseCholesky::factorize_shared: the matrix is given on the "
          "node's first rank, and only there");

      // the node's first rank factorises; the header and which arrays it
      // has go to the others
      int status = 0;
      if (node_rank == 0)
        try
          {
            factorize(*A);
            if (data->factor->itype != CHOLMOD_INT ||
                data->factor->xtype != CHOLMOD_REAL)
              throw std::runtime_error("CHOLMOD: an unexpected factor type");
          }
        catch (...)
          {
            status = 1;
            MPI_Bcast(&status, 1, MPI_INT, 0, node);
            throw;
          }
      MPI_Bcast(&status, 1, MPI_INT, 0, node);
      if (status != 0)
        throw std::runtime_error(
          "CHOLMOD: the matrix is not positive definite");
      cholmod_factor &view = data->view;
      if (node_rank == 0)
        view = *data->factor;
      MPI_Bcast(&view, sizeof(view), MPI_BYTE, 0, node);
      data->n = view.n;

      // one window of all arrays, each at a multiple of 64 bytes, filled by
      // the first rank (which then frees its own copy)
      const auto          arrays = factor_arrays(view);
      std::vector<char>   present(arrays.size());
      std::vector<size_t> offset(arrays.size() + 1, 0);
      for (unsigned int a = 0; a < arrays.size(); ++a)
        {
          const auto &[field, count, size] = arrays[a];
          present[a]                       = *field != nullptr;
          offset[a + 1] =
            offset[a] + (present[a] ? (count * size + 63) / 64 * 64 : 0);
        }
      char *base = nullptr;
      MPI_Win_allocate_shared(node_rank == 0 ? offset.back() : 0,
                              1,
                              MPI_INFO_NULL,
                              node,
                              &base,
                              &data->window);
      if (node_rank != 0)
        {
          MPI_Aint size;
          int      unit;
          MPI_Win_shared_query(data->window, 0, &size, &unit, &base);
        }
      for (unsigned int a = 0; a < arrays.size(); ++a)
        {
          const auto &[field, count, size] = arrays[a];
          if (node_rank == 0 && present[a])
            std::memcpy(base + offset[a], *field, count * size);
          *field = present[a] ? base + offset[a] : nullptr;
        }
      view.IPerm = nullptr;
      view.z     = nullptr;
      if (node_rank == 0)
        cholmod_free_factor(&data->factor, &data->common);
      data->factor = &view;
      data->analysed_p.clear();
      data->analysed_i.clear();
      MPI_Win_fence(0, data->window);
    }


    std::size_t
    SparseCholesky::memory_bytes() const
    {
      if (data->factor == nullptr)
        return 0;
      std::size_t bytes = 0;
      for (const auto &[field, count, size] : factor_arrays(*data->factor))
        if (*field != nullptr)
          bytes += count * size;
      return bytes;
    }


    void
    SparseCholesky::solve(const dealii::Vector<double> &b,
                          dealii::Vector<double>       &x) const
    {
      cholmod_dense *X = data->solve(b.begin(), 1);
      x.reinit(data->n, true);
      const auto *values = static_cast<const double *>(X->x);
      std::copy(values, values + data->n, x.begin());
      cholmod_free_dense(&X, &data->common);
    }


    void
    SparseCholesky::schur_complement(const std::vector<int>           &p,
                                     const std::vector<int>           &i,
                                     const std::vector<double>        &x,
                                     dealii::LAPACKFullMatrix<double> &S) const
    {
      const cholmod_factor *A = data->factor;
      if (A == nullptr || p.size() < data->n + 1)
        throw std::logic_error(
          "SparseCholesky::schur_complement: factorize the leading block "
          "first");
      const std::size_t n = p.size() - 1, n_A = data->n, n_c = n - n_A;
      S.reinit(n_c, n_c);
      if (n_c == 0)
        return;

      // A's fill-reducing order (which CHOLMOD has post-ordered), then the
      // trailing rows; given as it is (no ordering, no post-ordering), so
      // that the factor's last n_c columns are the trailing rows
      std::vector<int> order(n);
      const int       *perm = static_cast<const int *>(A->Perm);
      for (std::size_t k = 0; k < n; ++k)
        order[k] = k < n_A ? (perm != nullptr ? perm[k] : int(k)) : int(k);
      cholmod_common common;
      cholmod_start(&common);
      common.print              = 0;
      common.nmethods           = 1;
      common.method[0].ordering = CHOLMOD_GIVEN;
      common.postorder          = 0;
      common.supernodal         = CHOLMOD_SUPERNODAL;
      cholmod_sparse *M         = upper_triangle(p, i, x, common);
      cholmod_factor *L =
        cholmod_analyze_p(M, order.data(), nullptr, 0, &common);
      if (L != nullptr)
        cholmod_factorize(M, L, &common);
      const bool factorised = L != nullptr && common.status == CHOLMOD_OK &&
                              L->minor == n && L->is_super;
      bool in_order = factorised;
      for (std::size_t k = n_A; in_order && k < n; ++k)
        in_order = static_cast<const int *>(L->Perm)[k] == int(k);

      // L_cc: the rows and columns from n_A of the supernodal factor (each
      // supernode a dense column-major block of its rows, its first rows
      // its own columns)
      dealii::LAPACKFullMatrix<double> L_cc(n_c, n_c);
      if (in_order)
        {
          const int *super = static_cast<const int *>(L->super),
                    *pi    = static_cast<const int *>(L->pi),
                    *px    = static_cast<const int *>(L->px),
                    *rows  = static_cast<const int *>(L->s);
          const double *lx = static_cast<const double *>(L->x);
          for (std::size_t k = 0; k < L->nsuper; ++k)
            {
              const int first = super[k], n_rows = pi[k + 1] - pi[k];
              for (int j = std::max(first, int(n_A)); j < super[k + 1]; ++j)
                for (int r = 0; r < n_rows; ++r)
                  {
                    const int row = rows[pi[k] + r];
                    if (row >= j)
                      L_cc(row - n_A, j - n_A) =
                        lx[px[k] + r + std::size_t(j - first) * n_rows];
                  }
            }
        }
      cholmod_free_sparse(&M, &common);
      if (L != nullptr)
        cholmod_free_factor(&L, &common);
      cholmod_finish(&common);
      if (!factorised)
        throw std::runtime_error(
          "CHOLMOD: the matrix is not positive definite");
      if (!in_order)
        throw std::logic_error(
          "CHOLMOD reordered the trailing rows of a given ordering");

      L_cc.mTmult(S, L_cc);
    }


    void
    SparseCholesky::solve(const dealii::FullMatrix<double> &B,
                          dealii::FullMatrix<double>       &X) const
    {
      const std::size_t   m = B.n();
      std::vector<double> columns(data->n * m);
      for (std::size_t r = 0; r < data->n; ++r)
        for (std::size_t c = 0; c < m; ++c)
          columns[c * data->n + r] = B(r, c);
      cholmod_dense *result = data->solve(columns.data(), m);
      const auto    *values = static_cast<const double *>(result->x);
      X.reinit(data->n, m);
      for (std::size_t r = 0; r < data->n; ++r)
        for (std::size_t c = 0; c < m; ++c)
          X(r, c) = values[c * data->n + r];
      cholmod_free_dense(&result, &data->common);
    }
  } // namespace solvers
} // namespace rsfcycle
