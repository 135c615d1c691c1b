#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <rsfcycle/output/files.h>
#include <rsfcycle/output/recorder.h>
#include <stdexcept>

namespace rsfcycle
{
  namespace output
  {
    Recorder::Recorder(const std::string    &dir,
                       const time::Layout   &layout,
                       const bool            resume,
                       const FileSizes      &sizes,
                       const SeasParameters &seas_parameters)
    {
      // Node order of the profile: along the base, then (3D) by z.
      const auto        &s = layout.positions;
      const auto        &z = layout.lateral_positions;
      const unsigned int n = s.size();
      order.resize(n);
      for (unsigned int k = 0; k < n; ++k)
        order[k] = k;
      std::sort(order.begin(), order.end(), [&](unsigned int i, unsigned j) {
        if (s[i] != s[j])
          return s[i] < s[j];
        return !z.empty() && z[i] < z[j];
      });
      // on every rank: its refusals (stations off the contact) are alike
      if (seas_parameters.enabled())
        seas = std::make_unique<SeasFiles>(dir, seas_parameters, layout);

      // the first rank writes; the others keep the interface
      if (!writing)
        return;
      paths = {{dir + "/time-series.csv",
                dir + "/base-profile.csv",
                dir + "/events.csv"}};
      if (resume)
        {
          // drop what was written after the checkpoint, then append; first
          // check all files, so that a refusal changes nothing
          std::vector<std::string> all(paths.begin(), paths.end());
          std::vector<long long>   kept = {sizes.series,
                                           sizes.profile,
                                           sizes.catalogue};
          if (seas)
            {
              if (sizes.seas.size() != seas->paths().size())
                throw std::invalid_argument(
                  dir + "/checkpoint.bin: recorded " +
                  std::to_string(sizes.seas.size()) + " SEAS files, " +
                  "Output/SEAS of parameters.prm asks for " +
                  std::to_string(seas->paths().size()));
              all.insert(all.end(), seas->paths().begin(), seas->paths().end());
              kept.insert(kept.end(), sizes.seas.begin(), sizes.seas.end());
            }
          cut_to_sizes(all, kept);
        }
      std::ofstream *const files[3] = {&series, &profile, &catalogue};
      for (unsigned int i = 0; i < 3; ++i)
        {
          files[i]->open(paths[i], resume ? std::ios::app : std::ios::out);
          if (!*files[i])
            throw file_error(paths[i], errno);
        }
      if (seas)
        seas->open(resume);
      if (!resume)
        {
          write_headers(layout);
          flush();
        }
    }


    void
    Recorder::write_headers(const time::Layout &layout)
    {
      series << "time_s,step_size_s,fixed_point_iterations,tnnmg_iterations,"
                "linear_iterations,spatial_problems,max_slip_rate_m_per_s";
      for (const auto &name : layout.observation_names)
        series << "," << name;
      series << ",all_tnnmg_iterations,all_linear_iterations\n";

      const bool lateral = !layout.lateral_positions.empty();
      profile << "# slip rate [m/s] of the contact nodes; first row: "
                 "position along the base [m]"
              << (lateral ? " (then the z coordinate in the second row)" : "")
              << "\n"
              << "time_s";
      for (const unsigned int k : order)
        profile << "," << layout.positions[k];
      profile << "\n";
      if (lateral)
        {
          profile << "z_m";
          for (const unsigned int k : order)
            profile << "," << layout.lateral_positions[k];
          profile << "\n";
        }
      catalogue << EventDetector::csv_header() << "\n";
    }


    void
    Recorder::write_step(const double                t,
                         const double                step_size,
                         const time::Sample         &sample,
                         const unsigned int          spatial_problems,
                         const time::StepStatistics &work)
    {
      if (!writing)
        return;
      const auto fastest =
        std::max_element(sample.slip_rates.begin(), sample.slip_rates.end());
      const double max_rate =
        (fastest == sample.slip_rates.end()) ? 0. : *fastest;
      const auto &counts = sample.statistics;
      series_row.precise(t)
        << step_size << counts.fixed_point_iterations << counts.tnnmg_iterations
        << counts.linear_iterations << spatial_problems << max_rate;
      for (const double value : sample.observations)
        series_row << value;
      // the work of every spatial problem solved for this step, the
      // controller's comparisons and rejected attempts included
      series_row << work.tnnmg_iterations << work.linear_iterations;
      series_row.write_line(series);
      check();
      if (seas)
        seas->write_step(t, sample);
    }


    void
    Recorder::write_seas_profile(const double t, const time::Sample &sample)
    {
      if (writing && seas)
        seas->write_profile(t, sample);
    }


    void
    Recorder::write_profile(const double t, const std::vector<double> &rates)
    {
      if (!writing)
        return;
      profile_row.precise(t);
      for (const unsigned int k : order)
        profile_row << rates[k];
      profile_row.write_line(profile);
      check();
    }


    void
    Recorder::write_event(const unsigned int index, const Event &event)
    {
      if (!writing)
        return;
      EventDetector::write_csv_row(catalogue, index, event);
      catalogue.flush();
      check();
    }


    void
    Recorder::flush()
    {
      if (!writing)
        return;
      series.flush();
      profile.flush();
      catalogue.flush();
      check();
      if (seas)
        seas->flush();
    }


    FileSizes
    Recorder::sync()
    {
      if (!writing)
        return {};
      flush();
      for (const auto &path : paths)
        sync_to_disk(path);
      FileSizes sizes;
      sizes.series    = series.tellp();
      sizes.profile   = profile.tellp();
      sizes.catalogue = catalogue.tellp();
      if (seas)
        {
          sizes.seas = seas->sizes();
          for (const auto &path : seas->paths())
            sync_to_disk(path);
        }
      return sizes;
    }


    void
    Recorder::check() const
    {
      // after a failed write, errno still holds its reason: the streams
      // make no system call after it
      const std::ofstream *const files[3] = {&series, &profile, &catalogue};
      for (unsigned int i = 0; i < 3; ++i)
        if (!*files[i])
          throw file_error(paths[i], errno);
    }
  } // namespace output
} // namespace rsfcycle
