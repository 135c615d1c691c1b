// SPDX-License-Identifier: LGPL-2.1-or-later
#include <cmath>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>
#include <iostream>
#include <rsfcycle/format.h>
#include <rsfcycle/scenes/friction_field.h>
#include <rsfcycle/scenes/pore_fluid.h>
#include <sstream>
#include <stdexcept>

namespace rsfcycle
{
  namespace scenes
  {
    namespace
    {
      /** The entries: name, default expression, documentation. */
      struct Entry
      {
        const char *name;
        const char *default_value;
        const char *documentation;
      };

      const Entry entries[] = {
        {"a",
         "0.002",
         "Direct-effect parameter a [-] on the contact, a function of the "
         "mesh's coordinates x, y (and z in 3D) [m]; > 0"},
        {"b - a",
         "0.015",
         "b - a [-] on the contact, a function of x, y (and z in 3D) [m]; "
         "> 0 is rate weakening, where the mesh is refined toward the "
         "contact"},
        {"Characteristic slip distance",
         "22.5e-6",
         "L [m] on the contact, a function of x, y (and z in 3D) [m]; > 0"},
        {"Reference friction coefficient",
         "0.7",
         "mu* [-] on the contact, a function of x, y (and z in 3D) [m]; "
         ">= 0"},
        {"Reference slip rate",
         "50e-6",
         "V* [m/s] on the contact, a function of x, y (and z in 3D) [m]; "
         "> 0"},
        {"Cohesion",
         "0",
         "Cohesion C [Pa] on the contact, a function of x, y (and z in 3D) "
         "[m]; >= 0"},
        {"Initial state",
         "",
         "Initial state theta_0 [s] on the contact, a function of x, y (and "
         "z in 3D) [m]; > 0. Empty: theta_0 = L / V* (the steady state at "
         "V*)"},
        {"Normal stress",
         "",
         "Compressive normal stress |sigma_n| [Pa] on the contact, a "
         "function of x, y (and z in 3D) [m]; > 0, constant in time. Empty: "
         "the normal stress of the gravity equilibrium"},
        {"Shear prestress",
         "",
         "Shear stress tau_0 [Pa] on the contact that is not from the "
         "body's deformation (SEAS BP1's initial shear stress), constant in "
         "time, acting on the body along the load velocity, a function of "
         "x, y (and z in 3D) [m]. Empty: none"},
        {"Shear stress perturbation",
         "",
         "A shear stress Delta tau [Pa] on the contact added to Shear "
         "prestress, along the load velocity, a function of x, y (and z in "
         "3D) [m], multiplied by Shear stress perturbation history at the "
         "time t (SEAS BP7's prescribed nucleation, 1.75e6 G1(r)). Needs "
         "Solver/Bulk = green-function. Empty: none"},
        {"Shear stress perturbation history",
         "1",
         "The factor g(t) [-] of Shear stress perturbation at the time t "
         "[s], a function of t alone (SEAS BP7's G2: a smooth ramp from 0 "
         "at t = 0 to 1 at t = 1 s, if(t < 1, exp((t - 1)^2 / (t * (t - "
         "2))), 1)); used only with Shear stress perturbation"},
        {"Radiation damping",
         "",
         "Radiation damping eta [Pa s/m] on the contact (Solver/Dynamics = "
         "quasi-dynamic: the shear stress eta V is added to the friction), "
         "a function of x, y (and z in 3D) [m]; >= 0. Empty: the shear "
         "impedance sqrt(G rho) of the material next to the contact"},
        {"Pore pressure",
         "",
         "Pore-fluid pressure p [Pa] on the contact, a function of x, y (and "
         "z in 3D) [m] and the time t [s] (SEAS BP6: the closed-form "
         "pressure of a fluid injection): the friction acts on the "
         "effective normal stress |sigma_n| - p, which must stay > 0 (a run "
         "where it does not stops, naming the place and the time). Needs "
         "Normal stress and Solver/Bulk = green-function. Empty: none"},
        {"Darcy velocity",
         "",
         "The pore fluid's Darcy velocity q [m/s] along the contact, a "
         "function of x, y (and z in 3D) [m] and the time t [s], only "
         "reported (the SEAS station column darcy_vel; for a pressure p and "
         "a mobility k / eta_f, q = -(k / eta_f) dp/ds along the contact). "
         "Needs Pore pressure. Empty: not reported"}};


    } // namespace


    template <int dim>
    std::shared_ptr<Function<dim>>
    FrictionField<dim>::parse_expression(const std::string &expression,
                                         const std::string &entry,
                                         const bool         time_dependent)
    {
      {
        const std::string variables = std::string(dim == 2 ? "x,y" : "x,y,z") +
                                      (time_dependent ? ",t" : "");
        auto function = std::make_shared<FunctionParser<dim>>(1);
        // deal.II writes muparser's diagnosis to std::cerr before it
        // throws: keep it for the one-line message instead
        std::ostringstream diagnosis;
        std::streambuf    *cerr_buffer = std::cerr.rdbuf(diagnosis.rdbuf());
        try
          {
            function->initialize(variables,
                                 expression,
                                 {{"pi", M_PI}},
                                 time_dependent);
            // deal.II parses on the first evaluation
            function->value(Point<dim>());
          }
        catch (const std::exception &)
          {
            std::cerr.rdbuf(cerr_buffer);
            std::string        why;
            std::istringstream lines(diagnosis.str());
            for (std::string line; std::getline(lines, line);)
              if (line.rfind("Message:", 0) == 0)
                why = " (" + Utilities::trim(line.substr(8)) + ")";
            throw std::invalid_argument(
              entry + " = " + expression + ": not an expression of " +
              variables + why +
              "; muparser syntax, e.g. if(x > 0.1, 0.002, 0.02)");
          }
        std::cerr.rdbuf(cerr_buffer);
        return function;
      }
    }


    template <int dim>
    FrictionField<dim>::FrictionField(Functions functions)
      : f(std::move(functions))
    {}


    template <int dim>
    void
    FrictionField<dim>::declare_parameters(ParameterHandler &prm)
    {
      for (const Entry &entry : entries)
        prm.declare_entry(entry.name,
                          entry.default_value,
                          Patterns::Anything(),
                          entry.documentation);
      PoreFluid::declare_parameters(prm);
    }


    /**
     * The pore pressure and Darcy velocity: the expressions of the
     * subsection, or the diffusion of its `Pore fluid` (PoreFluid).
     */
    template <int dim>
    void
    FrictionField<dim>::parse_pore_fluid(ParameterHandler  &prm,
                                         const std::string &section,
                                         Functions         &functions)
    {
      const std::string source = PoreFluid::source(prm);
      for (const char *name : {"Pore pressure", "Darcy velocity"})
        if (source != "function" && !prm.get(name).empty())
          throw std::invalid_argument(
            section + "/" + name + " = " + prm.get(name) +
            ": given with Pore fluid/Source = " + source +
            "; it needs Source = function");
      const bool diffusing = source != "none" && source != "function";
      if ((diffusing || !prm.get("Pore pressure").empty()) &&
          !functions.normal_stress)
        throw std::invalid_argument(
          section +
          (diffusing ? "/Pore fluid/Source = " + source :
                       "/Pore pressure = " + prm.get("Pore pressure")) +
          ": needs Normal stress (the effective normal stress is Normal "
          "stress - the pore pressure)");
      if (diffusing)
        {
          const auto fluid         = PoreFluid::parse<dim>(prm, section);
          functions.pore_pressure  = fluid.pressure;
          functions.darcy_velocity = fluid.darcy_velocity;
          return;
        }
      const auto get_of_time = [&](const char *name) {
        return parse_expression(prm.get(name), section + "/" + name, true);
      };
      if (!prm.get("Pore pressure").empty())
        functions.pore_pressure = get_of_time("Pore pressure");
      if (!prm.get("Darcy velocity").empty())
        {
          if (!functions.pore_pressure)
            throw std::invalid_argument(
              section + "/Darcy velocity = " + prm.get("Darcy velocity") +
              ": needs Pore pressure");
          functions.darcy_velocity = get_of_time("Darcy velocity");
        }
    }


    template <int dim>
    FrictionField<dim>
    FrictionField<dim>::parse(ParameterHandler &prm, const std::string &section)
    {
      const auto get = [&](const char *name) {
        return parse_expression(prm.get(name), section + "/" + name);
      };
      Functions functions;
      functions.a         = get("a");
      functions.b_minus_a = get("b - a");
      functions.L         = get("Characteristic slip distance");
      functions.mu_star   = get("Reference friction coefficient");
      functions.v_star    = get("Reference slip rate");
      functions.cohesion  = get("Cohesion");
      if (!prm.get("Initial state").empty())
        functions.initial_state = get("Initial state");
      if (!prm.get("Normal stress").empty())
        functions.normal_stress = get("Normal stress");
      if (!prm.get("Shear prestress").empty())
        functions.shear_prestress = get("Shear prestress");
      if (!prm.get("Radiation damping").empty())
        functions.radiation_damping = get("Radiation damping");
      const auto get_of_time = [&](const char *name) {
        return parse_expression(prm.get(name), section + "/" + name, true);
      };
      if (!prm.get("Shear stress perturbation").empty())
        {
          functions.shear_perturbation = get("Shear stress perturbation");
          const std::string entry =
            section + "/Shear stress perturbation history";
          functions.perturbation_history =
            get_of_time("Shear stress perturbation history");
          // (a function of t alone: the same at two points, three times)
          Point<dim> far;
          for (unsigned int d = 0; d < dim; ++d)
            far[d] = 1e3 * (d + 1);
          for (const double t : {0., 0.5, 7.})
            {
              functions.perturbation_history->set_time(t);
              if (functions.perturbation_history->value(Point<dim>()) !=
                  functions.perturbation_history->value(far))
                throw std::invalid_argument(
                  entry + " = " + prm.get("Shear stress perturbation history") +
                  ": must be a function of the time t alone");
            }
        }
      else if (prm.get("Shear stress perturbation history") != "1")
        throw std::invalid_argument(
          section + "/Shear stress perturbation history = " +
          prm.get("Shear stress perturbation history") +
          ": needs Shear stress perturbation");
      parse_pore_fluid(prm, section, functions);
      return FrictionField(functions);
    }


    template <int dim>
    friction::Parameters
    FrictionField<dim>::parameters(const Point<dim> &x) const
    {
      friction::Parameters p;
      p.a        = f.a->value(x);
      p.b        = p.a + f.b_minus_a->value(x);
      p.L        = f.L->value(x);
      p.mu_star  = f.mu_star->value(x);
      p.v_star   = f.v_star->value(x);
      p.cohesion = f.cohesion->value(x);
      return p;
    }


    template <int dim>
    double
    FrictionField<dim>::initial_alpha(const Point<dim> &x) const
    {
      if (!f.initial_state)
        return 0;
      return std::log(f.initial_state->value(x) * f.v_star->value(x) /
                      f.L->value(x));
    }


    namespace
    {
      /** The value of an optional function at x; none if it is not given. */
      template <int dim>
      std::optional<double>
      value_if_given(const std::shared_ptr<const Function<dim>> &function,
                     const Point<dim>                           &x)
      {
        if (!function)
          return {};
        return function->value(x);
      }
    } // namespace


    template <int dim>
    std::optional<double>
    FrictionField<dim>::normal_stress(const Point<dim> &x) const
    {
      return value_if_given(f.normal_stress, x);
    }


    template <int dim>
    std::optional<double>
    FrictionField<dim>::shear_prestress(const Point<dim> &x) const
    {
      return value_if_given(f.shear_prestress, x);
    }


    template <int dim>
    std::optional<double>
    FrictionField<dim>::shear_perturbation(const Point<dim> &x) const
    {
      return value_if_given(f.shear_perturbation, x);
    }


    template <int dim>
    double
    FrictionField<dim>::perturbation_history(const double t) const
    {
      if (!f.perturbation_history)
        return 0;
      f.perturbation_history->set_time(t);
      return f.perturbation_history->value(Point<dim>());
    }


    template <int dim>
    std::optional<double>
    FrictionField<dim>::pore_pressure(const Point<dim> &x, const double t) const
    {
      if (!f.pore_pressure)
        return {};
      f.pore_pressure->set_time(t);
      return f.pore_pressure->value(x);
    }


    template <int dim>
    std::optional<std::array<double, 2>>
    FrictionField<dim>::darcy_velocity(const Point<dim> &x,
                                       const double      t) const
    {
      if (!f.darcy_velocity)
        return {};
      f.darcy_velocity->set_time(t);
      std::array<double, 2> q = {{f.darcy_velocity->value(x, 0), 0.}};
      if (f.darcy_velocity->n_components > 1)
        q[1] = f.darcy_velocity->value(x, 1);
      return q;
    }


    template <int dim>
    std::optional<double>
    FrictionField<dim>::radiation_damping(const Point<dim> &x) const
    {
      return value_if_given(f.radiation_damping, x);
    }


    template <int dim>
    double
    FrictionField<dim>::b_minus_a(const Point<dim> &x) const
    {
      return f.b_minus_a->value(x);
    }


    template <int dim>
    void
    FrictionField<dim>::check(const Point<dim>  &x,
                              const std::string &section) const
    {
      const friction::Parameters p  = parameters(x);
      std::string                at = "(";
      for (unsigned int d = 0; d < dim; ++d)
        at += (d ? ", " : "") + format_number(x[d]);
      at += ") m";
      const auto require = [&](const bool   ok,
                               const char  *entry,
                               const double value,
                               const char  *range) {
        if (!ok || !std::isfinite(value))
          throw std::invalid_argument(section + "/" + entry + " = " +
                                      format_number(value) + " at " + at +
                                      ": must be " + range);
      };
      require(p.a > 0, "a", p.a, "> 0");
      require(p.b >= 0, "b - a", p.b - p.a, ">= -a (b >= 0)");
      require(p.L > 0, "Characteristic slip distance", p.L, "> 0");
      require(p.mu_star >= 0,
              "Reference friction coefficient",
              p.mu_star,
              ">= 0");
      require(p.v_star > 0, "Reference slip rate", p.v_star, "> 0");
      require(p.cohesion >= 0, "Cohesion", p.cohesion, ">= 0");
      if (f.initial_state)
        {
          const double theta = f.initial_state->value(x);
          require(theta > 0, "Initial state", theta, "> 0");
        }
      if (const auto sigma = normal_stress(x))
        require(*sigma > 0, "Normal stress", *sigma, "> 0");
      if (const auto tau = shear_prestress(x))
        require(true, "Shear prestress", *tau, "finite");
      if (const auto dtau = shear_perturbation(x))
        require(true, "Shear stress perturbation", *dtau, "finite");
      if (const auto eta = radiation_damping(x))
        require(*eta >= 0, "Radiation damping", *eta, ">= 0");
      if (const auto p = pore_pressure(x, 0.))
        require(*p < *normal_stress(x),
                "Pore pressure",
                *p,
                "finite and below Normal stress at t = 0");
      if (const auto q = darcy_velocity(x, 0.))
        require(true, "Darcy velocity", (*q)[0] + (*q)[1], "finite at t = 0");
    }


    template class FrictionField<2>;
    template class FrictionField<3>;
  } // namespace scenes
} // namespace rsfcycle
