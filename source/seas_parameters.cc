// SPDX-License-Identifier: LGPL-2.1-or-later
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <rsfcycle/format.h>
#include <rsfcycle/seas_parameters.h>
#include <sstream>
#include <stdexcept>

namespace rsfcycle
{
  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  namespace
  {
    /** The names of SeasParameters::Benchmark, in its order. */
    const char *const benchmark_names =
      "none|custom|BP1-QD|BP1-FD|BP2-QD|BP3-QD|BP3-FD|BP4-QD|BP5-QD|"
      "BP5-FD|BP6-QD-A|BP6-QD-S|BP7-QD|BP8-QD-GS|BP8-QD-PW";

    SeasParameters::Benchmark
    parse_benchmark(const std::string &name)
    {
      const auto names =
        dealii::Utilities::split_string_list(benchmark_names, '|');
      for (unsigned int i = 0; i < names.size(); ++i)
        if (names[i] == name)
          return static_cast<SeasParameters::Benchmark>(i);
      throw std::invalid_argument("Output/SEAS/Benchmark: '" + name +
                                  "' is not one of " + benchmark_names);
    }
  } // namespace


  void
  SeasParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("SEAS");
    prm.declare_entry(
      "Benchmark",
      "none",
      Patterns::Selection(benchmark_names),
      "The SEAS benchmark whose files the run writes, with the names, "
      "headers, field lines and extra files its description asks for "
      "(doc/seas.md lists them per benchmark): none (no SEAS files), "
      "custom (the files of Problem, for a model of your own), or one of "
      "BP1-QD, BP1-FD, BP2-QD, BP3-QD, BP3-FD, BP4-QD, BP5-QD, BP5-FD, "
      "BP6-QD-A, "
      "BP6-QD-S, BP7-QD, BP8-QD-GS, BP8-QD-PW. The stations and profiles are placed by the "
      "entries below; python3 -m rsfcycle.seas check RUN checks a run "
      "folder against the benchmark's description");
    prm.declare_entry(
      "Problem",
      "",
      Patterns::Anything(),
      "With Benchmark = custom (or none): the problem's name, written as "
      "`# problem=` into the headers of the SEAS files; given with "
      "Benchmark = none it switches the custom files on. 2D: fltst_dpXXX, "
      "srfst_NAME, global.dat, slip.dat; 3D (a fault in a plane y = const "
      "of the mesh, x along strike, z up): fltst_strkXXdpYY, blkst_NAME, "
      "global.dat, rupture.dat and the strike and depth profiles "
      "(doc/output.md)");
    prm.declare_entry(
      "Modeler",
      "",
      Patterns::Anything(),
      "The modeler's name in the headers (`# modeler=`, in BP1 and BP2 "
      "`# author=`), as the benchmark's web server shows it; empty: "
      "'unknown', which python3 -m rsfcycle.seas check refuses");
    prm.declare_entry(
      "Description",
      "",
      Patterns::Anything(),
      "Anything else for the headers, as one line `# description=...` "
      "(e.g. BP3's 'thrust, dip 60', which the description asks uploads "
      "to state); empty: no such line");
    prm.declare_entry(
      "Moment rate region",
      "1",
      Patterns::Anything(),
      "3D: where global.dat's max_slip_rate and moment_rate are taken: a "
      "function of x2 (along strike) and x3 (depth, positive down) [m], "
      "> 0 inside (muparser syntax, e.g. BP5's abs(x2) <= 34e3 && x3 <= "
      "20e3); 1: the whole contact");
    prm.declare_entry(
      "VW moment rate region",
      "",
      Patterns::Anything(),
      "3D: a second region, as Moment rate region, whose moment rate "
      "global.dat writes as a fourth column moment_rate_vw (BP7: the "
      "velocity-weakening disc, x2^2 + x3^2 <= 200^2); empty: no such "
      "column");
    prm.declare_entry(
      "Rupture region",
      "1",
      Patterns::Anything(),
      "3D: the nodes rupture.dat lists, as Moment rate region (BP5: "
      "abs(x2) <= 34e3 && x3 <= 20e3); each with the time its slip rate "
      "first reaches Rupture threshold in the first event, 1e9 if never");
    prm.declare_entry(
      "Fault stations",
      "0, 2.5e3, 5e3, 7.5e3, 10e3, 12.5e3, 15e3, 17.5e3, 20e3, 25e3, "
      "30e3, 35e3",
      Patterns::List(Patterns::Double()),
      "Positions of the SEAS on-fault stations along the contact from "
      "Fault station origin, in the along-base coordinate of "
      "base-profile.csv (the depth on a vertical fault) [m]; each writes "
      "fltst_dpXXX (XXX: the position in units of 100 m; >= 0) or, with "
      "Fault station names = strike, fltst_strk+XX (signed), with the "
      "values interpolated linearly between the two contact nodes around "
      "it");
    prm.declare_entry(
      "Fault station origin",
      "0",
      Patterns::Double(),
      "The along-base coordinate (as in base-profile.csv) that the fault "
      "stations and the slip profile count from [m]: 0 is the contact's "
      "first node (the top of a vertical fault); SEAS BP6: the injection "
      "point");
    prm.declare_entry(
      "Fault station names",
      "down-dip",
      Patterns::Selection("down-dip|strike"),
      "down-dip: fltst_dpXXX (SEAS BP1, BP2: XXX the distance in units of "
      "100 m, 3 digits); strike: fltst_strk+XX (SEAS BP6: signed, 2 "
      "digits)");
    prm.declare_entry(
      "Slip profile",
      "0, 35e3, 100",
      Patterns::List(Patterns::Double(), 3, 3),
      "The positions of the SEAS slip profiles in slip.dat along the "
      "contact (along-base coordinate, from Fault station origin): first, "
      "last, spacing [m]; all within the contact nodes (the nodes of a "
      "load boundary are not contact nodes)");
    prm.declare_entry("Slip profile interval",
                      "1.57788e8",
                      Patterns::Double(0),
                      "Simulated time between rows of the SEAS slip.dat "
                      "outside events [s] (5 years: the SEAS value)");
    prm.declare_entry("Event slip profile interval",
                      "1",
                      Patterns::Double(0),
                      "Simulated time between rows of the SEAS slip.dat "
                      "during events (see Output/Event threshold) [s]");
    prm.declare_entry(
      "Shear modulus",
      "0",
      Patterns::Double(0),
      "The shear modulus G of the moment rate G int V ds in the SEAS "
      "global.dat [Pa]: the benchmark's (for a fault modelled against a "
      "rigid mirror, that of the full body, twice the model's); must be "
      "> 0 when SEAS Problem is given");
    prm.declare_entry(
      "Plane stations",
      "-36e3, 0; -16e3, 0; 0, 0; 16e3, 0; 36e3, 0; -24e3, 10e3; -16e3, "
      "10e3; 0, 10e3; 16e3, 10e3; 0, 22e3",
      Patterns::Anything(),
      "3D: the on-fault stations as 'x2, x3; x2, x3' [m], x2 the mesh's x "
      "(along strike), x3 the depth -z (positive down); each writes "
      "fltst_strk+XXdp+YY (x2 and x3 in units of Plane station names, "
      "signed), or the name after '=' ('x2, x3 = fltst_NAME'), bilinear "
      "between the four contact nodes around it (a structured grid of the "
      "contact there). The default: SEAS BP5's ten stations");
    prm.declare_entry(
      "Plane station names",
      "km",
      Patterns::Selection("km|100 m|m"),
      "3D: the unit of the station file names: km, 2 digits (SEAS BP5, "
      "fltst_strk-36dp+10), 100 m, 3 digits (SEAS BP4, "
      "fltst_strk-360dp+100), or m, 3 digits (SEAS BP7, "
      "fltst_strk-100dp+100)");
    prm.declare_entry(
      "Strike profile",
      "10e3, -38e3, 38e3, 1e3",
      Patterns::List(Patterns::Double(), 4, 4),
      "3D: the along-strike profiles (slip_2_strike.dat, slip_3_strike.dat, "
      "shear_stress_2_strike.dat, shear_stress_3_strike.dat): depth x3 of "
      "the line, then first, last and spacing of x2 [m]; within the contact "
      "nodes");
    prm.declare_entry(
      "Depth profile",
      "0, 0, 39e3, 1e3",
      Patterns::List(Patterns::Double(), 4, 4),
      "3D: the down-dip profiles (slip_2_depth.dat ... "
      "shear_stress_3_depth.dat): x2 of the line, then first, last and "
      "spacing of the depth x3 [m]; within the contact nodes (those of a "
      "load boundary, e.g. at the rate-and-state region's bottom, are "
      "not)");
    prm.declare_entry(
      "Rupture threshold",
      "1e-3",
      Patterns::Double(0),
      "3D: rupture.dat lists x2, x3 and the time at which the slip rate "
      "of a contact node first reaches this value [m/s] in each event "
      "(interpolated in log10 V between steps; a node counts again once "
      "the fastest node of the fault is below it)");
    prm.declare_entry(
      "Boundary slip rate",
      "0",
      Patterns::Double(),
      "The slip rate of the load or creep boundary where the contact ends "
      "(the SEAS benchmarks' plate rate V_p, 1e-9) [m/s], as the files "
      "report it (2D: after Thrust slip; 3D: along strike, slip_2): a "
      "profile position up to one cell beyond the contact's last node "
      "is that boundary's node, whose slip the files give as this rate "
      "times t and whose stresses as those of the contact node next to it "
      "(the descriptions' profiles end there: BP1, BP3 at 40 km, BP5 at 40 "
      "km depth, BP7 at +-400 m). 0: every profile position within the "
      "contact nodes");
    prm.declare_entry(
      "Thrust slip",
      "as computed",
      Patterns::Selection("as computed|reversed"),
      "2D: the sign of the slip, the slip rate and the shear stress in the "
      "fault station files and profiles. as computed: the contact's "
      "tangential axis (the rotated frame's x, down dip without gravity). "
      "reversed: the opposite; SEAS BP3 counts thrust slip positive, which "
      "on a contact on the hanging wall is slip up dip, against the "
      "frame's x (prm/seas-bp3-qd.prm)");
    prm.declare_entry(
      "Mirror model",
      "false",
      Patterns::Bool(),
      "Whether the model is one side of a fault between two equal bodies "
      "computed against a rigid mirror (the SEAS symmetric reduction): "
      "the SEAS surface stations then report the benchmark's side, half "
      "of the model's displacement and velocity");
    prm.leave_subsection();
  }


  void
  SeasParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("SEAS");
    problem   = prm.get("Problem");
    benchmark = parse_benchmark(prm.get("Benchmark"));
    if (benchmark == Benchmark::none && !problem.empty())
      benchmark = Benchmark::custom;
    modeler          = prm.get("Modeler");
    description      = prm.get("Description");
    moment_region    = prm.get("Moment rate region");
    vw_moment_region = prm.get("VW moment rate region");
    rupture_region   = prm.get("Rupture region");
    fault_stations.clear();
    for (const auto &item :
         dealii::Utilities::split_string_list(prm.get("Fault stations")))
      fault_stations.push_back(std::stod(item));
    origin       = prm.get_double("Fault station origin");
    strike_names = prm.get("Fault station names") == "strike";
    const auto profile =
      dealii::Utilities::split_string_list(prm.get("Slip profile"));
    for (unsigned int i = 0; i < 3; ++i)
      slip_profile[i] = std::stod(profile[i]);
    profile_interval       = prm.get_double("Slip profile interval");
    event_profile_interval = prm.get_double("Event slip profile interval");
    shear_modulus          = prm.get_double("Shear modulus");
    mirror                 = prm.get_bool("Mirror model");
    slip_sign              = prm.get("Thrust slip") == "reversed" ? -1. : 1.;
    plane_stations.clear();
    plane_station_names.clear();
    for (const auto &entry :
         dealii::Utilities::split_string_list(prm.get("Plane stations"), ';'))
      {
        // 'x2, x3' or 'x2, x3 = NAME'
        const auto  named  = dealii::Utilities::split_string_list(entry, '=');
        const auto &item   = named.front();
        const auto  values = dealii::Utilities::split_string_list(item, ',');
        std::array<double, 2> x{};
        bool                  ok = values.size() == 2;
        for (unsigned int i = 0; ok && i < 2; ++i)
          {
            char *end = nullptr;
            x[i]      = std::strtod(values[i].c_str(), &end);
            ok =
              end != values[i].c_str() && *end == '\0' && std::isfinite(x[i]);
          }
        ok =
          ok && named.size() <= 2 && (named.size() == 1 || !named[1].empty());
        if (!ok)
          throw std::invalid_argument("Output/SEAS/Plane stations: '" + entry +
                                      "' is not 'x2, x3' (two numbers [m]) "
                                      "or 'x2, x3 = NAME'");
        plane_stations.push_back(x);
        plane_station_names.push_back(named.size() == 2 ? named[1] : "");
      }
    {
      const std::string names = prm.get("Plane station names");
      station_unit   = names == "km" ? 1e3 : names == "100 m" ? 1e2 : 1.;
      station_digits = names == "km" ? 2 : 3;
    }
    const auto read4 = [&](const std::string &name) {
      const auto items = dealii::Utilities::split_string_list(prm.get(name));
      std::array<double, 4> v{};
      for (unsigned int i = 0; i < 4; ++i)
        v[i] = std::stod(items[i]);
      return v;
    };
    strike_profile     = read4("Strike profile");
    depth_profile      = read4("Depth profile");
    rupture_threshold  = prm.get_double("Rupture threshold");
    boundary_slip_rate = prm.get_double("Boundary slip rate");
    prm.leave_subsection();
  }


  void
  SeasParameters::validate(const unsigned int dimension) const
  {
    if (!enabled())
      return;
    const std::string entry = "Output/SEAS/";
    if (!(shear_modulus > 0))
      throw std::invalid_argument(
        entry + "Shear modulus = " + format_number(shear_modulus) +
        ": must be > 0 when SEAS files are written (the moment rate's G)");
    if (benchmark == Benchmark::custom && problem.empty())
      throw std::invalid_argument(
        entry + "Problem: empty with Benchmark = custom; give the name "
                "of the problem for the headers");
    for (const std::string *text : {&modeler, &description, &problem})
      if (text->find('\n') != std::string::npos)
        throw std::invalid_argument(
          entry + "Modeler, Description and Problem: one line each");
    if (dimension == 3)
      {
        validate_plane();
        return;
      }
    if (!(slip_profile[2] > 0) || !(slip_profile[1] >= slip_profile[0]))
      throw std::invalid_argument(
        entry + "Slip profile = " + format_number(slip_profile[0]) + ", " +
        format_number(slip_profile[1]) + ", " + format_number(slip_profile[2]) +
        ": needs first <= last and a spacing > 0");
    std::vector<std::string> names;
    for (const double x : fault_stations)
      {
        if (!strike_names && x < 0)
          throw std::invalid_argument(
            entry + "Fault stations: " + format_number(x) +
            " m is negative; down-dip names (fltst_dpXXX) need positions "
            ">= 0 from the origin (Fault station names = strike: signed)");
        names.push_back(fault_station_file(x));
      }
    std::sort(names.begin(), names.end());
    if (std::adjacent_find(names.begin(), names.end()) != names.end())
      throw std::invalid_argument(
        entry + "Fault stations: two stations share a file name (the "
                "names count 100 m): give stations at least 100 m apart");
    if ((slip_profile[1] - slip_profile[0]) / slip_profile[2] > 1e5)
      throw std::invalid_argument(
        entry + "Slip profile: more than 100000 positions; choose a "
                "larger spacing");
  }


  void
  SeasParameters::validate_plane() const
  {
    const std::string entry = "Output/SEAS/";
    for (const auto &[name, range] :
         {std::make_pair(std::string("Strike profile"), strike_profile),
          std::make_pair(std::string("Depth profile"), depth_profile)})
      {
        if (!(range[3] > 0) || !(range[2] >= range[1]))
          throw std::invalid_argument(
            entry + name + " = " + format_number(range[0]) + ", " +
            format_number(range[1]) + ", " + format_number(range[2]) + ", " +
            format_number(range[3]) +
            ": needs first <= last and a spacing > 0 (the second to fourth "
            "numbers)");
        if ((range[2] - range[1]) / range[3] > 1e5)
          throw std::invalid_argument(
            entry + name +
            ": more than 100000 positions; choose a larger spacing");
      }
    if (!(rupture_threshold > 0))
      throw std::invalid_argument(
        entry + "Rupture threshold = " + format_number(rupture_threshold) +
        ": must be > 0");
    std::vector<std::string> names;
    for (unsigned int i = 0; i < plane_stations.size(); ++i)
      names.push_back(plane_station_file(i));
    std::sort(names.begin(), names.end());
    if (std::adjacent_find(names.begin(), names.end()) != names.end())
      throw std::invalid_argument(
        entry + "Plane stations: two stations share the file name " +
        *std::adjacent_find(names.begin(), names.end()) +
        " (the names count Plane station names): give them further apart");
  }


  std::string
  SeasParameters::plane_station_file(const std::array<double, 2> &x) const
  {
    std::ostringstream name;
    name << "fltst_";
    for (const auto &[label, value] :
         {std::make_pair("strk", x[0]), std::make_pair("dp", x[1])})
      {
        const long units = std::lround(value / station_unit);
        name << label << (units < 0 ? '-' : '+') << std::setfill('0')
             << std::setw(station_digits) << std::labs(units);
      }
    return name.str();
  }


  std::string
  SeasParameters::plane_station_file(const unsigned int i) const
  {
    if (i < plane_station_names.size() && !plane_station_names[i].empty())
      return plane_station_names[i];
    return plane_station_file(plane_stations[i]);
  }


  std::string
  SeasParameters::benchmark_name() const
  {
    const auto names =
      dealii::Utilities::split_string_list(benchmark_names, '|');
    return names[static_cast<unsigned int>(benchmark)];
  }


  SeasConventions
  SeasParameters::conventions() const
  {
    SeasConventions   c;
    const std::string name = benchmark_name();
    c.problem              = "SEAS Benchmark " + name;
    switch (benchmark)
      {
        case Benchmark::none:
        case Benchmark::custom:
          c.problem = problem;
          break;
        case Benchmark::bp1_qd:
        case Benchmark::bp1_fd:
        case Benchmark::bp2_qd:
          // D1 (the BP1-QD description) section 4 and 5: "SEAS Benchmark
          // No.1", author and code_version, the slip evolution in devol.dat
          // under the field lines z and t max_slip_rate slip, no global.dat
          if (benchmark != Benchmark::bp1_fd)
            c.problem = benchmark == Benchmark::bp1_qd ? "SEAS Benchmark No.1" :
                                                         "SEAS Benchmark No.2";
          c.bp1_keys          = true;
          c.position_name     = "z";
          c.slip_profile_file = "devol.dat";
          c.global            = false;
          c.off_fault         = false;
          c.station_location  = "km depth";
          break;
        case Benchmark::bp3_qd:
        case Benchmark::bp3_fd:
          // D3 section 4: modeler in every header, the profiles' field lines
          // x_d and t max_slip_rate slip, no global.dat
          c.profile_author_key = "modeler";
          c.position_name      = "x_d";
          c.global             = false;
          c.station_location   = "km down-dip distance";
          break;
        case Benchmark::bp4_qd:
          // no description stored: HBI's BP4 writer and BP5's conventions
          c.profile_name_lines = 4;
          c.off_fault          = false;
          break;
        case Benchmark::bp5_qd:
        case Benchmark::bp5_fd:
        case Benchmark::bp7_qd:
          // D5, D7 section 4: catalog.dat, the profiles stress_2_*, 4 lines
          c.profile_name_lines = 4;
          c.catalog            = true;
          if (benchmark == Benchmark::bp7_qd)
            c.problem = "SEAS Benchmark BP7-QD-A";
          break;
        case Benchmark::bp8_qd_gs:
        case Benchmark::bp8_qd_pw:
          // BP8 (Table 1 and its output list, as EQquasi's BP8 submission
          // check reads them): every file .dat, the profiles
          // shear_stress_2_*, 4 lines, no off-fault stations, catalog or
          // rupture times
          c.profile_name_lines = 4;
          c.stress_profile     = "shear_stress";
          c.station_extension  = ".dat";
          c.off_fault          = false;
          c.rupture            = false;
          break;
        case Benchmark::bp6_qd_a:
        case Benchmark::bp6_qd_s:
          // D6 section 4: "SEAS Benchmark BP6-A", the profiles along z
          c.problem            = benchmark == Benchmark::bp6_qd_a ?
                                   "SEAS Benchmark BP6-A" :
                                   "SEAS Benchmark BP6-S";
          c.profile_name_lines = 4;
          c.position_name      = "z";
          c.off_fault          = false;
          c.station_location   = "km along strike (z)";
          break;
      }
    return c;
  }


  std::string
  SeasParameters::fault_station_file(const double x) const
  {
    const long         units = std::lround(x / 100);
    std::ostringstream name;
    if (strike_names)
      name << "fltst_strk" << (units < 0 ? '-' : '+') << std::setfill('0')
           << std::setw(2) << std::labs(units);
    else
      name << "fltst_dp" << std::setfill('0') << std::setw(3) << units;
    return name.str();
  }


} // namespace rsfcycle
