// SPDX-License-Identifier: LGPL-2.1-or-later
// The operator file green-operator.bin (physics/green_operator.h): written
// and read collectively, every rank its own rows of S.
#include <boost/crc.hpp>
#include <cstring>
#include <deal.II/base/mpi.h>
#include <filesystem>
#include <fstream>
#include <rsfcycle/la.h>
#include <rsfcycle/physics/green_operator.h>
#include <stdexcept>

namespace rsfcycle
{
  namespace physics
  {
    namespace
    {
      // the header (little-endian, as written)
      constexpr char        magic[8] = {'r', 's', 'f', 'g', 'r', 'e', 'e', 'n'};
      constexpr std::size_t header_size    = 56;
      constexpr std::size_t format_at      = 8;  // uint32
      constexpr std::size_t fingerprint_at = 12; // uint32
      constexpr std::size_t n_dofs_at      = 16; // uint64
      constexpr std::size_t n_contact_at   = 24; // uint64
      constexpr std::size_t n_obs_at       = 32; // uint64
      constexpr std::size_t n_ranks_at     = 40; // uint32
      constexpr std::size_t normal_at      = 44; // uint32: 1 with N rows
      constexpr std::size_t payload_crc_at = 48; // uint32, of the payload
      constexpr std::size_t header_crc_at  = 52; // uint32, of [0, 52)

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

      // the doubles before the rows of S: g0, g1, O, o0, o1
      std::size_t
      small_doubles(const std::uint64_t n_c, const std::uint64_t n_o)
      {
        return 2 * n_c + n_o * n_c + 2 * n_o;
      }

      // the first non-empty message of any rank, on every rank
      std::string
      first_error(const MPI_Comm comm, const std::string &error)
      {
        for (const auto &e : dealii::Utilities::MPI::all_gather(comm, error))
          if (!e.empty())
            return e;
        return "";
      }
    } // namespace


    void
    write_green_operator(const std::string   &file,
                         const GreenOperator &op,
                         const std::uint32_t  fingerprint,
                         const std::uint64_t  n_dofs,
                         const MPI_Comm       comm)
    {
      const unsigned int  rank = dealii::Utilities::MPI::this_mpi_process(comm);
      const unsigned int  size = dealii::Utilities::MPI::n_mpi_processes(comm);
      const std::uint64_t n_c = op.n_contact(), n_o = op.O.m();
      const std::string   tmp = file + ".tmp";
      std::string         error;
      std::vector<std::array<double, 2>> g;
      for (unsigned int r = 0; r < op.n_rows(); ++r)
        g.push_back({{op.g0[r], op.g1[r]}});
      g = la::all_gather(comm, g);

      // the first rank: the header (its checksums at the end) and g0, g1,
      // O, o0, o1; then every rank appends its rows in turn
      if (rank == 0)
        {
          std::vector<double> small;
          for (const auto &gk : g)
            small.push_back(gk[0]);
          for (const auto &gk : g)
            small.push_back(gk[1]);
          for (unsigned int p = 0; p < n_o; ++p)
            small.insert(small.end(), &op.O(p, 0), &op.O(p, 0) + n_c);
          small.insert(small.end(), op.o0.begin(), op.o0.end());
          small.insert(small.end(), op.o1.begin(), op.o1.end());
          std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
          out.write(std::string(header_size, '\0').data(), header_size);
          out.write(reinterpret_cast<const char *>(small.data()),
                    8 * small.size());
          out.close();
          if (!out)
            error = tmp + ": cannot be written";
        }
      // (the rows of S, then those of the normal coupling: n0, n1, N)
      for (unsigned int part = 0; part < (op.normal_coupling ? 2 : 1); ++part)
        for (unsigned int r = 0; r < size; ++r)
          {
            if (r == rank && error.empty() && op.n_rows() > 0)
              {
                std::ofstream out(tmp, std::ios::binary | std::ios::app);
                if (part == 0)
                  out.write(reinterpret_cast<const char *>(&op.S(0, 0)),
                            8 * op.S.m() * op.S.n());
                else
                  for (unsigned int i = 0; i < op.n_rows(); ++i)
                    {
                      const double n01[2] = {op.n0[i], op.n1[i]};
                      out.write(reinterpret_cast<const char *>(n01), 16);
                      out.write(reinterpret_cast<const char *>(&op.N(i, 0)),
                                8 * n_c);
                    }
                out.close();
                if (!out)
                  error = tmp + ": cannot be written";
              }
            MPI_Barrier(comm);
          }
      error = first_error(comm, error);

      // the first rank: the payload's checksum, the header, the rename
      if (rank == 0 && error.empty())
        {
          std::fstream io(tmp, std::ios::binary | std::ios::in | std::ios::out);
          io.seekg(header_size);
          boost::crc_32_type crc;
          std::vector<char>  chunk(1 << 20);
          while (io.read(chunk.data(), chunk.size()) || io.gcount() > 0)
            crc.process_bytes(chunk.data(), io.gcount());
          io.clear();
          std::string header(header_size, '\0');
          std::memcpy(header.data(), magic, sizeof magic);
          put(header, format_at, green_operator_format);
          put(header, fingerprint_at, fingerprint);
          put(header, n_dofs_at, n_dofs);
          put(header, n_contact_at, n_c);
          put(header, n_obs_at, n_o);
          put(header, n_ranks_at, static_cast<std::uint32_t>(size));
          put(header,
              normal_at,
              static_cast<std::uint32_t>(op.normal_coupling ? 1 : 0));
          put(header, payload_crc_at, crc.checksum());
          put(header, header_crc_at, crc32(header.data(), header_crc_at));
          io.seekp(0);
          io.write(header.data(), header_size);
          io.close();
          std::error_code renamed;
          if (!io)
            error = tmp + ": cannot be written";
          else if (std::filesystem::rename(tmp, file, renamed); renamed)
            error = file + ": cannot be written (" + renamed.message() + ")";
        }
      error = first_error(comm, error);
      if (!error.empty())
        throw std::runtime_error(error);
    }


    GreenOperator
    read_green_operator(const std::string  &file,
                        const std::string  &what,
                        const std::uint32_t fingerprint,
                        const std::uint64_t n_dofs,
                        const unsigned int  n_contact,
                        const unsigned int  n_observations,
                        const unsigned int  first_row,
                        const unsigned int  n_rows,
                        const MPI_Comm      comm)
    {
      const auto refuse = [&](const std::string &why) {
        return std::invalid_argument(what + ": " + file + ": " + why);
      };
      std::ifstream in(file, std::ios::binary | std::ios::ate);
      if (!in)
        throw refuse("cannot be read");
      const auto  file_size = static_cast<std::uint64_t>(in.tellg());
      std::string header(header_size, '\0');
      in.seekg(0);
      if (file_size < header_size || !in.read(header.data(), header_size) ||
          std::memcmp(header.data(), magic, sizeof magic) != 0)
        throw refuse("not a Green's-function operator file of rsfcycle");
      if (crc32(header.data(), header_crc_at) !=
          get<std::uint32_t>(header, header_crc_at))
        throw refuse("checksum mismatch in the header: the file is damaged");
      if (const auto format = get<std::uint32_t>(header, format_at);
          format != green_operator_format)
        throw refuse("format " + std::to_string(format) +
                     ", this program reads format " +
                     std::to_string(green_operator_format));
      const auto n_c    = get<std::uint64_t>(header, n_contact_at);
      const auto n_o    = get<std::uint64_t>(header, n_obs_at);
      const bool normal = get<std::uint32_t>(header, normal_at) != 0;
      const auto expected =
        header_size + 8 * (small_doubles(n_c, n_o) + n_c * n_c +
                           (normal ? n_c * (n_c + 2) : 0));
      if (file_size != expected)
        throw refuse("truncated (" + std::to_string(file_size) +
                     " bytes, the header promises " + std::to_string(expected) +
                     ")");

      // the payload, streamed: the checksum of all of it, this rank's part
      const bool          fits = n_c == n_contact && n_o == n_observations;
      boost::crc_32_type  crc;
      std::vector<double> small(small_doubles(n_c, n_o)), row(n_c);
      in.read(reinterpret_cast<char *>(small.data()), 8 * small.size());
      crc.process_bytes(small.data(), 8 * small.size());
      GreenOperator op;
      op.S.reinit(fits ? n_rows : 0, n_c);
      for (std::uint64_t r = 0; r < n_c && in; ++r)
        {
          in.read(reinterpret_cast<char *>(row.data()), 8 * n_c);
          crc.process_bytes(row.data(), 8 * n_c);
          if (fits && r >= first_row && r < first_row + n_rows)
            std::copy(row.begin(), row.end(), &op.S(r - first_row, 0));
        }
      op.normal_coupling = normal;
      if (normal)
        {
          op.N.reinit(fits ? n_rows : 0, n_c);
          op.n0.reinit(fits ? n_rows : 0);
          op.n1.reinit(op.n0.size());
          row.resize(n_c + 2);
          for (std::uint64_t r = 0; r < n_c && in; ++r)
            {
              in.read(reinterpret_cast<char *>(row.data()), 8 * (n_c + 2));
              crc.process_bytes(row.data(), 8 * (n_c + 2));
              if (fits && r >= first_row && r < first_row + n_rows)
                {
                  op.n0[r - first_row] = row[0];
                  op.n1[r - first_row] = row[1];
                  std::copy(row.begin() + 2,
                            row.end(),
                            &op.N(r - first_row, 0));
                }
            }
        }
      if (!in || crc.checksum() != get<std::uint32_t>(header, payload_crc_at))
        throw refuse("checksum mismatch in the operator: the file is damaged");
      if (!fits || get<std::uint64_t>(header, n_dofs_at) != n_dofs)
        throw refuse(
          "written for " +
          std::to_string(get<std::uint64_t>(header, n_dofs_at)) +
          " unknowns, " + std::to_string(n_c) + " contact nodes and " +
          std::to_string(n_o) + " observation points; this run has " +
          std::to_string(n_dofs) + ", " + std::to_string(n_contact) + " and " +
          std::to_string(n_observations) + " (another mesh or scene)");
      const auto ranks = get<std::uint32_t>(header, n_ranks_at);
      if (ranks != dealii::Utilities::MPI::n_mpi_processes(comm))
        throw refuse(
          "written on " + std::to_string(ranks) +
          " MPI rank(s), this run has " +
          std::to_string(dealii::Utilities::MPI::n_mpi_processes(comm)) +
          " (the dof numbering depends on it): run on " +
          std::to_string(ranks) + " or leave the entry empty");
      if (get<std::uint32_t>(header, fingerprint_at) != fingerprint)
        throw refuse("written for another stiffness, load or set of "
                     "observation points than this run's (the same sizes, "
                     "another material, boundary role, load or prestress)");

      op.n_nodes   = n_c;
      op.first_row = first_row;
      op.g0.reinit(n_rows);
      op.g1.reinit(n_rows);
      for (unsigned int r = 0; r < n_rows; ++r)
        {
          op.g0[r] = small[first_row + r];
          op.g1[r] = small[n_c + first_row + r];
        }
      op.O.reinit(n_o, n_c);
      std::size_t at = 2 * n_c;
      for (unsigned int p = 0; p < n_o; ++p, at += n_c)
        std::copy(&small[at], &small[at] + n_c, &op.O(p, 0));
      op.o0.reinit(n_o);
      op.o1.reinit(n_o);
      std::copy(&small[at], &small[at] + n_o, op.o0.begin());
      std::copy(&small[at + n_o], &small[at + n_o] + n_o, op.o1.begin());
      return op;
    }
  } // namespace physics
} // namespace rsfcycle
