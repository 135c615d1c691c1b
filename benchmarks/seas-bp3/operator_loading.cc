// SPDX-License-Identifier: LGPL-2.1-or-later
// The BP3 operator's response to a slip reaching the surface, against the
// half-space closed form (README.md here, "Resolution and distance from
// converged" and "The surface end against the closed form").
//
//   bp3_operator_loading PRM DIP [GLOBAL LOCAL [PROFILE W]] > loading.csv
//
// PRM is a BP3 parameter file (prm/seas-bp3-qd.prm or a variant of it:
// a split fault from the surface, `Solver/Bulk = green-function`), DIP its
// dip in degrees, GLOBAL and LOCAL overrides of its `Mesh/Global
// refinements` and `Mesh/Local refinements`. The slip s(x_d) (down-dip
// distance x_d from the surface, m):
//  - without PROFILE, every contact node (0 to W_f down dip) slips 1 m.
//    This is the loading pattern: a uniform slip of the frictional fault
//    is the plates' motion with the creeping extension held, so the
//    stress rate of the locked fault is -V_p times it (g1 = -V_p S s,
//    checked);
//  - PROFILE `uniform`: s = 1 m above W, 0 below;
//  - PROFILE `linear`: s = 1 - x_d / W m above W, 0 below (its gradient
//    at the surface is -1/W);
//  - PROFILE `cosine`: s = cos^2(pi x_d / (2 W)) m above W, 0 below (no
//    gradient at the surface);
//  - PROFILE `file`, W the path of a CSV file of rows `x_d,slip` (m, m;
//    other lines skipped) from x_d = 0, increasing, to at most W_f: s
//    interpolated linearly between the rows, 0 below the last;
// W in metres, at most W_f. The operator as the run uses it gives the
// shear and normal traction changes -(S s)_k / w_k and (N s)_k / w_k at
// the contact nodes. The closed form is the half-space edge dislocation
// (Segall 2010, tests/edge_dislocation.h) T(t, z) integrated over the
// slip's dislocation density -s'(z): T(x, W_f) for the uniform slip
// (W_f half a node spacing below the last contact node; T(x, W_e),
// W_e half-way between the nodes either side of W, for a uniform slip
// above W), and int_0^W -s'(z) T(x, z) dz for a profile (plus s(W) T(x,
// W) for a file's last row) (adaptive Gauss-Legendre, the
// shear's Cauchy principal value by subtracting its pole; relative
// accuracy 1e-9). Where a density that does not vanish ends, the
// closed form's shear is infinite (ln), printed as inf; at the surface
// the normal stress too (the linear profile, most files): both diverge as
// ln x_d there, while the operator gives finite values that grow as the
// cells shrink (README.md here, "The surface end against the closed
// form").
// The signs are the closed form's for a unit thrust slip: the shear in
// the slip's direction (negative: the slip relaxes it), the normal
// compression positive. One rank. CSV columns:
//   x_d [m], shear [Pa], shear_exact [Pa], normal [Pa], normal_exact [Pa],
//   loading_check (g1 / (-V_p (S s)_k), 1 up to rounding; without
//   PROFILE only)
#include "../../tests/edge_dislocation.h"
#include "../green_operator_tool.h"

#include <algorithm>
#include <fstream>
#include <functional>
#include <iomanip>
#include <limits>
#include <vector>

namespace
{
  /**
   * The integral of f over [a, b], each piece's two estimates within
   * 1e-9 `scale` of each other (adaptive bisection, at most 40 levels,
   * 8-point Gauss-Legendre on each piece).
   */
  double
  integrate(const std::function<double(double)> &f,
            const double                         a,
            const double                         b,
            const double                         scale,
            const unsigned int                   depth = 0)
  {
    static const double xi[4] = {0.1834346424956498,
                                 0.5255324099163290,
                                 0.7966664774136267,
                                 0.9602898564975363},
                        wi[4] = {0.3626837833783620,
                                 0.3137066458778873,
                                 0.2223810344533745,
                                 0.1012285362903763};
    const auto gauss          = [&](const double l, const double r) {
      const double m = 0.5 * (l + r), h = 0.5 * (r - l);
      double       sum = 0;
      for (unsigned int q = 0; q < 4; ++q)
        sum += wi[q] * (f(m - h * xi[q]) + f(m + h * xi[q]));
      return h * sum;
    };
    const double m = 0.5 * (a + b), whole = gauss(a, b),
                 halves = gauss(a, m) + gauss(m, b);
    if (std::abs(whole - halves) < 1e-9 * scale || depth > 40)
      return halves;
    return integrate(f, a, m, scale, depth + 1) +
           integrate(f, m, b, scale, depth + 1);
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace rsfcycle;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      if (argc != 3 && argc != 5 && argc != 7)
        throw std::invalid_argument(
          "usage: bp3_operator_loading PRM DIP [GLOBAL LOCAL [PROFILE W]]");
      const std::string profile = argc == 7 ? argv[5] : "uniform";
      if (profile != "uniform" && profile != "linear" && profile != "cosine" &&
          profile != "file")
        throw std::invalid_argument(
          "PROFILE: one of uniform, linear, cosine, file");
      // BP3's shear modulus and Poisson ratio
      const double mu = 32.04e9, nu = 0.25;
      const double delta = std::stod(argv[2]) * M_PI / 180;
      if (!(delta > 0 && delta <= M_PI / 2))
        throw std::invalid_argument("DIP: between 0 and 90 degrees");

      dealii::ParameterHandler prm;
      app::declare_parameters(prm);
      app::parse_parameter_file(prm, argv[1]);
      if (argc >= 5)
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

      // the slip: pieces [z_i, z_i+1] of a smooth dislocation density
      // -s' (a, b, density), and the slip's steps (z, jump of -s)
      struct Piece
      {
        double                        a, b;
        std::function<double(double)> density;
      };
      std::vector<Piece>                     pieces;
      std::vector<std::pair<double, double>> steps;
      std::function<double(double)>          slip;
      const double                           pi = M_PI;
      if (profile == "file")
        {
          std::ifstream in(argv[6]);
          if (!in)
            throw std::invalid_argument("W: cannot read " +
                                        std::string(argv[6]));
          std::vector<double> z, v;
          for (std::string line; std::getline(in, line);)
            {
              std::istringstream row(line);
              double             zi, vi;
              char               comma;
              if (row >> zi >> comma >> vi && comma == ',')
                {
                  if (!z.empty() && !(zi > z.back()))
                    throw std::invalid_argument(
                      std::string(argv[6]) +
                      ": x_d must increase from row to row");
                  z.push_back(zi);
                  v.push_back(vi);
                }
            }
          if (z.size() < 2 || z.front() != 0 || z.back() > W_f)
            throw std::invalid_argument(
              std::string(argv[6]) +
              ": at least two rows x_d,slip from x_d = 0 to at most W_f = " +
              std::to_string(W_f) + " m");
          for (unsigned int i = 0; i + 1 < z.size(); ++i)
            {
              const double rho = -(v[i + 1] - v[i]) / (z[i + 1] - z[i]);
              pieces.push_back({z[i], z[i + 1], [rho](double) { return rho; }});
            }
          steps.emplace_back(z.back(), v.back());
          slip = [z, v](const double t) {
            if (t >= z.back())
              return 0.;
            const auto i =
              std::upper_bound(z.begin(), z.end(), t) - z.begin() - 1;
            return v[i] + (v[i + 1] - v[i]) * (t - z[i]) / (z[i + 1] - z[i]);
          };
        }
      else
        {
          double W = W_f;
          if (argc == 7)
            {
              W = std::stod(argv[6]);
              if (!(W > 0 && W <= W_f))
                throw std::invalid_argument(
                  "W: between 0 and W_f = " + std::to_string(W_f) + " m");
            }
          if (profile == "uniform")
            {
              // the dislocation half-way between the last node that
              // slips and the first that does not
              double above = 0, below = W_f;
              for (const double xk : x)
                (xk < W ? above : below) =
                  xk < W ? std::max(above, xk) : std::min(below, xk);
              steps.emplace_back(W < W_f ? 0.5 * (above + below) : W_f, 1.);
              slip = [W](const double t) { return t < W ? 1. : 0.; };
            }
          else if (profile == "linear")
            {
              pieces.push_back({0, W, [W](double) { return 1 / W; }});
              slip = [W](const double t) { return t < W ? 1 - t / W : 0.; };
            }
          else
            {
              pieces.push_back({0, W, [W, pi](const double z) {
                                  return 0.5 * pi / W * std::sin(pi * z / W);
                                }});
              slip = [W, pi](const double t) {
                return t < W ? std::pow(std::cos(0.5 * pi * t / W), 2) : 0.;
              };
            }
        }

      // the frame's x is down dip: s = 1 is normal faulting, the thrust
      // slip -1 (tests/green_operator_split_normal.cc)
      std::vector<double> s(n), shear(n), normal(n, 0.), zero(n, 0.),
        normal0(n, 0.);
      for (unsigned int k = 0; k < n; ++k)
        s[k] = slip(x[k]);
      op.apply(s.data(), shear.data());
      if (op.normal_coupling && !op.normal_negligible)
        {
          op.apply_normal(s.data(), 0, normal.data());
          op.apply_normal(zero.data(), 0, normal0.data());
        }

      // the closed form at t: {shear, normal} of the thrust slip
      const double infinity = std::numeric_limits<double>::infinity();
      const auto   exact    = [&](const double t) -> std::array<double, 2> {
        std::array<double, 2> sum{{0, 0}};
        for (const auto &[z, jump] : steps)
          {
            const auto T = edge_dislocation(t, z, delta, mu, nu);
            sum[0] += jump * T[0];
            sum[1] += jump * T[1];
          }
        for (const auto &piece : pieces)
          {
            const double scale =
              mu / (pi * (1 - nu)) *
              std::max({std::abs(piece.density(piece.a)),
                        std::abs(piece.density(0.5 * (piece.a + piece.b))),
                        std::abs(piece.density(piece.b)),
                        1e-12});
            const auto normal_part = [&](const double z) {
              return piece.density(z) *
                     edge_dislocation(t, z, delta, mu, nu)[1];
            };
            const auto shear_part = [&](const double z) {
              return piece.density(z) *
                     edge_dislocation(t, z, delta, mu, nu)[0];
            };
            // ln-divergent where a density that does not vanish ends
            const bool at_end = (t == piece.a && piece.density(t) != 0) ||
                                (t == piece.b && piece.density(t) != 0);
            if (t == 0 && at_end)
              return {{infinity, infinity}};
            if (at_end)
              sum[0] = infinity;
            if (t > piece.a && t < piece.b)
              {
                // T_s (t - z) is smooth: subtract the pole's residue
                const auto residue = [&](const double z) {
                  return shear_part(z) * (t - z);
                };
                const double r0 =
                  0.5 * (residue(t * (1 + 1e-7)) + residue(t * (1 - 1e-7)));
                const auto smooth = [&](const double z) {
                  return (residue(z) - r0) / (t - z);
                };
                sum[1] += integrate(normal_part, piece.a, t, scale) +
                          integrate(normal_part, t, piece.b, scale);
                sum[0] += integrate(smooth, piece.a, t, scale) +
                          integrate(smooth, t, piece.b, scale) +
                          r0 * std::log((t - piece.a) / (piece.b - t));
              }
            else
              {
                sum[1] += integrate(normal_part, piece.a, piece.b, scale);
                if (!at_end)
                  sum[0] += integrate(shear_part, piece.a, piece.b, scale);
              }
          }
        return sum;
      };
      const double v_p = 1e-9;
      std::cout << std::setprecision(10)
                << "x_d,shear,shear_exact,normal,normal_exact,loading_check\n";
      for (unsigned int k = 0; k < n; ++k)
        {
          const auto e = exact(x[k]);
          std::cout << x[k] << ',' << -shear[k] / nodes[k].weight << ',' << e[0]
                    << ',' << -(normal[k] - normal0[k]) / nodes[k].weight << ','
                    << e[1] << ',';
          if (argc < 7)
            std::cout << op.g1[k] / (-v_p * shear[k]);
          std::cout << '\n';
        }
    }
  catch (std::exception &exc)
    {
      std::cerr << "bp3_operator_loading: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
