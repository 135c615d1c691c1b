// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_seas_parameters_h
#define rsfcycle_seas_parameters_h

#include <array>
#include <deal.II/base/parameter_handler.h>
#include <string>
#include <vector>

namespace rsfcycle
{
  /** The entries of `Output/SEAS` (declared by declare_parameters()). */
  struct SeasParameters
  {
    /** `# problem=` of the headers; empty: no SEAS files. */
    std::string         problem;
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

    bool
    enabled() const
    {
      return !problem.empty();
    }

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
