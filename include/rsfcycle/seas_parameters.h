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
    std::string           problem;
    std::vector<double>   fault_stations; // along the contact [m]
    std::array<double, 3> slip_profile{}; // from, to, spacing [m]
    double                profile_interval       = 1.57788e8; // [s]
    double                event_profile_interval = 1;         // [s]
    double                shear_modulus          = 0;         // [Pa]
    bool                  mirror                 = false;

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
     * naming the entry): 2D only, Shear modulus > 0, the profile's range.
     */
    void
    validate(unsigned int dimension) const;

    /**
     * The file of the fault station at x [m] along the contact:
     * fltst_dpXXX, XXX = x in units of 100 m (3 digits at least).
     */
    static std::string
    fault_station_file(double x);
  };
} // namespace rsfcycle

#endif
