// SPDX-License-Identifier: LGPL-2.1-or-later
// The run of a parsed parameter file: MPI, the run folder and its log, the
// simulation.
#include <cerrno>
#include <cstdlib>
#include <deal.II/base/multithread_info.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <rsfcycle/app/simulation.h>
#include <rsfcycle/output/files.h>
#include <stdexcept>
#include <streambuf>

namespace rsfcycle
{
  namespace app
  {
    namespace
    {
      /**
       * The buffer of the log stream: every character goes to the screen and
       * to log.txt in the run folder. log.txt is opened at the first character
       * (appended to on resume), so that a run refused before its first log
       * line, such as a resume from a damaged checkpoint, leaves the folder as
       * it was. A failed write to log.txt throws "log.txt: reason" (the stream
       * passes it on with exceptions(badbit)); the screen's failures are
       * ignored, log.txt being the record.
       */
      class LogBuffer : public std::streambuf
      {
      public:
        LogBuffer(std::streambuf *screen, const std::string &path, bool append)
          : screen(screen)
          , path(path)
          , mode(std::ios::out | (append ? std::ios::app : std::ios::trunc))
        {}

      protected:
        int
        overflow(int c) override
        {
          if (c == EOF)
            return !EOF;
          screen->sputc(c);
          if (!file.is_open() && !file.open(path, mode))
            throw output::file_error(path, errno);
          if (file.sputc(c) == EOF)
            throw output::file_error(path, errno);
          return c;
        }
        int
        sync() override
        {
          screen->pubsync();
          if (file.is_open() && file.pubsync() != 0)
            throw output::file_error(path, errno);
          return 0;
        }

      private:
        std::streambuf          *screen;
        const std::string        path;
        const std::ios::openmode mode;
        std::filebuf             file;
      };

      /** The log of the ranks other than the first: nothing is written. */
      class NullBuffer : public std::streambuf
      {
      protected:
        int
        overflow(int c) override
        {
          return c == EOF ? !EOF : c;
        }
      };


      /**
       * The run folder must not hold an earlier run unless the user asked to
       * overwrite it; it must be writable. Checked before anything is written.
       */
      void
      prepare_output_directory(const std::string &dir, const bool overwrite)
      {
        namespace fs = std::filesystem;
        if (fs::exists(dir) && !fs::is_directory(dir))
          throw std::invalid_argument("Output directory = " + dir +
                                      ": exists and is not a folder");
        if (fs::exists(dir) && !fs::is_empty(dir) && !overwrite)
          throw std::invalid_argument(
            "Output directory = " + dir +
            ": holds an earlier run; choose another folder, or use --force "
            "(or set Overwrite output = true) to overwrite it");
        std::error_code error;
        fs::create_directories(dir, error);
        // an earlier run's SEAS files (their names depend on the benchmark and
        // its stations, so the new run might not write over each of them): an
        // upload must not carry stray files; removed only in a folder whose
        // parameters.prm says rsfcycle wrote it
        std::string first_line;
        std::getline(std::ifstream(dir + "/parameters.prm"), first_line);
        if (overwrite && first_line.rfind("# rsfcycle ", 0) == 0)
          for (const auto &entry : fs::directory_iterator(dir, error))
            {
              const std::string name = entry.path().filename().string();
              const bool        seas = name.rfind("fltst_", 0) == 0 ||
                                name.rfind("srfst_", 0) == 0 ||
                                name.rfind("blkst_", 0) == 0 ||
                                (entry.path().extension() == ".dat");
              if (seas && entry.is_regular_file())
                fs::remove(entry.path(), error);
            }
        const std::string probe = dir + "/.rsfcycle-write-test";
        if (error || !std::ofstream(probe))
          throw std::invalid_argument("Output directory = " + dir +
                                      ": cannot be created or written");
        fs::remove(probe);
      }
    } // namespace


    std::pair<unsigned int, unsigned int>
    launched_processes()
    {
      for (const auto &[size, rank] :
           {std::pair{"OMPI_COMM_WORLD_SIZE", "OMPI_COMM_WORLD_RANK"},
            std::pair{"PMI_SIZE", "PMI_RANK"},
            std::pair{"SLURM_NTASKS", "SLURM_PROCID"}})
        if (const char *n = std::getenv(size))
          {
            const char *r = std::getenv(rank);
            return {std::max(1, std::atoi(n)), r ? std::atoi(r) : 0};
          }
      return {1, 0};
    }


    bool
    run(const Parameters                                        &parameters,
        dealii::ParameterHandler                                &prm,
        const bool                                               resume,
        std::optional<dealii::Utilities::MPI::MPI_InitFinalize> &mpi,
        int                                                     &argc,
        char                                                  **&argv)
    {
      // make_simulation() checks every rule across entries (check_run())
      const auto simulation = make_simulation(parameters, prm);
      if (simulation->needs_mpi())
        mpi.emplace(argc, argv, 1);
      else
        dealii::MultithreadInfo::set_thread_limit(1);
      simulation->prepare(resume);
      // The first rank prepares the folder and writes the log; every rank
      // learns whether the folder was refused.
      const bool root = output::is_root();
      if (!resume)
        {
          std::string refused;
          if (root)
            try
              {
                prepare_output_directory(parameters.run.output_directory,
                                         parameters.run.overwrite_output);
              }
            catch (const std::invalid_argument &error)
              {
                refused = error.what();
              }
          if (mpi)
            refused =
              dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, refused);
          if (!refused.empty())
            throw std::invalid_argument(refused);
        }
      LogBuffer    buffer(std::cout.rdbuf(),
                       parameters.run.output_directory + "/log.txt",
                       resume);
      NullBuffer   nothing;
      std::ostream log(root ? static_cast<std::streambuf *>(&buffer) :
                              &nothing);
      log.exceptions(std::ios::badbit);
      const bool completed = simulation->run(prm, log, resume);
      log.flush();
      return completed;
    }
  } // namespace app
} // namespace rsfcycle
