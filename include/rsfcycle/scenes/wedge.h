// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_scenes_wedge_h
#define rsfcycle_scenes_wedge_h

#include <memory>
#include <rsfcycle/physics/scene.h>
#include <rsfcycle/scenes/friction_field.h>

namespace rsfcycle
{
  namespace scenes
  {
    using namespace dealii;
    using physics::Material;
    using physics::Scene;

    /**
     * The laboratory subduction wedge of the paper (doc/model.md §5; §6 in 3D,
     * where it is extruded in z). In physical coordinates (metres, trench
     * at the origin, x toward the backstop, y up) the wedge is the triangle
     * A = (0, 0), C = (length, 0), B = (length, -depth); it is rotated by the
     * dip angle so that the base A-B lies on y = 0.
     */
    template <int dim>
    class Wedge : public Scene<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      explicit Wedge(ParameterHandler &prm);

      void
      create_coarse_mesh(Triangulation<dim> &tria) const override;
      double
      distance_to_patch(const BoundingBox<dim> &box,
                        double                  margin) const override;
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
      convergence_rate() const override;
      std::vector<std::pair<std::string, Point<dim>>>
      observation_points() const override;

      /** Physical (unrotated) coordinates of a point of the rotated frame. */
      Point<dim>
      to_physical(const Point<dim> &p) const;

      /** Rotated-frame coordinates of a physical point. */
      Point<dim>
      from_physical(const Point<dim> &x) const;

      /** Along-base extent [s_up, s_down(z)] of the patch at lateral z. */
      std::pair<double, double>
      patch_extent(double z) const;

      /** Whether a point of the base lies on the patch (ends included). */
      bool
      on_patch(const Point<dim> &p) const;

    private:
      double   length, depth, width;
      double   patch_downdip_x, patch_length, patch_length_0, patch_length_1;
      double   lower_thickness;
      Material upper, lower;
      double   g;
      /** The friction on and off the patch, as functions of the point. */
      std::unique_ptr<const FrictionField<dim>> friction_field;
      double                                    v0, t0;
      std::vector<double>                       observation_x;
      double                                    cos_phi, sin_phi;
    };
  } // namespace scenes
} // namespace rsfcycle

#endif
