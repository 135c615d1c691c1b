// SPDX-License-Identifier: LGPL-2.1-or-later
// Checks the explicit step (models::ExplicitStep, Time stepping/Integrator
// = explicit) against closed forms, on the antiplane block of
// block_scene.h (1 m x 0.25 m, held at x = 1, traction free at x = 0 and
// on the top, the base a contact without normal force: free), refined
// three times globally: square cells of h = 1/32 m, rho = 1000 kg/m^3,
// G = 0.6 MPa, c_s = sqrt(G / rho) = 24.4949 m/s.
//  - The stable step of both schemes. With the lumped mass the largest
//    eigenvalue of a square Q1 cell's K_e x = lambda M_L,e x is 4 c^2 /
//    h^2, so omega_max = 2 c / h and the bound Omega / omega_max is h /
//    c_s = 1.27578e-3 s for central differences (Omega = 2) and 1.872515
//    h / c_s for Noh and Bathe's p = 0.54 (Omega = 3.745029, where the
//    spectral radius of its amplification matrix reaches 1); printed as
//    the ratio of the computed stable step to it (1).
//  - A plane shear wave, the standing mode u = cos(k x), k = pi/2 m^-1,
//    uniform in y (free at x = 0, zero at x = 1). It is an exact
//    eigenvector of the lumped system with lambda_h = 4 c^2 sin^2(k h/2)
//    / h^2, so a step maps the mode's (u, v, a) as the scheme maps those
//    of the oscillator u'' = -lambda_h u (central differences: u(t_n) =
//    cos(n theta) cos(k x) with cos theta = 1 - tau^2 lambda_h / 2, which
//    the test checks too), to rounding: checked after 36 steps of 0.9 h /
//    c_s (a quarter period, where u changes fastest), printed "yes" when
//    every dof agrees to 1e-10. The continuum's cos(c k t) differs from it
//    by the discretisation's dispersion: with central differences the
//    space's -(k h)^2/24 and the time's +(c k tau)^2/24 in the frequency
//    (-1.0e-4 and +8.1e-5), their difference at x = 0 printed (about 1.6 x
//    2e-5 = 3e-5); Noh and Bathe's time error is far smaller (+1.2e-5 in
//    the frequency at omega tau = 0.044), so the space's error dominates:
//    about 1.6 x 8.8e-5 = 1.4e-4.
//  - Stability as predicted: the mode of the largest eigenvalue here is
//    uniform in x but for the held end (lambda_max = (4 - 4/3 sin^2(pi /
//    128)) c^2/h^2, 0.9998 of the bound). From a rough start (values
//    between -0.5 and 0.5 at every free dof), 2000 steps of 0.99 of the
//    stable step stay bounded (max |u| below 20 times its start: yes);
//    200 steps of 1.01 of it grow beyond 1e6 times the start (the growth
//    factor of that mode is 1.33 per step for central differences, 1.32 for
//    Noh and Bathe): yes.
//  - The sponge (Scene::sponge_damping, C = alpha M): with alpha = 20/s
//    everywhere the same mode follows u'' + alpha u' + lambda_h u = 0, u(0)
//    = 1, u'(0) = 0: exp(-alpha t/2) (cos w t + alpha/(2 w) sin w t), w^2 =
//    lambda_h - alpha^2/4. After 100 Noh-Bathe steps (0.115 s, where the
//    undamped mode is at -0.29) the mode keeps its shape at every dof (yes)
//    and u(0, t) is the closed form's -0.2141 to the time step's error
//    (within 1e-3: yes).
//  - The sponge on the block refined once more toward its base (hanging
//    nodes): alpha M is lumped after the hanging nodes' condensation, so C
//    is diagonal (the explicit step is not refused: yes) and its trace is
//    alpha times the body's mass, 20/s x 1000 kg/m^3 x 0.25 m^2 = 5000
//    kg/(m s) per metre of antiplane depth (to rounding: yes).
#include "block_scene.h"
#include "tests.h"

#include <deal.II/base/function.h>
#include <deal.II/numerics/vector_tools.h>
#include <memory>
#include <rsfcycle/friction/laws.h>
#include <rsfcycle/models/explicit_step.h>

namespace
{
  class Mode : public Function<2>
  {
  public:
    double
    value(const Point<2> &p, const unsigned int) const override
    {
      return std::cos(numbers::PI / 2 * p[0]);
    }
  };

  double
  max_abs(const la::Vector &u)
  {
    return u.linfty_norm();
  }

  /** The block assembled (lumped mass) and its contact. */
  struct Assembled
  {
    Assembled(const MeshParameters &mesh, const Block &scene)
      : d(mesh, scene, {true, false, true})
    {
      d.make_grid();
      d.setup_system();
      d.setup_boundary_conditions();
      d.assemble_matrices();
      contact.setup(d.dof_handler,
                    d.scalar_dof_handler,
                    d.hanging_constraints,
                    *d.partitioner,
                    d.fixed,
                    [&](const Point<2> &p) {
                      return scene.friction_parameters(p);
                    });
    }
    physics::Discretisation<2>    d;
    physics::ContactQuadrature<2> contact;
  };

  /** Noh and Bathe's explicit step on an assembled block. */
  std::unique_ptr<models::ExplicitStep<2>>
  noh_bathe(const Assembled &block, const friction::Law &law)
  {
    return std::make_unique<models::ExplicitStep<2>>(
      block.d,
      block.contact,
      law,
      [](const Point<2> &p) { return p[0]; },
      true);
  }


  /** The dof of the point (0, 0). */
  unsigned int
  origin_dof(const physics::Discretisation<2> &d)
  {
    unsigned int origin = 0;
    for (const auto &cell : d.dof_handler.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (cell->vertex(v).norm() < 1e-12)
          origin = cell->vertex_dof_index(v, 0);
    return origin;
  }

  /** The mode at rest, u = cos(k x), a = -lambda_h u, no state. */
  BodyState
  mode_at_rest(const Assembled &block, const double lambda_h)
  {
    BodyState state;
    block.d.reinit(state.u);
    block.d.reinit(state.v);
    block.d.reinit(state.a);
    VectorTools::interpolate(block.d.dof_handler, Mode(), state.u);
    state.a = state.u;
    state.a *= -lambda_h;
    state.alpha.assign(block.contact.n_nodes(), 0.);
    return state;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(6);
  MeshParameters mesh;
  mesh.global_refinements = 3;
  mesh.local_refinements  = 0;
  Block           scene;
  const Assembled block(mesh, scene);
  const auto     &d       = block.d;
  const auto     &contact = block.contact;
  const auto      law     = friction::make_law("ageing");
  const double    h = 1. / 32, c = std::sqrt(0.6e6 / 1000);
  const double    k     = numbers::PI / 2,
               lambda_h = 4 * c * c * std::pow(std::sin(k * h / 2), 2) / h / h;
  for (const bool two_stages : {false, true})
    {
      const double omega_tau = two_stages ? 3.745029 : 2.;
      deallog << (two_stages ? "noh-bathe" : "central-differences")
              << std::endl;
      models::ExplicitStep<2> step(
        d, contact, *law, [](const Point<2> &p) { return p[0]; }, two_stages);
      deallog << "stable step / (Omega / 2 h / c_s): "
              << step.stable_step() / (omega_tau / 2 * h / c) << "; refused: "
              << (step.refusal().empty() ? "no" : step.refusal()) << std::endl;

      // the standing wave
      BodyState          state = mode_at_rest(block, lambda_h);
      const BodyState    start = state;
      const double       tau   = 0.9 * h / c;
      const unsigned int n     = 36;
      double             t     = 0;
      // the scheme on the oscillator: a central-difference stage from
      // (u, v, a) over dt with the base velocity w and the mass's
      // coefficient kappa (models::ExplicitStep's class comment)
      using Mode3 = std::array<double, 3>;
      const auto stage =
        [&](const Mode3 &m, double dt, double w, double kappa) {
          const double u = m[0] + dt * m[1] + dt * dt / 2 * m[2];
          const double v = (kappa * w - lambda_h * u) / kappa;
          return Mode3{{u, v, kappa * (v - w)}};
        };
      Mode3 mode{{1., 0., -lambda_h}};
      for (unsigned int i = 0; i < n; ++i, t += tau)
        {
          state = *step(state, t, tau);
          if (!two_stages)
            mode = stage(mode, tau, mode[1] + tau / 2 * mode[2], 2 / tau);
          else
            {
              const double p = 0.54, q1 = (1 - 2 * p) / (2 * p * (1 - p)),
                           q2 = 0.5 - p * q1, q0 = 0.5 - q1 - q2;
              const double t1 = p * tau, t2 = (1 - p) * tau;
              const Mode3  m1 =
                stage(mode, t1, mode[1] + t1 / 2 * mode[2], 2 / t1);
              mode = stage(m1,
                           t2,
                           m1[1] + t2 * (q0 * mode[2] + (0.5 + q1) * m1[2]),
                           1 / (t2 * q2));
            }
        }
      la::Vector expect = start.u;
      expect *= mode[0];
      expect -= state.u;
      if (!two_stages)
        {
          const double theta = std::acos(1 - tau * tau * lambda_h / 2);
          AssertThrow(std::abs(mode[0] - std::cos(n * theta)) < 1e-12,
                      ExcInternalError());
        }
      const unsigned int origin = origin_dof(d);
      deallog << "standing wave after " << n << " steps of " << tau
              << " s: the discrete closed form at every dof: "
              << (max_abs(expect) < 1e-10 ? "yes" : "no")
              << "; u(0, t) - cos(c k t) = " << std::setprecision(2)
              << state.u(origin) - std::cos(c * k * t) << std::setprecision(6)
              << std::endl;

      // stability at and above the limit
      for (const auto &[fraction, steps] :
           {std::pair{0.99, 2000u}, std::pair{1.01, 200u}})
        {
          BodyState rough = start;
          rough.v         = 0;
          rough.a         = 0;
          for (unsigned int i = 0; i < rough.u.locally_owned_size(); ++i)
            rough.u.local_element(i) =
              d.fixed[i] ? 0. : ((i * 7919) % 101) / 101. - 0.5;
          const double first = max_abs(rough.u);
          double       most  = first;
          const double dt    = fraction * step.stable_step();
          for (unsigned int i = 0; i < steps; ++i)
            {
              rough = *step(rough, i * dt, dt);
              most  = std::max(most, max_abs(rough.u));
            }
          deallog << fraction << " x the stable step, " << steps
                  << " steps: max |u| / start "
                  << (fraction < 1 ? "below 20: " : "above 1e6: ")
                  << ((fraction < 1 ? most < 20 * first : most > 1e6 * first) ?
                        "yes" :
                        "no")
                  << std::endl;
        }
    }

  // the sponge: C = alpha M, so the mode follows u'' + alpha u' + lambda_h
  // u = 0 (Noh and Bathe)
  Block damped_scene;
  damped_scene.sponge = 20;
  const Assembled    damped(mesh, damped_scene);
  const auto         step  = noh_bathe(damped, *law);
  BodyState          state = mode_at_rest(damped, lambda_h);
  const BodyState    start = state;
  const double       tau   = 0.9 * h / c;
  const unsigned int n     = 100;
  for (unsigned int i = 0; i < n; ++i)
    state = *(*step)(state, i * tau, tau);
  const double t = n * tau, alpha = damped_scene.sponge,
               omega = std::sqrt(lambda_h - alpha * alpha / 4);
  const double exact =
    std::exp(-alpha * t / 2) *
    (std::cos(omega * t) + alpha / (2 * omega) * std::sin(omega * t));
  const double u0    = state.u(origin_dof(damped.d));
  la::Vector   shape = start.u;
  shape *= u0;
  shape -= state.u;
  deallog << "sponge damping " << alpha << "/s, " << n << " steps of " << tau
          << " s: the mode keeps its shape: "
          << (max_abs(shape) < 1e-10 ? "yes" : "no")
          << "; u(0, t) against the damped oscillator's "
          << std::setprecision(4) << exact
          << " within 1e-3: " << (std::abs(u0 - exact) < 1e-3 ? "yes" : "no")
          << std::endl;

  // the sponge across hanging nodes
  MeshParameters refined    = mesh;
  refined.local_refinements = 1;
  const Assembled        hanging(refined, damped_scene);
  const auto             hanging_step = noh_bathe(hanging, *law);
  const la::LocalMatrix &C            = hanging.d.viscosity_local;
  double                 trace        = 0;
  bool                   diagonal     = true;
  for (unsigned int i = 0; i < C.m(); ++i)
    if (!hanging.d.hanging_constraints.is_constrained(
          hanging.d.partitioner->local_to_global(i)))
      for (unsigned int j = C.row_begin(i); j < C.row_end(i); ++j)
        if (C.column(j) == i)
          trace += C.value(j);
        else if (C.value(j) != 0)
          diagonal = false;
  deallog << "sponge across hanging nodes ("
          << hanging.d.hanging_constraints.n_constraints()
          << " constraints): C diagonal: " << (diagonal ? "yes" : "no")
          << "; explicit step refused: "
          << (hanging_step->refusal().empty() ? "no" : "yes")
          << "; trace of C / (alpha rho |body|) = 1: "
          << (std::abs(trace / (alpha * 1000 * 0.25) - 1) < 1e-12 ? "yes" :
                                                                    "no")
          << std::endl;
}
