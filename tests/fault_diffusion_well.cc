// SPDX-License-Identifier: LGPL-2.1-or-later
// Checks the Peaceman well of physics::FaultDiffusion (doc/model.md §9):
//  - The steady state: a constant Q = 0.003 m^3/s into the well at the
//    centre of [-200, 200]^2 m with p = 0 on the boundary (h = 5 m, run to
//    4e6 s, 100 times the slowest decay time, for S_well = 1e-9 and
//    1e-6 m^3/Pa: the storage changes the way there, not the end). Against
//    the closed forms of the steady state:
//     - the well's drawdown p_w - p_h(0) = Q / WI (to 1e-8);
//     - the plane's pressure, p(r) = (Q eta / (2 pi k L)) ln(R / r), the
//       Green's function of the square near its centre, R = 8 sqrt(pi) l /
//       Gamma(1/4)^2 = 1.0787 l its conformal radius (the Schwarz-
//       Christoffel map of the disc onto the square), at r = 10 ... 40 m on
//       the axis and the diagonal (the discrete error falls as (h / r)^2;
//       within 1 %);
//     - the Darcy velocity's radial component, Q / (2 pi L r), at 20 ... 40
//       m (within 1 %);
//     - the well's equivalent radius: r e^{-(p_h(0) - p_h(r)) / C} / h, the
//       r_e at which the analytic pressure equals the discrete one at the
//       well's node, measured from nodes on the axis and the diagonal at
//       about 40 and 60 m, whose mean (the mesh's anisotropy and the
//       walls' effect, both as cos 4 theta, cancel in it) is checked
//       against the constant FaultDiffusion::peaceman_factor (within 2e-4;
//       the 5-point stencil's 0.198 would fail).
//  - The storage: BP8's well (S_well = 1e-7 m^3/Pa, no flux, h = 20 m,
//    dt = 0.25 s) in its first seconds fills at dp_w/dt = Q / S_well, less
//    the outflow WI (p_w - p_h(0)) ~ WI Q t / S_well: the rate over [1, 2] s
//    and [2, 4] s against Q / S_well (1 - WI t / S_well), t the interval's
//    middle (within 1e-4 of Q / S_well; the outflow's share is 1e-3), and
//    the volume S_well p_w + sum_i beta phi L m_i p_i = Q t to 1e-12.
#include "tests.h"

#include <cmath>
#include <limits>
#include <rsfcycle/physics/fault_diffusion.h>

using namespace dealii;
using namespace rsfcycle::physics;

namespace
{
  std::string
  yes_no(const bool holds)
  {
    return holds ? "yes" : "no";
  }

  void
  steady_state(const double well_storage)
  {
    FaultDiffusionParameters p;
    p.source       = FaultDiffusionParameters::Source::well;
    p.boundary     = FaultDiffusionParameters::Boundary::fixed_pressure;
    p.shut_in_time = std::numeric_limits<double>::infinity();
    p.half_width   = 200;
    p.cell_size    = 5;
    p.time_step    = 4e4;
    p.well_storage = well_storage;
    const FaultDiffusion<2> diffusion(p);
    const double            t = 4e6, q = p.injection_rate;
    const double            c =
      q * p.viscosity / (2 * numbers::PI * p.permeability * p.thickness);
    const double R = 8 * std::sqrt(numbers::PI) * p.half_width /
                     std::pow(std::tgamma(0.25), 2);
    const double p0 = diffusion.value(Point<2>(), t);

    const double drawdown =
      (diffusion.well_pressure(t) - p0) * diffusion.well_index() / q;
    dealii::deallog << "S_well = " << well_storage << " m^3/Pa: p_w = "
                    << to_fixed(diffusion.well_pressure(t) / 1e6, 4)
                    << " MPa, p_h(0) = " << to_fixed(p0 / 1e6, 4)
                    << " MPa; (p_w - p_h(0)) WI / Q = 1 to 1e-8: "
                    << yes_no(std::abs(drawdown - 1) < 1e-8) << std::endl;

    bool plane_holds = true;
    for (const Point<2> x : {Point<2>(10, 0),
                             Point<2>(20, 0),
                             Point<2>(40, 0),
                             Point<2>(10, 10),
                             Point<2>(20, 20)})
      {
        const double exact = c * std::log(R / x.norm());
        const double error = (diffusion.value(x, t) - exact) / exact;
        dealii::deallog << "  r = " << to_fixed(x.norm(), 2)
                        << " m: p / (C ln(R / r)) - 1 = " << to_fixed(error, 5)
                        << std::endl;
        plane_holds = plane_holds && std::abs(error) < 0.01;
      }
    dealii::deallog << "  the plane's pressure C ln(R / r) within 1 %: "
                    << yes_no(plane_holds) << std::endl;

    // the Darcy velocity Q / (2 pi L r) outward
    bool darcy_holds = true;
    dealii::deallog << "  q . x / r / (Q / (2 pi L r)) - 1 at r =";
    for (const Point<2> x :
         {Point<2>(20, 0), Point<2>(40, 0), Point<2>(20, 20)})
      {
        const double exact = q / (2 * numbers::PI * p.thickness * x.norm());
        const Tensor<1, 2> darcy = diffusion.darcy_velocity(x, t);
        const double       error = darcy * x / x.norm() / exact - 1;
        dealii::deallog << " " << to_fixed(x.norm(), 2)
                        << " m: " << to_fixed(error, 5);
        darcy_holds = darcy_holds && std::abs(error) < 0.01;
      }
    dealii::deallog << "; within 1 %: " << yes_no(darcy_holds) << std::endl;

    // the lattice's anisotropy and the square's walls both go as cos 4 theta:
    // opposite on the axis and the diagonal, which the mean cancels
    bool factor_holds = true;
    dealii::deallog << "  r_e / h (axis, diagonal, mean) from r =";
    for (const auto &[axis, diagonal] :
         {std::pair(Point<2>(40, 0), Point<2>(30, 30)),
          std::pair(Point<2>(60, 0), Point<2>(40, 40))})
      {
        double mean = 0;
        dealii::deallog << " " << to_fixed(axis.norm(), 2) << ", "
                        << to_fixed(diagonal.norm(), 2) << " m:";
        for (const Point<2> &x : {axis, diagonal})
          {
            const double factor = x.norm() *
                                  std::exp(-(p0 - diffusion.value(x, t)) / c) /
                                  p.cell_size;
            dealii::deallog << " " << to_fixed(factor, 5);
            mean += factor / 2;
          }
        dealii::deallog << " " << to_fixed(mean, 5) << ";";
        factor_holds =
          factor_holds &&
          std::abs(mean - FaultDiffusion<2>::peaceman_factor) < 2e-4;
      }
    dealii::deallog << " peaceman_factor within 2e-4: " << yes_no(factor_holds)
                    << std::endl;
  }

  void
  storage()
  {
    FaultDiffusionParameters p;
    p.source    = FaultDiffusionParameters::Source::well;
    p.cell_size = 20;
    p.time_step = 0.25;
    const FaultDiffusion<2> diffusion(p);
    const double            rate  = p.injection_rate / p.well_storage;
    bool                    holds = true, volume_kept = true;
    for (const auto &[t1, t2] : {std::pair(1., 2.), std::pair(2., 4.)})
      {
        const double measured =
          (diffusion.well_pressure(t2) - diffusion.well_pressure(t1)) /
          (t2 - t1);
        const double outflow =
          diffusion.well_index() * (t1 + t2) / 2 / p.well_storage;
        dealii::deallog << "dp_w/dt over [" << t1 << ", " << t2
                        << "] s / (Q / S_well) - 1 = "
                        << to_fixed(measured / rate - 1, 6)
                        << ", the outflow's share WI t / S_well = "
                        << to_fixed(outflow, 6) << std::endl;
        holds = holds && std::abs(measured / rate - 1 + outflow) < 1e-4;
        for (const double t : {t1, t2})
          volume_kept = volume_kept && std::abs(diffusion.stored_volume(t) -
                                                p.injection_rate * t) <=
                                         1e-12 * p.injection_rate * t;
      }
    dealii::deallog << "the well fills at Q / S_well (1 - WI t / S_well) "
                    << "to 1e-4: " << yes_no(holds)
                    << "; volume = Q t to 1e-12: " << yes_no(volume_kept)
                    << std::endl;
  }
} // namespace


int
main()
{
  initlog();
  try
    {
      steady_state(1e-9);
      steady_state(1e-6);
      storage();
    }
  catch (const std::exception &error)
    {
      dealii::deallog << "error: " << error.what() << std::endl;
      return 1;
    }
}
