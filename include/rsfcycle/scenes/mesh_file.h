// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_scenes_mesh_file_h
#define rsfcycle_scenes_mesh_file_h

#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>
#include <map>
#include <memory>
#include <rsfcycle/physics/scene.h>
#include <rsfcycle/scenes/contact_patch.h>
#include <rsfcycle/scenes/friction_field.h>
#include <string>
#include <vector>

namespace rsfcycle
{
  namespace scenes
  {
    using namespace dealii;
    using physics::Material;
    using physics::Scene;

    /**
     * A scene that is pure data: a gmsh mesh (quadrilaterals in 2D,
     * hexahedra in 3D) whose physical tags the .prm maps to roles
     * (boundaries: contact, load, free, free-slip; volumes: materials),
     * friction parameters and initial state as functions of the mesh's
     * coordinates (FrictionField), gravity and the load velocity as
     * vectors.
     *
     * The contact must be planar. The scene rotates the mesh into the
     * solver's frame (doc/model.md §1: contact in y = 0, body above it, x down
     * dip where gravity defines a dip) and every vector with it; the
     * functions and observation points of the .prm stay in the mesh's
     * coordinates. Free-slip boundaries fix one Cartesian component of the
     * rotated frame, the last one: in 2D they must be parallel to the
     * contact, in 3D perpendicular to it and all with one normal (it
     * becomes z).
     */
    template <int dim>
    class MeshFile : public Scene<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      /**
       * Parse the parameters, read and check the mesh: bad input throws
       * std::invalid_argument with a one-line message naming the entry.
       */
      explicit MeshFile(ParameterHandler &prm);

      void
      create_coarse_mesh(Triangulation<dim> &tria) const override;
      double
      distance_to_patch(const BoundingBox<dim> &box,
                        double                  margin) const override;
      unsigned int
      zone_refinements(const Point<dim> &cell_center) const override;
      types::material_id
      material_id(const Point<dim>  &cell_center,
                  types::material_id mesh_id) const override;
      Material
      material(types::material_id id) const override;
      Tensor<1, dim>
      gravity() const override;
      Tensor<1, dim>
      vertical() const override;
      Tensor<1, dim>
      backstop_velocity(double t) const override;
      friction::Parameters
      friction_parameters(const Point<dim> &p) const override;
      double
      initial_state(const Point<dim> &p) const override;
      std::function<double(const Point<dim> &)>
      normal_stress() const override;
      std::function<Tensor<1, dim>(const Point<dim> &)>
      shear_prestress() const override;
      std::function<Tensor<1, dim>(const Point<dim> &)>
      shear_perturbation() const override;
      std::function<double(double)>
      shear_perturbation_history() const override;
      bool
      contact_normal_free() const override
      {
        return normal_free;
      }
      bool
      split_fault() const override
      {
        return split;
      }
      std::function<double(const Point<dim> &, double)>
      pore_pressure() const override;
      std::function<std::array<double, 2>(const Point<dim> &, double)>
      darcy_velocity() const override;
      double
      radiation_damping(const Point<dim> &p,
                        const Material   &material) const override;
      double
      sponge_damping(const Point<dim> &p) const override;
      double
      convergence_rate() const override;
      std::vector<std::pair<std::string, Point<dim>>>
      observation_points() const override;

      /** Up, or with `Observation components = all` the mesh's axes. */
      std::vector<std::pair<std::string, Tensor<1, dim>>>
      observation_directions() const override;
      double
      along_base_coordinate(const Point<dim> &p) const override;
      /** The mesh's own coordinates. */
      std::pair<Tensor<2, dim>, Point<dim>>
      output_frame() const override;

      /** Mesh coordinates of a point of the rotated frame. */
      Point<dim>
      to_physical(const Point<dim> &p) const;

      /** Rotated-frame coordinates of a point of the mesh. */
      Point<dim>
      from_physical(const Point<dim> &x) const;

    private:
      /** Rotation R (rows: the rotated axes in mesh coordinates) and origin. */
      Tensor<2, dim> rotation;
      Point<dim>     origin;
      /**
       * The SEAS fault stations and slip profile within the coarse
       * contact's extent (std::invalid_argument naming the entry).
       */
      void
      check_seas_positions(ParameterHandler &prm) const;

      /** along-base coordinate s = along_sign x' - along_offset. */
      double along_sign = 1, along_offset = 0;

      /** The coarse mesh in the rotated frame with rsfcycle's ids. */
      Triangulation<dim> coarse;

      std::map<types::material_id, Material> materials;
      Tensor<1, dim>                         g, up, load_velocity;
      /** `Refine where` (null: b - a > 0). */
      std::shared_ptr<const Function<dim>> refine_where;
      /** Sponge damping (empty: none). */
      std::shared_ptr<const Function<dim>> sponge;
      std::shared_ptr<const Function<dim>> refine_zone;
      /** Displacement = antiplane: load_velocity[0] is out of the plane. */
      bool antiplane = false;
      /** `Contact normal = free`. */
      bool normal_free = false;
      /** A boundary tag with the role fault-opposite. */
      bool split = false;
      /** The load velocity in the rotated frame, parallel to the contact. */
      Tensor<1, dim>                                  load_rotated;
      double                                          ramp_time;
      std::vector<std::pair<std::string, Point<dim>>> observation;
      bool                                            all_components = false;
      std::unique_ptr<const FrictionField<dim>>       friction_field;

      /** The rate-weakening (b - a > 0) part of the contact. */
      ContactPatch<dim> patch;

      void
      read_mesh(const std::string &file);
      /** Parse and check `Sponge damping` (after read_mesh()). */
      void
      read_sponge(ParameterHandler &prm, const std::string &text);
      void
      assign_roles(const std::map<types::boundary_id, std::string> &roles);
      void
      sample_patch(unsigned int n_refinements);
    };
  } // namespace scenes
} // namespace rsfcycle

#endif
