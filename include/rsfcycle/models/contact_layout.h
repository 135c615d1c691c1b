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
      output::Layout      layout;
      std::vector<double> s, z, w;
      for (const auto &node : contact.nodes())
        {
          s.push_back(scene.along_base_coordinate(node.position));
          z.push_back(node.position[dim - 1]);
          w.push_back(node.weight);
        }
      layout.positions = contact.gather(s);
      layout.weights   = contact.gather(w);
      if (dim == 3)
        layout.lateral_positions = contact.gather(z);
      for (const auto &point : scene.observation_points())
        {
          layout.observation_names.push_back(point.first + "_m");
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
