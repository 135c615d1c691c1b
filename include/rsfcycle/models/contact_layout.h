// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_models_contact_layout_h
#define rsfcycle_models_contact_layout_h

#include <rsfcycle/output/sample.h>
#include <rsfcycle/physics/contact_quadrature.h>
#include <rsfcycle/physics/scene.h>
#include <vector>

namespace rsfcycle
{
  namespace models
  {
    /**
     * The output layout of a model whose fault is the scene's contact
     * (ProblemBase, GreenFault): every node's position along the base (and
     * across it in 3D) and lumped weight, gathered onto every rank, the
     * scene's observation points and convergence rate. Event times and
     * slips are interpolated, as accurate as the solution rather than
     * quantised by the onset step (which also makes them independent of the
     * number of ranks, whose iterates differ within the solver tolerances).
     */
    template <int dim>
    output::Layout
    contact_layout(const physics::Scene<dim>             &scene,
                   const physics::ContactQuadrature<dim> &contact)
    {
      output::Layout                     layout;
      std::vector<double>                s, z, w, G;
      std::vector<std::array<double, 3>> points;
      const auto [Q, c] = scene.output_frame();
      for (const auto &node : contact.nodes())
        {
          s.push_back(scene.along_base_coordinate(node.position));
          z.push_back(node.position[dim - 1]);
          w.push_back(node.weight);
          G.push_back(scene.material(node.material).shear_modulus());
          const dealii::Point<dim> x = c + Q * node.position;
          std::array<double, 3>    p{};
          for (unsigned int d = 0; d < dim; ++d)
            p[d] = x[d];
          points.push_back(p);
        }
      layout.positions    = contact.gather(s);
      layout.weights      = contact.gather(w);
      layout.shear_moduli = contact.gather(G);
      if (dim == 3)
        {
          layout.lateral_positions = contact.gather(z);
          layout.points            = contact.gather(points);
          // the tangential dofs of a node are the rotated frame's x and z
          // (ContactQuadrature), in the mesh's frame the columns of Q
          for (unsigned int d = 0; d < dim; ++d)
            {
              layout.slip_axes[0][d] = Q[d][0];
              layout.slip_axes[1][d] = Q[d][dim - 1];
            }
        }
      const auto directions         = scene.observation_directions();
      layout.observation_components = directions.size();
      for (const auto &point : scene.observation_points())
        {
          for (const auto &direction : directions)
            layout.observation_names.push_back(point.first + direction.first +
                                               "_m");
          layout.station_names.push_back(point.first);
        }
      layout.convergence_rate        = scene.convergence_rate();
      layout.interpolate_event_times = true;
      layout.pore_pressure           = bool(scene.pore_pressure());
      layout.darcy_velocity          = bool(scene.darcy_velocity());
      return layout;
    }
  } // namespace models
} // namespace rsfcycle

#endif
