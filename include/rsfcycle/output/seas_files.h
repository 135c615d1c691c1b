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
     * The plain-text files of the SCEC SEAS benchmarks for a 2D model (a
     * 1D fault), as the benchmark's description names and heads them
     * (SeasConventions; doc/seas.md, "The files each problem writes"),
     * written by the first rank into the run folder, from t = 0:
     *  - fltst_dpXXX, one per fault station at the along-contact position
     *    XXX x 100 m: t slip slip_rate shear_stress state (s, m, log10 m/s,
     *    MPa, log10 s), every accepted step, linear between the two nodes
     *    around the station; with a split fault's normal coupling (BP3)
     *    normal_stress (MPa) before state, with a pore fluid (BP6)
     *    pore_pressure (MPa) and darcy_vel (m/s), and with strike names
     *    fltst_strk+XX, XX from `Fault station origin`;
     *  - srfst_NAME, one per observation point NAME (where the benchmark
     *    asks for them): t disp vel, or disp_1 disp_2 vel_1 vel_2;
     *  - global.dat (where asked for): t max_slip_rate moment_rate (s,
     *    log10 m/s, N/s per metre along strike: G int V ds);
     *  - the profiles (slip.dat or BP1's devol.dat; shear_stress.dat and
     *    normal_stress.dat with a normal coupling or a pore fluid,
     *    darcy_vel.dat with a Darcy velocity): a row of positions after two
     *    zeros, then t, max_slip_rate and the values at those positions,
     *    every `Slip profile interval`, during events every `Event slip
     *    profile interval`. With `Boundary slip rate`, the load or creep
     *    node one cell beyond the contact's end is a position too.
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

      /** The station and global rows of the step, the profiles when due. */
      void
      write(const Record &record) override;

    private:
      void
      write_headers() override;

      void
      write_rows(const Record &record) override;

      /** The station and global rows of an accepted step. */
      void
      write_step(double t);

      /** One row of each profile. */
      void
      write_profile(double t);

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
       * state) and fill in the boundary nodes at time t; returns log10 of
       * the maximum slip rate over the contact.
       */
      double
      sort_sample(double t, const Sample &sample);

      /**
       * The nodes by position; -1: a load or creep node beyond the
       * contact's end (`Boundary slip rate`).
       */
      std::vector<int>    order;
      std::vector<double> positions; // sorted
      std::vector<double> weights;   // sorted like positions
      /** The profile files' fields: name and description with unit. */
      std::vector<Column> profile_fields;
      /** The sample being written, and log10 of its largest slip rate. */
      const Sample              *current        = nullptr;
      double                     log10_max_rate = 0;
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
