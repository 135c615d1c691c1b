// SPDX-License-Identifier: LGPL-2.1-or-later
// rsfcycle: earthquake cycles of a Kelvin-Voigt body on a rate-and-state
// base (Pipping, Kornhuber, Rosenau, Oncken 2016). The thin driver: read the
// parameter file, build the scene, run the generic solver.

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/parameter_handler.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <rsfcycle/output/files.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/scenes/registry.h>
#include <rsfcycle/version.h>
#include <streambuf>
#include <string>
#include <utility>

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
        throw rsfcycle::output::file_error(path, errno);
      if (file.sputc(c) == EOF)
        throw rsfcycle::output::file_error(path, errno);
      return c;
    }
    int
    sync() override
    {
      screen->pubsync();
      if (file.is_open() && file.pubsync() != 0)
        throw rsfcycle::output::file_error(path, errno);
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

  void
  print_help()
  {
    std::cout
      << "Usage: rsfcycle [--force] FILE.prm   (--force: overwrite the run folder)\n"
         "       rsfcycle --resume RUNDIR      continue an interrupted run from\n"
         "                                     its checkpoint (Ctrl-C or SIGTERM\n"
         "                                     write one and stop)\n"
         "       rsfcycle --print-parameters   all parameters with their\n"
         "                                     documentation and defaults\n"
         "       rsfcycle --version            version, git commit, deal.II, build\n"
         "       rsfcycle --help\n\n"
         "Paths in FILE.prm (include, Mesh file/File) are looked up beside\n"
         "FILE.prm first, then in the working directory.\n\n"
         "Scenes (entry `Scene`): "
      << rsfcycle::scenes::scene_names()
      << "\n"
         "  wedge: the laboratory subduction wedge of Pipping et al. (2016),\n"
         "         2D (plane strain) or 3D (`Dimension = 3`), parameters in\n"
         "         subsection `Wedge`.\n"
         "  mesh-file: your own body from a gmsh mesh (2D, antiplane or 3D):\n"
         "         boundary roles, materials per volume tag and friction as\n"
         "         functions of position in subsection `Mesh file`\n"
         "         (doc/mesh-file.md).\n"
         "  spring-slider: one block on a rate-and-state base loaded\n"
         "         through a spring (no mesh), parameters in subsection\n"
         "         `Spring slider`.\n\n"
         "Ready-made files in prm/:\n"
         "  wedge-2d.prm          the paper's 2D laboratory wedge (the demo)\n"
         "  wedge-2d-paper.prm    the same at the paper's resolution\n"
         "  wedge-2d-mesh.prm     the 2D wedge from a gmsh mesh (mesh-file)\n"
         "  wedge-3d.prm          the 3D laboratory wedge\n"
         "  wedge-3d-paper.prm    the 3D wedge at the paper's resolution\n"
         "  subduction-2d.prm     a kilometre-scale subduction zone (mesh-file)\n"
         "  subduction-2d-slab.prm  the same with a deformable slab "
         "(split fault)\n"
         "  seas-bp1-qd.prm       SEAS BP1-QD (antiplane, quasi-dynamic)\n"
         "  seas-bp1-fd.prm       SEAS BP1-FD (antiplane, fully dynamic)\n"
         "  seas-bp2-qd.prm       SEAS BP2-QD (BP1-QD with D_c = 4 mm)\n"
         "  seas-bp3-qd.prm       SEAS BP3-QD (60-degree thrust between two "
         "deformable sides)\n"
         "  seas-bp3-fd.prm       SEAS BP3-FD (the same, fully dynamic; "
         "volume method, one rank)\n"
         "  seas-bp4-qd.prm       SEAS BP4-QD (3D whole space, free rake)\n"
         "  seas-bp5-qd.prm       SEAS BP5-QD (3D half-space, free rake)\n"
         "  seas-bp6-qd-a.prm     SEAS BP6-QD-A (fluid injection, ageing law)\n"
         "  seas-bp6-qd-s.prm     SEAS BP6-QD-S (the same, slip law)\n"
         "  seas-bp7-qd.prm       SEAS BP7-QD (3D, a 200 m disc, nucleation)\n"
         "  spring-slider.prm     a spring-slider in stick-slip\n"
         "  spring-slider-stable.prm  a stable spring-slider\n";
  }

  /**
   * deal.II's exception texts span many lines (file, line, condition,
   * "Additional information:"): keep only the information, on one line.
   */
  std::string
  one_line(const std::string &what)
  {
    std::string       text   = what;
    const std::string marker = "Additional information:";
    if (const auto pos = text.find(marker); pos != std::string::npos)
      text = text.substr(pos + marker.size());
    if (const auto pos = text.find("Stacktrace:"); pos != std::string::npos)
      text = text.substr(0, pos);
    std::string result;
    bool        space = false;
    for (const char c : text)
      if (std::isspace(static_cast<unsigned char>(c)))
        space = !result.empty();
      else
        {
          if (space)
            result += ' ';
          result += c;
          space = false;
        }
    return result;
  }

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

  /**
   * The number of processes and this process's rank as the MPI launcher
   * (Open MPI's mpirun, or a PMI launcher such as MPICH's or Slurm's) set
   * them in the environment, known before MPI is started (the spring-slider
   * never starts it); 1 and 0 without a launcher.
   */
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

  /**
   * Build the scene's simulation (bad input fails here, before anything is
   * written), start MPI if it needs it (one thread either way), let the
   * simulation prepare what may still refuse the input, prepare the run
   * folder and the log, run. Returns false if the run was interrupted by
   * a signal.
   */
  bool
  run(const rsfcycle::Parameters                              &parameters,
      dealii::ParameterHandler                                &prm,
      const bool                                               resume,
      std::optional<dealii::Utilities::MPI::MPI_InitFinalize> &mpi,
      int                                                     &argc,
      char                                                  **&argv)
  {
    const auto simulation = rsfcycle::scenes::make_simulation(parameters, prm);
    const unsigned int n_processes = launched_processes().first;
    if (!simulation->needs_mpi() && n_processes > 1)
      throw std::invalid_argument(
        "Scene = " + parameters.run.scene + " runs on one MPI rank, not on " +
        std::to_string(n_processes) + ": start it without mpirun");
    if (simulation->needs_mpi())
      mpi.emplace(argc, argv, 1);
    else
      dealii::MultithreadInfo::set_thread_limit(1);
    if (n_processes > 1 &&
        parameters.solver.linear_correction ==
          rsfcycle::SolverParameters::LinearCorrection::direct)
      throw std::invalid_argument(
        "Solver/Linear correction = direct runs on one MPI rank, not on " +
        std::to_string(n_processes) +
        ": choose multigrid or amg, or start it without mpirun");
    if (n_processes > 1 && parameters.solver.direct_fallback)
      throw std::invalid_argument(
        "Solver/Direct fallback = true runs on one MPI rank, not on " +
        std::to_string(n_processes) + ": set it false, or start it without " +
        "mpirun");
    simulation->prepare(resume);
    // The first rank prepares the folder and writes the log; every rank
    // learns whether the folder was refused.
    const bool root = rsfcycle::output::is_root();
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
          refused = dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, refused);
        if (!refused.empty())
          throw std::invalid_argument(refused);
      }
    LogBuffer    buffer(std::cout.rdbuf(),
                     parameters.run.output_directory + "/log.txt",
                     resume);
    NullBuffer   nothing;
    std::ostream log(root ? static_cast<std::streambuf *>(&buffer) : &nothing);
    log.exceptions(std::ios::badbit);
    const bool completed = simulation->run(prm, log, resume);
    log.flush();
    return completed;
  }
} // namespace


int
main(int argc, char **argv)
{
  // Trilinos (the amg correction) needs MPI; one process, one thread. It is
  // started only for a run whose simulation needs it (run()): its start-up
  // is most of the program start (benchmarks/time-stepping/README.md), which
  // --help, --print-parameters, bad input and the spring-slider need not
  // pay.
  std::optional<dealii::Utilities::MPI::MPI_InitFinalize> mpi;
  // A file over the size limit (ulimit -f) is then a failed write (EFBIG),
  // reported with the file's name, instead of a kill by SIGXFSZ.
  std::signal(SIGXFSZ, SIG_IGN);
  try
    {
      dealii::ParameterHandler prm;
      rsfcycle::scenes::declare_parameters(prm);

      std::string file, resume_dir;
      bool        force = false;
      for (int i = 1; i < argc; ++i)
        {
          const std::string argument = argv[i];
          if (argument == "--help" || argument == "-h")
            {
              print_help();
              return 0;
            }
          else if (argument == "--version")
            {
              std::cout << rsfcycle::version::describe() << std::endl;
              return 0;
            }
          else if (argument == "--print-parameters")
            {
              prm.print_parameters(std::cout, dealii::ParameterHandler::PRM);
              return 0;
            }
          else if (argument == "--force")
            force = true;
          else if (argument == "--resume" && i + 1 < argc && file.empty())
            {
              resume_dir = argv[++i];
              file       = resume_dir + "/parameters.prm";
            }
          else if (argument.rfind("-", 0) == 0 || !file.empty())
            throw std::invalid_argument("unknown argument " + argument +
                                        " (see rsfcycle --help)");
          else
            file = argument;
        }
      if (file.empty())
        {
          print_help();
          return 1;
        }
      if (!std::filesystem::is_regular_file(file))
        throw std::invalid_argument("parameter file " + file +
                                    " does not exist");

      rsfcycle::scenes::parse_parameter_file(prm, file);
      rsfcycle::Parameters parameters;
      parameters.parse_parameters(prm);
      if (force)
        parameters.run.overwrite_output = true;
      const bool resume = !resume_dir.empty();
      if (resume)
        parameters.run.output_directory = resume_dir;
      if (!run(parameters, prm, resume, mpi, argc, argv))
        return 130;
    }
  catch (std::exception &exc)
    {
      // every process fails alike; one line from the first
      if (launched_processes().second == 0)
        std::cerr << "rsfcycle: error: " << one_line(exc.what()) << std::endl;
      return 1;
    }
  catch (...)
    {
      std::cerr << "rsfcycle: unknown exception" << std::endl;
      return 1;
    }
  return 0;
}
