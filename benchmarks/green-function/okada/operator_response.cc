// SPDX-License-Identifier: LGPL-2.1-or-later
// The Green's-function operator's response to a uniform slip patch, for the
// comparison with Okada's (1992) half-space solution (README.md here).
//
//   okada_operator_response PRM REFINEMENTS X1 X2 Z1 Z2 > response.csv
//
// PRM is a 3D `Solver/Bulk = green-function` parameter file whose fault is
// the plane y = 0 (prm/seas-bp5-qd.prm), REFINEMENTS its `Mesh/Local
// refinements`. Every contact node with X1 <= x <= X2 and Z1 <= z <= Z2 [m]
// slips 1 m along x (strike), every other node 0 (so the slip ramps over
// one cell outside the patch); the operator as the run uses it (an
// H-matrix if the run compresses) gives the traction change
// -(S s)_i / w_k of each contact dof, and its observation rows the
// displacement O s at the observation points, both in the mesh's frame
// (the .prm's coordinates). One rank. Written as CSV with the columns
// kind,index,name,x,y,z,weight,slip,component,value:
//   node,k,,x,y,z,w_k,s_k,c,traction [Pa]       (s_k 1 on the patch, else 0;
//                                                c = 0, 1, 2: x, y, z)
//   station,i,name,x,y,z,0,0,c,displacement [m] (c = 0, 1, 2 as the
//                                                Observation components)
#include "../../green_operator_tool.h"

#include <iomanip>
#include <vector>

int
main(int argc, char **argv)
{
  using namespace rsfcycle;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      if (argc != 7)
        throw std::invalid_argument(
          "usage: okada_operator_response PRM REFINEMENTS X1 X2 Z1 Z2");
      const double x1 = std::stod(argv[3]), x2 = std::stod(argv[4]);
      const double z1 = std::stod(argv[5]), z2 = std::stod(argv[6]);

      dealii::ParameterHandler prm;
      app::declare_parameters(prm);
      app::parse_parameter_file(prm, argv[1]);
      prm.enter_subsection("Mesh");
      prm.set("Local refinements", std::string(argv[2]));
      prm.leave_subsection();
      const GreenOperatorTool<3> tool(prm, argv[1]);
      const auto                &op = tool.fault->green_operator();
      const auto &nodes             = tool.fault->contact_quadrature().nodes();
      if (op.n_contact() != 2 * nodes.size() || op.n_rows() != op.n_contact())
        throw std::runtime_error("expected two tangential dofs per node");

      // the mesh's frame (the .prm's x, y, z): a point p of the solver's
      // rotated frame is c + Q p there, its unit vector e_c is Q e_c
      const auto [Q, c]  = tool.scene->output_frame();
      const auto in_mesh = [&](const dealii::Point<3> &p) { return c + Q * p; };
      const auto axis    = [&](const unsigned int component) {
        dealii::Tensor<1, 3> e;
        e[component] = 1;
        return Q * e;
      };

      std::vector<double> slip(op.n_contact(), 0.), force(op.n_rows(), 0.);
      for (unsigned int k = 0; k < nodes.size(); ++k)
        {
          const auto p = in_mesh(nodes[k].position);
          // (1 mm of slack: the frame's rounding)
          if (p[0] >= x1 - 1e-3 && p[0] <= x2 + 1e-3 && p[2] >= z1 - 1e-3 &&
              p[2] <= z2 + 1e-3)
            for (unsigned int d = 0; d < 2; ++d)
              slip[2 * k + d] = axis(nodes[k].components[d])[0];
        }
      op.apply(slip.data(), force.data());

      std::cout << std::setprecision(10);
      std::cout << "kind,index,name,x,y,z,weight,slip,component,value\n";
      for (unsigned int k = 0; k < nodes.size(); ++k)
        {
          const auto           p = in_mesh(nodes[k].position);
          dealii::Tensor<1, 3> traction;
          for (unsigned int d = 0; d < 2; ++d)
            traction += -force[2 * k + d] / nodes[k].weight *
                        axis(nodes[k].components[d]);
          for (unsigned int d = 0; d < 3; ++d)
            std::cout << "node," << k << ",," << p[0] << ',' << p[1] << ','
                      << p[2] << ',' << nodes[k].weight << ','
                      << (slip[2 * k] != 0 || slip[2 * k + 1] != 0) << ',' << d
                      << ',' << traction[d] << '\n';
        }

      // the observation rows: point by point, the scene's directions
      const auto points     = tool.scene->observation_points();
      const auto directions = tool.scene->observation_directions();
      if (op.O.m() != points.size() * directions.size())
        throw std::runtime_error("observation rows do not match the points");
      dealii::Vector<double> s(slip.begin(), slip.end()), u(op.O.m());
      op.O.vmult(u, s);
      for (unsigned int i = 0; i < points.size(); ++i)
        for (unsigned int d = 0; d < directions.size(); ++d)
          {
            const auto &name = points[i].first;
            const auto  p    = in_mesh(points[i].second);
            std::cout << "station," << i << ',' << name << ',' << p[0] << ','
                      << p[1] << ',' << p[2] << ",0,0," << d << ','
                      << u[i * directions.size() + d] << '\n';
          }
    }
  catch (std::exception &exc)
    {
      std::cerr << "okada_operator_response: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
