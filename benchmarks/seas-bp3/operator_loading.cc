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
// (Segall 2010, as tests/green_operator_split_normal.cc): T_s(x, W_f) and
// T_n(x, W_f), with W_f half a node spacing below the last contact node.
// The signs are the closed form's for a unit thrust slip: the shear in
// the slip's direction (negative: the slip relaxes it), the normal
// compression positive. One rank. CSV columns:
//   x_d [m], shear [Pa], shear_exact [Pa], normal [Pa], normal_exact [Pa],
//   loading_check (g1 / (-V_p (S s)_k), 1 up to rounding)
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <iomanip>
#include <iostream>
#include <rsfcycle/models/green_fault.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/scenes/registry.h>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  const double mu = 32.04e9, nu = 0.25;

  /** Shear and normal stress at x_d = t of a unit thrust edge dislocation
   * at x_d = z on a fault of dip delta through a half-space's surface. */
  std::array<double, 2>
  dislocation(const double t, const double z, const double delta)
  {
    const double c2 = std::cos(2 * delta), sd = std::sin(delta);
    const double D = t * t + z * z - 2 * t * z * c2, D3 = D * D * D;
    const double t2 = t * t, z2 = z * z;
    const double P1 =
      t2 * t2 - 3 * t2 * t * z + 7 * t2 * z2 - 3 * t * z2 * z + z2 * z2;
    const double P2 =
      t2 * t2 - 5 * t2 * t * z + 4 * t2 * z2 - 5 * t * z2 * z + z2 * z2;
    const double shear = 2 * mu * z * (t + z) * sd * sd *
                         (P1 + P2 * c2 + t2 * z2 * std::cos(4 * delta)) /
                         (M_PI * (1 - nu) * (t - z) * D3);
    const double normal = -4 * mu * z2 * std::cos(delta) * sd * sd * sd *
                          (z2 * z - 3 * t2 * z + 2 * t2 * t * c2) /
                          (M_PI * (1 - nu) * D3);
    return {{shear, normal}};
  }
} // namespace

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
      if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) != 1)
        throw std::invalid_argument("runs on one rank");
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
      Parameters parameters;
      parameters.parse_parameters(prm);
      if (parameters.solver.bulk != SolverParameters::Bulk::green_function)
        throw std::invalid_argument(std::string(argv[1]) +
                                    ": Solver/Bulk must be green-function");
      if (prm.get_integer("Dimension") != 2)
        throw std::invalid_argument(std::string(argv[1]) +
                                    ": Dimension must be 2");

      const auto         scene = scenes::make_scene<2>(prm.get("Scene"), prm);
      std::ostringstream log;
      models::GreenFault<2> fault(parameters, *scene, log);
      fault.setup();
      std::cerr << log.str();
      const auto        &op    = fault.green_operator();
      const auto        &nodes = fault.contact_quadrature().nodes();
      const unsigned int n     = nodes.size();
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
          const auto exact = dislocation(x[k], W_f, delta);
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
