// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_seas_parameters_h
#define rsfcycle_seas_parameters_h

#include <array>
#include <deal.II/base/parameter_handler.h>
#include <string>
#include <vector>

namespace rsfcycle
{
  /**
   * What a SEAS benchmark's description asks of its files beyond the
   * stations and profiles a `.prm` places (doc/seas.md, "The files each
   * problem writes", cites the description for each): the problem line,
   * the header's keys, the profiles' file names and field lines, and which
   * of global.dat and catalog.dat it wants.
   */
  struct SeasConventions
  {
    /** `# problem=` of every header. */
    std::string problem;
    /**
     * The BP1 and BP2 keys `author` and `code_version` in the time series'
     * headers (BP3 and later: `modeler`, `version`, and the lines "This is
     * the file header" and "Here is the time-series data").
     */
    bool bp1_keys = false;
    /** The key of the modeler in the profiles' headers. */
    std::string profile_author_key = "author";
    /**
     * The profiles' field list: 2 lines (the positions' name, then `t
     * max_slip_rate FIELD`: BP1, BP2, BP3) or 4 (one name a line: BP5 and
     * later).
     */
    unsigned int profile_name_lines = 2;
    /** 2D: the name of the positions (z, x_d) and the slip profile's file. */
    std::string position_name = "x", slip_profile_file = "slip.dat";
    /** 3D: the stress profiles' prefix (stress_2_strike.dat, ...). */
    std::string stress_profile = "stress";
    /** Whether global.dat and catalog.dat are written. */
    bool global = true, catalog = false;
    /** 3D: whether rupture.dat is written (not BP8). */
    bool rupture = true;
    /** The extension of the fault stations' files (BP8: .dat). */
    std::string station_extension;
    /**
     * Whether the observation points write off-fault station files
     * (srfst_NAME in 2D: BP3; blkst_NAME in 3D: BP5, BP7).
     */
    bool off_fault = true;
    /** How a 2D fault station's location reads (after "on fault, "). */
    std::string station_location = "km along the contact";
  };

  /** The entries of `Output/SEAS` (declared by declare_parameters()). */
  struct SeasParameters
  {
    /** The benchmarks whose conventions the files follow. */
    enum class Benchmark
    {
      none,
      custom,
      bp1_qd,
      bp1_fd,
      bp2_qd,
      bp3_qd,
      bp3_fd,
      bp4_qd,
      bp5_qd,
      bp5_fd,
      bp6_qd_a,
      bp6_qd_s,
      bp7_qd,
      bp8_qd_gs,
      bp8_qd_pw
    };
    Benchmark benchmark = Benchmark::none;
    /** `# problem=` of a custom problem's headers. */
    std::string problem;
    /** The author line, and anything else a user wants in the headers. */
    std::string modeler, description;
    /**
     * 3D: the regions of the fault (functions of x2 and x3 [m], > 0
     * inside) of global.dat's max_slip_rate and moment_rate, of the fourth
     * column moment_rate_vw (BP7; empty: none) and of rupture.dat.
     */
    std::string moment_region = "1", vw_moment_region, rupture_region = "1";
    std::vector<double> fault_stations; // from the origin [m]
    double              origin = 0;     // along the contact [m]
    /** fltst_dpXXX (down-dip distance) or fltst_strk+XX (along strike). */
    bool                  strike_names = false;
    std::array<double, 3> slip_profile{}; // from, to, spacing [m]
    double                profile_interval       = 1.57788e8; // [s]
    double                event_profile_interval = 1;         // [s]
    double                shear_modulus          = 0;         // [Pa]
    bool                  mirror                 = false;
    /** +1, or -1 with Thrust slip = reversed (2D station files). */
    double slip_sign = 1;
    /** 3D: the stations (x2 along strike, x3 depth) [m]. */
    std::vector<std::array<double, 2>> plane_stations;
    /** 3D: a station's file name where the entry gives one (else empty). */
    std::vector<std::string> plane_station_names;
    /**
     * 3D: the unit of the file names [m] (km, 100 m or m) and their digits
     * (2 for km, else 3).
     */
    double       station_unit   = 1e3;
    unsigned int station_digits = 2;
    /** 3D: depth, first, last, spacing of x2 [m]. */
    std::array<double, 4> strike_profile{};
    /** 3D: x2, first, last, spacing of the depth [m]. */
    std::array<double, 4> depth_profile{};
    /** 3D: the slip rate of a rupture front in rupture.dat [m/s]. */
    double rupture_threshold = 1e-3;
    /**
     * The slip rate reported at the load or creep nodes where the contact
     * ends (SEAS: the plate rate V_p) [m/s]; 0: none (the profiles stay
     * within the contact).
     */
    double boundary_slip_rate = 0;

    bool
    enabled() const
    {
      return benchmark != Benchmark::none;
    }

    /** The conventions of the chosen benchmark (custom: the defaults). */
    SeasConventions
    conventions() const;

    /** The benchmark's name as `Output/SEAS/Benchmark` spells it. */
    std::string
    benchmark_name() const;

    /** The subsection SEAS (called inside subsection Output). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * Checks across entries (throws std::invalid_argument, one line
     * naming the entry): Shear modulus > 0; 2D: the profile's range, no
     * negative station with down-dip names, distinct file names; 3D: the
     * profiles' ranges, the rupture threshold, distinct station names.
     */
    void
    validate(unsigned int dimension) const;

    /**
     * The file of the 3D station x = (x2, x3) [m]: fltst_strk+XXdp+YY in
     * km (2 digits at least) or in units of 100 m (3 digits).
     */
    std::string
    plane_station_file(const std::array<double, 2> &x) const;

    /** The file of the i-th plane station: its own name or the above. */
    std::string
    plane_station_file(unsigned int i) const;

    /**
     * The file of the fault station x [m] from the origin: fltst_dpXXX,
     * XXX = x in units of 100 m (3 digits at least), or with strike names
     * fltst_strk+XX (signed, 2 digits at least; SEAS BP6).
     */
    std::string
    fault_station_file(double x) const;

  private:
    void
    validate_plane() const;
  };
} // namespace rsfcycle

#endif
