// SPDX-License-Identifier: LGPL-2.1-or-later
// SEAS BP5-QD (prm/seas-bp5-qd.prm, the shipped set-up) on its coarse 4 km
// cells (no local refinement; 240 contact nodes, one rank, the
// Green's-function method) through its first event, which the nucleation
// patch's initial slip rate V_i = 0.03 m/s starts at once. Checks the 3D
// SEAS files (output::SeasPlaneFiles; yes/no lines):
//  - the 30 files of the BP5-QD description are written: 10
//    fltst_strk+XXdp+YY, 9 blkst_*, global.dat, rupture.dat, catalog.dat
//    and the 8 strike and depth profiles slip_2, slip_3, stress_2,
//    stress_3 (their first row the positions: -38 ... 38 km along strike,
//    0 ... 40 km down dip, the creeping node at 40 km included);
//  - the first rows of the stations (t = 0) equal the benchmark's initial
//    condition in closed form (BP5: the steady state of V_p with tau_0 =
//    sigma_n a asinh(V/(2 V_0) exp((f_0 + b ln(V_0 / V_p))/a)) + eta V):
//    at (0, 10) km (a_0, V_p), at (-24, 10) km (a_0 on the nucleation
//    patch, V_i = 0.03 m/s, L = 0.13 m), at (-36, 0) km (a_max, V_p): zero
//    slip, log10 V, shear stress tau_0 - eta V and log10 theta =
//    log10(L/V_p), to 1e-3;
//  - rupture.dat lists the nodes of the region |x2| <= 34, x3 <= 20 km
//    (the description's); its earliest times (t = 0) are nodes of the
//    nucleation patch (x2 in [-30, -18], x3 in [4, 16] km) only, among
//    them its four inner nodes (on the patch's edges the quadrature of the
//    prestress mixes the patch's and the neighbours' values, and those
//    nodes start slower); the rupture then spreads: along strike at 8 km
//    depth east of the patch the arrival times grow with the distance;
//  - catalog.dat has the first event from t = 0 to its end, over a
//    rupture area of at least the patch (144 km^2), with a positive mean
//    slip and a mean shear stress that drops;
//  - the rake stays free but near pure strike slip (|slip_3| < 5 % of
//    slip_2 at the stations that slip more than 1 m; it turns at the
//    rectangle's ends), the slip is right-lateral (slip_2 > 0) and the
//    surface station beside the fault at (0, 8, 0) km moves along +x2 by
//    less than half the fault's slip at (0, 0) km (the antisymmetric half
//    of the slip, spread over distance);
//  - blkst's rates are the time derivatives of its displacements (each
//    component's change over the event against the trapezoidal integral
//    of its rate, to 1 % of the largest change).
// Printed: the first event's peak slip rate, its end (the maximum slip rate
// through 1 mm/s, between rows; not the run's last row, whose step the
// controller sizes; to 50 s: it moved from 744 to 737 s with the rounding of
// another machine's arithmetic, the rows near the end being seconds apart)
// and the slips at two stations (rounded: the run is coarse; its resolution
// is not the benchmark's, benchmarks/seas-bp5/README.md).
#include "run_model.h"
#include "tests.h"

#include <cmath>
#include <deal.II/base/mpi.h>
#include <filesystem>
#include <iomanip>

using namespace rsfcycle;

namespace
{
  const char *
  yes(const bool ok)
  {
    return ok ? "yes" : "no";
  }

  /** BP5's tau_0 - eta V [MPa] at slip rate V with a. */
  double
  initial_friction(const double a, const double V)
  {
    return 25 * a *
           std::asinh(V / 2e-6 *
                      std::exp((0.6 + 0.03 * std::log(1e-6 / 1e-9)) / a));
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(6);
  const std::string        source = SOURCE_DIR;
  dealii::ParameterHandler prm;
  app::declare_parameters(prm);
  app::parse_parameter_file(prm, source + "/../prm/seas-bp5-qd.prm");
  std::filesystem::remove_all("bp5-run"); // (the files of an earlier run)
  prm.parse_input_from_string("set Output directory = bp5-run\n"
                              "set Overwrite output = true\n"
                              "set Stop after events = 1\n"
                              "subsection Mesh\n"
                              "  set Local refinements = 0\n"
                              "end\n"
                              "subsection Output\n"
                              "  set Progress interval = 1e9\n"
                              "end\n");
  run_model<3>(prm);
  const std::string out = "bp5-run/";

  const std::vector<std::string> stations = {"strk-36dp+00",
                                             "strk-16dp+00",
                                             "strk+00dp+00",
                                             "strk+16dp+00",
                                             "strk+36dp+00",
                                             "strk-24dp+10",
                                             "strk-16dp+10",
                                             "strk+00dp+10",
                                             "strk+16dp+10",
                                             "strk+00dp+22"};
  unsigned int                   files    = 0;
  for (const auto &name : stations)
    files += std::filesystem::exists(out + "fltst_" + name);
  for (const std::string name : {"strk+00fn+08dp+00",
                                 "strk+00fn+08dp+10",
                                 "strk+00fn+16dp+00",
                                 "strk+00fn+16dp+10",
                                 "strk+00fn+32dp+00",
                                 "strk+00fn+32dp+10",
                                 "strk+00fn+48dp+00",
                                 "strk+16fn+08dp+00",
                                 "strk-16fn+08dp+00"})
    files += std::filesystem::exists(out + "blkst_" + name);
  files += std::filesystem::exists(out + "global.dat") +
           std::filesystem::exists(out + "rupture.dat") +
           std::filesystem::exists(out + "catalog.dat");
  bool positions = true;
  for (const std::string line : {"strike", "depth"})
    for (const std::string field : {"slip_2", "slip_3", "stress_2", "stress_3"})
      {
        const auto rows = read_seas(out + field + "_" + line + ".dat");
        files += !rows.empty();
        // row 1: 0 0, then 77 (x2 -38 ... 38 km) or 41 (0 ... 40 km)
        // positions
        positions = positions && !rows.empty() &&
                    rows[0].size() == (line == "strike" ? 79u : 43u) &&
                    rows.size() > 2 && rows[1].size() == rows[0].size();
      }
  dealii::deallog << "30 SEAS files, profiles with their positions: "
                  << yes(files == 30 && positions) << std::endl;

  // columns: t slip_2 slip_3 slip_rate_2 slip_rate_3 shear_stress_2
  // shear_stress_3 state
  double initial_error = 0;
  for (const auto &[name, a, V, L] :
       std::vector<std::tuple<std::string, double, double, double>>{
         {"strk+00dp+10", 0.004, 1e-9, 0.14},
         {"strk-24dp+10", 0.004, 0.03, 0.13},
         {"strk-36dp+00", 0.04, 1e-9, 0.14}})
    {
      const auto first = read_seas(out + "fltst_" + name).front();
      initial_error    = std::max({initial_error,
                                   std::abs(first[0]),
                                   std::abs(first[1]),
                                   std::abs(first[2]),
                                   std::abs(first[3] - std::log10(V)),
                                   std::abs(first[5] - initial_friction(a, V)),
                                   std::abs(first[6]),
                                   std::abs(first[7] - std::log10(L / 1e-9))});
    }
  dealii::deallog << "stations start at the closed-form initial condition "
                     "(1e-3): "
                  << yes(initial_error < 1e-3) << std::endl;

  // rupture.dat: x2 x3 t
  const auto rupture = read_seas(out + "rupture.dat");
  double     first_t = 1e9;
  bool       region  = !rupture.empty();
  for (const auto &r : rupture)
    {
      first_t = std::min(first_t, r[2]);
      region  = region && std::abs(r[0]) <= 34e3 && r[1] <= 20e3;
    }
  unsigned int first_rows = 0, inner = 0;
  bool         in_patch = true;
  for (const auto &r : rupture)
    if (r[2] == first_t)
      {
        ++first_rows;
        in_patch = in_patch && r[0] >= -30e3 && r[0] <= -18e3 && r[1] >= 4e3 &&
                   r[1] <= 16e3;
        inner += r[0] > -30e3 && r[0] < -18e3 && r[1] > 4e3 && r[1] < 16e3;
      }
  std::vector<std::pair<double, double>> front; // x2, t at 8 km depth
  for (const auto &r : rupture)
    if (std::abs(r[1] - 8e3) < 1 && r[0] > -18e3 && r[2] < 1e9)
      front.emplace_back(r[0], r[2]);
  std::sort(front.begin(), front.end());
  bool spreads = front.size() >= 3;
  for (unsigned int i = 1; i < front.size(); ++i)
    spreads = spreads && front[i].second > front[i - 1].second;
  dealii::deallog << "rupture.dat: nucleation-patch nodes at the first step "
                     "(its 4 inner ones among them), then a front spreading "
                     "along strike: "
                  << yes(region && first_t == 0 && in_patch && inner == 4 &&
                         spreads)
                  << " (" << first_rows << " nodes at the first step, "
                  << front.size() << " east of the patch at 8 km)" << std::endl;

  // catalog.dat: event_no t_start t_end rup_area avg_stress_start
  // avg_stress_end avg_slip
  const auto catalog = read_seas(out + "catalog.dat");
  dealii::deallog << "catalog.dat: the first event from t = 0, over at least "
                     "the patch, slipping, its stress dropping: "
                  << yes(!catalog.empty() && catalog[0][0] == 1 &&
                         catalog[0][1] == 0 && catalog[0][2] > 0 &&
                         catalog[0][3] >= 144e6 && catalog[0][6] > 0 &&
                         catalog[0][5] < catalog[0][4])
                  << std::endl;

  bool rake = true;
  for (const auto &name : stations)
    {
      const auto last = read_seas(out + "fltst_" + name).back();
      rake            = rake && last[1] > 0 &&
             (last[1] < 1 || std::abs(last[2]) < 0.05 * last[1]);
    }
  const double fault_slip = read_seas(out + "fltst_strk+00dp+00").back()[1];
  const auto   block      = read_seas(out + "blkst_strk+00fn+08dp+00");
  const double moved      = block.back()[2] - block.front()[2];
  dealii::deallog << "right-lateral, near pure strike slip; the surface "
                     "beside the fault follows by less than half: "
                  << yes(rake && moved > 0 && moved < 0.5 * fault_slip)
                  << std::endl;

  // blkst: disp_1..3 against the integral of vel_1..3
  double largest = 0, mismatch = 0;
  for (unsigned int c = 1; c <= 3; ++c)
    {
      double integral = 0;
      for (unsigned int i = 1; i < block.size(); ++i)
        integral += 0.5 * (block[i][c + 3] + block[i - 1][c + 3]) *
                    (block[i][0] - block[i - 1][0]);
      const double change = block.back()[c] - block.front()[c];
      largest             = std::max(largest, std::abs(change));
      mismatch            = std::max(mismatch, std::abs(integral - change));
    }
  const bool rates = largest > 0 && mismatch <= 0.01 * largest;
  dealii::deallog << "blkst velocities integrate to the displacements (1 %): "
                  << yes(rates) << std::endl;

  // the peak, and the end of the event: where log10 V falls through -3
  // (linear between the rows)
  const auto global = read_seas(out + "global.dat");
  double     peak = -100, end = 0;
  for (unsigned int i = 0; i < global.size(); ++i)
    {
      peak = std::max(peak, global[i][1]);
      if (i > 0 && global[i - 1][1] >= -3 && global[i][1] < -3)
        end = global[i - 1][0] + (global[i][0] - global[i - 1][0]) *
                                   (global[i - 1][1] + 3) /
                                   (global[i - 1][1] - global[i][1]);
    }
  std::ostringstream digest;
  digest << std::fixed << std::setprecision(1) << "first event: peak log10 V "
         << peak << ", below 1 mm/s from t " << std::setprecision(0)
         << 50 * std::round(end / 50) << " s; slip at (0, 10) km "
         << std::setprecision(1)
         << read_seas(out + "fltst_strk+00dp+10").back()[1] * 1e3
         << " mm, at (-24, 10) km "
         << read_seas(out + "fltst_strk-24dp+10").back()[1] * 1e3 << " mm";
  dealii::deallog << digest.str() << std::endl;
  return 0;
}
