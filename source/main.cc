// rsfcycle: earthquake cycles of a Kelvin-Voigt body on a rate-and-state
// base (Pipping, Kornhuber, Rosenau, Oncken 2016). The thin driver: read the
// parameter file, build the scene, run the generic solver.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <rsfcycle/parameters.h>
#include <rsfcycle/problem_base.h>
#include <rsfcycle/scenes/scene.h>
#include <streambuf>
#include <string>

namespace
{
  /** A stream buffer that writes to two others: the screen and log.txt. */
  class TeeBuffer : public std::streambuf
  {
  public:
    TeeBuffer(std::streambuf *first, std::streambuf *second)
      : first(first)
      , second(second)
    {}

  protected:
    int
    overflow(int c) override
    {
      if (c == EOF)
        return !EOF;
      const int r1 = first->sputc(c), r2 = second->sputc(c);
      return (r1 == EOF || r2 == EOF) ? EOF : c;
    }
    int
    sync() override
    {
      const int r1 = first->pubsync(), r2 = second->pubsync();
      return (r1 == 0 && r2 == 0) ? 0 : -1;
    }

  private:
    std::streambuf *first, *second;
  };

  void
  print_help()
  {
    std::cout
      << "Usage: rsfcycle FILE.prm\n"
         "       rsfcycle --print-parameters   all parameters with their\n"
         "                                     documentation and defaults\n"
         "       rsfcycle --help\n\n"
         "Scenes (entry `Scene`): "
      << rsfcycle::scenes::scene_names()
      << "\n"
         "  wedge: the laboratory subduction wedge of Pipping et al. (2016),\n"
         "         2D (plane strain) or 3D (`Dimension = 3`), parameters in\n"
         "         subsection `Wedge`.\n\n"
         "Ready-made files: prm/wedge-2d.prm (default resolution),\n"
         "prm/wedge-2d-paper.prm (the paper's resolution).\n";
  }

  template <int dim>
  void
  run(const rsfcycle::Parameters &parameters, dealii::ParameterHandler &prm)
  {
    const auto scene =
      rsfcycle::scenes::make_scene<dim>(parameters.run.scene, prm);
    std::filesystem::create_directories(parameters.run.output_directory);
    std::ofstream log_file(parameters.run.output_directory + "/log.txt");
    TeeBuffer     tee(std::cout.rdbuf(), log_file.rdbuf());
    std::ostream  log(&tee);
    rsfcycle::ProblemBase<dim> problem(parameters, *scene, log);
    problem.run(prm);
  }
} // namespace


int
main(int argc, char **argv)
{
  try
    {
      dealii::ParameterHandler prm;
      rsfcycle::Parameters::declare_parameters(prm);

      if (argc != 2)
        {
          print_help();
          return 1;
        }
      const std::string argument = argv[1];
      if (argument == "--help" || argument == "-h")
        {
          print_help();
          return 0;
        }
      if (argument == "--print-parameters")
        {
          prm.print_parameters(std::cout, dealii::ParameterHandler::PRM);
          return 0;
        }

      prm.parse_input(argument);
      rsfcycle::Parameters parameters;
      parameters.parse_parameters(prm);
      if (parameters.run.dimension == 2)
        run<2>(parameters, prm);
      else
        run<3>(parameters, prm);
    }
  catch (std::exception &exc)
    {
      std::cerr << "rsfcycle: error: " << exc.what() << std::endl;
      return 1;
    }
  catch (...)
    {
      std::cerr << "rsfcycle: unknown exception" << std::endl;
      return 1;
    }
  return 0;
}
