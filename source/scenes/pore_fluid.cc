// SPDX-License-Identifier: LGPL-2.1-or-later
#include <cmath>
#include <deal.II/base/function_parser.h>
#include <iostream>
#include <rsfcycle/format.h>
#include <rsfcycle/physics/fault_diffusion.h>
#include <rsfcycle/scenes/pore_fluid.h>
#include <sstream>
#include <stdexcept>

namespace rsfcycle
{
  namespace scenes
  {
    namespace
    {
      /** The positive numbers: entry, default, documentation. */
      struct Entry
      {
        const char *name;
        const char *default_value;
        const char *documentation;
      };

      const Entry numbers[] = {
        {"Injection rate",
         "0.003",
         "The injection rate Q0 from t = 0 to the shut-in: in 3D a volume "
         "rate [m^3/s] (SEAS BP8: 0.003); in 2D, where the fluid domain is "
         "a line, a rate per unit length across the model's plane [m^2/s], "
         "the injected Darcy flux times Fault zone thickness (SEAS BP6: "
         "1.25e-6 m/s x 1 m). Any sign"},
        {"Shut-in time",
         "360000",
         "t_off [s]: the injection stops at t_off (SEAS BP8: 100 hours = "
         "360000 s; BP6: 100 days); > 0"},
        {"Fluid compressibility",
         "1e-8",
         "The compressibility beta of the fluid-filled fault zone [1/Pa]; "
         "> 0"},
        {"Porosity", "0.1", "The porosity phi of the fault zone [-]; > 0"},
        {"Permeability",
         "5e-14",
         "The permeability k of the fault zone [m^2]; > 0. The "
         "diffusivity is alpha = k / (phi beta eta) [m^2/s] (SEAS BP8: "
         "0.05)"},
        {"Fluid viscosity",
         "1e-3",
         "The fluid's dynamic viscosity eta [Pa s]; > 0"},
        {"Fault zone thickness",
         "1",
         "The thickness L of the fault zone the fluid flows in [m]; > 0"},
        {"Injection width",
         "50",
         "Source = gaussian: the standard deviation L_inj [m] of the "
         "Gaussian source exp(-r^2 / (2 L_inj^2)), normalised to take the "
         "injection rate (SEAS BP8-GS: 50); > 0"},
        {"Well radius",
         "0.05",
         "Source = well: the well's radius r_w [m] in the Peaceman well "
         "index (SEAS BP8-PW: 0.05); > 0"},
        {"Well storage",
         "1e-7",
         "Source = well: the well's storage S_well [m^3/Pa] (SEAS BP8-PW: "
         "1e-7); > 0"},
        {"Half width",
         "400",
         "l [m]: the fluid domain is [-l, l] (2D) or [-l, l]^2 (3D) in "
         "Plane coordinates, with no flux across its boundary (SEAS BP8: "
         "400); every contact node must lie in it; > 0"},
        {"Cell size",
         "10",
         "The uniform cell size h of the fluid domain's own mesh [m]; 2 l "
         "/ h must be an integer, and even for the point and well sources "
         "(the injection at the node at the origin); > 0"},
        {"Time step",
         "600",
         "The largest internal time step of the diffusion [s]: the step is "
         "the largest t_off / N not above it, so that the steps hit the "
         "shut-in; the pressure at other times is interpolated; > 0"}};

      /**
       * p (darcy = false) or the Darcy velocity's dim - 1 components at a
       * contact point: the diffusion's fields at the point's plane
       * coordinates, at the function's time.
       */
      template <int dim>
      class DiffusionField : public Function<dim>
      {
      public:
        DiffusionField(
          std::shared_ptr<const physics::FaultDiffusion<dim - 1>> diffusion,
          std::shared_ptr<const FunctionParser<dim>>              to_plane,
          const bool                                              darcy,
          const std::string                                      &section)
          : Function<dim>(darcy ? dim - 1 : 1)
          , diffusion(std::move(diffusion))
          , to_plane(std::move(to_plane))
          , darcy(darcy)
          , section(section)
        {}

        double
        value(const Point<dim> &x, const unsigned int component) const override
        {
          const Point<dim - 1> s = plane_point(x);
          if (!darcy)
            return diffusion->value(s, this->get_time());
          return diffusion->darcy_velocity(s, this->get_time())[component];
        }

      private:
        Point<dim - 1>
        plane_point(const Point<dim> &x) const
        {
          Vector<double> values(dim - 1);
          to_plane->vector_value(x, values);
          Point<dim - 1> s;
          for (unsigned int d = 0; d < dim - 1; ++d)
            s[d] = values[d];
          if (!diffusion->contains(s))
            {
              std::string at, in;
              for (unsigned int d = 0; d < dim; ++d)
                at += (d ? ", " : "") + format_number(x[d]);
              for (unsigned int d = 0; d < dim - 1; ++d)
                in += (d ? ", " : "") + format_number(s[d]);
              throw std::invalid_argument(
                section + "/Half width: the contact point (" + at +
                ") m lies at (" + in +
                ") m in Plane coordinates, outside the fluid domain (each "
                "coordinate must lie in [-Half width, Half width])");
            }
          return s;
        }

        const std::shared_ptr<const physics::FaultDiffusion<dim - 1>> diffusion;
        const std::shared_ptr<const FunctionParser<dim>>              to_plane;
        const bool                                                    darcy;
        const std::string                                             section;
      };


      /** The map from the contact's coordinates to the plane's. */
      template <int dim>
      std::shared_ptr<const FunctionParser<dim>>
      parse_plane_coordinates(const std::string &given,
                              const std::string &entry)
      {
        const std::string expression =
          !given.empty() ? given : (dim == 2 ? "y" : "x; z");
        const std::string  variables = dim == 2 ? "x,y" : "x,y,z";
        auto               map = std::make_shared<FunctionParser<dim>>(dim - 1);
        std::ostringstream diagnosis;
        std::streambuf    *cerr_buffer = std::cerr.rdbuf(diagnosis.rdbuf());
        try
          {
            map->initialize(variables, expression, {{"pi", M_PI}});
            map->value(Point<dim>());
          }
        catch (const std::exception &)
          {
            std::cerr.rdbuf(cerr_buffer);
            throw std::invalid_argument(
              entry + " = " + expression + ": must be " +
              std::to_string(dim - 1) + " expression(s) of " + variables +
              (dim == 2 ? "" : " separated by ';'") + " (muparser syntax)");
          }
        std::cerr.rdbuf(cerr_buffer);
        return map;
      }


      /** The diffusion's parameters, each number checked with its entry. */
      physics::FaultDiffusionParameters
      parse_numbers(ParameterHandler &prm, const std::string &section)
      {
        for (const Entry &entry : numbers)
          if (!(prm.get_double(entry.name) > 0) ||
              !std::isfinite(prm.get_double(entry.name)))
            if (std::string(entry.name) != "Injection rate")
              throw std::invalid_argument(section + "/" + entry.name + " = " +
                                          prm.get(entry.name) +
                                          ": must be > 0 and finite");
        physics::FaultDiffusionParameters p;
        p.injection_rate  = prm.get_double("Injection rate");
        p.shut_in_time    = prm.get_double("Shut-in time");
        p.compressibility = prm.get_double("Fluid compressibility");
        p.porosity        = prm.get_double("Porosity");
        p.permeability    = prm.get_double("Permeability");
        p.viscosity       = prm.get_double("Fluid viscosity");
        p.thickness       = prm.get_double("Fault zone thickness");
        p.injection_width = prm.get_double("Injection width");
        p.well_radius     = prm.get_double("Well radius");
        p.well_storage    = prm.get_double("Well storage");
        p.half_width      = prm.get_double("Half width");
        p.cell_size       = prm.get_double("Cell size");
        p.time_step       = prm.get_double("Time step");
        p.boundary =
          prm.get("Boundary") == "no flux" ?
            physics::FaultDiffusionParameters::Boundary::no_flux :
            physics::FaultDiffusionParameters::Boundary::fixed_pressure;
        return p;
      }
    } // namespace


    void
    PoreFluid::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Pore fluid");
      prm.declare_entry(
        "Source",
        "function",
        Patterns::Selection("none|function|gaussian|point|well"),
        "Where the pore pressure p on the contact comes from (the friction "
        "acts on Normal stress - p): none; function, the expressions "
        "Friction/Pore pressure and Darcy velocity (empty: none; SEAS "
        "BP6's closed form); or the pressure diffusing in the fault zone "
        "from an injection at the origin of Plane coordinates, solved on "
        "a mesh of its own (doc/model.md section 9): gaussian, a Gaussian "
        "source of width Injection width (SEAS BP8-GS); point, the "
        "injection at one node (SEAS BP6); well, a Peaceman well with "
        "storage (SEAS BP8-PW, 3D only). The diffusing sources need "
        "Friction/Normal stress and Solver/Bulk = green-function");
      for (const Entry &entry : numbers)
        prm.declare_entry(entry.name,
                          entry.default_value,
                          Patterns::Double(),
                          entry.documentation);
      prm.declare_entry("Boundary",
                        "no flux",
                        Patterns::Selection("no flux|fixed pressure"),
                        "The fluid domain's boundary: no flux (SEAS), or "
                        "fixed pressure p = 0");
      prm.declare_entry(
        "Plane coordinates",
        "",
        Patterns::Anything(),
        "The fluid domain's coordinates [m] of a contact point, as "
        "expressions of the scene's x, y (and z in 3D): one in 2D, two "
        "separated by ';' in 3D; the injection is at their origin and the "
        "Darcy velocity's components (SEAS darcy_vel, darcy_vel_2, "
        "darcy_vel_3) are along their axes. Empty: y in 2D, x; z in 3D");
      prm.leave_subsection();
    }


    std::string
    PoreFluid::source(ParameterHandler &prm)
    {
      prm.enter_subsection("Pore fluid");
      const std::string source = prm.get("Source");
      prm.leave_subsection();
      return source;
    }


    template <int dim>
    PoreFluid::Functions<dim>
    PoreFluid::parse(ParameterHandler &prm, const std::string &section)
    {
      using Source             = physics::FaultDiffusionParameters::Source;
      const std::string here   = section + "/Pore fluid";
      const std::string source = PoreFluid::source(prm);
      Functions<dim>    result;
      if (source == "none" || source == "function")
        return result;
      prm.enter_subsection("Pore fluid");
      auto p   = parse_numbers(prm, here);
      p.source = source == "gaussian" ? Source::gaussian :
                 source == "point"    ? Source::point :
                                        Source::well;
      const auto to_plane =
        parse_plane_coordinates<dim>(prm.get("Plane coordinates"),
                                     here + "/Plane coordinates");
      prm.leave_subsection();
      if (p.source == Source::well && dim != 3)
        throw std::invalid_argument(here +
                                    "/Source = well: a Peaceman well "
                                    "needs Dimension = 3 (the fault plane)");
      const double cells = 2 * p.half_width / p.cell_size;
      const bool   whole = std::abs(cells - std::round(cells)) <= 1e-9 * cells;
      const bool   even  = whole && std::lround(cells) % 2 == 0;
      if (!whole || (p.source != Source::gaussian && !even))
        throw std::invalid_argument(
          here + "/Cell size = " + format_number(p.cell_size) + ": 2 x Half " +
          "width / Cell size = " + format_number(cells) + " must be " +
          (p.source == Source::gaussian ? "an integer" :
                                          "an even integer (the injection "
                                          "at the node at the origin)"));
      std::shared_ptr<const physics::FaultDiffusion<dim - 1>> diffusion;
      try
        {
          diffusion = std::make_shared<physics::FaultDiffusion<dim - 1>>(p);
        }
      catch (const std::invalid_argument &e)
        {
          throw std::invalid_argument(here + ": " + e.what());
        }
      result.pressure =
        std::make_shared<DiffusionField<dim>>(diffusion, to_plane, false, here);
      result.darcy_velocity =
        std::make_shared<DiffusionField<dim>>(diffusion, to_plane, true, here);
      return result;
    }


    template PoreFluid::Functions<2>
    PoreFluid::parse<2>(ParameterHandler &, const std::string &);
    template PoreFluid::Functions<3>
    PoreFluid::parse<3>(ParameterHandler &, const std::string &);
  } // namespace scenes
} // namespace rsfcycle
