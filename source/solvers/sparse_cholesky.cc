#include <algorithm>
#include <cholmod.h>
#include <rsfcycle/solvers/sparse_cholesky.h>
#include <stdexcept>
#include <vector>

namespace rsfcycle
{
  namespace solvers
  {
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

      Data()
      {
        cholmod_start(&common);
        common.print = 0;
      }
      ~Data()
      {
        if (factor != nullptr)
          cholmod_free_factor(&factor, &common);
        cholmod_finish(&common);
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


    SparseCholesky::SparseCholesky()
      : data(std::make_unique<Data>())
    {}


    SparseCholesky::~SparseCholesky() = default;


    void
    SparseCholesky::factorize(const dealii::SparseMatrix<double> &A)
    {
      const std::size_t n = A.m();
      // Upper triangle in compressed-column form: for a symmetric matrix,
      // column j holds the entries of row j with column index <= j.
      std::size_t nnz = 0;
      for (std::size_t j = 0; j < n; ++j)
        for (auto it = A.begin(j); it != A.end(j); ++it)
          if (it->column() <= j)
            ++nnz;
      cholmod_sparse *S = cholmod_allocate_sparse(n,
                                                  n,
                                                  nnz,
                                                  /*sorted*/ 0,
                                                  /*packed*/ 1,
                                                  /*stype*/ 1,
                                                  CHOLMOD_REAL,
                                                  &data->common);
      auto           *p = static_cast<int *>(S->p);
      auto           *i = static_cast<int *>(S->i);
      auto           *x = static_cast<double *>(S->x);
      std::size_t     k = 0;
      for (std::size_t j = 0; j < n; ++j)
        {
          p[j] = k;
          for (auto it = A.begin(j); it != A.end(j); ++it)
            if (it->column() <= j)
              {
                i[k] = it->column();
                x[k] = it->value();
                ++k;
              }
        }
      p[n] = k;

      const bool same_pattern =
        data->factor != nullptr &&
        std::equal(p,
                   p + n + 1,
                   data->analysed_p.begin(),
                   data->analysed_p.end()) &&
        std::equal(i, i + k, data->analysed_i.begin(), data->analysed_i.end());
      if (!same_pattern)
        {
          if (data->factor != nullptr)
            cholmod_free_factor(&data->factor, &data->common);
          data->factor = cholmod_analyze(S, &data->common);
          data->analysed_p.assign(p, p + n + 1);
          data->analysed_i.assign(i, i + k);
        }
      cholmod_factorize(S, data->factor, &data->common);
      const int status = data->common.status;
      cholmod_free_sparse(&S, &data->common);
      if (status != CHOLMOD_OK || data->factor->minor < n)
        throw std::runtime_error(
          "CHOLMOD: the matrix is not positive definite");
      data->n = n;
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
