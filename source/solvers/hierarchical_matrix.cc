// SPDX-License-Identifier: LGPL-2.1-or-later
// A matrix of point interactions compressed by hmat-oss
// (solvers/hierarchical_matrix.h).
#include <algorithm>
#include <functional>
#include <hmat/hmat.h>
#include <rsfcycle/solvers/hierarchical_matrix.h>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace rsfcycle
{
  namespace solvers
  {
    namespace
    {
      // hmat-oss's interface of a precision, each initialised once
      hmat_interface_t &
      interface(const HierarchicalMatrix::Precision precision)
      {
        const auto make = [](const hmat_value_t type) {
          hmat_interface_t h;
          hmat_init_default_interface(&h, type);
          if (h.init() != 0)
            throw std::runtime_error("hmat-oss: initialisation failed");
          return h;
        };
        static hmat_interface_t hmat_double = make(HMAT_DOUBLE_PRECISION);
        static hmat_interface_t hmat_single = make(HMAT_SIMPLE_PRECISION);
        return precision == HierarchicalMatrix::Precision::single_precision ?
                 hmat_single :
                 hmat_double;
      }

      using Entry = std::function<double(unsigned int, unsigned int)>;

      // the entry callback of the assembly: (i, j) in the original order;
      // hmat-oss asks for a double in either precision (it compresses in
      // double and stores in the matrix's precision)
      void
      entry_of(void *context, const int i, const int j, void *result)
      {
        *static_cast<double *>(result) =
          (*static_cast<const Entry *>(context))(i, j);
      }
    } // namespace


    struct HierarchicalMatrix::Data
    {
      Precision            precision = Precision::double_precision;
      hmat_cluster_tree_t *rows = nullptr, *columns = nullptr;
      hmat_matrix_t       *matrix = nullptr;
      // the clusterings' orders: position k holds original index order[k]
      const int  *row_order = nullptr, *column_order = nullptr;
      hmat_info_t info;
      // x and y in the clusterings' orders (the product is not const in
      // hmat-oss's interface)
      mutable std::vector<double> x, y;
      // the same in single precision
      mutable std::vector<float> x_single, y_single;

      ~Data()
      {
        if (matrix != nullptr)
          interface(precision).destroy(matrix);
        if (columns != nullptr && columns != rows)
          hmat_delete_cluster_tree(columns);
        if (rows != nullptr)
          hmat_delete_cluster_tree(rows);
      }
    };


    namespace
    {
      hmat_cluster_tree_t *
      cluster_tree(const std::vector<double> &points,
                   const unsigned int         dim,
                   const unsigned int         leaf_size)
      {
        hmat_clustering_algorithm_t *median = hmat_create_clustering_median();
        hmat_clustering_algorithm_t *algorithm =
          hmat_create_clustering_max_dof(median, leaf_size);
        hmat_cluster_tree_t *tree =
          hmat_create_cluster_tree(const_cast<double *>(points.data()),
                                   dim,
                                   points.size() / dim,
                                   algorithm);
        hmat_delete_clustering(algorithm);
        hmat_delete_clustering(median);
        if (tree == nullptr)
          throw std::runtime_error("hmat-oss: the clustering failed");
        return tree;
      }
    } // namespace


    HierarchicalMatrix::HierarchicalMatrix(
      const dealii::FullMatrix<double> &A,
      const std::vector<double>        &row_points,
      const std::vector<double>        &column_points,
      const unsigned int                dim,
      const double                      tolerance,
      const bool                        symmetric,
      const Precision                   precision,
      const unsigned int                leaf_size,
      const double                      eta)
      : HierarchicalMatrix(
          A.m(),
          A.n(),
          [&A](const unsigned int i, const unsigned int j) { return A(i, j); },
          row_points,
          column_points,
          dim,
          tolerance,
          symmetric,
          precision,
          leaf_size,
          eta)
    {}


    HierarchicalMatrix::HierarchicalMatrix(
      const unsigned int         m,
      const unsigned int         n,
      const Entry               &entry,
      const std::vector<double> &row_points,
      const std::vector<double> &column_points,
      const unsigned int         dim,
      const double               tolerance,
      const bool                 symmetric,
      const Precision            precision,
      const unsigned int         leaf_size,
      const double               eta)
      : data(std::make_unique<Data>())
    {
      data->precision = precision;
      auto      &hmat = interface(precision);
      const auto fail = [](const std::string &what) {
        return std::runtime_error("hmat-oss: " + what + " failed");
      };
      if (row_points.size() != dim * m || column_points.size() != dim * n)
        throw std::invalid_argument(
          "HierarchicalMatrix: one point per row and per column");
      if (symmetric && row_points != column_points)
        throw std::invalid_argument(
          "HierarchicalMatrix: a symmetric matrix has the same points for "
          "its rows and columns");

      data->rows = cluster_tree(row_points, dim, leaf_size);
      data->columns =
        symmetric ? data->rows : cluster_tree(column_points, dim, leaf_size);
      data->row_order    = hmat_cluster_get_indices(data->rows);
      data->column_order = hmat_cluster_get_indices(data->columns);

      hmat_admissibility_t *admissibility =
        hmat_create_admissibility_standard(eta);
      data->matrix = hmat.create_empty_hmatrix_admissibility(data->rows,
                                                             data->columns,
                                                             symmetric ? 1 : 0,
                                                             admissibility);
      hmat_delete_admissibility(admissibility);
      if (data->matrix == nullptr)
        throw fail("the block tree");
      // the recompression after ACA+ truncates at 1e-4 unless told
      hmat.set_low_rank_epsilon(data->matrix, tolerance);

      hmat_assemble_context_t context;
      hmat_assemble_context_init(&context);
      context.compression     = hmat_create_compression_aca_plus(tolerance);
      context.simple_compute  = entry_of;
      context.user_context    = const_cast<Entry *>(&entry);
      context.lower_symmetric = symmetric ? 1 : 0;
      context.progress        = nullptr;
      const int error         = hmat.assemble_generic(data->matrix, &context);
      hmat_delete_compression(context.compression);
      if (error != 0)
        throw fail("the assembly");
      hmat.get_info(data->matrix, &data->info);
      data->x.resize(n);
      data->y.resize(m);
      if (precision == Precision::single_precision)
        {
          data->x_single.resize(n);
          data->y_single.resize(m);
        }
    }


    HierarchicalMatrix::~HierarchicalMatrix() = default;


    void
    HierarchicalMatrix::vmult(const double *x, double *y, const bool add) const
    {
      product('N', x, y, add);
    }


    void
    HierarchicalMatrix::Tvmult(const double *x, double *y, const bool add) const
    {
      product('T', x, y, add);
    }


    void
    HierarchicalMatrix::product(const char    transpose,
                                const double *x,
                                double       *y,
                                const bool    add) const
    {
      // x and y in the clusterings' orders: A x reads the columns' order
      // and writes the rows', A^T x the other way round
      const bool           t   = transpose == 'T';
      std::vector<double> &in  = t ? data->y : data->x,
                          &out = t ? data->x : data->y;
      const int *in_order      = t ? data->row_order : data->column_order,
                *out_order     = t ? data->column_order : data->row_order;
      for (unsigned int k = 0; k < in.size(); ++k)
        in[k] = x[in_order[k]];
      const auto gemm = [&](auto &in_p, auto &out_p) {
        using Number     = typename std::decay_t<decltype(in_p)>::value_type;
        const Number one = 1, zero = 0;
        const int    error = interface(data->precision)
                            .gemm_dense(transpose,
                                        'N',
                                        'L',
                                        &one,
                                        data->matrix,
                                        in_p.data(),
                                        &zero,
                                        out_p.data(),
                                        1);
        if (error != 0)
          throw std::runtime_error("hmat-oss: the product failed");
      };
      if (data->precision == Precision::single_precision)
        {
          std::vector<float> &in_single  = t ? data->y_single : data->x_single,
                             &out_single = t ? data->x_single : data->y_single;
          std::copy(in.begin(), in.end(), in_single.begin());
          gemm(in_single, out_single);
          std::copy(out_single.begin(), out_single.end(), out.begin());
        }
      else
        gemm(in, out);
      for (unsigned int k = 0; k < out.size(); ++k)
        y[out_order[k]] = (add ? y[out_order[k]] : 0.) + out[k];
    }


    unsigned int
    HierarchicalMatrix::m() const
    {
      return data->y.size();
    }


    unsigned int
    HierarchicalMatrix::n() const
    {
      return data->x.size();
    }


    std::size_t
    HierarchicalMatrix::memory_consumption() const
    {
      return stored_entries() *
             (data->precision == Precision::single_precision ? sizeof(float) :
                                                               sizeof(double));
    }


    std::size_t
    HierarchicalMatrix::stored_entries() const
    {
      return data->info.compressed_size;
    }


    std::size_t
    HierarchicalMatrix::n_low_rank_blocks() const
    {
      return data->info.rk_count;
    }


    std::size_t
    HierarchicalMatrix::n_dense_blocks() const
    {
      return data->info.full_count;
    }
  } // namespace solvers
} // namespace rsfcycle
