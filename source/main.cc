// SPDX-License-Identifier: LGPL-2.1-or-later
// rsfcycle: earthquake cycles of a Kelvin-Voigt body on a rate-and-state
// base (Pipping, Kornhuber, Rosenau, Oncken 2016). The command line: it
// parses the arguments and the parameter file and hands the run to the
// composition root (app/simulation.h).

#include <algorithm>
#include <cctype>
#include <csignal>
#include <cstdlib>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <rsfcycle/app/simulation.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/scenes/scenes.h>
#include <rsfcycle/version.h>
#include <string>
#include <utility>

namespace
{
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
         "  seas-bp5-fd.prm       SEAS BP5-FD (BP5 with inertia: explicit steps in events)\n"
         "  seas-bp6-qd-a.prm     SEAS BP6-QD-A (fluid injection, ageing law)\n"
         "  seas-bp6-qd-s.prm     SEAS BP6-QD-S (the same, slip law)\n"
         "  seas-bp7-qd.prm       SEAS BP7-QD (3D, a 200 m disc, nucleation)\n"
         "  seas-bp8-qd-gs.prm    SEAS BP8-QD-GS (3D, injection, the pore "
         "pressure diffusing from a Gaussian source)\n"
         "  seas-bp8-qd-pw.prm    SEAS BP8-QD-PW (the same from a Peaceman "
         "well)\n"
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
      rsfcycle::app::declare_parameters(prm);

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

      rsfcycle::app::parse_parameter_file(prm, file);
      rsfcycle::Parameters parameters;
      parameters.parse_parameters(prm);
      if (force)
        parameters.run.overwrite_output = true;
      const bool resume = !resume_dir.empty();
      if (resume)
        parameters.run.output_directory = resume_dir;
      if (!rsfcycle::app::run(parameters, prm, resume, mpi, argc, argv))
        return 130;
    }
  catch (std::exception &exc)
    {
      // every process fails alike; one line from the first
      if (rsfcycle::app::launched_processes().second == 0)
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
