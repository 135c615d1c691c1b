// SPDX-License-Identifier: LGPL-2.1-or-later
// The boundary roles of a mesh-file scene (scenes/mesh_file.h,
// MeshFile::assign_roles): the tags checked against the roles, the
// contact's plane, the rotated frame and rsfcycle's boundary ids.
#include <algorithm>
#include <cmath>
#include <deal.II/grid/grid_tools.h>
#include <limits>
#include <rsfcycle/format.h>
#include <rsfcycle/ids.h>
#include <rsfcycle/scenes/mesh_file.h>
#include <rsfcycle/scenes/mesh_file_input.h>
#include <set>

namespace rsfcycle
{
  namespace scenes
  {
    namespace
    {
      using namespace mesh_file_input;

      /** Unit normal of a face pointing out of its cell, and its measure. */
      template <int dim, class CellIterator>
      std::pair<Tensor<1, dim>, double>
      outward_normal(const CellIterator &cell, const unsigned int f)
      {
        const auto     face = cell->face(f);
        Tensor<1, dim> n;
        if constexpr (dim == 2)
          {
            const Tensor<1, 2> t = face->vertex(1) - face->vertex(0);
            n[0]                 = t[1];
            n[1]                 = -t[0];
          }
        else
          n = cross_product_3d(face->vertex(1) - face->vertex(0),
                               face->vertex(2) - face->vertex(0));
        if (n * (face->center() - cell->center()) < 0)
          n = -n;
        const double measure = n.norm();
        return {n / measure, measure};
      }
    } // namespace


    /**
     * Check the tags against the roles, find the contact's plane, rotate the
     * mesh into the solver's frame and set rsfcycle's boundary ids.
     */
    template <int dim>
    void
    MeshFile<dim>::assign_roles(
      const std::map<types::boundary_id, std::string> &roles)
    {
      // every tag has a role and every role's tag is in the mesh
      std::set<types::boundary_id> boundary_tags;
      std::set<types::material_id> volume_tags;
      for (const auto &cell : coarse.active_cell_iterators())
        {
          volume_tags.insert(cell->material_id());
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              boundary_tags.insert(face->boundary_id());
        }
      for (const auto tag : boundary_tags)
        if (roles.count(tag) == 0)
          fail("Boundary roles",
               ": the mesh's boundary tag " + std::to_string(tag) +
                 " has no role" +
                 (tag == 0 ? " (tag 0: faces without a physical tag)" : ""));
      for (const auto &[tag, role] : roles)
        if (boundary_tags.count(tag) == 0)
          fail("Boundary roles",
               ": tag " + std::to_string(tag) + " (" + role +
                 ") is not a boundary tag of the mesh");
      for (const auto tag : volume_tags)
        if (materials.count(tag) == 0)
          fail("Materials",
               ": the mesh's volume tag " + std::to_string(tag) +
                 " has no material");
      for (const auto &[tag, m] : materials)
        if (volume_tags.count(tag) == 0)
          fail("Materials",
               ": tag " + std::to_string(tag) +
                 " is not a volume tag of the mesh");
      const auto role_of = [&roles](const types::boundary_id tag) {
        return roles.at(tag);
      };
      if (std::none_of(roles.begin(), roles.end(), [](const auto &r) {
            return r.second == "contact";
          }))
        fail("Boundary roles", ": no tag has the role contact");

      // the contact's plane: area-weighted mean of the outward normals,
      // every contact vertex on it
      Tensor<1, dim>          normal;
      std::vector<Point<dim>> contact_vertices;
      const double            diameter = GridTools::diameter(coarse);
      for (const auto &cell : coarse.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              role_of(cell->face(f)->boundary_id()) == "contact")
            {
              const auto [n, measure] = outward_normal<dim>(cell, f);
              normal += measure * n;
              for (const unsigned int v : cell->face(f)->vertex_indices())
                contact_vertices.push_back(cell->face(f)->vertex(v));
            }
      if (normal.norm() == 0)
        fail("Boundary roles", ": the contact faces have no common plane");
      normal /= normal.norm();
      const Point<dim> x0 = contact_vertices.front();
      for (const auto &x : contact_vertices)
        if (std::abs((x - x0) * normal) > 1e-6 * diameter)
          fail("Boundary roles",
               ": the contact is not planar (vertex " +
                 format_point(&x[0], dim) + " lies " +
                 format_number(std::abs((x - x0) * normal)) +
                 " m off its plane); curved faults are not supported "
                 "(doc/mesh-file.md)");

      // the rotated frame: y into the body, x down dip where gravity
      // defines a dip, in 3D z along the free-slip normal or the strike
      up = (g.norm() > 0) ? Tensor<1, dim>(-g / g.norm()) : Tensor<1, dim>();
      if (g.norm() == 0)
        up[dim - 1] = 1;
      const Tensor<1, dim> e_y      = -normal;
      Tensor<1, dim>       down_dip = -(up - (up * e_y) * e_y);
      const bool           has_dip  = down_dip.norm() > 1e-12;
      Tensor<1, dim>       e_x, e_z;
      if constexpr (dim == 2)
        {
          e_x[0]     = e_y[1];
          e_x[1]     = -e_y[0];
          along_sign = (has_dip && down_dip * e_x < 0) ? -1 : 1;
        }
      else
        {
          // a free-slip face across the contact (one parallel to it fixes
          // the normal component y and orients nothing)
          Tensor<1, dim> free_slip;
          for (const auto &cell : coarse.active_cell_iterators())
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  role_of(cell->face(f)->boundary_id()) == "free-slip")
                {
                  const Tensor<1, dim> n = outward_normal<dim>(cell, f).first;
                  if (std::abs(n * e_y) < 1 - 1e-6)
                    free_slip = n;
                }
          Tensor<1, dim> strike = cross_product_3d(up, e_y);
          if (free_slip.norm() > 0)
            e_z = free_slip - (free_slip * e_y) * e_y;
          else if (strike.norm() > 1e-12)
            e_z = strike;
          else
            {
              Tensor<1, dim> any;
              any[std::abs(e_y[0]) < 0.9 ? 0 : 2] = 1;
              e_z                                 = cross_product_3d(any, e_y);
            }
          if (e_z.norm() < 1e-12)
            fail("Boundary roles",
                 ": the free-slip boundaries must be perpendicular to the "
                 "contact in 3D");
          e_z /= e_z.norm();
          e_x = cross_product_3d(e_y, e_z);
          if (has_dip && down_dip * e_x < 0)
            {
              e_x = -e_x;
              e_z = -e_z;
            }
        }
      for (unsigned int d = 0; d < dim; ++d)
        {
          rotation[0][d] = e_x[d];
          rotation[1][d] = e_y[d];
          if (dim == 3)
            rotation[dim - 1][d] = e_z[d];
        }
      origin = x0;
      GridTools::transform(
        [this](const Point<dim> &x) { return from_physical(x); }, coarse);

      // rsfcycle's ids; the contact exactly in y = 0; free-slip faces
      // normal to the rotated frame's last axis
      const std::map<std::string, types::boundary_id> id_of = {
        {"contact", boundary_id::contact},
        {"load", boundary_id::backstop},
        {"load-opposite", boundary_id::backstop_opposite},
        {"fault-opposite", boundary_id::fault_opposite},
        {"creep", boundary_id::creep},
        {"free", boundary_id::surface},
        {"free-slip", boundary_id::lateral},
        {"absorbing", boundary_id::absorbing}};
      along_offset      = std::numeric_limits<double>::max();
      bool holds_normal = false; // a face that fixes the motion along y
      for (const auto &cell : coarse.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          {
            const auto face = cell->face(f);
            if (!face->at_boundary())
              continue;
            const std::string role = role_of(face->boundary_id());
            // free slip fixes the component along the face's normal: y
            // (parallel to the contact) or, in 3D, z
            bool parallel = false;
            if (role == "free-slip")
              {
                const Tensor<1, dim> n = outward_normal<dim>(cell, f).first;
                parallel               = std::abs(n[1]) > 1 - 1e-6;
                if (!parallel && (dim == 2 || std::abs(n[2]) < 1 - 1e-6))
                  fail("Boundary roles",
                       ": a free-slip face (tag " +
                         std::to_string(face->boundary_id()) + ") is " +
                         (dim == 2 ? "not parallel to the contact" :
                                     "neither parallel to the contact nor "
                                     "perpendicular to it with the normal of "
                                     "the other free-slip faces") +
                         " (free slip fixes one component of the contact's "
                         "frame)");
              }
            if (role == "creep" || role == "fault-opposite")
              for (const unsigned int v : face->vertex_indices())
                {
                  if (std::abs(face->vertex(v)[1]) > 1e-6 * diameter)
                    fail("Boundary roles",
                         ": a " + role + " face (tag " +
                           std::to_string(face->boundary_id()) +
                           ") is not in the contact's plane (a vertex " +
                           format_number(std::abs(face->vertex(v)[1])) +
                           " m off it)");
                  face->vertex(v)[1] = 0;
                }
            if (role == "contact")
              for (const unsigned int v : face->vertex_indices())
                {
                  face->vertex(v)[1] = 0;
                  along_offset =
                    std::min(along_offset, along_sign * face->vertex(v)[0]);
                }
            face->set_boundary_id(parallel ? boundary_id::parallel :
                                             id_of.at(role));
            holds_normal = holds_normal || parallel || role == "load" ||
                           role == "load-opposite";
            split = split || role == "fault-opposite";
          }

      if (normal_free && split)
        fail("Contact normal",
             " = free: not with a fault-opposite side (the two sides of a "
             "split fault share their normal displacement)");

      // a free normal with nothing else holding y: the body's rigid
      // motions along y (and its rotations about x and z, where the
      // contact's plane only holds tangential components) are free, and
      // the elastic problem is singular
      if (normal_free && !holds_normal)
        fail("Contact normal",
             " = free: no boundary holds the body's motion normal to the "
             "contact (give a load face, or a free-slip face parallel to the "
             "contact)");

      // antiplane: component 0 is the one out of the plane, not rotated
      load_rotated = antiplane ? load_velocity : rotation * load_velocity;
      if (std::abs(load_rotated[1]) > 1e-6 * load_rotated.norm())
        fail("Load velocity",
             " = " + format_point(&load_velocity[0], dim) +
               ": has a component normal to the contact; give a velocity "
               "parallel to it");
      load_rotated[1] = 0; // (rounding of the given digits)
    }


    template void
    MeshFile<2>::assign_roles(
      const std::map<types::boundary_id, std::string> &roles);
    template void
    MeshFile<3>::assign_roles(
      const std::map<types::boundary_id, std::string> &roles);
  } // namespace scenes
} // namespace rsfcycle
