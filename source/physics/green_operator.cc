// The fault's Green's functions from the assembled stiffness
// (physics/green_operator.h, MODEL.md §8.1).
#include <algorithm>
#include <boost/crc.hpp>
#include <cmath>
#include <cstring>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <filesystem>
#include <fstream>
#include <rsfcycle/format.h>
#include <rsfcycle/physics/green_operator.h>
#include <rsfcycle/solvers/sparse_cholesky.h>
#include <stdexcept>

namespace rsfcycle
{
  namespace physics
  {
    template <int dim>
    std::vector<ObservationRow>
    observation_rows(const Discretisation<dim> &discretisation,
                     const Scene<dim>          &scene,
                     const bool                 antiplane)
    {
      const auto                 &fe = discretisation.fe;
      const MappingQ1<dim>        mapping;
      const auto                 &hanging = discretisation.hanging_constraints;
      std::vector<ObservationRow> rows;
      for (const auto &[name, point] : scene.observation_points())
        {
          const auto cell_and_point =
            GridTools::find_active_cell_around_point(mapping,
                                                     discretisation.dof_handler,
                                                     point);
          const Quadrature<dim> q(
            GeometryInfo<dim>::project_to_unit_cell(cell_and_point.second));
          FEValues<dim> fe_values(mapping, fe, q, update_values);
          fe_values.reinit(cell_and_point.first);
          std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
          cell_and_point.first->get_dof_indices(indices);
          const Tensor<1, dim> up = scene.vertical();
          ObservationRow       row;
          const auto add = [&](const types::global_dof_index i, double w) {
            row.emplace_back(discretisation.local_index(i), w);
          };
          for (unsigned int i = 0; i < indices.size(); ++i)
            {
              const unsigned int c = fe.system_to_component_index(i).first;
              const double       w =
                fe_values.shape_value(i, 0) * (antiplane ? 1. : up[c]);
              if (w == 0)
                continue;
              // a hanging node's value is that of the dofs it depends on
              if (const auto *entries =
                    hanging.get_constraint_entries(indices[i]))
                for (const auto &[j, factor] : *entries)
                  add(j, w * factor);
              else
                add(indices[i], w);
            }
          rows.push_back(row);
        }
      return rows;
    }


    template <int dim>
    GreenOperator
    compute_green_operator(const Discretisation<dim>         &discretisation,
                           const solvers::ContactSet         &contact,
                           const std::vector<ObservationRow> &observations,
                           const unsigned int                 block_size)
    {
      if (Utilities::MPI::n_mpi_processes(
            discretisation.triangulation.get_communicator()) > 1)
        throw std::invalid_argument(
          "Solver/Bulk = green-function runs on one MPI rank in this "
          "version: start it without mpirun");
      // one rank: local indices are the global ones
      const la::LocalMatrix   &K     = discretisation.stiffness_local;
      const std::vector<bool> &fixed = discretisation.fixed;
      const unsigned int       n     = K.m();
      const unsigned int       n_c   = contact.nodes.size();
      const unsigned int       n_o   = observations.size();

      // the contact's dofs (c), the unknowns besides them (I)
      std::vector<int>          contact_index(n, -1), interior_index(n, -1);
      std::vector<unsigned int> contact_dofs, interior;
      for (unsigned int k = 0; k < n_c; ++k)
        {
          if (contact.nodes[k].n_dofs != 1)
            throw std::invalid_argument(
              "Solver/Bulk = green-function: contact nodes with two "
              "tangential dofs (3D) are not done yet");
          contact_index[contact.nodes[k].dofs[0]] = k;
          contact_dofs.push_back(contact.nodes[k].dofs[0]);
        }
      for (unsigned int i = 0; i < n; ++i)
        if (!fixed[i] && contact_index[i] < 0)
          {
            interior_index[i] = interior.size();
            interior.push_back(i);
          }
      const unsigned int n_I = interior.size();

      GreenOperator op;
      op.n_interior = n_I;

      // K_II and its Cholesky factor
      dealii::DynamicSparsityPattern dsp(n_I, n_I);
      for (unsigned int k = 0; k < n_I; ++k)
        for (unsigned int e = K.row_begin(interior[k]);
             e < K.row_end(interior[k]);
             ++e)
          if (interior_index[K.column(e)] >= 0)
            dsp.add(k, interior_index[K.column(e)]);
      dealii::SparsityPattern pattern;
      pattern.copy_from(dsp);
      dealii::SparseMatrix<double> K_II(pattern);
      for (unsigned int k = 0; k < n_I; ++k)
        for (unsigned int e = K.row_begin(interior[k]);
             e < K.row_end(interior[k]);
             ++e)
          if (interior_index[K.column(e)] >= 0)
            K_II.set(k, interior_index[K.column(e)], K.value(e));
      solvers::SparseCholesky cholesky;
      cholesky.factorize(K_II);

      // The loads: the force f (body force and shear prestress) and the
      // prescribed velocity v_b of the fixed dofs (zero but on loads).
      la::Vector v_b;
      discretisation.reinit(v_b);
      discretisation.set_fixed_values(v_b, 0.);
      const auto f = [&](const unsigned int i) {
        return discretisation.body_force.local_element(i) +
               discretisation.prestress_force.local_element(i);
      };
      // sum over the fixed columns j of row i of K: K_ij v_b,j
      const auto K_fixed_v = [&](const unsigned int i) {
        double sum = 0;
        for (unsigned int e = K.row_begin(i); e < K.row_end(i); ++e)
          if (fixed[K.column(e)])
            sum += K.value(e) * v_b.local_element(K.column(e));
        return sum;
      };

      // Z = K_II^-1 [f_I, -K_Ib v_b]
      {
        dealii::FullMatrix<double> B(n_I, 2), Z;
        for (unsigned int k = 0; k < n_I; ++k)
          {
            B(k, 0) = f(interior[k]);
            B(k, 1) = -K_fixed_v(interior[k]);
          }
        cholesky.solve(B, Z);
        ++op.n_blocks;
        op.g0.reinit(n_c);
        op.g1.reinit(n_c);
        for (unsigned int r = 0; r < n_c; ++r)
          {
            const unsigned int row = contact_dofs[r];
            op.g0[r]               = f(row);
            op.g1[r]               = -K_fixed_v(row);
            for (unsigned int e = K.row_begin(row); e < K.row_end(row); ++e)
              if (const int i = interior_index[K.column(e)]; i >= 0)
                {
                  op.g0[r] -= K.value(e) * Z(i, 0);
                  op.g1[r] -= K.value(e) * Z(i, 1);
                }
          }
        op.o0.reinit(n_o);
        op.o1.reinit(n_o);
        for (unsigned int p = 0; p < n_o; ++p)
          for (const auto &[j, w] : observations[p])
            if (const int i = interior_index[j]; i >= 0)
              {
                op.o0[p] += w * Z(i, 0);
                op.o1[p] += w * Z(i, 1);
              }
            else if (fixed[j])
              op.o1[p] += w * v_b.local_element(j);
      }

      // S and O, block_size columns at a time: X = K_II^-1 K_Ic
      op.S.reinit(n_c, n_c);
      op.O.reinit(n_o, n_c);
      for (unsigned int b0 = 0; b0 < n_c; b0 += block_size)
        {
          const unsigned int         nb = std::min(block_size, n_c - b0);
          dealii::FullMatrix<double> B(n_I, nb), X;
          // K symmetric: column j of K_Ic is row c_j restricted to I
          for (unsigned int jj = 0; jj < nb; ++jj)
            {
              const unsigned int row = contact_dofs[b0 + jj];
              for (unsigned int e = K.row_begin(row); e < K.row_end(row); ++e)
                if (const int i = interior_index[K.column(e)]; i >= 0)
                  B(i, jj) = K.value(e);
            }
          cholesky.solve(B, X);
          ++op.n_blocks;
          for (unsigned int r = 0; r < n_c; ++r)
            {
              const unsigned int row = contact_dofs[r];
              for (unsigned int e = K.row_begin(row); e < K.row_end(row); ++e)
                {
                  const unsigned int col = K.column(e);
                  if (const int i = interior_index[col]; i >= 0)
                    for (unsigned int jj = 0; jj < nb; ++jj)
                      op.S(r, b0 + jj) -= K.value(e) * X(i, jj);
                  else if (const int q = contact_index[col];
                           q >= static_cast<int>(b0) &&
                           q < static_cast<int>(b0 + nb))
                    op.S(r, q) += K.value(e);
                }
            }
          for (unsigned int p = 0; p < n_o; ++p)
            for (const auto &[j, w] : observations[p])
              if (const int i = interior_index[j]; i >= 0)
                for (unsigned int jj = 0; jj < nb; ++jj)
                  op.O(p, b0 + jj) -= w * X(i, jj);
              else if (const int q = contact_index[j];
                       q >= static_cast<int>(b0) &&
                       q < static_cast<int>(b0 + nb))
                op.O(p, q) += w;
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


    double
    GreenOperator::compress(const std::vector<double> &points,
                            const unsigned int         dim,
                            const double               tolerance)
    {
      compressed = std::make_shared<const solvers::HierarchicalMatrix>(
        S, points, dim, tolerance);
      const unsigned int  n = S.m();
      std::vector<double> x(n), dense(n), h(n);
      double              error = 0;
      for (unsigned int test = 0; test < 2; ++test)
        {
          // a uniform slip; a reproducible pseudo-random one in [-1, 1]
          std::uint32_t seed = 12345;
          for (auto &xi : x)
            {
              seed = 1664525u * seed + 1013904223u;
              xi   = test == 0 ? 1. : seed / 2147483648. - 1.;
            }
          for (unsigned int r = 0; r < n; ++r)
            {
              dense[r] = 0;
              for (unsigned int j = 0; j < n; ++j)
                dense[r] += S(r, j) * x[j];
            }
          compressed->vmult(x.data(), h.data());
          double diff = 0, norm = 0;
          for (unsigned int r = 0; r < n; ++r)
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
    }


    template <int dim>
    std::uint32_t
    operator_fingerprint(const Discretisation<dim>         &discretisation,
                         const solvers::ContactSet         &contact,
                         const std::vector<ObservationRow> &observations)
    {
      boost::crc_32_type crc;
      const auto add = [&](const auto x) { crc.process_bytes(&x, sizeof x); };
      const la::LocalMatrix &K = discretisation.stiffness_local;
      la::Vector             v_b;
      discretisation.reinit(v_b);
      discretisation.set_fixed_values(v_b, 0.);
      add(static_cast<std::uint64_t>(K.m()));
      for (unsigned int i = 0; i < K.m(); ++i)
        {
          add(static_cast<std::uint8_t>(discretisation.fixed[i]));
          add(discretisation.body_force.local_element(i));
          add(discretisation.prestress_force.local_element(i));
          add(v_b.local_element(i));
          for (unsigned int e = K.row_begin(i); e < K.row_end(i); ++e)
            {
              add(static_cast<std::uint32_t>(K.column(e)));
              add(K.value(e));
            }
        }
      for (const auto &node : contact.nodes)
        add(static_cast<std::uint32_t>(node.dofs[0]));
      for (const auto &row : observations)
        {
          add(static_cast<std::uint64_t>(row.size()));
          for (const auto &[j, w] : row)
            {
              add(static_cast<std::uint32_t>(j));
              add(w);
            }
        }
      return crc.checksum();
    }


    namespace
    {
      // the header of green-operator.bin (little-endian, as written)
      constexpr char        magic[8] = {'r', 's', 'f', 'g', 'r', 'e', 'e', 'n'};
      constexpr std::size_t header_size    = 48;
      constexpr std::size_t format_at      = 8;  // uint32
      constexpr std::size_t fingerprint_at = 12; // uint32
      constexpr std::size_t n_dofs_at      = 16; // uint64
      constexpr std::size_t n_contact_at   = 24; // uint64
      constexpr std::size_t n_obs_at       = 32; // uint64
      constexpr std::size_t payload_crc_at = 40; // uint32, of the payload
      constexpr std::size_t header_crc_at  = 44; // uint32, of [0, 44)

      std::uint32_t
      crc32(const char *data, const std::size_t n)
      {
        boost::crc_32_type crc;
        crc.process_bytes(data, n);
        return crc.checksum();
      }

      template <class T>
      void
      put(std::string &bytes, const std::size_t at, const T x)
      {
        std::memcpy(bytes.data() + at, &x, sizeof x);
      }

      template <class T>
      T
      get(const std::string &bytes, const std::size_t at)
      {
        T x;
        std::memcpy(&x, bytes.data() + at, sizeof x);
        return x;
      }

      std::size_t
      payload_doubles(const std::uint64_t n_c, const std::uint64_t n_o)
      {
        return n_c * n_c + 2 * n_c + n_o * n_c + 2 * n_o;
      }
    } // namespace


    void
    write_green_operator(const std::string   &file,
                         const GreenOperator &op,
                         const std::uint32_t  fingerprint,
                         const std::uint64_t  n_dofs)
    {
      const std::uint64_t n_c = op.S.m(), n_o = op.O.m();
      std::string bytes(header_size + 8 * payload_doubles(n_c, n_o), '\0');
      std::size_t at     = header_size;
      const auto  append = [&](const double *x, const std::size_t n) {
        std::memcpy(bytes.data() + at, x, 8 * n);
        at += 8 * n;
      };
      for (unsigned int r = 0; r < n_c; ++r)
        append(&op.S(r, 0), n_c);
      append(op.g0.data(), n_c);
      append(op.g1.data(), n_c);
      for (unsigned int p = 0; p < n_o; ++p)
        append(&op.O(p, 0), n_c);
      append(op.o0.data(), n_o);
      append(op.o1.data(), n_o);
      std::memcpy(bytes.data(), magic, sizeof magic);
      put(bytes, format_at, green_operator_format);
      put(bytes, fingerprint_at, fingerprint);
      put(bytes, n_dofs_at, n_dofs);
      put(bytes, n_contact_at, n_c);
      put(bytes, n_obs_at, n_o);
      put(bytes,
          payload_crc_at,
          crc32(bytes.data() + header_size, bytes.size() - header_size));
      put(bytes, header_crc_at, crc32(bytes.data(), header_crc_at));

      const std::string tmp = file + ".tmp";
      {
        std::ofstream out(tmp, std::ios::binary);
        out.write(bytes.data(), bytes.size());
        out.close();
        if (!out)
          throw std::runtime_error(tmp + ": cannot be written");
      }
      std::error_code error;
      std::filesystem::rename(tmp, file, error);
      if (error)
        throw std::runtime_error(file + ": cannot be written (" +
                                 error.message() + ")");
    }


    GreenOperator
    read_green_operator(const std::string  &file,
                        const std::string  &what,
                        const std::uint32_t fingerprint,
                        const std::uint64_t n_dofs,
                        const unsigned int  n_contact,
                        const unsigned int  n_observations)
    {
      const auto refuse = [&](const std::string &why) {
        return std::invalid_argument(what + ": " + file + ": " + why);
      };
      std::ifstream in(file, std::ios::binary);
      if (!in)
        throw refuse("cannot be read");
      const std::string bytes((std::istreambuf_iterator<char>(in)),
                              std::istreambuf_iterator<char>());
      if (bytes.size() < header_size ||
          std::memcmp(bytes.data(), magic, sizeof magic) != 0)
        throw refuse("not a Green's-function operator file of rsfcycle");
      if (crc32(bytes.data(), header_crc_at) !=
          get<std::uint32_t>(bytes, header_crc_at))
        throw refuse("checksum mismatch in the header: the file is damaged");
      if (const auto format = get<std::uint32_t>(bytes, format_at);
          format != green_operator_format)
        throw refuse("format " + std::to_string(format) +
                     ", this program reads format " +
                     std::to_string(green_operator_format));
      const auto n_c = get<std::uint64_t>(bytes, n_contact_at);
      const auto n_o = get<std::uint64_t>(bytes, n_obs_at);
      if (bytes.size() != header_size + 8 * payload_doubles(n_c, n_o))
        throw refuse(
          "truncated (" + std::to_string(bytes.size()) +
          " bytes, the header promises " +
          std::to_string(header_size + 8 * payload_doubles(n_c, n_o)) + ")");
      if (crc32(bytes.data() + header_size, bytes.size() - header_size) !=
          get<std::uint32_t>(bytes, payload_crc_at))
        throw refuse("checksum mismatch in the operator: the file is damaged");
      if (n_c != n_contact || n_o != n_observations ||
          get<std::uint64_t>(bytes, n_dofs_at) != n_dofs)
        throw refuse(
          "written for " +
          std::to_string(get<std::uint64_t>(bytes, n_dofs_at)) + " unknowns, " +
          std::to_string(n_c) + " contact nodes and " + std::to_string(n_o) +
          " observation points; this run has " + std::to_string(n_dofs) + ", " +
          std::to_string(n_contact) + " and " + std::to_string(n_observations) +
          " (another mesh or scene)");
      if (get<std::uint32_t>(bytes, fingerprint_at) != fingerprint)
        throw refuse("written for another stiffness, load or set of "
                     "observation points than this run's (the same sizes, "
                     "another material, boundary role, load or prestress)");

      GreenOperator op;
      std::size_t   at   = header_size;
      const auto    take = [&](double *x, const std::size_t n) {
        std::memcpy(x, bytes.data() + at, 8 * n);
        at += 8 * n;
      };
      op.S.reinit(n_c, n_c);
      op.g0.reinit(n_c);
      op.g1.reinit(n_c);
      op.O.reinit(n_o, n_c);
      op.o0.reinit(n_o);
      op.o1.reinit(n_o);
      for (unsigned int r = 0; r < n_c; ++r)
        take(&op.S(r, 0), n_c);
      take(op.g0.data(), n_c);
      take(op.g1.data(), n_c);
      for (unsigned int p = 0; p < n_o; ++p)
        take(&op.O(p, 0), n_c);
      take(op.o0.data(), n_o);
      take(op.o1.data(), n_o);
      return op;
    }


    template std::vector<ObservationRow>
    observation_rows(const Discretisation<2> &, const Scene<2> &, bool);
    template std::vector<ObservationRow>
    observation_rows(const Discretisation<3> &, const Scene<3> &, bool);
    template GreenOperator
    compute_green_operator(const Discretisation<2> &,
                           const solvers::ContactSet &,
                           const std::vector<ObservationRow> &,
                           unsigned int);
    template GreenOperator
    compute_green_operator(const Discretisation<3> &,
                           const solvers::ContactSet &,
                           const std::vector<ObservationRow> &,
                           unsigned int);
    template std::uint32_t
    operator_fingerprint(const Discretisation<2> &,
                         const solvers::ContactSet &,
                         const std::vector<ObservationRow> &);
    template std::uint32_t
    operator_fingerprint(const Discretisation<3> &,
                         const solvers::ContactSet &,
                         const std::vector<ObservationRow> &);
  } // namespace physics
} // namespace rsfcycle
