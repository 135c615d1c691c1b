// SPDX-License-Identifier: LGPL-2.1-or-later
#include <boost/crc.hpp>
#include <cerrno>
#include <cstdio>
#include <deal.II/base/mpi.h>
#include <filesystem>
#include <fstream>
#include <rsfcycle/output/checkpoint.h>
#include <rsfcycle/output/files.h>
#include <rsfcycle/version.h>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace rsfcycle
{
  namespace output
  {
    namespace
    {
      /**
       * The header of checkpoint format 1 (doc/checkpoints.md): byte
       * offsets of its fields, integers little-endian, texts ASCII padded
       * with NUL. The magic, the format and the program version keep their
       * places in every format, so that a checkpoint of another format can
       * be named.
       */
      enum Offset : std::size_t
      {
        magic_at        = 0,  // "rsfcycle"
        format_at       = 8,  // uint32
        program_at      = 12, // char[16]
        scene_at        = 28, // char[32]
        dimension_at    = 60, // uint32
        unknowns_at     = 64, // uint64
        ranks_at        = 72, // uint32
        payload_size_at = 76, // uint64
        payload_crc_at  = 84, // uint32, CRC32 of the payload
        header_crc_at   = 88, // uint32, CRC32 of bytes [0, 88)
        header_size     = 92
      };
      const std::string magic = "rsfcycle";

      void
      put_number(std::string        &bytes,
                 const std::size_t   at,
                 const std::uint64_t value,
                 const unsigned int  n_bytes)
      {
        for (unsigned int i = 0; i < n_bytes; ++i)
          bytes[at + i] = static_cast<char>((value >> (8 * i)) & 0xff);
      }

      std::uint64_t
      get_number(const std::string &bytes,
                 const std::size_t  at,
                 const unsigned int n_bytes)
      {
        std::uint64_t value = 0;
        for (unsigned int i = 0; i < n_bytes; ++i)
          value |= std::uint64_t(static_cast<unsigned char>(bytes[at + i]))
                   << (8 * i);
        return value;
      }

      void
      put_text(std::string       &bytes,
               const std::size_t  at,
               const std::string &text,
               const std::size_t  length)
      {
        if (text.size() >= length)
          throw std::logic_error("checkpoint header: \"" + text +
                                 "\" is too long");
        bytes.replace(at, text.size(), text);
      }

      /** A text field up to its first NUL, with anything unprintable as ?. */
      std::string
      get_text(const std::string &bytes,
               const std::size_t  at,
               const std::size_t  length)
      {
        std::string text;
        for (std::size_t i = at; i < at + length && bytes[i] != '\0'; ++i)
          text += (bytes[i] >= ' ' && bytes[i] <= '~') ? bytes[i] : '?';
        return text;
      }

      std::uint32_t
      crc32(const char *data, const std::size_t n_bytes)
      {
        boost::crc_32_type crc;
        crc.process_bytes(data, n_bytes);
        return crc.checksum();
      }

      std::string
      make_header(const CheckpointIdentity &identity,
                  const std::string        &payload)
      {
        std::string header(header_size, '\0');
        header.replace(magic_at, magic.size(), magic);
        put_number(header, format_at, checkpoint_format, 4);
        put_text(header, program_at, version::number, scene_at - program_at);
        put_text(header, scene_at, identity.scene, dimension_at - scene_at);
        put_number(header, dimension_at, identity.dimension, 4);
        put_number(header, unknowns_at, identity.n_unknowns, 8);
        put_number(header, ranks_at, identity.n_ranks, 4);
        put_number(header, payload_size_at, payload.size(), 8);
        put_number(header,
                   payload_crc_at,
                   crc32(payload.data(), payload.size()),
                   4);
        put_number(header,
                   header_crc_at,
                   crc32(header.data(), header_crc_at),
                   4);
        return header;
      }

      /**
       * What is wrong with the checkpoint `bytes` for a run of `expected`,
       * in the order in which each check can be trusted: magic, format
       * (the layout of the rest depends on it), header checksum, size,
       * payload checksum, then the identity. Empty if nothing.
       */
      std::string
      find_problem(const std::string &bytes, const CheckpointIdentity &expected)
      {
        const std::size_t size = bytes.size();
        const auto n = [](const std::uint64_t x) { return std::to_string(x); };
        if (bytes.compare(0, magic.size(), magic, 0, size) != 0)
          return bytes.find("serialization::archive") < 64 ?
                   "written by an rsfcycle older than checkpoint format 1 "
                   "(it has no header): resume it with that version" :
                   "not an rsfcycle checkpoint (it does not begin with \"" +
                     magic + "\")";
        if (size < program_at)
          return "truncated (" + n(size) + " of at least " + n(header_size) +
                 " bytes)";
        if (const auto format = get_number(bytes, format_at, 4);
            format != checkpoint_format)
          return "written in checkpoint format " + n(format) +
                 (size >= scene_at ?
                    " by rsfcycle " + get_text(bytes, program_at, 16) :
                    std::string()) +
                 ", this rsfcycle " + version::number + " reads format " +
                 n(checkpoint_format) +
                 ": resume with the rsfcycle version that wrote it";
        if (size < header_size)
          return "truncated (" + n(size) + " of at least " + n(header_size) +
                 " bytes)";
        if (crc32(bytes.data(), header_crc_at) !=
            get_number(bytes, header_crc_at, 4))
          return "checksum mismatch in the header: the checkpoint is damaged";
        const std::uint64_t total =
          header_size + get_number(bytes, payload_size_at, 8);
        if (size < total)
          return "truncated (" + n(size) + " of " + n(total) + " bytes)";
        if (size > total)
          return n(size) + " bytes where the header says " + n(total) +
                 ": the checkpoint is damaged";
        if (crc32(bytes.data() + header_size, size - header_size) !=
            get_number(bytes, payload_crc_at, 4))
          return "checksum mismatch: the checkpoint is damaged";

        const std::string scene = get_text(bytes, scene_at, 32);
        if (scene != expected.scene)
          return "written for the scene " + scene + ", this run is " +
                 expected.scene;
        if (const auto dim = get_number(bytes, dimension_at, 4);
            dim != expected.dimension)
          return "written for dimension " + n(dim) + ", this run has " +
                 n(expected.dimension);
        if (const auto ranks = get_number(bytes, ranks_at, 4);
            ranks != expected.n_ranks)
          return "written on " + n(ranks) + " MPI rank" +
                 (ranks == 1 ? "" : "s") + ", this run has " +
                 n(expected.n_ranks) + ": resume with mpirun -np " + n(ranks);
        if (const auto unknowns = get_number(bytes, unknowns_at, 8);
            unknowns != expected.n_unknowns)
          return "written for " + n(unknowns) + " unknowns, this run has " +
                 n(expected.n_unknowns) +
                 " (another mesh: was parameters.prm changed?)";
        return {};
      }

      /** The whole file; a file that cannot be read is a file_error. */
      std::string
      read_bytes(const std::string &path)
      {
        std::ifstream in(path, std::ios::binary);
        if (!in)
          throw file_error(path, errno);
        std::ostringstream bytes;
        bytes << in.rdbuf();
        if (in.bad())
          throw file_error(path, errno);
        return bytes.str();
      }

      /**
       * Keep checkpoint.bin as checkpoint.bin.prev. A hard link leaves
       * checkpoint.bin in place until the new one replaces it; where the
       * file system has no hard links, a rename (checkpoint.bin is then
       * missing for a moment, and the error on resume points to .prev).
       */
      void
      keep_previous(const std::string &bin, const std::string &prev)
      {
        const std::string link = prev + ".tmp";
        ::unlink(link.c_str());
        const bool linked = ::link(bin.c_str(), link.c_str()) == 0;
        if (std::rename((linked ? link : bin).c_str(), prev.c_str()) != 0)
          throw file_error(prev, errno);
      }
    } // namespace


    namespace
    {
      MPI_Comm
      world()
      {
        return MPI_COMM_WORLD;
      }

      /** The number of MPI ranks (1 if MPI is not started). */
      unsigned int
      n_ranks()
      {
        int started = 0;
        MPI_Initialized(&started);
        return started ? dealii::Utilities::MPI::n_mpi_processes(world()) : 1;
      }

      /**
       * The payload of N > 1 ranks: per rank its size (8 bytes, little
       * endian) and its bytes.
       */
      std::string
      join(const std::vector<std::string> &parts)
      {
        std::string joined;
        for (const auto &part : parts)
          {
            std::string size(8, '\0');
            for (unsigned int b = 0; b < 8; ++b)
              size[b] = static_cast<char>((part.size() >> (8 * b)) & 0xff);
            joined += size + part;
          }
        return joined;
      }

      std::vector<std::string>
      split(const std::string &joined)
      {
        std::vector<std::string> parts;
        std::size_t              at = 0;
        while (at + 8 <= joined.size())
          {
            std::uint64_t size = 0;
            for (unsigned int b = 0; b < 8; ++b)
              size |= std::uint64_t(static_cast<unsigned char>(joined[at + b]))
                      << (8 * b);
            parts.push_back(joined.substr(at + 8, size));
            at += 8 + size;
          }
        return parts;
      }

      /** Write the file (first rank); a failure as its message. */
      std::string
      write_file_with_backup(const std::string &dir, const std::string &file)
      {
        const std::string bin = dir + "/checkpoint.bin", prev = bin + ".prev",
                          tmp = dir + "/checkpoint.tmp";
        std::error_code ignore;
        const bool      has_last = std::filesystem::exists(bin, ignore);
        try
          {
            write_file(tmp, file, true);
            if (has_last)
              keep_previous(bin, prev);
            if (std::rename(tmp.c_str(), bin.c_str()) != 0)
              throw file_error(bin, errno);
            sync_to_disk(dir);
          }
        catch (const std::runtime_error &error)
          {
            ::unlink(tmp.c_str());
            return error.what() +
                   (std::filesystem::exists(bin, ignore) ?
                      "; the last checkpoint " + bin + " is unchanged" :
                      std::string());
          }
        return {};
      }

      /**
       * The checkpoint file's bytes if it is intact for `identity`, else
       * the message of the refusal (first rank).
       */
      std::string
      check_file(const std::string        &dir,
                 const CheckpointIdentity &identity,
                 std::string              &bytes)
      {
        const std::string bin = dir + "/checkpoint.bin", prev = bin + ".prev";
        std::string       problem;
        std::error_code   ignore;
        if (!std::filesystem::exists(bin, ignore))
          problem = "does not exist";
        else
          {
            bytes   = read_bytes(bin);
            problem = find_problem(bytes, identity);
          }
        if (problem.empty())
          return {};
        bool prev_intact = false;
        try
          {
            prev_intact = std::filesystem::exists(prev, ignore) &&
                          find_problem(read_bytes(prev), identity).empty();
          }
        catch (const std::runtime_error &)
          {}
        return bin + ": " + problem +
               (prev_intact ?
                  "; the previous checkpoint " + prev +
                    " is intact: move it to " + bin + " and resume" :
                  std::string());
      }
    } // namespace


    /**
     * Every rank serialises its part; on N > 1 ranks the first gathers
     * them into the one file (the header records N) and every rank learns
     * whether the write failed.
     */
    void
    write_checkpoint(
      const std::string                                            &dir,
      const CheckpointIdentity                                     &identity,
      const std::function<void(boost::archive::binary_oarchive &)> &save)
    {
      std::ostringstream payload;
      {
        boost::archive::binary_oarchive archive(payload);
        save(archive);
      }
      std::string file = payload.str();
      if (n_ranks() > 1)
        {
          const auto parts = dealii::Utilities::MPI::gather(world(), file, 0);
          file             = is_root() ? join(parts) : std::string();
        }
      std::string error;
      if (is_root())
        {
          file.insert(0, make_header(identity, file));
          error = write_file_with_backup(dir, file);
        }
      if (n_ranks() > 1)
        error = dealii::Utilities::MPI::broadcast(world(), error, 0);
      if (!error.empty())
        throw std::runtime_error(error);
    }


    void
    read_checkpoint(
      const std::string                                            &dir,
      const CheckpointIdentity                                     &identity,
      const std::function<void(boost::archive::binary_iarchive &)> &load)
    {
      std::string bytes, problem;
      if (is_root())
        problem = check_file(dir, identity, bytes);
      if (n_ranks() > 1)
        problem = dealii::Utilities::MPI::broadcast(world(), problem, 0);
      if (!problem.empty())
        throw std::invalid_argument(problem);

      std::string own = is_root() ? bytes.substr(header_size) : std::string();
      if (n_ranks() > 1)
        {
          std::vector<std::string> parts;
          if (is_root())
            parts = split(own);
          parts = dealii::Utilities::MPI::broadcast(world(), parts, 0);
          own   = parts.at(dealii::Utilities::MPI::this_mpi_process(world()));
        }
      std::istringstream payload(own);
      try
        {
          boost::archive::binary_iarchive archive(payload);
          load(archive);
        }
      catch (const boost::archive::archive_exception &error)
        {
          throw std::invalid_argument(
            dir +
            "/checkpoint.bin: cannot be read although its checksum is "
            "right (" +
            error.what() + "): a program error, please report it");
        }
    }
  } // namespace output
} // namespace rsfcycle
