// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_physics_scene_h
#define rsfcycle_physics_scene_h

#include <array>
#include <cmath>
#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>
#include <functional>
#include <memory>
#include <rsfcycle/friction/law.h>
#include <string>
#include <utility>
#include <vector>

namespace rsfcycle
{
  namespace physics
  {
    using namespace dealii;

    /** Bulk material of one region (material id). */
    struct Material
    {
      double density         = 900; // [kg/m^3]
      double bulk_modulus    = 5e4; // K [Pa]
      double poisson_ratio   = 0.3; // nu [-]
      double shear_viscosity = 1e3; // [Pa s]
      double bulk_viscosity  = 1e3; // [Pa s]

      /** G = 3 K (1 - 2 nu) / (2 (1 + nu)) [Pa]. */
      double
      shear_modulus() const
      {
        return 3. * bulk_modulus * (1. - 2. * poisson_ratio) /
               (2. * (1. + poisson_ratio));
      }
    };

    /**
     * A scene: everything that describes one physical set-up, handed to the
     * generic solver (ExaDG's split of scenario and solver). The geometry is
     * given in the rotated frame of doc/model.md §1: the base (boundary id
     * `contact`) lies in y = 0 and the body above it. Adding a scene never
     * touches the solver: it is a class in scenes/ and a line in each
     * function of scenes/scenes.cc.
     */
    template <int dim>
    class Scene
    {
    public:
      virtual ~Scene() = default;

      /**
       * The coarse mesh with boundary ids set (ids.h); it is refined by the
       * solver toward the patch.
       */
      virtual void
      create_coarse_mesh(Triangulation<dim> &tria) const = 0;

      /**
       * Distance of a box (a cell's bounding box, or a point when the box
       * is degenerate) to the seismogenic patch widened by `margin` in the
       * plane of the base (beyond its ends and lateral edges) [m]; zero
       * when they overlap. The refinement laws of
       * Discretisation::make_grid() use it.
       */
      virtual double
      distance_to_patch(const BoundingBox<dim> &box, double margin) const = 0;

      /**
       * How many local refinements a cell with this centre gets whatever
       * the refinement law says: Discretisation::make_grid() refines it in
       * the cycles k < this number. By default none.
       */
      virtual unsigned int
      zone_refinements(const Point<dim> &) const
      {
        return 0;
      }

      /**
       * The region (material id) of a cell (on any level) with the given
       * centre; `mesh_id` is the id the cell has from the coarse mesh (a
       * mesh file's volume tag, inherited by the children).
       */
      virtual types::material_id
      material_id(const Point<dim>  &cell_center,
                  types::material_id mesh_id) const = 0;

      /** Density, elastic moduli and viscosities of a region. */
      virtual Material
      material(types::material_id id) const = 0;

      /** Body force per unit mass in the rotated frame [m/s^2]. */
      virtual Tensor<1, dim>
      gravity() const = 0;

      /** Unit vector "up" of the physical frame, in the rotated frame. */
      virtual Tensor<1, dim>
      vertical() const = 0;

      /** Prescribed velocity of the backstop at time t [m/s]. */
      virtual Tensor<1, dim>
      backstop_velocity(double t) const = 0;

      /**
       * Rate-and-state parameters and cohesion of the base at a point of
       * the base.
       */
      virtual friction::Parameters
      friction_parameters(const Point<dim> &p) const = 0;

      /**
       * The initial state at a point of the base, as alpha =
       * log(theta V* / L) (doc/model.md §2); 0 is theta = L / V*.
       */
      virtual double
      initial_state(const Point<dim> &) const
      {
        return 0;
      }

      /**
       * The radiation damping eta [Pa s/m] of `Solver/Dynamics =
       * quasi-dynamic` at a point of the contact, in a cell of `material`:
       * the shear stress eta V that the quasi-dynamic approximation adds to
       * the friction. By default the shear impedance rho c_s = sqrt(G rho)
       * of the material: a body sliding on a rigid base radiates into its
       * own side only (for a fault between two equal half-spaces reduced
       * to one side with G/2 and rho/2 this is the usual G / (2 c_s)); a
       * split fault (split_fault()) radiates into both sides: half the
       * impedance, G / (2 c_s), of the contact side's material.
       */
      virtual double
      radiation_damping(const Point<dim> &, const Material &material) const
      {
        return std::sqrt(material.shear_modulus() * material.density) /
               (split_fault() ? 2 : 1);
      }

      /**
       * The rate alpha [1/s] of the mass-proportional damping at a point
       * of the body (rotated frame): the momentum balance gets the force
       * -alpha rho v (C += alpha M), so a wave decays as exp(-alpha t / 2)
       * where it is positive. 0 (the default): none.
       */
      virtual double
      sponge_damping(const Point<dim> &) const
      {
        return 0;
      }

      /**
       * The compressive normal stress |sigma_n| [Pa] on the contact as a
       * function of the point (rotated frame), constant in time; an empty
       * function (the default): the normal stress of the gravity
       * equilibrium.
       */
      virtual std::function<double(const Point<dim> &)>
      normal_stress() const
      {
        return {};
      }

      /**
       * Whether the contact's normal displacement is free (the normal
       * traction on the body stays zero, the friction takes normal_stress():
       * the symmetry plane of an antisymmetric problem); false (the
       * default): held at zero, a rigid base or mirror.
       */
      virtual bool
      contact_normal_free() const
      {
        return false;
      }

      /**
       * Whether the fault lies between two deformable parts of the body
       * (faces with boundary_id::fault_opposite pair with the contact and
       * creep faces): the slip is the jump of the tangential displacement,
       * the normal displacement is continuous; false (the default): one
       * body on a rigid base or mirror.
       */
      virtual bool
      split_fault() const
      {
        return false;
      }

      /**
       * The pore-fluid pressure p [Pa] on the contact as a function of the
       * point (rotated frame) and the time [s]: the friction acts on the
       * effective normal stress |sigma_n| - p. An empty function (the
       * default): none.
       */
      virtual std::function<double(const Point<dim> &, double)>
      pore_pressure() const
      {
        return {};
      }

      /**
       * The pore fluid's Darcy velocity [m/s] along the contact at a point
       * (rotated frame) and time [s], only reported: one component in 2D,
       * two in 3D (along the fluid domain's axes; the second 0 in 2D). An
       * empty function (the default): none.
       */
      virtual std::function<std::array<double, 2>(const Point<dim> &, double)>
      darcy_velocity() const
      {
        return {};
      }

      /**
       * A shear traction on the body at the contact, constant in time
       * [Pa], as a vector of the rotated frame at a point of the contact:
       * the part of the fault's shear stress that is not from the body's
       * deformation (SEAS BP1's initial shear stress tau_0). An empty
       * function (the default): none.
       */
      virtual std::function<Tensor<1, dim>(const Point<dim> &)>
      shear_prestress() const
      {
        return {};
      }

      /**
       * A shear traction on the body at the contact that changes in time,
       * added to shear_prestress(): its spatial part [Pa] as a vector of
       * the rotated frame at a point of the contact, to be multiplied by
       * shear_perturbation_history() (SEAS BP7's prescribed nucleation).
       * An empty function (the default): none.
       */
      virtual std::function<Tensor<1, dim>(const Point<dim> &)>
      shear_perturbation() const
      {
        return {};
      }

      /** The factor g(t) [-] of shear_perturbation() at the time t [s]. */
      virtual std::function<double(double)>
      shear_perturbation_history() const
      {
        return {};
      }

      /** The plate convergence rate v0 [m/s] (event threshold, output). */
      virtual double
      convergence_rate() const = 0;

      /**
       * Named surface points where the physical vertical displacement is
       * recorded every step (rotated frame).
       */
      virtual std::vector<std::pair<std::string, Point<dim>>>
      observation_points() const = 0;

      /**
       * What is recorded at every observation point, in this order: the
       * displacement along each unit direction of the rotated frame, with
       * the suffix of its column name. The default: the vertical alone
       * (no suffix).
       */
      virtual std::vector<std::pair<std::string, Tensor<1, dim>>>
      observation_directions() const
      {
        return {{"", vertical()}};
      }

      /**
       * The frame of the VTU output: a point p of the rotated frame is
       * written as c + Q p, a vector v as Q v. The identity (the default)
       * writes the rotated frame.
       */
      virtual std::pair<Tensor<2, dim>, Point<dim>>
      output_frame() const
      {
        return {Tensor<2, dim>(unit_symmetric_tensor<dim>()), Point<dim>()};
      }

      /**
       * Coordinate along the base reported in profiles: distance from the
       * trench along the base [m].
       */
      virtual double
      along_base_coordinate(const Point<dim> &p) const
      {
        return p[0];
      }
    };
  } // namespace physics
} // namespace rsfcycle

#endif
