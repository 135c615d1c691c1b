// SPDX-License-Identifier: LGPL-2.1-or-later
// Minimal test support for rsfcycle's ctest suite (deal.II's test
// mechanism from an external project): every unit test writes through
// deallog into the file "output", which deal_ii_pickup_tests() compares
// with NAME.output using numdiff.
#ifndef rsfcycle_tests_h
#define rsfcycle_tests_h

#include <cctype>
#include <deal.II/base/logstream.h>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

inline std::ofstream &
initlog(const unsigned int precision = 8)
{
  static std::ofstream logfile("output");
  logfile << std::setprecision(precision);
  dealii::deallog.attach(logfile);
  dealii::deallog.depth_console(0);
  return logfile;
}


/**
 * The rows of a CSV file after its header, as numbers ("-" and empty cells
 * as 0).
 */
inline std::vector<std::vector<double>>
read_csv(const std::string &file)
{
  std::ifstream                    in(file);
  std::string                      line;
  std::vector<std::vector<double>> rows;
  std::getline(in, line);
  while (std::getline(in, line))
    {
      std::vector<double> row;
      std::stringstream   s(line);
      std::string         cell;
      while (std::getline(s, cell, ','))
        row.push_back(cell == "-" || cell.empty() ? 0. : std::stod(cell));
      rows.push_back(row);
    }
  return rows;
}

/** The numeric rows of a SEAS file (comments and the names line left out). */
inline std::vector<std::vector<double>>
read_seas(const std::string &file)
{
  std::ifstream                    in(file);
  std::string                      line;
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line))
    {
      if (line.empty() || line[0] == '#' || std::isalpha(line[0]))
        continue;
      std::vector<double> row;
      std::stringstream   s(line);
      double              value;
      while (s >> value)
        row.push_back(value);
      rows.push_back(row);
    }
  return rows;
}

/** Whether the test runs on more than one MPI rank (NAME.mpirun=N). */
inline bool
on_ranks()
{
  return dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1;
}

/** x with `digits` digits after the point (a rounded digest value). */
inline std::string
to_fixed(const double x, const int digits)
{
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << x;
  return out.str();
}

#endif
