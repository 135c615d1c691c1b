// SPDX-License-Identifier: LGPL-2.1-or-later
// The scene of the unit tests of the time step and the damping: a 1 m x
// 0.25 m plane-strain block (4 x 1 coarse cells) on a base (contact) at
// y = 0, held at the backstop x = 1, traction free elsewhere (or the top
// absorbing: absorbing_top); no gravity,
// zero friction (mu* = 0, b = 0; with no gravity every normal force
// vanishes). Density 1000 kg/m^3, K = 1 MPa, nu = 0.25 (G = 0.6 MPa),
// viscosities relaxation_time x the moduli. Local refinement goes toward
// the origin (the trench end of the base).
#ifndef rsfcycle_tests_block_scene_h
#define rsfcycle_tests_block_scene_h

#include <cmath>
#include <deal.II/grid/grid_generator.h>
#include <rsfcycle/ids.h>
#include <rsfcycle/physics/scene.h>

using namespace dealii;
using namespace rsfcycle;

class Block : public physics::Scene<2>
{
public:
  /** Kelvin-Voigt relaxation time eta/G = eta_b/K [s]; 0: inviscid. */
  double relaxation_time = 0;
  /** The top y = 0.25 m absorbing instead of traction free. */
  bool absorbing_top = false;
  /** The rate of the mass-proportional damping everywhere [1/s]. */
  double sponge = 0;

  double
  sponge_damping(const Point<2> &) const override
  {
    return sponge;
  }

  void
  create_coarse_mesh(Triangulation<2> &tria) const override
  {
    GridGenerator::subdivided_hyper_rectangle(tria,
                                              {4, 1},
                                              Point<2>(0, 0),
                                              Point<2>(1, 0.25));
    for (const auto &face : tria.active_face_iterators())
      if (face->at_boundary())
        {
          const Point<2> c = face->center();
          face->set_boundary_id(
            std::abs(c[1]) < 1e-12     ? boundary_id::contact :
            std::abs(c[0] - 1) < 1e-12 ? boundary_id::backstop :
            absorbing_top && std::abs(c[1] - 0.25) < 1e-12 ?
                                         boundary_id::absorbing :
                                         boundary_id::surface);
        }
  }
  double
  distance_to_patch(const BoundingBox<2> &box, double margin) const override
  {
    return std::max(0., box.get_boundary_points().first.norm() - margin);
  }
  types::material_id
  material_id(const Point<2> &, types::material_id) const override
  {
    return 0;
  }
  /** Density and bulk modulus are scaled by this (the Poisson ratio kept). */
  double material_scale = 1;

  physics::Material
  material(types::material_id) const override
  {
    physics::Material m;
    m.density         = 1000 * material_scale;
    m.bulk_modulus    = 1e6 * material_scale;
    m.poisson_ratio   = 0.25;
    m.shear_viscosity = relaxation_time * m.shear_modulus();
    m.bulk_viscosity  = relaxation_time * m.bulk_modulus;
    return m;
  }
  Tensor<1, 2>
  gravity() const override
  {
    return Tensor<1, 2>();
  }
  Tensor<1, 2>
  vertical() const override
  {
    return Tensor<1, 2>({0., 1.});
  }
  Tensor<1, 2>
  backstop_velocity(double) const override
  {
    return Tensor<1, 2>();
  }
  friction::Parameters
  friction_parameters(const Point<2> &) const override
  {
    friction::Parameters p;
    p.mu_star = 0;
    p.b       = 0;
    return p;
  }
  double
  convergence_rate() const override
  {
    return 1e-3;
  }
  std::vector<std::pair<std::string, Point<2>>>
  observation_points() const override
  {
    return {{"top", Point<2>(0.5, 0.25)}};
  }
};

#endif
