// SPDX-License-Identifier: LGPL-2.1-or-later
// The velocity step through the whole spring-slider code path (Newmark step,
// exact 1-DOF friction solve, rate/state fixed point, step doubling): a
// very stiff spring (k = 1e12 Pa/m = 1000 a |sigma_n| / L, no damping,
// quasi-dynamic) makes the block follow the load point, whose velocity
// jumps from V1 = v0 = 1e-6 m/s to V2 = 10 V1 at t = 1 s; steady sliding at
// V1 before. Steps are capped at 1e-4 s, below the spring's relaxation time
// a |sigma_n| / (k V2) = 1e-3 s, which the trapezoidal rule would
// otherwise let ring. Checked against the closed forms at the imposed
// rate (as in velocity_step.cc), for the ageing and the slip law, at slip
// d = 0.01, 0.5, 1, 2, 5, 20 L after the step: the slip rate is V2 to 0.5 %
// (the spring takes up the jump within about 0.005 L; later the deviation,
// <= 0.35 % from 0.5 L on, is the spring's compliance, |V2 - V| / V ~
// |sigma_n| (dmu/dd) / k; a stiffer spring needs smaller steps), the
// friction (mu - mu_ss(V1)) / a agrees with the closed form to 0.02 (i.e.
// 1 % of the direct effect a log 10; measured <= 0.0045 for the ageing law
// and <= 0.013 for the slip law, largest at 0.01 L where the spring is
// still building up the direct effect), and after 20 L the change is
// (a - b) log(V2/V1).
#include "tests.h"

#include <cmath>
#include <fstream>
#include <map>
#include <rsfcycle/app/simulation.h>
#include <rsfcycle/models/spring_slider.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/scenes/scenes.h>
#include <sstream>

using namespace rsfcycle;

int
main()
{
  initlog(6);
  using dealii::deallog;
  const double a = 0.01, b = 0.015, L = 1e-5, V1 = 1e-6, V2 = 1e-5, t_s = 1;

  for (const std::string law : {"ageing", "slip"})
    {
      ParameterHandler prm;
      app::declare_parameters(prm);
      prm.parse_input_from_string(
        "set Scene = spring-slider\n"
        "set End time = 21\n"
        "set Output directory = output-" +
        law +
        "\n"
        "subsection Time stepping\n"
        "  set Controller = step-doubling\n"
        "  set Tolerance = 1e-6\n"
        "  set Initial step = 1e-5\n"
        "  set Maximum step = 1e-4\n"
        "end\n"
        "subsection Solver\n"
        "  set State law = " +
        law +
        "\n"
        "  set Fixed-point tolerance = 1e-8\n"
        "end\n"
        "subsection Output\n"
        "  set Writers = time series, base profile, events\n"
        "  set Progress interval = 1e9\n"
        "end\n"
        "subsection Spring slider\n"
        "  set Stiffness = 1e12\n"
        "  set Radiation damping = 0\n"
        "  set Initial slip rate = 1e-6\n"
        "  set Initial state = 0\n"
        "  set Velocity step time = 1\n"
        "  set Velocity step factor = 10\n"
        "end\n");
      Parameters parameters;
      parameters.parse_parameters(prm);
      models::SpringSlider slider(parameters, prm);
      std::ostringstream   log;
      slider.run(prm, log);

      // the columns of time-series.csv by name (doc/output.md)
      std::ifstream                    in("output-" + law + "/time-series.csv");
      std::string                      line;
      std::vector<std::vector<double>> rows;
      std::getline(in, line);
      std::map<std::string, unsigned int> column;
      {
        std::stringstream header(line);
        std::string       name;
        while (std::getline(header, name, ','))
          column.emplace(name, column.size());
      }
      const unsigned int time_s = column.at("time_s"),
                         rate   = column.at("slip_rate_m_per_s"),
                         mu     = column.at("friction_coefficient");
      while (std::getline(in, line))
        {
          std::vector<double> row;
          std::stringstream   s(line);
          std::string         cell;
          while (std::getline(s, cell, ','))
            row.push_back(std::stod(cell));
          rows.push_back(row);
        }

      deallog << law << " law:" << std::endl;
      const double mu1 = 0.6; // mu_ss(V1) = mu* since V1 = V*
      for (const double d_over_L : {0.01, 0.5, 1., 2., 5., 20.})
        {
          const double t    = t_s + d_over_L * L / V2;
          std::size_t  best = 0;
          for (std::size_t i = 0; i < rows.size(); ++i)
            if (std::abs(rows[i][time_s] - t) <
                std::abs(rows[best][time_s] - t))
              best = i;
          const auto  &row = rows[best];
          const double d   = (row[time_s] - t_s) * V2 / L; // imposed slip / L
          double       alpha_exact;
          if (law == "ageing")
            alpha_exact =
              std::log((L / V2 + (L / V1 - L / V2) * std::exp(-d)) * 1e-6 / L);
          else
            alpha_exact =
              std::log(V2 / V1) * std::exp(-d) - std::log(V2 / 1e-6);
          const double mu_exact =
            0.6 + a * std::log(V2 / 1e-6) + b * alpha_exact;
          deallog << "  slip " << d_over_L << " L: V/V2 within 0.5%: "
                  << (std::abs(row[rate] / V2 - 1) < 5e-3 ? "yes" : "no")
                  << ", (mu - mu_ss(V1))/a = " << (row[mu] - mu1) / a
                  << ", closed form " << (mu_exact - mu1) / a
                  << ", |difference| < 0.02: "
                  << (std::abs(row[mu] - mu_exact) / a < 0.02 ? "yes" : "no")
                  << std::endl;
        }
      deallog << "  after 20 L: change / ((a - b) log(V2/V1)) = "
              << (rows.back()[mu] - mu1) / ((a - b) * std::log(V2 / V1))
              << std::endl;
    }
}
