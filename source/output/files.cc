// SPDX-License-Identifier: LGPL-2.1-or-later
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <deal.II/base/mpi.h>
#include <fcntl.h>
#include <filesystem>
#include <rsfcycle/output/files.h>
#include <rsfcycle/version.h>
#include <sstream>
#include <unistd.h>

namespace rsfcycle
{
  namespace output
  {
    bool
    is_root()
    {
      int started = 0;
      MPI_Initialized(&started);
      return started == 0 ||
             dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    }


    int
    max_over_ranks(const int value)
    {
      int started = 0;
      MPI_Initialized(&started);
      return started == 0 ? value :
                            dealii::Utilities::MPI::max(value, MPI_COMM_WORLD);
    }


    std::runtime_error
    file_error(const std::string &path, const int error)
    {
      return std::runtime_error(
        path + ": " + (error != 0 ? std::strerror(error) : "write failed"));
    }


    void
    write_file(const std::string &path,
               const std::string &content,
               const bool         durable)
    {
      const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (fd < 0)
        throw file_error(path, errno);
      const char *data   = content.data();
      std::size_t remain = content.size();
      int         error  = 0;
      while (remain > 0 && error == 0)
        {
          const ssize_t n = ::write(fd, data, remain);
          if (n > 0)
            {
              data += n;
              remain -= n;
            }
          else if (n < 0 && errno != EINTR)
            error = errno;
        }
      if (error == 0 && durable && ::fsync(fd) != 0)
        error = errno;
      // close() reports what a file system defers (NFS, quota)
      if (::close(fd) != 0 && error == 0)
        error = errno;
      if (error != 0)
        {
          ::unlink(path.c_str());
          throw file_error(path, error);
        }
    }


    void
    replace_file(const std::string &path, const std::string &content)
    {
      const std::string tmp = path + ".tmp";
      write_file(tmp, content);
      if (std::rename(tmp.c_str(), path.c_str()) != 0)
        {
          const int error = errno;
          ::unlink(tmp.c_str());
          throw file_error(path, error);
        }
    }


    void
    sync_to_disk(const std::string &path)
    {
      // O_RDONLY suffices: fsync acts on the file (or folder), not on the
      // descriptor
      const int fd = ::open(path.c_str(), O_RDONLY);
      if (fd < 0)
        throw file_error(path, errno);
      const int error = (::fsync(fd) != 0) ? errno : 0;
      ::close(fd);
      if (error != 0)
        throw file_error(path, error);
    }


    void
    cut_to_sizes(const std::vector<std::string> &paths,
                 const std::vector<long long>   &sizes)
    {
      for (unsigned int i = 0; i < paths.size(); ++i)
        {
          std::error_code error;
          const auto      size = std::filesystem::file_size(paths[i], error);
          if (error)
            throw std::invalid_argument(paths[i] + ": " + error.message());
          if (size < static_cast<std::uintmax_t>(sizes[i]))
            throw std::invalid_argument(
              paths[i] + ": " + std::to_string(size) +
              " bytes, shorter than the " + std::to_string(sizes[i]) +
              " bytes the checkpoint recorded: the file was cut after the "
              "checkpoint was written");
        }
      for (unsigned int i = 0; i < paths.size(); ++i)
        {
          std::error_code error;
          std::filesystem::resize_file(paths[i], sizes[i], error);
          if (error)
            throw std::runtime_error(paths[i] + ": " + error.message());
        }
    }


    void
    write_parameters(const std::string              &dir,
                     const dealii::ParameterHandler &prm)
    {
      if (!is_root())
        return;
      std::filesystem::create_directories(dir);
      std::ostringstream text;
      text << "# " << version::describe() << "\n";
      prm.print_parameters(text, dealii::ParameterHandler::PRM);
      write_file(dir + "/parameters.prm", text.str());
    }
  } // namespace output
} // namespace rsfcycle
