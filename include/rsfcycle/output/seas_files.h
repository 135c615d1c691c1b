// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_output_seas_files_h
#define rsfcycle_output_seas_files_h

#include <rsfcycle/output/sample.h>
#include <rsfcycle/output/seas_file_set.h>
#include <rsfcycle/seas_parameters.h>
#include <string>
#include <vector>

namespace rsfcycle
{
  namespace output
  {
    /**
     * The plain-text files of the SCEC SEAS benchmarks (Erickson et al.
     * 2020, Seismol. Res. Lett. 91, 874; the BP1-QD description), written
     * by the first rank into the run folder, for a 2D model (a 1D fault):
     *  - fltst_dpXXX, one per fault station at the along-contact position
     *    XXX x 100 m: t slip slip_rate shear_stress state (s, m, log10 m/s,
     *    MPa, log10 s), every accepted step, linear between the two nodes
     *    around the station; with a pore fluid (SEAS BP6) also
     *    pore_pressure (MPa) and darcy_vel (m/s) before state, and with
     *    strike names fltst_strk+XX, XX from `Fault station origin`;
     *  - srfst_NAME, one per observation point NAME: t disp vel (m, m/s);
     *  - global.dat: t max_slip_rate moment_rate (s, log10 m/s, N/s per
     *    metre along strike: G int V ds with the entry Shear modulus);
     *  - slip.dat: a row of positions (after two zeros), then t,
     *    max_slip_rate and the slip at those positions, every `Slip profile
     *    interval`, during events every `Event slip profile interval`.
     * With `Mirror model` (one side of a fault between two equal bodies
     * computed against a rigid mirror, the SEAS symmetric reduction), the
     * surface stations report the benchmark's side x > 0: half of the
     * model's displacement and rate.
     */
    class SeasFiles : public SeasFileSet
    {
    public:
      /**
       * Throws std::invalid_argument (one line, naming the entry) if a
       * station or the profile lies outside the contact or the model is
       * 3D; nothing is written (open() creates or appends to the files).
       */
      SeasFiles(const std::string    &dir,
                const SeasParameters &parameters,
                const Layout         &layout);

      std::string
      name() const override
      {
        return "SEAS files";
      }

      /** The station and global rows of the step, slip.dat when due. */
      void
      write(const Record &record) override;

    private:
      void
      write_headers() override;

      /** The station and global rows of an accepted step. */
      void
      write_step(double t, const Sample &sample);

      /** One row of slip.dat (and shear_stress.dat, normal_stress.dat). */
      void
      write_profile(double t, const Sample &sample);

      /** A value at a position: nodes k and k + 1 with weights. */
      struct Interpolation
      {
        unsigned int k      = 0;
        double       weight = 0; // of node k + 1
      };

      Interpolation
      locate(double position, const std::string &entry) const;

      double
      interpolate(const Interpolation &where, const double *values) const;

      /**
       * Sort the sample's node values by position (slip, rates, stress,
       * state); returns log10 of the maximum slip rate.
       */
      double
      sort_sample(const Sample &sample);

      std::vector<unsigned int>  order;     // nodes by position
      std::vector<double>        positions; // sorted
      std::vector<double>        weights;   // sorted like positions
      std::vector<Interpolation> stations, profile;
      std::vector<double>        profile_positions;
      std::vector<std::string>   surface_names;
      /** The station columns pore_pressure and darcy_vel (SEAS BP6). */
      const bool pore_pressure, darcy_velocity;
      /**
       * The station column normal_stress and the profiles
       * shear_stress.dat and normal_stress.dat (SEAS BP3).
       */
      const bool normal_stress;
      /** Per surface station: 1 (up) or 2 (x, and down: SEAS BP3). */
      const unsigned int components;
      /** The first profile file's index in the set (slip.dat). */
      unsigned int        first_profile = 0;
      std::vector<double> slip, rate, log10_rate, stress, normal,
        log10_state;                       // sorted
      std::vector<double> pressure, darcy; // sorted, [MPa], [m/s]
    };
  } // namespace output
} // namespace rsfcycle

#endif
