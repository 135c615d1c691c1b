#include <algorithm>
#include <cerrno>
#include <cmath>
#include <iomanip>
#include <rsfcycle/format.h>
#include <rsfcycle/output/files.h>
#include <rsfcycle/output/seas_files.h>
#include <sstream>
#include <stdexcept>

namespace rsfcycle
{
  namespace output
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
        Patterns::List(Patterns::Double(0)),
        "Positions of the SEAS on-fault stations along the contact, in the "
        "along-base coordinate of base-profile.csv (the depth on a vertical "
        "fault) [m]; each writes fltst_dpXXX (XXX: the position in units "
        "of 100 m) with the values interpolated linearly between the two "
        "contact nodes around it");
      prm.declare_entry(
        "Slip profile",
        "0, 35e3, 100",
        Patterns::List(Patterns::Double(0), 3, 3),
        "The positions of the SEAS slip profiles in slip.dat along the "
        "contact (along-base coordinate): first, last, spacing [m]; all "
        "within the contact nodes (the nodes of a load boundary are not "
        "contact nodes)");
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
          format_number(slip_profile[1]) + ", " +
          format_number(slip_profile[2]) +
          ": needs first <= last and a spacing > 0");
      std::vector<std::string> names;
      for (const double x : fault_stations)
        names.push_back(fault_station_file(x));
      std::sort(names.begin(), names.end());
      if (std::adjacent_find(names.begin(), names.end()) != names.end())
        throw std::invalid_argument(
          entry + "Fault stations: two stations share the file name "
                  "fltst_dpXXX (XXX counts 100 m): give stations at least "
                  "100 m apart");
      if ((slip_profile[1] - slip_profile[0]) / slip_profile[2] > 1e5)
        throw std::invalid_argument(
          entry + "Slip profile: more than 100000 positions; choose a "
                  "larger spacing");
    }


    std::string
    SeasParameters::fault_station_file(const double x)
    {
      std::ostringstream name;
      name << "fltst_dp" << std::setfill('0') << std::setw(3)
           << std::lround(x / 100);
      return name.str();
    }


    SeasFiles::SeasFiles(const std::string    &dir,
                         const SeasParameters &parameters,
                         const time::Layout   &layout)
      : parameters(parameters)
    {
      if (!layout.lateral_positions.empty())
        throw std::invalid_argument(
          "Output/SEAS/Problem: SEAS files are written for 2D models only");
      const auto        &s = layout.positions;
      const unsigned int n = s.size();
      order.resize(n);
      for (unsigned int k = 0; k < n; ++k)
        order[k] = k;
      std::sort(order.begin(), order.end(), [&](unsigned i, unsigned j) {
        return s[i] < s[j];
      });
      for (const unsigned int k : order)
        {
          positions.push_back(s[k]);
          weights.push_back(layout.weights[k]);
        }
      element_size = n > 1 ? positions.back() - positions.front() : 0;
      for (unsigned int k = 1; k < n; ++k)
        element_size = std::min(element_size, positions[k] - positions[k - 1]);

      for (const double x : parameters.fault_stations)
        {
          stations.push_back(locate(x, "Fault stations"));
          file_paths.push_back(dir + "/" +
                               SeasParameters::fault_station_file(x));
        }
      for (const auto &name : layout.station_names)
        {
          surface_names.push_back(name);
          file_paths.push_back(dir + "/srfst_" + name);
        }
      const auto  &range = parameters.slip_profile;
      const double count = std::floor((range[1] - range[0]) / range[2] + 1e-9);
      for (long i = 0; i <= static_cast<long>(count); ++i)
        {
          profile_positions.push_back(range[0] + i * range[2]);
          profile.push_back(locate(profile_positions.back(), "Slip profile"));
        }
      file_paths.push_back(dir + "/global.dat");
      file_paths.push_back(dir + "/slip.dat");
    }


    SeasFiles::Interpolation
    SeasFiles::locate(const double x, const std::string &entry) const
    {
      const double tolerance = 1e-9 * std::max(1., std::abs(x));
      if (positions.empty() || x < positions.front() - tolerance ||
          x > positions.back() + tolerance)
        throw std::invalid_argument(
          "Output/SEAS/" + entry + ": " + format_number(x) +
          " m lies outside the contact (along-base coordinates " +
          (positions.empty() ? std::string("none") :
                               format_number(positions.front()) + " ... " +
                                 format_number(positions.back())) +
          " m)");
      if (positions.size() == 1)
        return {0, 0.};
      const auto upper =
        std::upper_bound(positions.begin(), positions.end(), x);
      const unsigned int k =
        std::min<long>(std::max<long>(upper - positions.begin() - 1, 0),
                       positions.size() - 2);
      const double weight =
        std::clamp((x - positions[k]) / (positions[k + 1] - positions[k]),
                   0.,
                   1.);
      return {k, weight};
    }


    double
    SeasFiles::interpolate(const Interpolation &where,
                           const double        *values) const
    {
      if (where.weight == 0)
        return values[where.k];
      return (1 - where.weight) * values[where.k] +
             where.weight * values[where.k + 1];
    }


    std::string
    SeasFiles::header(const std::string &location) const
    {
      std::ostringstream text;
      text << "# This is the file header:\n"
           << "# problem=" << parameters.problem << "\n"
           << "# code=rsfcycle " << RSFCYCLE_VERSION << "\n"
           << "# element_size=" << element_size << " m\n"
           << "# location=" << location << "\n";
      return text.str();
    }


    void
    SeasFiles::open(const bool resume)
    {
      for (const auto &path : file_paths)
        {
          files.push_back(std::make_unique<std::ofstream>(
            path, resume ? std::ios::app : std::ios::out));
          if (!*files.back())
            throw file_error(path, errno);
        }
      if (!resume)
        write_headers();
      flush();
    }


    void
    SeasFiles::write_headers()
    {
      unsigned int f = 0;
      for (unsigned int i = 0; i < stations.size(); ++i, ++f)
        {
          std::ostringstream location;
          location << "on fault, " << parameters.fault_stations[i] / 1e3
                   << " km along the contact (down-dip distance)";
          *files[f] << header(location.str())
                    << "# Column #1 = Time (s)\n"
                       "# Column #2 = Slip (m)\n"
                       "# Column #3 = Slip rate (log10 m/s)\n"
                       "# Column #4 = Shear stress (MPa)\n"
                       "# Column #5 = State (log10 s)\n"
                       "# The line below lists the names of the data fields:\n"
                       "t slip slip_rate shear_stress state\n"
                       "# Here is the time-series data.\n";
        }
      for (const auto &name : surface_names)
        *files[f++] << header("off fault, observation point " + name)
                    << "# Column #1 = Time (s)\n"
                       "# Column #2 = Displacement (m)\n"
                       "# Column #3 = Velocity (m/s)\n"
                       "# The line below lists the names of the data fields:\n"
                       "t disp vel\n"
                       "# Here is the time-series data.\n";
      *files[f++] << header("global")
                  << "# Column #1 = Time (s)\n"
                     "# Column #2 = Max slip rate (log10 m/s)\n"
                     "# Column #3 = Moment rate (N/s per m along strike)\n"
                     "# The line below lists the names of the data fields:\n"
                     "t max_slip_rate moment_rate\n"
                     "# Here is the time-series data.\n";
      *files[f] << header("on fault, slip profiles")
                << "# Row #1 = 0 0, then the positions along the contact (m)\n"
                   "# Column #1 = Time (s)\n"
                   "# Column #2 = Max slip rate (log10 m/s)\n"
                   "# Column #3 ... = Slip (m)\n"
                   "# The line below lists the names of the data fields:\n"
                   "t max_slip_rate slip\n"
                   "# Here is the data.\n";
      row << 0. << 0.;
      for (const double x : profile_positions)
        row << x;
      row.write_line(*files[f]);
    }


    double
    SeasFiles::sort_sample(const time::Sample &sample)
    {
      const unsigned int n = order.size();
      slip.resize(n);
      rate.resize(n);
      log10_rate.resize(n);
      stress.resize(n);
      log10_state.resize(n);
      double max_rate = 0;
      for (unsigned int i = 0; i < n; ++i)
        {
          const unsigned int k = order[i];
          const double       V = sample.slip_rates[k];
          slip[i]              = sample.slip[k][0];
          rate[i]              = V;
          log10_rate[i]        = std::log10(std::max(V, 1e-300));
          stress[i]            = sample.shear_stresses[k] / 1e6;
          log10_state[i]       = sample.log10_states[k];
          max_rate             = std::max(max_rate, V);
        }
      return std::log10(std::max(max_rate, 1e-300));
    }


    void
    SeasFiles::write_step(const double t, const time::Sample &sample)
    {
      const double log10_max_rate = sort_sample(sample);
      unsigned int f              = 0;
      for (const auto &where : stations)
        {
          row.precise(t) << interpolate(where, slip.data())
                         << interpolate(where, log10_rate.data())
                         << interpolate(where, stress.data())
                         << interpolate(where, log10_state.data());
          row.write_line(*files[f++]);
        }
      const double factor = parameters.mirror ? 0.5 : 1.;
      for (unsigned int i = 0; i < surface_names.size(); ++i)
        {
          row.precise(t) << factor * sample.observations[i]
                         << factor * sample.observation_rates[i];
          row.write_line(*files[f++]);
        }
      // G int V ds by the nodes' lumped weights
      double moment_rate = 0;
      for (unsigned int i = 0; i < rate.size(); ++i)
        moment_rate += weights[i] * rate[i];
      row.precise(t) << log10_max_rate
                     << parameters.shear_modulus * moment_rate;
      row.write_line(*files[f]);
      check();
    }


    void
    SeasFiles::write_profile(const double t, const time::Sample &sample)
    {
      row.precise(t) << sort_sample(sample);
      for (const auto &where : profile)
        row << interpolate(where, slip.data());
      row.write_line(*files.back());
      check();
    }


    void
    SeasFiles::check() const
    {
      // after a failed write, errno still holds its reason
      for (unsigned int i = 0; i < files.size(); ++i)
        if (!*files[i])
          throw file_error(file_paths[i], errno);
    }


    void
    SeasFiles::flush()
    {
      for (const auto &file : files)
        file->flush();
      check();
    }


    std::vector<long long>
    SeasFiles::sizes()
    {
      flush();
      std::vector<long long> result;
      for (const auto &file : files)
        result.push_back(file->tellp());
      return result;
    }
  } // namespace output
} // namespace rsfcycle
