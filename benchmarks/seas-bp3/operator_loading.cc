// The BP3 operator's response to a uniform slip over the whole frictional
// fault, against the half-space closed form (README.md here, "How accurate
// the operator is").
//
//   bp3_operator_loading PRM DIP [GLOBAL LOCAL] > loading.csv
//
// PRM is a BP3 parameter file (prm/seas-bp3-qd.prm or a variant of it:
// a split fault from the surface, `Solver/Bulk = green-function`), DIP its
// dip in degrees, GLOBAL and LOCAL overrides of its `Mesh/Global
// refinements` and `Mesh/Local refinements`. Every contact node (0 to W_f
// down dip) slips 1 m; the operator as the run uses it gives the shear and
// normal traction changes -(S s)_k / w_k and (N s)_k / w_k. This is the
// loading pattern: a uniform slip of the frictional fault is the plates'
// motion with the creeping extension held, so the stress rate of the
// locked fault is -V_p times it (g1 = -V_p S s, checked). The closed
// form is the half-space edge dislocation at the frictional fault's end
// (Segall 2010, tests/edge_dislocation.h): T_s(x, W_f) and
// T_n(x, W_f), with W_f half a node spacing below the last contact node.
// The signs are the closed form's for a unit thrust slip: the shear in
// the slip's direction (negative: the slip relaxes it), the normal
// compression positive. One rank. CSV columns:
//   x_d [m], shear [Pa], shear_exact [Pa], normal [Pa], normal_exact [Pa],
//   loading_check (g1 / (-V_p (S s)_k), 1 up to rounding)
#include "../../tests/edge_dislocation.h"
#include "../green_operator_tool.h"

#include <iomanip>
#include <vector>

int
main(int argc, char **argv)
{
  using namespace rsfcycle;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      if (argc != 3 && argc != 5)
        throw std::invalid_argument(
          "usage: bp3_operator_loading PRM DIP [GLOBAL LOCAL]");
      // BP3's shear modulus and Poisson ratio
      const double mu = 32.04e9, nu = 0.25;
      const double delta = std::stod(argv[2]) * M_PI / 180;
      if (!(delta > 0 && delta <= M_PI / 2))
        throw std::invalid_argument("DIP: between 0 and 90 degrees");

      dealii::ParameterHandler prm;
      scenes::declare_parameters(prm);
      scenes::parse_parameter_file(prm, argv[1]);
      if (argc == 5)
        {
          prm.enter_subsection("Mesh");
          prm.set("Global refinements", std::string(argv[3]));
          prm.set("Local refinements", std::string(argv[4]));
          prm.leave_subsection();
        }
      const GreenOperatorTool<2> tool(prm, argv[1]);
      const auto                &scene = tool.scene;
      const auto                &fault = *tool.fault;
      const auto                &op    = fault.green_operator();
      const auto                &nodes = fault.contact_quadrature().nodes();
      const unsigned int         n     = nodes.size();
      if (op.n_rows() != n)
        throw std::runtime_error("expected one tangential dof per node");

      // down-dip distances from the surface node
      std::vector<double> x(n);
      double              lo = 1e300, hi = -1e300, spacing = 1e300;
      for (unsigned int k = 0; k < n; ++k)
        {
          x[k] = scene->along_base_coordinate(nodes[k].position);
          lo   = std::min(lo, x[k]);
        }
      for (auto &xk : x)
        {
          xk -= lo;
          hi = std::max(hi, xk);
        }
      for (unsigned int k = 0; k < n; ++k)
        if (hi - x[k] > 0)
          spacing = std::min(spacing, hi - x[k]);
      const double W_f = hi + 0.5 * spacing;

      // the frame's x is down dip: s = 1 is normal faulting, the thrust
      // slip -1 (tests/green_operator_split_normal.cc)
      std::vector<double> s(n, 1.), shear(n), normal(n, 0.), zero(n, 0.),
        normal0(n, 0.);
      op.apply(s.data(), shear.data());
      if (op.normal_coupling && !op.normal_negligible)
        {
          op.apply_normal(s.data(), 0, normal.data());
          op.apply_normal(zero.data(), 0, normal0.data());
        }
      const double v_p = 1e-9;
      std::cout << std::setprecision(10)
                << "x_d,shear,shear_exact,normal,normal_exact,loading_check\n";
      for (unsigned int k = 0; k < n; ++k)
        {
          const auto exact = edge_dislocation(x[k], W_f, delta, mu, nu);
          std::cout << x[k] << ',' << -shear[k] / nodes[k].weight << ','
                    << exact[0] << ','
                    << -(normal[k] - normal0[k]) / nodes[k].weight << ','
                    << exact[1] << ',' << op.g1[k] / (-v_p * shear[k]) << '\n';
        }
    }
  catch (std::exception &exc)
    {
      std::cerr << "bp3_operator_loading: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
