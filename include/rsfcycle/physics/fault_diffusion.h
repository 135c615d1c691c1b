// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_physics_fault_diffusion_h
#define rsfcycle_physics_fault_diffusion_h

#include <array>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deque>
#include <limits>
#include <map>
#include <vector>

namespace rsfcycle
{
  namespace physics
  {
    using namespace dealii;

    /**
     * The pore fluid in the fault zone and its injection (doc/model.md §9).
     * The defaults are SEAS BP8's. In the line (plane_dim = 1) the
     * injection rate is per unit length across the line [m^2/s]; in the
     * plane it is a volume rate [m^3/s].
     */
    struct FaultDiffusionParameters
    {
      /** How the fluid enters the fault zone. */
      enum class Source
      {
        /** Q(t) w(x), w the normalised Gaussian of width L_inj. */
        gaussian,
        /** Q(t) into the node at the origin (BP6's injection). */
        point,
        /** A Peaceman well at the origin with storage (plane only). */
        well
      };
      /** The condition on the boundary of the fluid domain. */
      enum class Boundary
      {
        /** No flux across it (SEAS). */
        no_flux,
        /** p = 0 on it (a far field at the initial pressure). */
        fixed_pressure
      };

      Source   source   = Source::gaussian;
      Boundary boundary = Boundary::no_flux;
      /** Q0 [m^3/s in the plane, m^2/s in the line]. */
      double injection_rate = 0.003;
      /** t_off [s]: Q(t) = Q0 for 0 <= t < t_off, 0 after; may be inf. */
      double shut_in_time = 100 * 3600.;
      /** beta [1/Pa]. */
      double compressibility = 1e-8;
      /** phi [-]. */
      double porosity = 0.1;
      /** k [m^2]. */
      double permeability = 5e-14;
      /** eta [Pa s]. */
      double viscosity = 1e-3;
      /** L, the thickness of the fault zone the fluid flows in [m]. */
      double thickness = 1.;
      /** L_inj, the Gaussian source's standard deviation [m]. */
      double injection_width = 50.;
      /** r_w [m]. */
      double well_radius = 0.05;
      /** S_well [m^3/Pa], > 0. */
      double well_storage = 1e-7;
      /** l: the fluid domain is [-l, l]^plane_dim [m]. */
      double half_width = 400.;
      /** h, the uniform cell size [m]; 2 l / h must be an integer. */
      double cell_size = 10.;
      /**
       * The largest internal time step [s]; the step used is the largest
       * t_off / N not above it, so that the steps hit t_off.
       */
      double time_step = 600.;
      /** M: a snapshot of the solution every M internal steps. */
      unsigned int snapshot_interval = 32;

      /** alpha = k / (phi beta eta) [m^2/s]. */
      double
      diffusivity() const
      {
        return permeability / (porosity * compressibility * viscosity);
      }
      /** Q(t) [m^3/s or m^2/s]. */
      double
      rate(const double t) const
      {
        return (t >= 0 && t < shut_in_time) ? injection_rate : 0.;
      }
    };

    /**
     * The pore pressure p [Pa] (the change from the initial pressure) in a
     * fault zone of thickness L, on its own mesh of the fluid domain
     * [-l, l]^plane_dim (plane_dim = 1: a line, SEAS BP6; 2: a square,
     * SEAS BP8):
     *
     *   beta phi L dp/dt = (k L / eta) lap p + Q(t) w(x)   in the domain,
     *   grad p . n = 0 (or p = 0) on its boundary,  p(x, 0) = 0,
     *
     * alpha = k / (phi beta eta) the diffusivity. Three sources:
     *  - gaussian: w(x) = exp(-r^2 / (2 L_inj^2)) / (2 pi L_inj^2) in the
     *    plane, exp(-x^2 / (2 L_inj^2)) / (sqrt(2 pi) L_inj) in the line,
     *    so that w integrates to 1 and the closed form below holds. (SEAS
     *    BP8's description writes the Gaussian without 1/(2 pi); that
     *    source integrates to 2 pi and contradicts the description's own
     *    closed form, which is the one below.)
     *  - point: Q(t) enters at the node at the origin.
     *  - well: a Peaceman well at the origin, one more unknown p_w,
     *      S_well dp_w/dt = Q(t) - q,  q = WI (p_w - p_h(0)),
     *      WI = 2 pi k L / (eta ln(r_e / r_w)),  r_e = c_Q1 h,
     *    q entering the plane at the node at the origin. c_Q1 = 0.1146
     *    (peaceman_factor): the distance at which the analytic pressure of
     *    a point source, (q eta / (2 pi k L)) ln(R / r), equals the
     *    steady discrete (Q1) solution at the source's node, found from
     *    the discrete solution far from the node (doc/model.md §9).
     *
     * Closed form of the Gaussian source, constant rate Q0 from t = 0, in
     * the infinite plane (v0 = L_inj^2, v(t) = L_inj^2 + 2 alpha t,
     * E1 the exponential integral):
     *
     *   P(r, t) = Q0 eta / (4 pi k L) [E1(r^2 / (2 v(t))) - E1(r^2 / (2 v0))],
     *   P(0, t) = Q0 eta / (4 pi k L) ln(v(t) / v0),
     *   q(r, t) = Q0 / (2 pi L r) [exp(-r^2 / (2 v(t))) - exp(-r^2 / (2 v0))]
     *
     * (q radial, outward), and in the infinite line, with
     * F(v) = sqrt(2 v / pi) exp(-x^2 / (2 v)) - |x| erfc(|x| / sqrt(2 v)),
     *
     *   P(x, t) = Q0 eta / (2 k L) [F(v(t)) - F(v0)],
     *   q(x, t) = sign(x) Q0 / (2 L) [erfc(|x| / sqrt(2 v(t)))
     *                                 - erfc(|x| / sqrt(2 v0))]
     *
     * (L_inj -> 0 gives BP6's closed form, Q0 / L its injected flux). With
     * the shut-in, p(x, t) = P(x, t) - P(x, t - t_off) for t > t_off, which
     * in the plane is Q0 eta / (4 pi k L) [E1(r^2 / (2 v(t))) -
     * E1(r^2 / (2 v(t - t_off)))]. gaussian_injection_pressure() and
     * gaussian_injection_darcy_velocity() evaluate them.
     *
     * Discretisation: Q1 elements on the uniform mesh of cell size h; the
     * mass lumped (the vertex quadrature), so that the storage is diagonal
     * and the well's unknown couples to the one node, and the matrix of a
     * step, M + c dt K, is an M-matrix at any step (Q1's off-diagonal
     * stiffness on squares is negative, the lumped mass adds to the
     * diagonal only), where the consistent mass's positive off-diagonal
     * entries make the pressure undershoot ahead of the front at short
     * steps. In time, TR-BDF2 (the trapezoidal rule to t + gamma dt, then
     * BDF2; gamma = 2 - sqrt(2)) with a fixed step dt that hits t_off:
     * second order, one step (a snapshot is one state), L-stable (a stiff
     * component, the well's with a small S_well or the mesh's shortest
     * waves with dt >> h^2 / alpha, is damped in one step, where
     * Crank-Nicolson carries it along with the factor -1, and the source's
     * kinks at 0 and t_off need no special start), and with this gamma
     * both stages have the one matrix M + c dt K, c = 1 - 1/sqrt(2),
     * factorised once (UMFPACK): two solves per step. The source is
     * constant over every step, so the injected volume is exact:
     * sum_i beta phi L m_i p_i (+ S_well p_w) = Q0 min(t, t_off) to
     * rounding with no flux.
     *
     * Questions at any time t >= 0, in any order: the part keeps the state
     * every M internal steps (snapshots) and every state since the
     * last-but-one snapshot (the window); a time before the window is
     * recomputed from the nearest snapshot before it, at most M steps. A
     * time between two internal states is interpolated linearly (second
     * order, as the scheme). The answers are a function of t alone, bit for
     * bit, whatever was asked before. Not thread-safe (the state is cached).
     *
     * The pressure at a point is the Q1 interpolant; the Darcy velocity
     * -(k / eta) grad p that of the nodal gradient recovered by the lumped
     * L2 projection (second order at the nodes of the uniform mesh, where
     * the elementwise gradient jumps), with the boundary condition's
     * components on the boundary.
     *
     * Use: a model holds one FaultDiffusion (every MPI rank its own copy,
     * the answers the same on all), maps each contact node into the fluid
     * domain's coordinates and asks value() (and darcy_velocity()) at every
     * time its integrator tries. The first question at a new t advances
     * the internal steps up to t (two solves with the factor each)
     * or, behind the window, recomputes up to M of them, and interpolates
     * the state, O(n_nodes); every further point at the same t is O(1)
     * (the first Darcy velocity at t adds two sparse products). Memory:
     * the mesh, five sparse matrices and the factor, up to 2M + 1 states in the
     * window and one per M steps in the snapshots (BP8 at 10 m: 6561
     * nodes, 30 days of 600 s steps, M = 32: about 13 MB and the factor).
     */
    template <int plane_dim>
    class FaultDiffusion
    {
    public:
      /** r_e / h of the Peaceman well for Q1 elements on squares. */
      static constexpr double peaceman_factor = 0.1146;

      /**
       * Makes the mesh and the matrices and factorises the step matrix.
       * Throws std::invalid_argument for parameters that do not fit: 2 l / h
       * not an integer (or not even, for a source at the origin's node), a
       * well in the line, non-positive coefficients.
       */
      explicit FaultDiffusion(const FaultDiffusionParameters &parameters);

      /**
       * p(x, t) [Pa], x in the fluid domain (std::domain_error outside),
       * t >= 0 (std::domain_error before).
       */
      double
      value(const Point<plane_dim> &x, double t) const;

      /** The Darcy velocity -(k / eta) grad p at x and t [m/s]. */
      Tensor<1, plane_dim>
      darcy_velocity(const Point<plane_dim> &x, double t) const;

      /** The pressure in the well p_w at t [Pa] (source = well only). */
      double
      well_pressure(double t) const;

      /** The fluid stored at t: sum_i beta phi L m_i p_i + S_well p_w. */
      double
      stored_volume(double t) const;

      /** Whether x lies in the fluid domain [-l, l]^plane_dim. */
      bool
      contains(const Point<plane_dim> &x) const;

      /** The internal time step used [s]. */
      double
      time_step() const
      {
        return dt;
      }

      /** WI [m^3/(Pa s)] (source = well). */
      double
      well_index() const
      {
        return index_of_well;
      }

      /** The nodes of the mesh. */
      unsigned int
      n_nodes() const
      {
        return dof_handler.n_dofs();
      }

      /** The internal steps computed so far (recomputed ones included). */
      unsigned long
      n_steps_computed() const
      {
        return steps_computed;
      }

      /** The memory the part holds now [bytes]. */
      std::size_t
      memory_consumption() const;

    private:
      /** A stored internal state y = (p, p_w) at the end of step `step`. */
      struct Node
      {
        unsigned int   step;
        double         t;
        Vector<double> y;
      };

      void
      make_grid();
      void
      setup_system();
      void
      assemble_system();
      void
      assemble_source();
      void
      factorise();

      /** Makes the window reach t; the interpolated state at t. */
      const Vector<double> &
      state_at(double t) const;
      /** Restarts the window from the last snapshot at or before `step`. */
      void
      restart_window(unsigned int step) const;
      /** One internal step from the window's last state. */
      void
      advance() const;
      /** The nodal gradient of the state y into cached_gradient. */
      void
      recover_gradient(const Vector<double> &y) const;
      /** The Q1 interpolant of nodal values at x. */
      double
      interpolate(const Vector<double> &nodal, const Point<plane_dim> &x) const;
      void
      check_point(const Point<plane_dim> &x, double t) const;

      const FaultDiffusionParameters parameters;
      Triangulation<plane_dim>       triangulation;
      const FE_Q<plane_dim>          fe;
      DoFHandler<plane_dim>          dof_handler;
      /** Cells per direction. */
      unsigned int n_cells = 0;
      /** The dof of each vertex, lexicographic (x first). */
      std::vector<types::global_dof_index> node_dof;
      /** The dof at the origin (point and well sources). */
      types::global_dof_index origin_dof = 0;
      /** p's dofs, and the well's unknown after them. */
      unsigned int n_unknowns    = 0;
      double       dt            = 0;
      double       index_of_well = 0;

      /** int phi_i (the lumped mass), per dof. */
      Vector<double> lumped_mass;
      /** The diagonal storage: beta phi L m_i, and S_well. */
      Vector<double> storage;
      /** Zero rows of the fixed-pressure boundary. */
      std::vector<bool> fixed;
      /** The source's shape: f with sum_i f_i = 1, Q(t) f enters. */
      Vector<double> source_shape;

      SparsityPattern      sparsity;
      SparsityPattern      gradient_sparsity;
      SparseMatrix<double> stiffness;
      /** M + d dt K and M - d dt K, d = 1 - 1/sqrt(2). */
      SparseMatrix<double> implicit_matrix, explicit_matrix;
      /** The lumped L2 projection of each component of the gradient. */
      std::array<SparseMatrix<double>, plane_dim> gradient;
      SparseDirectUMFPACK                         solver;

      mutable std::map<unsigned int, Vector<double>> snapshots;
      mutable std::deque<Node>                       window;
      mutable unsigned long                          steps_computed = 0;
      mutable double cached_time = std::numeric_limits<double>::quiet_NaN();
      mutable Vector<double> cached_state;
      mutable bool           cached_gradient_valid = false;
      mutable std::array<Vector<double>, plane_dim> cached_gradient;
    };

    /**
     * The closed form of the Gaussian source in the infinite plane
     * (plane_dim = 2) or line (1) (see FaultDiffusion), with the shut-in;
     * the domain, boundary and mesh parameters are not used.
     */
    template <int plane_dim>
    double
    gaussian_injection_pressure(const FaultDiffusionParameters &parameters,
                                const Point<plane_dim>         &x,
                                double                          t);

    /** Its Darcy velocity -(k / eta) grad p [m/s]. */
    template <int plane_dim>
    Tensor<1, plane_dim>
    gaussian_injection_darcy_velocity(
      const FaultDiffusionParameters &parameters,
      const Point<plane_dim>         &x,
      double                          t);
  } // namespace physics
} // namespace rsfcycle

#endif
