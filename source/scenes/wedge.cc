// SPDX-License-Identifier: LGPL-2.1-or-later
#include <cmath>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_generator.h>
#include <rsfcycle/format.h>
#include <rsfcycle/ids.h>
#include <rsfcycle/scenes/wedge.h>

namespace rsfcycle
{
  namespace scenes
  {
    template <int dim>
    void
    Wedge<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Wedge");
      {
        prm.declare_entry("Length",
                          "1.0",
                          Patterns::Double(1e-6),
                          "Horizontal distance trench-backstop [m]");
        prm.declare_entry("Depth",
                          "0.27",
                          Patterns::Double(1e-6),
                          "Height of the vertical backstop [m]; the dip is "
                          "atan(Depth/Length)");
        prm.declare_entry("Width",
                          "0.6",
                          Patterns::Double(1e-6),
                          "Extent in z of the 3D wedge [m] (unused in 2D)");
        prm.declare_entry("Patch down-dip end",
                          "0.35",
                          Patterns::Double(0),
                          "Horizontal distance from the trench of the surface "
                          "point above the patch's down-dip end [m]");
        prm.declare_entry("Patch length",
                          "0.20",
                          Patterns::Double(0),
                          "Length of the seismogenic patch along the base in "
                          "2D [m]");
        prm.declare_entry("Patch length at z min",
                          "0.15",
                          Patterns::Double(0),
                          "3D: along-base length of the trapezoidal patch at "
                          "the lateral side z = 0 [m]");
        prm.declare_entry("Patch length at z max",
                          "0.25",
                          Patterns::Double(0),
                          "3D: along-base length of the trapezoidal patch at "
                          "the lateral side z = Width [m]");
        prm.declare_entry("Lower region thickness",
                          "0.06",
                          Patterns::Double(0),
                          "The viscous lower region is the part of the wedge "
                          "less than this height above the backstop's lower "
                          "corner B [m]");
        prm.declare_entry("Density upper",
                          "900",
                          Patterns::Double(1e-12),
                          "Mass density of the upper region [kg/m^3]");
        prm.declare_entry("Density lower",
                          "1000",
                          Patterns::Double(1e-12),
                          "Mass density of the lower region [kg/m^3]");
        prm.declare_entry("Shear viscosity upper",
                          "1e3",
                          Patterns::Double(0),
                          "Shear viscosity of the upper region [Pa s]");
        prm.declare_entry("Bulk viscosity upper",
                          "1e3",
                          Patterns::Double(0),
                          "Bulk viscosity of the upper region [Pa s]; the "
                          "paper gives one viscosity, used for both");
        prm.declare_entry("Shear viscosity lower",
                          "1e4",
                          Patterns::Double(0),
                          "Shear viscosity of the lower region [Pa s]");
        prm.declare_entry("Bulk viscosity lower",
                          "1e4",
                          Patterns::Double(0),
                          "Bulk viscosity of the lower region [Pa s]");
        prm.declare_entry("Bulk modulus",
                          "5e4",
                          Patterns::Double(1e-12),
                          "Bulk modulus K [Pa]");
        prm.declare_entry("Poisson ratio",
                          "0.3",
                          Patterns::Double(-0.999, 0.499),
                          "Poisson ratio nu, in (-1, 0.5)");
        prm.declare_entry("Gravity",
                          "9.81",
                          Patterns::Double(0),
                          "Gravitational acceleration [m/s^2]");
        prm.declare_entry("Patch a",
                          "0.002",
                          Patterns::Double(1e-12),
                          "Direct-effect parameter a on the patch [-]");
        prm.declare_entry("Patch b - a",
                          "0.015",
                          Patterns::Double(),
                          "b - a on the patch [-] (> 0: rate weakening)");
        prm.declare_entry("Outside a",
                          "0.020",
                          Patterns::Double(1e-12),
                          "Direct-effect parameter a off the patch [-]");
        prm.declare_entry("Outside b - a",
                          "-0.015",
                          Patterns::Double(),
                          "b - a off the patch [-] (< 0: rate strengthening)");
        prm.declare_entry("Reference friction coefficient",
                          "0.7",
                          Patterns::Double(0),
                          "mu* [-]");
        prm.declare_entry("Reference slip rate",
                          "50e-6",
                          Patterns::Double(1e-300),
                          "V* [m/s]");
        prm.declare_entry("Characteristic slip distance",
                          "22.5e-6",
                          Patterns::Double(1e-300),
                          "L [m]");
        prm.declare_entry("Cohesion", "10", Patterns::Double(0), "C [Pa]");
        prm.declare_entry("Convergence rate",
                          "50e-6",
                          Patterns::Double(1e-300),
                          "Plate convergence rate v0 [m/s]");
        prm.declare_entry("Ramp time",
                          "100",
                          Patterns::Double(0),
                          "t0 [s]: the backstop speed rises as "
                          "v0 (1 - cos(pi t/t0))/2 until t0");
        prm.declare_entry("Observation points",
                          "0.15, 0.30, 0.45",
                          Patterns::List(Patterns::Double(0)),
                          "Horizontal distances from the trench of the surface "
                          "points whose vertical displacement is recorded [m]");
      }
      prm.leave_subsection();
    }


    template <int dim>
    Wedge<dim>::Wedge(ParameterHandler &prm)
    {
      prm.enter_subsection("Wedge");
      length          = prm.get_double("Length");
      depth           = prm.get_double("Depth");
      width           = prm.get_double("Width");
      patch_downdip_x = prm.get_double("Patch down-dip end");
      patch_length    = prm.get_double("Patch length");
      patch_length_0  = prm.get_double("Patch length at z min");
      patch_length_1  = prm.get_double("Patch length at z max");
      lower_thickness = prm.get_double("Lower region thickness");
      double a_patch, b_minus_a_patch, a_outside, b_minus_a_outside;
      double mu_star, v_star, L, cohesion;
      upper.density         = prm.get_double("Density upper");
      lower.density         = prm.get_double("Density lower");
      upper.shear_viscosity = prm.get_double("Shear viscosity upper");
      upper.bulk_viscosity  = prm.get_double("Bulk viscosity upper");
      lower.shear_viscosity = prm.get_double("Shear viscosity lower");
      lower.bulk_viscosity  = prm.get_double("Bulk viscosity lower");
      upper.bulk_modulus    = prm.get_double("Bulk modulus");
      upper.poisson_ratio   = prm.get_double("Poisson ratio");
      lower.bulk_modulus    = upper.bulk_modulus;
      lower.poisson_ratio   = upper.poisson_ratio;
      g                     = prm.get_double("Gravity");
      a_patch               = prm.get_double("Patch a");
      b_minus_a_patch       = prm.get_double("Patch b - a");
      a_outside             = prm.get_double("Outside a");
      b_minus_a_outside     = prm.get_double("Outside b - a");
      mu_star               = prm.get_double("Reference friction coefficient");
      v_star                = prm.get_double("Reference slip rate");
      L                     = prm.get_double("Characteristic slip distance");
      cohesion              = prm.get_double("Cohesion");
      v0                    = prm.get_double("Convergence rate");
      t0                    = prm.get_double("Ramp time");
      observation_x         = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Observation points")));
      prm.leave_subsection();

      const double hyp = std::hypot(length, depth);
      cos_phi          = length / hyp;
      sin_phi          = depth / hyp;

      if (patch_downdip_x > length)
        throw std::invalid_argument(
          "Wedge/Patch down-dip end = " + format_number(patch_downdip_x) +
          ": must lie in [0, Length = " + format_number(length) + "]");
      const double s_down = patch_downdip_x / cos_phi;
      const double longest =
        (dim == 2) ? patch_length : std::max(patch_length_0, patch_length_1);
      if (s_down - patch_length < 0 || s_down - patch_length + longest > hyp)
        throw std::invalid_argument(
          "Wedge/Patch length: the patch must lie on the base (along-base "
          "extent [0, " +
          format_number(hyp) + "] m)");
      for (const double x : observation_x)
        if (x > length)
          throw std::invalid_argument(
            "Wedge/Observation points: " + format_number(x) +
            " lies beyond Length = " + format_number(length));
      if (lower_thickness >= depth)
        throw std::invalid_argument(
          "Wedge/Lower region thickness must be below Depth");

      // The patch as a function of the point: piecewise constant on and
      // off it, the other quantities constant.
      const auto piecewise = [this](const double inside, const double outside) {
        return std::make_shared<ScalarFunctionFromFunctionObject<dim>>(
          [this, inside, outside](const Point<dim> &p) {
            return on_patch(p) ? inside : outside;
          });
      };
      const auto constant = [](const double value) {
        return std::make_shared<Functions::ConstantFunction<dim>>(value);
      };
      typename FrictionField<dim>::Functions functions;
      functions.a         = piecewise(a_patch, a_outside);
      functions.b_minus_a = piecewise(b_minus_a_patch, b_minus_a_outside);
      functions.L         = constant(L);
      functions.mu_star   = constant(mu_star);
      functions.v_star    = constant(v_star);
      functions.cohesion  = constant(cohesion);
      friction_field      = std::make_unique<FrictionField<dim>>(functions);
    }


    template <int dim>
    Point<dim>
    Wedge<dim>::to_physical(const Point<dim> &p) const
    {
      Point<dim> x = p;
      x[0]         = cos_phi * p[0] + sin_phi * p[1];
      x[1]         = -sin_phi * p[0] + cos_phi * p[1];
      return x;
    }


    template <int dim>
    Point<dim>
    Wedge<dim>::from_physical(const Point<dim> &x) const
    {
      Point<dim> p = x;
      p[0]         = cos_phi * x[0] - sin_phi * x[1];
      p[1]         = sin_phi * x[0] + cos_phi * x[1];
      return p;
    }


    template <int dim>
    std::pair<double, double>
    Wedge<dim>::patch_extent(const double z) const
    {
      const double s_down = patch_downdip_x / cos_phi;
      const double s_up   = s_down - patch_length;
      if (dim == 2)
        return {s_up, s_down};
      const double zeta = std::min(std::max(z / width, 0.), 1.);
      return {s_up,
              s_up + patch_length_0 + zeta * (patch_length_1 - patch_length_0)};
    }


    template <int dim>
    bool
    Wedge<dim>::on_patch(const Point<dim> &p) const
    {
      const auto [s_up, s_down] = patch_extent(dim == 3 ? p[2] : 0.);
      const double tol          = 1e-10;
      return p[0] >= s_up - tol && p[0] <= s_down + tol;
    }


    template <int dim>
    void
    Wedge<dim>::create_coarse_mesh(Triangulation<dim> &tria) const
    {
      const double                hyp     = std::hypot(length, depth);
      const std::vector<Point<2>> corners = {Point<2>(0, 0),
                                             Point<2>(hyp, 0),
                                             Point<2>(length * cos_phi,
                                                      length * sin_phi)};
      if constexpr (dim == 2)
        GridGenerator::simplex(tria, corners);
      else
        {
          Triangulation<2> section;
          GridGenerator::simplex(section, corners);
          GridGenerator::extrude_triangulation(section, 2, width, tria);
        }

      const double tol = 1e-8 * hyp;
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const Point<dim> c = face->center();
              const Point<dim> x = to_physical(c);
              if (std::abs(c[1]) < tol)
                face->set_boundary_id(boundary_id::contact);
              else if (std::abs(x[0] - length) < tol)
                face->set_boundary_id(boundary_id::backstop);
              else if (std::abs(x[1]) < tol)
                face->set_boundary_id(boundary_id::surface);
              else
                face->set_boundary_id(boundary_id::lateral);
            }
    }


    /**
     * The patch is {y = 0, s_up <= x <= s_down(z), 0 <= z <= Width} with
     * s_down linear in z. The distance splits into the height of the box
     * above the base and the distance in the base plane between the box's
     * footprint and the patch, the latter reduced by the margin (the patch
     * widened by a disc of that radius in the plane). In 3D the in-plane
     * distance is the minimum over the patch's z of a convex function of z
     * (the along-base gap to [s_up, s_down(z)] and the lateral gap to the
     * box), found by ternary search.
     */
    template <int dim>
    double
    Wedge<dim>::distance_to_patch(const BoundingBox<dim> &box,
                                  const double            margin) const
    {
      const auto &[lo, hi] = box.get_boundary_points();
      const double s_up    = patch_extent(0.).first;
      const auto   at      = [&](const double z) {
        const double gx =
          std::max({0., s_up - hi[0], lo[0] - patch_extent(z).second});
        const double gz =
          (dim == 3) ? std::max({0., lo[dim - 1] - z, z - hi[dim - 1]}) : 0.;
        return std::hypot(gx, gz);
      };
      double in_plane = at(0.);
      if (dim == 3)
        {
          double a = 0, b = width;
          for (unsigned int i = 0; i < 80; ++i)
            {
              const double m1 = a + (b - a) / 3, m2 = b - (b - a) / 3;
              if (at(m1) < at(m2))
                b = m2;
              else
                a = m1;
            }
          in_plane = std::min({at(0.), at(width), at((a + b) / 2)});
        }
      return std::hypot(std::max(0., in_plane - margin), std::max(0., lo[1]));
    }


    template <int dim>
    types::material_id
    Wedge<dim>::material_id(const Point<dim> &cell_center,
                            types::material_id) const
    {
      const Point<dim> x = to_physical(cell_center);
      return (x[1] < -(depth - lower_thickness)) ? material_id::lower :
                                                   material_id::upper;
    }


    template <int dim>
    Material
    Wedge<dim>::material(const types::material_id id) const
    {
      return id == material_id::lower ? lower : upper;
    }


    template <int dim>
    Tensor<1, dim>
    Wedge<dim>::gravity() const
    {
      return -g * vertical();
    }


    template <int dim>
    Tensor<1, dim>
    Wedge<dim>::vertical() const
    {
      // physical (0, 1) in the rotated frame
      Tensor<1, dim> up;
      up[0] = -sin_phi;
      up[1] = cos_phi;
      return up;
    }


    template <int dim>
    Tensor<1, dim>
    Wedge<dim>::backstop_velocity(const double t) const
    {
      const double speed =
        (t < t0) ? 0.5 * v0 * (1. - std::cos(M_PI * t / t0)) : v0;
      Tensor<1, dim> v;
      v[0] = -speed; // parallel to the base, up-dip (toward the trench)
      return v;
    }


    template <int dim>
    friction::Parameters
    Wedge<dim>::friction_parameters(const Point<dim> &p) const
    {
      return friction_field->parameters(p);
    }


    template <int dim>
    double
    Wedge<dim>::convergence_rate() const
    {
      return v0;
    }


    template <int dim>
    std::vector<std::pair<std::string, Point<dim>>>
    Wedge<dim>::observation_points() const
    {
      std::vector<std::pair<std::string, Point<dim>>> points;
      for (const double x : observation_x)
        {
          Point<dim> physical;
          physical[0] = x;
          if (dim == 3)
            physical[2] = 0.5 * width;
          const std::string name =
            "uplift_" + std::to_string(static_cast<int>(std::round(x * 100))) +
            "cm";
          points.emplace_back(name, from_physical(physical));
        }
      return points;
    }


    template class Wedge<2>;
    template class Wedge<3>;
  } // namespace scenes
} // namespace rsfcycle
