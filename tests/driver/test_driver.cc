// SPDX-License-Identifier: LGPL-2.1-or-later
// Test driver for whole-run tests (NAME.prm.in): runs rsfcycle on the given
// parameter file exactly as the executable does, then writes the file
// "output" with a digest of the run that contains no timings and no paths:
// the deterministic lines of the screen log (mesh, events, summary), the
// normal forces of the gravity equilibrium, and selected rows of
// time-series.csv with slip rates as log10(V/v0) and uplift in micrometres,
// so that numdiff's absolute tolerance sees a wrong sign or factor.
// Scene = spring-slider: a digest of the spring-slider run instead (event
// count, recurrence time, slip per cycle / (v0 T), peak log10(V/v0), final
// state against steady sliding), see run_spring_slider().
// With Output/SEAS on, also a digest of the SEAS files (digest_seas()).
// Under mpirun (NAME.mpirun=N.output) every rank runs and the first writes
// the digest.
#include "../tests.h"

#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <rsfcycle/app/simulation.h>
#include <rsfcycle/models/problem_base.h>
#include <rsfcycle/models/spring_slider.h>
#include <rsfcycle/output/files.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/scenes/scenes.h>
#include <sstream>

namespace
{
  /**
   * The SEAS files: rows and last row of each station file (slips and
   * displacements in um, rates as log10 or over v0, stresses in MPa),
   * the peak of global.dat's max slip rate (where the benchmark has one),
   * the slip profile's rows (slip.dat, BP1's devol.dat) and the slips of
   * its last row at the first, middle and last position [um].
   */
  void
  digest_seas(const rsfcycle::Parameters     &parameters,
              const double                    v0,
              const std::vector<std::string> &surface_stations,
              std::ostream                   &out)
  {
    const std::string dir = parameters.run.output_directory + "/";
    out << "SEAS fault stations: rows; last t [s], slip [um], log10 V, "
           "shear stress [MPa], log10 theta\n";
    for (const double x : parameters.output.seas.fault_stations)
      {
        const std::string name = parameters.output.seas.fault_station_file(x);
        const auto        rows = read_seas(dir + name);
        const auto        last = rows.back();
        out << name << " " << rows.size() << "; " << last[0] << " "
            << last[1] * 1e6 << " " << last[2] << " " << last[3] << " "
            << last[4] << "\n";
      }
    const auto conventions = parameters.output.seas.conventions();
    out << "SEAS surface stations: rows; last t [s], disp [um], vel / v0\n";
    for (const auto &name : surface_stations)
      if (conventions.off_fault)
        {
          const auto rows = read_seas(dir + "srfst_" + name);
          const auto last = rows.back();
          out << "srfst_" << name << " " << rows.size() << "; " << last[0]
              << " " << last[1] * 1e6 << " " << last[2] / v0 << "\n";
        }
    if (conventions.global)
      {
        const auto  global = read_seas(dir + "global.dat");
        std::size_t peak   = 0;
        for (std::size_t r = 0; r < global.size(); ++r)
          if (global[r][1] > global[peak][1])
            peak = r;
        out << "global.dat rows " << global.size() << "; peak log10 max V "
            << global[peak][1] << " at t = " << global[peak][0]
            << " s; last moment rate [N/s] " << global.back()[2] << "\n";
      }
    const auto        profiles = read_seas(dir + conventions.slip_profile_file);
    const auto       &x        = profiles.front();
    const auto       &last     = profiles.back();
    const std::size_t n        = x.size();
    out << conventions.slip_profile_file << ": " << profiles.size() - 1
        << " profiles of " << n - 2 << " positions; last t = " << last[0]
        << " s, log10 max V " << last[1] << ", slip [um] at " << x[2] << " / "
        << x[n / 2 + 1] << " / " << x[n - 1] << " m: " << last[2] * 1e6 << " / "
        << last[n / 2 + 1] * 1e6 << " / " << last[n - 1] * 1e6 << "\n";
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
    // the contact nodes of all ranks
    double total = 0;
    for (const auto &node : problem.contact_nodes())
      total += node.normal_force;
    total = dealii::Utilities::MPI::sum(total, MPI_COMM_WORLD);
    // the first rank has the log and the files of the run folder
    if (!rsfcycle::output::is_root())
      return;
    std::cout << log.str();

    std::istringstream lines(log.str());
    std::string        line;
    while (std::getline(lines, line))
      if (line.rfind("Mesh:", 0) == 0 || line.rfind("    event", 0) == 0 ||
          line.rfind("Summary:", 0) == 0)
        out << line << "\n";

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
        for (std::size_t k = 7; k < 7 + scene->observation_points().size(); ++k)
          out << " " << row[k] * 1e6;
        out << "\n";
      }

    // The event catalogue: times, log10 of the peak slip rate over v0,
    // rupture width [m], slip [um], recurrence [s].
    std::ifstream catalogue(parameters.run.output_directory + "/events.csv");
    std::string   entry;
    std::getline(catalogue, entry); // header
    unsigned int       n_events = 0;
    std::ostringstream rows_out;
    while (std::getline(catalogue, entry))
      {
        std::vector<std::string> cells;
        std::stringstream        cells_in(entry);
        std::string              cell;
        while (std::getline(cells_in, cell, ','))
          cells.push_back(cell);
        ++n_events;
        rows_out << cells[0] << " start " << std::stod(cells[1]) << " end "
                 << std::stod(cells[2]) << " log10(peak/v0) "
                 << std::log10(std::stod(cells[5]) / v0) << " width "
                 << std::stod(cells[6]) << " slip " << std::stod(cells[7])
                 << " recurrence "
                 << (cells.size() > 8 && !cells[8].empty() ? cells[8] : "-")
                 << "\n";
      }
    out << "events.csv rows: " << n_events << "\n" << rows_out.str();

    // Fault output: records of fault.pvd and whether each file exists.
    std::ifstream fault_pvd(parameters.run.output_directory + "/fault.pvd");
    if (fault_pvd)
      {
        unsigned int n_records = 0, n_present = 0;
        std::string  record;
        while (std::getline(fault_pvd, record))
          {
            const auto at = record.find("file=\"");
            if (at == std::string::npos)
              continue;
            const auto begin = at + 6;
            const auto name =
              record.substr(begin, record.find('"', begin) - begin);
            ++n_records;
            if (std::ifstream(parameters.run.output_directory + "/" + name))
              ++n_present;
          }
        out << "fault.pvd records: " << n_records
            << ", files present: " << n_present << "\n";
      }

    if (parameters.output.seas.enabled())
      {
        std::vector<std::string> names;
        for (const auto &point : scene->observation_points())
          names.push_back(point.first);
        digest_seas(parameters, v0, names, out);
      }
  }

  /**
   * Digest of a spring-slider run: physical checks printed on scales that
   * numdiff can see (log10(V/v0), ratios, micrometres) and yes/no checks.
   */
  void
  run_spring_slider(const rsfcycle::Parameters &parameters,
                    dealii::ParameterHandler   &prm,
                    std::ostream               &out)
  {
    rsfcycle::models::SpringSlider slider(parameters, prm);
    std::ostringstream             log;
    const auto                     summary = slider.run(prm, log);
    std::cout << log.str();

    double v0, k, eta;
    prm.enter_subsection("Spring slider");
    v0  = prm.get_double("Load point velocity");
    k   = prm.get_double("Stiffness");
    eta = prm.get_double("Radiation damping");
    prm.leave_subsection();
    const auto &events = summary.events;
    const auto  yes_no = [](const bool b) { return b ? "yes" : "no"; };
    out << std::setprecision(5);
    out << "k / k_crit = " << k / slider.critical_stiffness() << "\n";
    out << "events: " << events.size() << "\n";
    out << "max fixed-point iterations per step <= 10: "
        << yes_no(summary.max_fixed_point <= 10) << "\n";
    if (events.size() >= 3)
      {
        const double T    = summary.mean_recurrence_time;
        double       peak = 0, min_slip = 1e300, max_slip = 0;
        for (std::size_t i = 1; i < events.size(); ++i)
          {
            peak     = std::max(peak, events[i].peak_slip_rate);
            min_slip = std::min(min_slip, events[i].slip);
            max_slip = std::max(max_slip, events[i].slip);
          }
        // Periodic cycle: over a period the block slips as far as the
        // load point moves, v0 T.
        const double cycle_slip =
          (events.back().start_slip - events[1].start_slip) /
          (events.size() - 2);
        out << "mean recurrence time (events 2..) [s]: " << T << "\n";
        out << "recurrence time varies by < 1%: "
            << yes_no(std::abs(events.back().start -
                               events[events.size() - 2].start - T) < 0.01 * T)
            << "\n";
        out << "slip per cycle / (v0 T): " << cycle_slip / (v0 * T)
            << ", within 1% of 1: "
            << yes_no(std::abs(cycle_slip / (v0 * T) - 1) < 0.01) << "\n";
        out << "event slip (minus v0 duration) [um]: " << min_slip * 1e6
            << " to " << max_slip * 1e6 << "\n";
        out << "peak log10(V / v0): " << std::log10(peak / v0) << "\n";
        // Quasi-dynamic: eta V <= k slip_event + friction drop, so the peak
        // rate cannot exceed the spring's stress drop over the radiation
        // damping by much: check V_peak < (k * event slip) / eta.
        if (eta > 0)
          out << "peak V < k (event slip) / eta: "
              << yes_no(peak < k * max_slip / eta) << "\n";
        out << "event duration / recurrence time < 0.05: "
            << yes_no((events.back().end - events.back().start) < 0.05 * T)
            << "\n";
      }
    const auto  &p = slider.friction_parameters();
    const double V = summary.final_state.velocity;
    const double mu_ss =
      slider.friction_law().steady_state_friction_coefficient(
        p, slider.load_point_velocity(summary.final_time));
    out << "final log10(V / v0): " << std::log10(std::abs(V) / v0) << "\n";
    out << "final slip / (v0 t): "
        << summary.final_state.slip / (v0 * summary.final_time) << "\n";
    out << "final (mu - mu_ss(v0)) / a: "
        << (summary.final_friction - mu_ss) / p.a << "\n";
    if (events.empty())
      out << "final |V / v0 - 1| < 1e-4: "
          << yes_no(std::abs(V / v0 - 1) < 1e-4)
          << ", |mu - mu_ss(v0)| < 1e-6: "
          << yes_no(std::abs(summary.final_friction - mu_ss) < 1e-6) << "\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  // Trilinos (the amg correction) needs MPI; one process, one thread.
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      if (argc != 2)
        throw std::invalid_argument("usage: rsfcycle_test_driver FILE.prm");
      dealii::ParameterHandler prm;
      rsfcycle::app::declare_parameters(prm);
      rsfcycle::app::parse_parameter_file(prm, argv[1]);
      rsfcycle::Parameters parameters;
      parameters.parse_parameters(prm);

      std::ostringstream out;
      out << std::setprecision(8);
      if (parameters.run.scene == "spring-slider")
        run_spring_slider(parameters, prm, out);
      else if (parameters.run.dimension == 2)
        run<2>(parameters, prm, out);
      else
        run<3>(parameters, prm, out);
      if (rsfcycle::output::is_root())
        std::ofstream("output") << out.str();
    }
  catch (std::exception &exc)
    {
      std::cerr << "error: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
