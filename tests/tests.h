// Minimal test support for rsfcycle's ctest suite (deal.II's test
// mechanism from an external project): every unit test writes through
// deallog into the file "output", which deal_ii_pickup_tests() compares
// with NAME.output using numdiff.
#ifndef rsfcycle_tests_h
#define rsfcycle_tests_h

#include <deal.II/base/logstream.h>
#include <fstream>
#include <iomanip>

inline std::ofstream &
initlog(const unsigned int precision = 8)
{
  static std::ofstream logfile("output");
  logfile << std::setprecision(precision);
  dealii::deallog.attach(logfile);
  dealii::deallog.depth_console(0);
  return logfile;
}

#endif
