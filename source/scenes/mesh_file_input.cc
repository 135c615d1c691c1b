// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/utilities.h>
#include <limits>
#include <rsfcycle/format.h>
#include <rsfcycle/ids.h>
#include <rsfcycle/scenes/mesh_file.h>
#include <rsfcycle/scenes/mesh_file_input.h>
#include <rsfcycle/seas_parameters.h>
#include <set>
#include <stdexcept>

namespace rsfcycle
{
  namespace scenes
  {
    namespace mesh_file_input
    {
      void
      fail(const std::string &entry, const std::string &message)
      {
        throw std::invalid_argument(section + "/" + entry + message);
      }


      std::string
      format_point(const double *x, const unsigned int n)
      {
        std::string s = "(";
        for (unsigned int d = 0; d < n; ++d)
          s += (d ? ", " : "") + format_number(x[d]);
        return s + ")";
      }


      template <int dim>
      Tensor<1, dim>
      parse_vector(const std::string &text, const std::string &entry)
      {
        const auto parts = Utilities::split_string_list(text, ',');
        if (parts.size() != dim)
          fail(entry,
               " = " + text + ": needs " + std::to_string(dim) +
                 (dim == 1 ? " component" :
                             " components (x, y" +
                               std::string(dim == 3 ? ", z" : "") + ")"));
        Tensor<1, dim> v;
        for (unsigned int d = 0; d < dim; ++d)
          v[d] = Utilities::string_to_double(parts[d]);
        return v;
      }


      /** "1: contact, 2: load": tag -> role, each tag with one role. */
      std::map<types::boundary_id, std::string>
      parse_roles(const std::string &text)
      {
        const std::set<std::string>               allowed = {"contact",
                                                             "load",
                                                             "load-opposite",
                                                             "creep",
                                                             "free",
                                                             "free-slip",
                                                             "absorbing",
                                                             "fault-opposite"};
        std::map<types::boundary_id, std::string> roles;
        for (const auto &item : Utilities::split_string_list(text, ','))
          {
            const auto pair = Utilities::split_string_list(item, ':');
            if (pair.size() != 2 || allowed.count(pair[1]) == 0)
              fail("Boundary roles",
                   ": '" + item +
                     "' is not 'tag: role' with role contact, load, "
                     "load-opposite, creep, free, free-slip, absorbing or "
                     "fault-opposite");
            const auto tag = static_cast<types::boundary_id>(
              Utilities::string_to_int(pair[0]));
            const auto [it, inserted] = roles.emplace(tag, pair[1]);
            if (!inserted && it->second != pair[1])
              fail("Boundary roles",
                   ": tag " + pair[0] + " has two roles (" + it->second + ", " +
                     pair[1] + ")");
          }
        return roles;
      }


      /**
       * "10: density 900, bulk modulus 5e4, Poisson ratio 0.3, shear
       * viscosity 1e3, bulk viscosity 1e3; 11: ...".
       */
      std::map<types::material_id, Material>
      parse_materials(const std::string &text)
      {
        const std::string                      entry = "Materials";
        std::map<types::material_id, Material> materials;
        for (const auto &region : Utilities::split_string_list(text, ';'))
          {
            const auto colon = region.find(':');
            if (colon == std::string::npos)
              fail(entry, ": '" + region + "' is not 'tag: properties'");
            const auto tag =
              static_cast<types::material_id>(Utilities::string_to_int(
                Utilities::trim(region.substr(0, colon))));
            std::map<std::string, double> values;
            for (const auto &item :
                 Utilities::split_string_list(region.substr(colon + 1), ','))
              {
                const auto space = item.find_last_of(' ');
                if (space == std::string::npos)
                  fail(entry, ": '" + item + "' is not 'name value'");
                values[Utilities::trim(item.substr(0, space))] =
                  Utilities::string_to_double(item.substr(space + 1));
              }
            Material   m;
            const auto take = [&](const std::string &name,
                                  const double       low,
                                  const double       high,
                                  const std::string &range) {
              const auto it = values.find(name);
              if (it == values.end())
                fail(entry,
                     ": tag " + std::to_string(tag) + " has no '" + name +
                       "' (each tag needs density, bulk modulus, Poisson "
                       "ratio, shear viscosity, bulk viscosity)");
              if (!(it->second >= low && it->second <= high))
                fail(entry,
                     ": tag " + std::to_string(tag) + " " + name + " = " +
                       format_number(it->second) + ": must be " + range);
              const double value = it->second;
              values.erase(it);
              return value;
            };
            const double inf = std::numeric_limits<double>::max();
            m.density        = take("density", 1e-300, inf, "> 0");
            m.bulk_modulus   = take("bulk modulus", 1e-300, inf, "> 0");
            m.poisson_ratio =
              take("Poisson ratio", -0.999, 0.499, "in (-1, 0.5)");
            m.shear_viscosity = take("shear viscosity", 0, inf, ">= 0");
            m.bulk_viscosity  = take("bulk viscosity", 0, inf, ">= 0");
            if (!values.empty())
              fail(entry,
                   ": tag " + std::to_string(tag) +
                     " has an unknown property '" + values.begin()->first +
                     "'");
            if (!materials.emplace(tag, m).second)
              fail(entry, ": tag " + std::to_string(tag) + " is given twice");
          }
        return materials;
      }


      template Tensor<1, 1>
      parse_vector<1>(const std::string &, const std::string &);
      template Tensor<1, 2>
      parse_vector<2>(const std::string &, const std::string &);
      template Tensor<1, 3>
      parse_vector<3>(const std::string &, const std::string &);
    } // namespace mesh_file_input


    /** The entries of `subsection Mesh file` (parsed by the constructor). */
    template <int dim>
    void
    MeshFile<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection(mesh_file_input::section);
      {
        prm.declare_entry("File",
                          "",
                          Patterns::Anything(),
                          "The gmsh mesh (.msh, format 2 or 4, ASCII; "
                          "quadrilaterals in 2D, hexahedra in 3D) of Scene = "
                          "mesh-file. A relative path is looked up beside the "
                          "parameter file first, then in the working "
                          "directory; the run folder's parameters.prm "
                          "records the absolute path");
        prm.declare_entry(
          "Refine where",
          "",
          Patterns::Anything(),
          "The part of the contact that the mesh is refined toward "
          "(Mesh/Local refinements with the refinement law): where this "
          "function of x, y (and z in 3D) [m] is > 0. Empty: where the "
          "fault is rate weakening, b - a > 0");
        prm.declare_entry(
          "Refine zone",
          "",
          Patterns::Anything(),
          "A part of the body refined whatever the refinement law says: a "
          "cell whose centre has this function of x, y (and z in 3D) [m] "
          "equal to n >= 1 (rounded) is refined in the first n of "
          "Mesh/Local refinements, so its cells are 2^-n of the coarse "
          "mesh's (a uniform zone, e.g. if(x < 10e3 & y > -45e3, 5, 0)); "
          "deal.II grades the cells around it 2:1. Empty or <= 0: no zone "
          "[number of refinements]");
        prm.declare_entry(
          "Boundary roles",
          "",
          Patterns::Anything(),
          "The role of each physical boundary tag of the mesh, as 'tag: "
          "role, tag: role'. Roles: contact (rate-and-state friction on a "
          "rigid base, zero normal velocity; one plane), load (prescribed "
          "velocity Load velocity, all components), load-opposite (the "
          "opposite velocity, minus Load velocity: the other plate of a "
          "fault between two parts of the body), creep (a part of the "
          "contact's plane outside the frictional contact that slides at "
          "Load velocity: its tangential displacement prescribed as on a "
          "load, its normal one held or free as Contact normal says; SEAS "
          "BP4, BP5; on a split fault its slip rate is the difference of "
          "the plates' velocities, twice Load velocity), fault-opposite (the "
          "other side of a fault between two parts of the body: faces of "
          "the contact's plane whose nodes duplicate those of the contact "
          "and creep faces at the same positions, e.g. from gmsh's "
          "Plugin(Crack); the slip is the jump of the tangential "
          "displacement across the fault, the normal displacement is "
          "continuous; with Gravity = 0, and in the volume method with "
          "Solver/Linear correction = direct or amg), free (traction free), "
          "free-slip (zero normal velocity; in 2D parallel to the contact, "
          "in 3D perpendicular to it with one normal for all), absorbing (the "
          "truncation of an unbounded body: the dashpot traction -rho (c_p "
          "v_n n + c_s v_t), antiplane -rho c_s v, of the adjacent cell's "
          "material lets waves that reach it normally leave; it also resists "
          "slow motion, by rho c_s v, about 5 kPa per mm/s for rock). Every "
          "boundary tag of the mesh needs a role; faces without a physical "
          "tag have tag 0");
        prm.declare_entry(
          "Contact normal",
          "held",
          Patterns::Selection("held|free"),
          "The contact's normal displacement. held: zero (a rigid base, or "
          "the rigid mirror of a problem symmetric about the fault plane, "
          "SEAS BP1); free: it follows the body and the normal traction on "
          "the body stays zero, while friction acts on Friction/Normal "
          "stress (needed) - the fault plane of a problem antisymmetric "
          "about it (SEAS BP4, BP5: strike-slip in a whole space, one side "
          "modelled). Not with Displacement = antiplane (its one component "
          "is the slip)");
        prm.declare_entry(
          "Materials",
          "",
          Patterns::Anything(),
          "The material of each physical volume tag of the mesh, as 'tag: "
          "density 900, bulk modulus 5e4, Poisson ratio 0.3, shear "
          "viscosity 1e3, bulk viscosity 1e3; tag: ...' (kg/m^3, Pa, -, "
          "Pa s, Pa s). Every volume tag of the mesh needs one");
        prm.declare_entry("Gravity",
                          "0, -9.81",
                          Patterns::List(Patterns::Double(), 2, 3),
                          "Gravitational acceleration in the mesh's "
                          "coordinates (2 or 3 components as the mesh) "
                          "[m/s^2]; it loads the contact (normal stress) and "
                          "defines 'up' for the observation points and the "
                          "dip direction");
        prm.declare_entry(
          "Sponge damping",
          "",
          Patterns::Anything(),
          "The rate alpha [1/s] of a mass-proportional damping of the body, "
          "a function of x, y (and z) [m] in the mesh's coordinates "
          "(muparser): the momentum balance gets the force -alpha rho v "
          "per volume, under which a wave decays as exp(-alpha t / 2). A "
          "sponge around the refined zone absorbs the waves of an event "
          "that the coarsening cells would send back (they carry no wave "
          "shorter than a few cells to the absorbing boundaries); keep it "
          "zero where the rupture's own waves matter (doc/model.md 8.3b). "
          "Needs Solver/Dynamics = dynamic. Empty: none");
        prm.declare_entry("Load velocity",
                          "-50e-6, 0",
                          Patterns::List(Patterns::Double(), 1, 3),
                          "Velocity of the load boundaries in the mesh's "
                          "coordinates (2 or 3 components as the mesh) [m/s], "
                          "parallel to the contact; its magnitude is the "
                          "plate rate v0 (event threshold, output). With "
                          "Displacement = antiplane one number: the velocity "
                          "out of the mesh's plane");
        prm.declare_entry("Ramp time",
                          "100",
                          Patterns::Double(0),
                          "t0 [s]: the load velocity rises as "
                          "(1 - cos(pi t/t0))/2 times Load velocity until t0");
        prm.declare_entry("Observation points",
                          "",
                          Patterns::Anything(),
                          "Points of the body whose displacement along 'up' "
                          "(minus Gravity) is recorded every step, as 'name: "
                          "x, y; name: x, y' (3D: x, y, z) in the mesh's "
                          "coordinates [m]; empty: none");
        prm.declare_entry(
          "Observation components",
          "up",
          Patterns::Selection("up|all"),
          "What is recorded at each observation point: up, the "
          "displacement along 'up' (minus Gravity; column NAME_m); all, "
          "its components along the mesh's x, y (and z) axes (columns "
          "NAME_x_m, NAME_y_m, NAME_z_m; the SEAS off-fault stations of "
          "3D models). Not with Displacement = antiplane");
        prm.enter_subsection("Friction");
        FrictionField<dim>::declare_parameters(prm);
        prm.leave_subsection();
      }
      prm.leave_subsection();
    }


    /**
     * The SEAS fault stations and slip profile (`Output/SEAS`) on the
     * contact's along-base extent of the coarse mesh, before the run folder
     * is made (SeasFiles checks them again against the contact nodes of the
     * refined mesh, which leave out vertices shared with a load).
     */
    template <int dim>
    void
    MeshFile<dim>::check_seas_positions(ParameterHandler &prm) const
    {
      SeasParameters seas;
      prm.enter_subsection("Output");
      seas.parse_parameters(prm);
      prm.leave_subsection();
      if (!seas.enabled())
        return;
      if (dim == 3)
        {
          // the contact's extent in x2 = x and x3 = -z of the mesh
          const auto [Q, c] = output_frame();
          double low[2] = {1e300, 1e300}, high[2] = {-1e300, -1e300};
          for (const auto &face : coarse.active_face_iterators())
            if (face->at_boundary() &&
                face->boundary_id() == boundary_id::contact)
              for (const unsigned int v : face->vertex_indices())
                {
                  const Point<dim> x = c + Q * face->vertex(v);
                  // (rounding of the rotation snapped to x = 0, z = 0)
                  double s[2] = {x[0], -x[dim - 1]};
                  for (double &v : s)
                    v = std::abs(v) < 1e-6 ? 0. : v;
                  for (unsigned int i = 0; i < 2; ++i)
                    {
                      low[i]  = std::min(low[i], s[i]);
                      high[i] = std::max(high[i], s[i]);
                    }
                }
          const auto inside = [&](const double       x2,
                                  const double       x3,
                                  const std::string &entry) {
            const double tol = 1e-9 * std::max(high[0] - low[0], 1.);
            if (x2 < low[0] - tol || x2 > high[0] + tol || x3 < low[1] - tol ||
                x3 > high[1] + tol)
              throw std::invalid_argument(
                "Output/SEAS/" + entry + ": (x2, x3) = (" + format_number(x2) +
                ", " + format_number(x3) + ") m lies outside the contact (x2 " +
                format_number(low[0]) + " ... " + format_number(high[0]) +
                " m, x3 " + format_number(low[1]) + " ... " +
                format_number(high[1]) + " m)");
          };
          for (const auto &x : seas.plane_stations)
            inside(x[0], x[1], "Plane stations");
          for (const unsigned int i : {1, 2})
            {
              inside(seas.strike_profile[i],
                     seas.strike_profile[0],
                     "Strike profile");
              inside(seas.depth_profile[0],
                     seas.depth_profile[i],
                     "Depth profile");
            }
          return;
        }
      double length = 0;
      for (const auto &face : coarse.active_face_iterators())
        if (face->at_boundary() && face->boundary_id() == boundary_id::contact)
          for (const unsigned int v : face->vertex_indices())
            length = std::max(length, along_base_coordinate(face->vertex(v)));
      const auto check = [&](const double x, const std::string &entry) {
        const double s = seas.origin + x;
        if (s < -1e-9 * length || s > length * (1 + 1e-9))
          throw std::invalid_argument(
            "Output/SEAS/" + entry + ": " + format_number(x) + " m" +
            (seas.origin != 0 ?
               " from the origin " + format_number(seas.origin) + " m" :
               "") +
            " lies outside the contact (along-base coordinates 0 ... " +
            format_number(length) + " m)");
      };
      for (const double x : seas.fault_stations)
        check(x, "Fault stations");
      check(seas.slip_profile[0], "Slip profile");
      check(seas.slip_profile[1], "Slip profile");
    }


    template void
    MeshFile<2>::declare_parameters(ParameterHandler &);
    template void
    MeshFile<3>::declare_parameters(ParameterHandler &);
    template void
    MeshFile<2>::check_seas_positions(ParameterHandler &) const;
    template void
    MeshFile<3>::check_seas_positions(ParameterHandler &) const;
  } // namespace scenes
} // namespace rsfcycle
