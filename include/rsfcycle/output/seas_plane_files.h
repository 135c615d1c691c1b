// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_output_seas_plane_files_h
#define rsfcycle_output_seas_plane_files_h

#include <array>
#include <optional>
#include <rsfcycle/output/sample.h>
#include <rsfcycle/output/seas_events.h>
#include <rsfcycle/output/seas_file_set.h>
#include <rsfcycle/seas_parameters.h>
#include <string>
#include <utility>
#include <vector>

namespace rsfcycle
{
  namespace output
  {
    /**
     * The plain-text files of the 3D SCEC SEAS benchmarks (BP4, BP5, BP7;
     * Jiang et al. 2022, JGR 127, e2021JB023519), as the benchmark's
     * description names and heads them (SeasConventions; doc/seas.md), for
     * a 3D model whose fault lies in a plane y = const of the mesh, in the
     * benchmarks' frame: x2 = the mesh's x (along strike), x3 = -z (depth,
     * positive down), 1 = the mesh's y (fault normal). Written by the first
     * rank, from t = 0:
     *  - fltst_strk+XXdp+YY, one per `Plane stations` entry: t slip_2 slip_3
     *    slip_rate_2 slip_rate_3 shear_stress_2 shear_stress_3 state (s, m,
     *    m, log10 m/s, log10 m/s, MPa, MPa, log10 s; a rate component's
     *    log10 of its magnitude), every accepted step, bilinear between the
     *    four contact nodes around the station (a grid of lines x = const,
     *    z = const there, as a structured mesh of the contact has);
     *  - blkst_NAME, one per observation point (`Mesh file/Observation
     *    components = all`, where the benchmark asks for them): t disp_1
     *    disp_2 disp_3 vel_1 vel_2 vel_3;
     *  - global.dat: t max_slip_rate moment_rate (s, log10 m/s, N m/s: G
     *    int |V| dA over `Moment rate region`), with `VW moment rate region`
     *    a fourth column moment_rate_vw;
     *  - rupture.dat: x2 x3 t for every node of `Rupture region`: the first
     *    time in the first event at which its slip rate reaches `Rupture
     *    threshold` (interpolated in log10 V), 1e9 if never; written when
     *    that event is over (or the run ends);
     *  - catalog.dat (BP5, BP7): a row per event of the description's
     *    definition (output::SeasEvents);
     *  - with a pore fluid (SEAS BP8), the station columns pore_pressure
     *    (MPa) and, with its Darcy velocity, darcy_vel_2 darcy_vel_3 (m/s,
     *    along the fluid domain's axes) before state;
     *  - slip_2, slip_3, stress_2, stress_3 (BP8's shear_stress_2, ...;
     *    with a pore fluid also pore_pressure) along
     *    the `Strike profile` line (FIELD_strike.dat) and the `Depth
     *    profile` line (FIELD_depth.dat): a row 0 0 and the positions, then
     *    t, max_slip_rate and the values, every `Slip profile interval`,
     *    during events every `Event slip profile interval`. With `Boundary
     *    slip rate`, the creep nodes one cell beyond the contact are
     *    positions too (their pore pressure that of the contact node next
     *    to them). BP8's files end in .dat, and it has no rupture.dat.
     * The shear stress is the friction stress along the slip rate (the
     * rake is free). With `Mirror model` the off-fault stations report the
     * benchmark's side y > 0: half of the model's displacement and rate.
     */
    class SeasPlaneFiles : public SeasFileSet
    {
    public:
      /**
       * Throws std::invalid_argument (one line, naming the entry) if the
       * contact is not in a plane y = const, a station or a profile point
       * is not surrounded by contact nodes, or the observation points do
       * not record all components; nothing is written.
       */
      SeasPlaneFiles(const std::string    &dir,
                     const SeasParameters &parameters,
                     const Layout         &layout);

      std::string
      name() const override
      {
        return "SEAS files";
      }

      /** The station, global and rupture rows, the profiles when due. */
      void
      write(const Record &record) override;

      /** The last event of catalog.dat and rupture.dat if still due. */
      void
      finish(const Record &record) override;

      void
      save(boost::archive::binary_oarchive &archive) const override;
      void
      load(boost::archive::binary_iarchive &archive) override;

    private:
      void
      write_headers() override;

      void
      write_rows(const Record &record) override;

      /** A value at a point: four nodes and their bilinear weights. */
      struct Bilinear
      {
        std::array<int, 4>    nodes{};
        std::array<double, 4> weights{};
      };

      Bilinear
      locate(double x2, double x3, const std::string &entry) const;

      double
      at(const Bilinear &where, const std::vector<double> &values) const;

      /** The node values of the sample in the benchmark's frame at t. */
      void
      fill(double t, const Sample &sample);

      /** The events' catalogue row, and rupture.dat once it is due. */
      void
      write_events(const std::optional<SeasEvents::Row> &row);

      /** rupture.dat's rows (once). */
      void
      write_rupture();

      // the contact nodes: (x2, x3), lumped weights, a grid of them; the
      // load or creep nodes one cell beyond it follow the contact's nodes
      // in `plane`, each with the contact node next to it in `neighbour`
      std::vector<std::array<double, 2>>   plane;
      std::vector<double>                  weights;
      std::vector<unsigned int>            neighbour;
      std::vector<double>                  grid_x2, grid_x3;
      std::vector<int>                     grid; // node at (i, j), or -1
      std::array<std::array<double, 3>, 2> axes;
      /** The contact nodes in Moment rate region, VW ..., Rupture region. */
      std::vector<char> in_moment, in_vw, in_rupture;

      std::vector<Bilinear>    stations, strike_line, depth_line;
      std::vector<double>      strike_x2, depth_x3;
      std::vector<std::string> block_names;
      unsigned int first_block = 0, global = 0, rupture = 0, catalog = 0,
                   first_profile = 0;

      // the sample's node values
      /** The profiles' fields: file name stem, header text. */
      std::vector<std::pair<std::string, std::string>>
      profile_fields() const
      {
        const std::string stress = conventions.stress_profile;
        std::vector<std::pair<std::string, std::string>> fields = {
          {"slip_2", "Slip_2 (m)"},
          {"slip_3", "Slip_3 (m)"},
          {stress + "_2", "Shear_stress_2 (MPa)"},
          {stress + "_3", "Shear_stress_3 (MPa)"}};
        if (pore_pressure)
          fields.emplace_back("pore_pressure", "Pore_pressure (MPa)");
        return fields;
      }

      std::vector<double> slip_2, slip_3, log10_rate_2, log10_rate_3,
        log10_rate, stress_2, stress_3, log10_state, pressure, darcy_2, darcy_3;
      /** Whether the samples carry a pore pressure, a Darcy velocity. */
      bool   pore_pressure = false, darcy_velocity = false;
      double log10_max_rate = 0;

      SeasEvents events;
      bool       rupture_written = false;
    };
  } // namespace output
} // namespace rsfcycle

#endif
