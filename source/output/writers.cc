// SPDX-License-Identifier: LGPL-2.1-or-later
#include <rsfcycle/output/base_profile.h>
#include <rsfcycle/output/event_catalogue.h>
#include <rsfcycle/output/seas_files.h>
#include <rsfcycle/output/seas_plane_files.h>
#include <rsfcycle/output/time_series.h>
#include <rsfcycle/output/writers.h>

namespace rsfcycle
{
  namespace output
  {
    std::vector<std::unique_ptr<Writer>>
    make_writers(const Parameters &parameters, const Layout &layout)
    {
      const std::string &dir = parameters.run.output_directory;
      const auto        &out = parameters.output;
      std::vector<std::unique_ptr<Writer>> writers;
      writers.push_back(std::make_unique<TimeSeries>(dir, layout));
      writers.push_back(std::make_unique<BaseProfile>(dir, layout, out));
      writers.push_back(
        std::make_unique<EventCatalogue>(dir,
                                         !layout.lateral_positions.empty()));
      if (out.seas.enabled() && layout.lateral_positions.empty())
        writers.push_back(std::make_unique<SeasFiles>(dir, out.seas, layout));
      else if (out.seas.enabled())
        writers.push_back(
          std::make_unique<SeasPlaneFiles>(dir, out.seas, layout));
      return writers;
    }
  } // namespace output
} // namespace rsfcycle
