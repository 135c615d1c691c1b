// SPDX-License-Identifier: LGPL-2.1-or-later
#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <fstream>
#include <limits>
#include <rsfcycle/format.h>
#include <rsfcycle/ids.h>
#include <rsfcycle/scenes/mesh_file.h>
#include <rsfcycle/scenes/mesh_file_input.h>
#include <set>
#include <sstream>
#include <stdexcept>

namespace rsfcycle
{
  namespace scenes
  {
    using namespace mesh_file_input;


    template <int dim>
    MeshFile<dim>::MeshFile(ParameterHandler &prm)
      : coarse(Triangulation<dim>::limit_level_difference_at_vertices)
    {
      prm.enter_subsection("Mesh");
      const unsigned int n_refinements = prm.get_integer("Global refinements") +
                                         prm.get_integer("Local refinements");
      prm.leave_subsection();

      antiplane = prm.get("Displacement") == "antiplane";
      prm.enter_subsection(section);
      const std::string file  = prm.get("File");
      const auto        roles = parse_roles(prm.get("Boundary roles"));
      materials               = parse_materials(prm.get("Materials"));
      g = parse_vector<dim>(prm.get("Gravity"), "Gravity");
      if (antiplane)
        load_velocity[0] =
          parse_vector<1>(prm.get("Load velocity"), "Load velocity")[0];
      else
        load_velocity =
          parse_vector<dim>(prm.get("Load velocity"), "Load velocity");
      ramp_time   = prm.get_double("Ramp time");
      normal_free = prm.get("Contact normal") == "free";
      if (!prm.get("Refine where").empty())
        refine_where =
          FrictionField<dim>::parse_expression(prm.get("Refine where"),
                                               section + "/Refine where");
      if (!prm.get("Refine zone").empty())
        refine_zone =
          FrictionField<dim>::parse_expression(prm.get("Refine zone"),
                                               section + "/Refine zone");
      const std::string sponge_text      = prm.get("Sponge damping");
      const std::string observation_text = prm.get("Observation points");
      all_components = prm.get("Observation components") == "all";
      prm.enter_subsection("Friction");
      friction_field = std::make_unique<FrictionField<dim>>(
        FrictionField<dim>::parse(prm, section + "/Friction"));
      prm.leave_subsection();
      prm.leave_subsection();

      if (antiplane && !friction_field->functions().normal_stress)
        fail("Friction/Normal stress",
             ": must be given with Displacement = antiplane (in-plane "
             "gravity does not load the out-of-plane displacement)");
      if (normal_free && antiplane)
        fail("Contact normal",
             " = free: not with Displacement = antiplane (its one component "
             "is the slip; there is no normal displacement)");
      if (normal_free && !friction_field->functions().normal_stress)
        fail("Contact normal",
             " = free: needs Friction/Normal stress (the contact then "
             "carries no normal force of its own)");
      if (all_components && antiplane)
        fail("Observation components",
             " = all: not with Displacement = antiplane (one component, out "
             "of the plane)");
      if (load_velocity.norm() == 0)
        fail("Load velocity",
             ": must not be zero (its magnitude is the plate rate v0)");

      read_mesh(file);
      read_sponge(prm, sponge_text);
      assign_roles(roles);
      sample_patch(n_refinements);
      check_seas_positions(prm);

      // observation points: inside the mesh
      for (const auto &item :
           Utilities::split_string_list(observation_text, ';'))
        {
          const auto colon = item.find(':');
          if (colon == std::string::npos)
            fail("Observation points",
                 ": '" + item + "' is not 'name: coordinates'");
          const std::string name = Utilities::trim(item.substr(0, colon));
          const Point<dim>  x(
            parse_vector<dim>(item.substr(colon + 1), "Observation points"));
          const Point<dim> p = from_physical(x);
          bool             inside;
          try
            {
              const auto cell =
                GridTools::find_active_cell_around_point(coarse, p);
              inside = cell.state() == IteratorState::valid;
            }
          catch (const std::exception &)
            {
              inside = false;
            }
          if (!inside)
            fail("Observation points",
                 ": " + name + " " + format_point(&x[0], dim) +
                   " lies outside the mesh");
          observation.emplace_back(name, p);
        }
    }


    /** Read the mesh and check that its cells are quads / hexes. */
    template <int dim>
    void
    MeshFile<dim>::read_mesh(const std::string &file)
    {
      std::ifstream in(file);
      if (file.empty() || !in)
        fail("File", " = " + file + ": cannot be read");
      Triangulation<dim> mesh;
      try
        {
          GridIn<dim> grid_in;
          grid_in.attach_triangulation(mesh);
          grid_in.read_msh(in);
        }
      catch (const std::exception &e)
        {
          // deal.II's messages span lines: keep the one that says why
          std::string       why;
          std::stringstream lines(e.what());
          for (std::string line; std::getline(lines, line);)
            if (line.find("Additional information") != std::string::npos &&
                std::getline(lines, line))
              {
                why = ": " + Utilities::trim(line);
                break;
              }
          fail("File",
               " = " + file + ": not a readable " + std::to_string(dim) +
                 "D gmsh mesh" + why);
        }
      if (!mesh.all_reference_cells_are_hyper_cube())
        fail(
          "File",
          " = " + file + ": has " + (dim == 2 ? "triangles" : "non-hexahedra") +
            "; only " + (dim == 2 ? "quadrilaterals" : "hexahedra") +
            " are supported (gmsh: Recombine, or Mesh.SubdivisionAlgorithm)");

      coarse.copy_triangulation(mesh);
    }


    /**
     * The friction functions checked on a grid of every coarse contact
     * face, and the part of the contact where `Refine where` > 0 (by
     * default the rate-weakening part, b - a > 0) as the patch of the
     * refinement laws.
     */
    template <int dim>
    void
    MeshFile<dim>::sample_patch(const unsigned int n_refinements)
    {
      const unsigned int n = 8;
      for (const auto &cell : coarse.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() &&
              face->boundary_id() == boundary_id::contact)
            for (unsigned int i = 0; i <= n; ++i)
              for (unsigned int j = 0; j <= (dim == 3 ? n : 0); ++j)
                friction_field->check(to_physical(face_point<dim>(
                                        face, double(i) / n, double(j) / n)),
                                      section + "/Friction");
      patch.build(
        coarse,
        [this](const Point<dim> &p) {
          return refine_where ? refine_where->value(to_physical(p)) > 0 :
                                friction_field->b_minus_a(to_physical(p)) > 0;
        },
        n_refinements);
    }


    template <int dim>
    void
    MeshFile<dim>::create_coarse_mesh(Triangulation<dim> &tria) const
    {
      const auto [vertices, cells, faces] =
        GridTools::get_coarse_mesh_description(coarse);
      tria.create_triangulation(vertices, cells, faces);
    }


    template <int dim>
    double
    MeshFile<dim>::distance_to_patch(const BoundingBox<dim> &box,
                                     const double            margin) const
    {
      return patch.distance(box, margin);
    }


    template <int dim>
    unsigned int
    MeshFile<dim>::zone_refinements(const Point<dim> &cell_center) const
    {
      if (!refine_zone)
        return 0;
      const double n = refine_zone->value(to_physical(cell_center));
      return n > 0 ? static_cast<unsigned int>(std::floor(n + 0.5)) : 0;
    }


    template <int dim>
    types::material_id
    MeshFile<dim>::material_id(const Point<dim> &,
                               const types::material_id mesh_id) const
    {
      return mesh_id;
    }


    template <int dim>
    Material
    MeshFile<dim>::material(const types::material_id id) const
    {
      return materials.at(id);
    }


    template <int dim>
    Tensor<1, dim>
    MeshFile<dim>::gravity() const
    {
      return rotation * g;
    }


    template <int dim>
    std::vector<std::pair<std::string, Tensor<1, dim>>>
    MeshFile<dim>::observation_directions() const
    {
      if (!all_components)
        return {{"", vertical()}};
      std::vector<std::pair<std::string, Tensor<1, dim>>> directions;
      for (unsigned int d = 0; d < dim; ++d)
        {
          Tensor<1, dim> axis;
          axis[d] = 1;
          directions.emplace_back(std::string("_") + "xyz"[d], rotation * axis);
        }
      return directions;
    }


    template <int dim>
    Tensor<1, dim>
    MeshFile<dim>::vertical() const
    {
      return rotation * up;
    }


    template <int dim>
    Tensor<1, dim>
    MeshFile<dim>::backstop_velocity(const double t) const
    {
      const double ramp =
        (t < ramp_time) ? 0.5 * (1. - std::cos(M_PI * t / ramp_time)) : 1.;
      return ramp * load_rotated;
    }


    template <int dim>
    friction::Parameters
    MeshFile<dim>::friction_parameters(const Point<dim> &p) const
    {
      return friction_field->parameters(to_physical(p));
    }


    template <int dim>
    double
    MeshFile<dim>::initial_state(const Point<dim> &p) const
    {
      return friction_field->initial_alpha(to_physical(p));
    }


    template <int dim>
    std::function<double(const Point<dim> &)>
    MeshFile<dim>::normal_stress() const
    {
      if (!friction_field->functions().normal_stress)
        return {};
      return [this](const Point<dim> &p) {
        return *friction_field->normal_stress(to_physical(p));
      };
    }


    template <int dim>
    std::function<double(const Point<dim> &, double)>
    MeshFile<dim>::pore_pressure() const
    {
      if (!friction_field->functions().pore_pressure)
        return {};
      return [this](const Point<dim> &p, const double t) {
        return *friction_field->pore_pressure(to_physical(p), t);
      };
    }


    template <int dim>
    std::function<std::array<double, 2>(const Point<dim> &, double)>
    MeshFile<dim>::darcy_velocity() const
    {
      if (!friction_field->functions().darcy_velocity)
        return {};
      return [this](const Point<dim> &p, const double t) {
        return *friction_field->darcy_velocity(to_physical(p), t);
      };
    }


    template <int dim>
    std::function<Tensor<1, dim>(const Point<dim> &)>
    MeshFile<dim>::shear_prestress() const
    {
      if (!friction_field->functions().shear_prestress)
        return {};
      return [this](const Point<dim> &p) {
        return *friction_field->shear_prestress(to_physical(p)) * load_rotated /
               load_rotated.norm();
      };
    }


    template <int dim>
    std::function<Tensor<1, dim>(const Point<dim> &)>
    MeshFile<dim>::shear_perturbation() const
    {
      if (!friction_field->functions().shear_perturbation)
        return {};
      return [this](const Point<dim> &p) {
        return *friction_field->shear_perturbation(to_physical(p)) *
               load_rotated / load_rotated.norm();
      };
    }


    template <int dim>
    std::function<double(double)>
    MeshFile<dim>::shear_perturbation_history() const
    {
      if (!friction_field->functions().shear_perturbation)
        return {};
      return [this](const double t) {
        return friction_field->perturbation_history(t);
      };
    }


    template <int dim>
    double
    MeshFile<dim>::radiation_damping(const Point<dim> &p,
                                     const Material   &material) const
    {
      return friction_field->radiation_damping(to_physical(p))
        .value_or(Scene<dim>::radiation_damping(p, material));
    }


    /**
     * Sponge damping: an expression, a dynamic run, >= 0 at the coarse
     * mesh's vertices (before the rotation: in the mesh's frame).
     */
    template <int dim>
    void
    MeshFile<dim>::read_sponge(ParameterHandler &prm, const std::string &text)
    {
      if (text.empty())
        return;
      sponge =
        FrictionField<dim>::parse_expression(text, section + "/Sponge damping");
      prm.enter_subsection("Solver");
      const std::string dynamics = prm.get("Dynamics");
      prm.leave_subsection();
      if (dynamics != "dynamic")
        fail("Sponge damping",
             ": needs Solver/Dynamics = dynamic (this run has " + dynamics +
               "; without inertia there are no waves to absorb)");
      for (const Point<dim> &x : coarse.get_vertices())
        if (const double alpha = sponge->value(x); !(alpha >= 0))
          fail("Sponge damping",
               " = " + format_number(alpha) + " at " +
                 format_point(&x[0], dim) + ": must be >= 0 [1/s]");
    }


    template <int dim>
    double
    MeshFile<dim>::sponge_damping(const Point<dim> &p) const
    {
      return sponge ? sponge->value(to_physical(p)) : 0.;
    }


    template <int dim>
    double
    MeshFile<dim>::convergence_rate() const
    {
      return load_rotated.norm();
    }


    template <int dim>
    std::vector<std::pair<std::string, Point<dim>>>
    MeshFile<dim>::observation_points() const
    {
      return observation;
    }


    template <int dim>
    double
    MeshFile<dim>::along_base_coordinate(const Point<dim> &p) const
    {
      return along_sign * p[0] - along_offset;
    }


    template <int dim>
    std::pair<Tensor<2, dim>, Point<dim>>
    MeshFile<dim>::output_frame() const
    {
      return {transpose(rotation), origin};
    }


    template <int dim>
    Point<dim>
    MeshFile<dim>::to_physical(const Point<dim> &p) const
    {
      return origin + transpose(rotation) * p;
    }


    template <int dim>
    Point<dim>
    MeshFile<dim>::from_physical(const Point<dim> &x) const
    {
      return Point<dim>(rotation * (x - origin));
    }


    template class MeshFile<2>;
    template class MeshFile<3>;
  } // namespace scenes
} // namespace rsfcycle
