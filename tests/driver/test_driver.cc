// Test driver for whole-run tests (NAME.prm.in): runs rsfcycle on the given
// parameter file exactly as the executable does, then writes the file
// "output" with a digest of the run that contains no timings and no paths:
// the deterministic lines of the screen log (mesh, events, summary), the
// normal forces of the gravity equilibrium, and selected rows of
// time-series.csv with slip rates as log10(V/v0) and uplift in micrometres,
// so that numdiff's absolute tolerance sees a wrong sign or factor.
#include <cmath>
#include <deal.II/base/parameter_handler.h>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <rsfcycle/parameters.h>
#include <rsfcycle/problem_base.h>
#include <rsfcycle/scenes/scene.h>
#include <sstream>

namespace
{
  std::vector<std::vector<double>>
  read_csv(const std::string &file)
  {
    std::ifstream                    in(file);
    std::string                      line;
    std::vector<std::vector<double>> rows;
    std::getline(in, line); // header
    while (std::getline(in, line))
      {
        std::vector<double> row;
        std::stringstream   s(line);
        std::string         cell;
        while (std::getline(s, cell, ','))
          row.push_back(std::stod(cell));
        rows.push_back(row);
      }
    return rows;
  }

  template <int dim>
  void
  run(const rsfcycle::Parameters &parameters,
      dealii::ParameterHandler   &prm,
      std::ostream               &out)
  {
    const auto scene =
      rsfcycle::scenes::make_scene<dim>(parameters.run.scene, prm);
    std::ostringstream         log;
    rsfcycle::ProblemBase<dim> problem(parameters, *scene, log);
    problem.run(prm);
    std::cout << log.str();

    std::istringstream lines(log.str());
    std::string        line;
    while (std::getline(lines, line))
      if (line.rfind("Mesh:", 0) == 0 || line.rfind("    event", 0) == 0 ||
          line.rfind("Summary:", 0) == 0)
        out << line << "\n";

    double total = 0;
    for (const auto &node : problem.contact_nodes())
      total += node.normal_force;
    out << "sum of contact normal forces [N/m^(3-dim)]: " << total << "\n";

    const double v0 = scene->convergence_rate();
    const auto   rows =
      read_csv(parameters.run.output_directory + "/time-series.csv");
    out << "time-series rows: " << rows.size() << "\n";
    out << "t [s], log10(max V / v0), uplift at observation points [um]\n";
    const std::size_t n = rows.size();
    for (const std::size_t r : {n / 4, n / 2, 3 * n / 4, n - 1})
      {
        const auto &row = rows[r];
        out << row[0] << " " << std::log10(std::max(row[6], 1e-300) / v0);
        for (std::size_t k = 7; k < row.size(); ++k)
          out << " " << row[k] * 1e6;
        out << "\n";
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  try
    {
      if (argc != 2)
        throw std::invalid_argument("usage: rsfcycle_test_driver FILE.prm");
      dealii::ParameterHandler prm;
      rsfcycle::Parameters::declare_parameters(prm);
      prm.parse_input(argv[1]);
      rsfcycle::Parameters parameters;
      parameters.parse_parameters(prm);

      std::ofstream out("output");
      out << std::setprecision(8);
      if (parameters.run.dimension == 2)
        run<2>(parameters, prm, out);
      else
        run<3>(parameters, prm, out);
    }
  catch (std::exception &exc)
    {
      std::cerr << "error: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
