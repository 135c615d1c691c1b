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


  void
  SeasParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("SEAS");
    prm.declare_entry(
      "Problem",
      "",
      Patterns::Anything(),
      "The SEAS benchmark's name, written as `# problem=` into the header "
      "of the SEAS files (e.g. SEAS Benchmark BP1-QD); empty: no SEAS "
      "files. The files (fltst_dpXXX, srfst_NAME, global.dat, slip.dat; "
      "README.md \"Output\") are written for 2D models only");
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
    problem = prm.get("Problem");
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
    prm.leave_subsection();
  }


  void
  SeasParameters::validate(const unsigned int dimension) const
  {
    if (!enabled())
      return;
    const std::string entry = "Output/SEAS/";
    if (dimension != 2)
      throw std::invalid_argument(
        entry + "Problem = " + problem +
        ": SEAS files are written for 2D models (a 1D fault) only, this "
        "run has Dimension = " +
        std::to_string(dimension));
    if (!(shear_modulus > 0))
      throw std::invalid_argument(
        entry + "Shear modulus = " + format_number(shear_modulus) +
        ": must be > 0 when Problem is given (the moment rate's G)");
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
