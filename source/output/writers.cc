// SPDX-License-Identifier: LGPL-2.1-or-later
#include <algorithm>
#include <functional>
#include <rsfcycle/output/base_profile.h>
#include <rsfcycle/output/event_catalogue.h>
#include <rsfcycle/output/hdf5_snapshots.h>
#include <rsfcycle/output/seas_files.h>
#include <rsfcycle/output/seas_plane_files.h>
#include <rsfcycle/output/snapshots.h>
#include <rsfcycle/output/time_series.h>
#include <rsfcycle/output/writers.h>
#include <stdexcept>

namespace rsfcycle
{
  namespace output
  {
    namespace
    {
      /** What make_writers() hands a writer's factory. */
      struct Context
      {
        const Parameters &parameters;
        const Layout     &layout;
        const Offer      &offer;
        const std::string dir;
      };

      /**
       * A writer's name, the fields it needs, its factory and the function
       * that declares its entries in subsection Output (none: nullptr).
       */
      struct WriterType
      {
        std::string                                             name;
        std::vector<Field>                                      needs;
        std::function<std::unique_ptr<Writer>(const Context &)> make;
        void (*declare)(dealii::ParameterHandler &) = nullptr;
      };

      /** The SEAS files of a 2D (a line of nodes) or a 3D fault. */
      std::unique_ptr<Writer>
      seas_files(const Context &c)
      {
        const auto &seas = c.parameters.output.seas;
        if (c.layout.lateral_positions.empty())
          return std::make_unique<SeasFiles>(c.dir, seas, c.layout);
        return std::make_unique<SeasPlaneFiles>(c.dir, seas, c.layout);
      }

      /** A body writer W<dim> of the offered BodySource<dim>. */
      template <template <int> class W>
      std::unique_ptr<Writer>
      body_writer(const Context &c)
      {
        if (const auto *b = std::any_cast<BodySource<2>>(&c.offer.body))
          return std::make_unique<W<2>>(c.dir, *b, c.parameters.output);
        return std::make_unique<W<3>>(c.dir,
                                      std::any_cast<const BodySource<3> &>(
                                        c.offer.body),
                                      c.parameters.output);
      }

      /** The list: one line per writer. */
      const std::vector<WriterType> &
      writer_types()
      {
        static const std::vector<WriterType> list = {
          {"time series",
           {Field::contact},
           [](const Context &c) {
             return std::make_unique<TimeSeries>(c.dir, c.layout);
           }},
          {"base profile",
           {Field::contact},
           [](const Context &c) {
             return std::make_unique<BaseProfile>(c.dir,
                                                  c.layout,
                                                  c.parameters.output);
           },
           BaseProfile::declare_parameters},
          {"events",
           {Field::contact},
           [](const Context &c) {
             return std::make_unique<EventCatalogue>(
               c.dir, !c.layout.lateral_positions.empty());
           },
           EventCatalogue::declare_parameters},
          {"seas",
           {Field::contact, Field::stresses},
           seas_files,
           SeasParameters::declare_parameters},
          {"vtu",
           {Field::body},
           body_writer<VtuSnapshots>,
           declare_snapshot_parameters},
          {"hdf5",
           {Field::body},
           body_writer<Hdf5Snapshots>,
           declare_snapshot_parameters}};
        return list;
      }

      const WriterType &
      type_of(const std::string &name)
      {
        for (const auto &type : writer_types())
          if (type.name == name)
            return type;
        throw std::invalid_argument("Output/Writers: '" + name +
                                    "': allowed are " + writer_names());
      }

      std::string
      field_name(const Field field)
      {
        switch (field)
          {
            case Field::contact:
              return "the contact's slip";
            case Field::stresses:
              return "the contact's stresses";
            case Field::body:
              return "the body on a mesh";
          }
        return "?";
      }

      bool
      listed(const Parameters &parameters, const std::string &name)
      {
        const auto &list = parameters.output.writers;
        return std::find(list.begin(), list.end(), name) != list.end();
      }
    } // namespace


    void
    declare_parameters(dealii::ParameterHandler &prm)
    {
      // a function shared by several writers (the snapshots') declares once
      std::vector<void (*)(dealii::ParameterHandler &)> done;
      prm.enter_subsection("Output");
      for (const auto &type : writer_types())
        if (type.declare &&
            std::find(done.begin(), done.end(), type.declare) == done.end())
          {
            type.declare(prm);
            done.push_back(type.declare);
          }
      prm.leave_subsection();
    }


    std::string
    writer_names()
    {
      std::string names;
      for (const auto &type : writer_types())
        names += (names.empty() ? "" : "|") + type.name;
      return names;
    }


    void
    check_writers(const Parameters         &parameters,
                  const std::vector<Field> &offered,
                  const std::string        &model)
    {
      const auto &names = parameters.output.writers;
      for (auto name = names.begin(); name != names.end(); ++name)
        if (std::find(names.begin(), name, *name) != name)
          throw std::invalid_argument("Output/Writers: " + *name +
                                      " is listed twice");
      const auto offers = [&](const WriterType &type) {
        return std::all_of(
          type.needs.begin(), type.needs.end(), [&](const Field field) {
            return std::find(offered.begin(), offered.end(), field) !=
                   offered.end();
          });
      };
      for (const std::string &name : names)
        if (const WriterType &type = type_of(name); !offers(type))
          {
            std::string usable;
            for (const auto &other : writer_types())
              if (offers(other))
                usable += (usable.empty() ? "" : ", ") + other.name;
            for (const Field field : type.needs)
              if (std::find(offered.begin(), offered.end(), field) ==
                  offered.end())
                throw std::invalid_argument(
                  "Output/Writers = " + name + ": needs " + field_name(field) +
                  ", which " + model +
                  " does not offer (its writers: " + usable + ")");
          }
      const bool seas = parameters.output.seas.enabled();
      if (listed(parameters, "seas") && !seas)
        throw std::invalid_argument(
          "Output/Writers = seas: needs Output/SEAS/Benchmark (or Problem)");
      if (seas && !listed(parameters, "seas"))
        throw std::invalid_argument(
          "Output/SEAS/Benchmark: the SEAS files need seas in "
          "Output/Writers");
    }


    std::vector<std::unique_ptr<Writer>>
    make_writers(const Parameters &parameters,
                 const Layout     &layout,
                 const Offer      &offer)
    {
      check_writers(parameters, offer.fields, offer.model);
      const Context                        context{parameters,
                            layout,
                            offer,
                            parameters.run.output_directory};
      std::vector<std::unique_ptr<Writer>> writers;
      for (const std::string &name : parameters.output.writers)
        writers.push_back(type_of(name).make(context));
      return writers;
    }
  } // namespace output
} // namespace rsfcycle
