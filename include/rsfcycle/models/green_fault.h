// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_models_green_fault_h
#define rsfcycle_models_green_fault_h

#include <array>
#include <cstdint>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <rsfcycle/models/continuum.h>
#include <rsfcycle/output/writer.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/physics/body_state.h>
#include <rsfcycle/physics/contact_quadrature.h>
#include <rsfcycle/physics/discretisation.h>
#include <rsfcycle/physics/global_system.h>
#include <rsfcycle/physics/green_operator.h>
#include <rsfcycle/physics/interior_solver.h>
#include <rsfcycle/physics/scene.h>
#include <rsfcycle/physics/static_solver.h>
#include <rsfcycle/solvers/fault_solver.h>
#include <rsfcycle/solvers/step_statistics.h>
#include <rsfcycle/time/implicit_model.h>
#include <rsfcycle/time/model.h>
#include <rsfcycle/time/ode_model.h>
#include <rsfcycle/time/time_scheme.h>
#include <string>
#include <vector>

namespace rsfcycle
{
  namespace models
  {
    using namespace dealii;

    /**
     * The fault's state: slip and slip rate of every contact dof (the
     * tangential dofs of the contact nodes: one per node in 2D, two in 3D
     * but on free-slip walls, a node's together), the state of every
     * contact node.
     */
    struct FaultState
    {
      std::vector<double> slip;  // s [m], per dof
      std::vector<double> alpha; // log(theta V* / L) [-], per node
      std::vector<double> rate;  // V = ds/dt [m/s], per dof, the balance's
      double              t = 0; // [s]
      /**
       * The solver counts of the implicit step that made this state (the
       * fault solver's iterations and CG products as TNNMG's and the linear
       * ones; statistics, not in checkpoints; zero otherwise).
       */
      solvers::StepStatistics statistics;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &slip &alpha &rate &t;
      }
    };

    /**
     * `Solver/Bulk = green-function` (doc/model.md §8.1): the quasi-dynamic
     * continuum with a linear elastic bulk reduced to its fault. The mesh,
     * the matrices and the contact quadrature are the volume path's
     * (physics::Discretisation, physics::ContactQuadrature); the bulk's
     * response is computed once (physics::GreenOperator: F = g0 + t g1 -
     * S s, the observation points o0 + t o1 + O s), and the run is the ODE
     * in (s, alpha) of every contact node k:
     *   F_k(s, t) - c_k V_k = N_k mu(|V_k|, alpha_k) sign V_k,
     *   ds_k/dt = V_k,  d alpha_k/dt = the state law's rate,
     * with c_k = eta_k w_k the radiation damping and N_k = w_k |sigma_n|
     * the normal force of the node (the same lumped weights as the volume
     * path). Every right-hand side applies S (a dense or H-matrix
     * product) and solves the balance for V_k node by node (a safeguarded
     * Newton in log |V|, the friction::Law of `Solver/State law`). On N
     * ranks every rank holds the state of all nodes and the rows of S of
     * its own; the rates are gathered after each right-hand side, so
     * ARKODE takes the same steps on every rank. The
     * simulator integrates it with `Time stepping/Integrator =
     * runge-kutta`, or with `implicit`: the volume path's implicit step
     * (`Solver/Theta`, the rate/state fixed point, the step-size control)
     * with its spatial problem on the fault's nodes only
     * (solvers::FaultSolver, green_fault_step.cc). It writes the same files
     * as the volume path, the VTU snapshots from a static solve of the body
     * at each output time.
     */
    template <int dim>
    class GreenFault : public Continuum<dim>,
                       public time::Model<FaultState>,
                       public time::OdeModel<FaultState>,
                       public time::ImplicitModel<FaultState>
    {
    public:
      using State = FaultState;

      /**
       * What the method cannot represent in this scene, refused in one
       * line naming the entry before anything is written: a normal stress
       * from gravity (it changes with slip), viscous materials, a load
       * that is not constant in time, cohesion.
       */
      static void
      check(const Parameters &parameters, const physics::Scene<dim> &scene);

      GreenFault(const Parameters          &parameters,
                 const physics::Scene<dim> &scene,
                 std::ostream              &log);

      /**
       * Mesh, matrices, contact, the operator, the initial state. The
       * operator is read from the run folder's green-operator.bin on
       * `resume`, else from `Solver/Green operator file` if it names one,
       * else computed; a file that does not fit is refused
       * (std::invalid_argument, one line). Nothing is written.
       */
      void
      setup(bool resume = false);

      /**
       * The run (or its resume), after setup() (called here if it was
       * not): writes parameters.prm and, unless it was read from there,
       * the operator to the run folder's green-operator.bin. False if
       * interrupted.
       */
      bool
      run(const ParameterHandler &prm, bool resume = false);

      const physics::GreenOperator &
      green_operator() const
      {
        return op;
      }

      const physics::ContactQuadrature<dim> &
      contact_quadrature() const
      {
        return contact;
      }

      /** The mesh, dofs and matrices of the body (body()'s numbering). */
      const physics::Discretisation<dim> &
      body_discretisation() const
      {
        return discretisation;
      }

      /**
       * The slip rate of node k at the force F, state alpha and normal
       * force N (NaN if N <= 0).
       */
      double
      slip_rate(unsigned int k, double force, double alpha, double N) const;

      /**
       * The normal force of node k at time t [N/m^(3-dim)]: w_k (|sigma_n|
       * - p(x_k, t)) with a pore pressure, else constant.
       */
      double
      normal_force(unsigned int k, double t) const;

      /**
       * The normal force of every node of this rank at the slip s (of all
       * dofs) and time t: normal_force(k, t) plus, with a split fault's
       * normal coupling, the slip's change n0 + t n1 + N s
       * (physics::GreenOperator; BP3's Delta sigma_n times w_k). A
       * reference to a buffer that the next call overwrites.
       */
      const std::vector<double> &
      normal_forces(const double *s, double t) const;

      /** @name The time::Model interface */
      /** @{ */
      State
      initial_state() const override
      {
        return initial;
      }
      output::Layout
      layout() const override;
      output::Sample
      sample(const State &state) const override;
      output::CheckpointIdentity
      checkpoint_identity() const override;
      void
      describe(std::ostream &log) const override;
      /**
       * The body for the snapshots of `Output/Writers` (vtu, hdf5): its
       * displacement and velocity at each output time from one static
       * solve each with the contact held at the slip and the slip rate
       * (body()).
       */
      output::Offer
      offer() override;
      /** @} */

      /**
       * The whole body at a state: u and v of the static equilibrium with
       * the contact's tangential dofs at the slip and the slip rate (a
       * split fault: the jump between its sides) and the load boundaries
       * at V t and V, and per node of this rank the friction state, the
       * slip, the slip rate and the traction (the normal stress too where
       * it changes).
       */
      BodyState
      body(const State &state) const;

      /** @name The time::OdeModel interface */
      /** @{ */
      Vector
      to_ode(const State &state) const override;
      State
      from_ode(const Vector &y, double t) const override;
      int
      ode_rhs(double t, const Vector &y, Vector &dy) const override;
      /** rtol L_k for the slip, rtol for alpha. */
      Vector
      ode_absolute_tolerances(double relative) const override;
      std::string
      stiff_alternative() const override
      {
        return "Time stepping/Integrator = implicit (the implicit step on "
               "the fault, with this operator) or Solver/Bulk = volume";
      }
      /** Not used by runge-kutta (every step is a sample). */
      double
      sample_interval(const State &) const override
      {
        return parameters.time_stepping.maximum_step;
      }
      /** @} */

      /** @name The time::ImplicitModel interface (green_fault_step.cc) */
      /** @{ */
      /**
       * The implicit step of `Solver/Time scheme` on the fault: for the
       * slip rates w = V_{n+1} (theta scheme) the balance
       *   g0 + t* g1 - S (s_n + tau (1 - theta) V_n + theta tau w) - D w
       *     = N mu(w, alpha)
       * is the minimum of the convex fault problem with A = theta tau S +
       * D (solvers::FaultSolver, `Solver/TNNMG tolerance`), inside the
       * rate/state fixed point (`Solver/Coupling`).
       */
      std::optional<State>
      step(const State &old, double t, double tau, const State *guess) override;
      /** The state distance (14), or the largest (`Error norm`). */
      double
      error_distance(const State &s1, const State &s2) const override;
      State
      predict(const std::array<const State *, 3> &states,
              const std::array<double, 3>        &weights) const override;
      double
      error_order() const override
      {
        return scheme->local_error_order();
      }
      /** @} */

    private:
      /**
       * The state distance (14), or the largest difference at a node, of
       * two states of all nodes (collective: ContactQuadrature's over this
       * rank's nodes).
       */
      double
      state_distance(const std::vector<double> &alpha1,
                     const std::vector<double> &alpha2,
                     bool                       largest = false) const;

      /**
       * values[offsets[r] ... offsets[r] + counts[r]) from rank r, on every
       * rank (nothing to do on one): per dof, or per node (`nodes`).
       */
      void
      gather_in_place(double *values, bool nodes = false) const;

      /**
       * The slip rates of all nodes at the slip s and time t (and, if
       * `alpha_rate` is given, the state rates); throws
       * std::runtime_error, on every rank, if the pore pressure leaves a
       * node without compression.
       */
      void
      slip_rates(const double *s,
                 const double *alpha,
                 double        t,
                 double       *V,
                 double       *alpha_rate = nullptr) const;

      /**
       * After non-finite rates at t: throw time::CompressionLost, naming
       * the place, if a pore pressure left a node without compression
       * (every rank finds the same node: the positions and stresses of all
       * nodes are kept).
       */
      void
      check_compression(double t) const;

      using Continuum<dim>::parameters;
      using Continuum<dim>::scene;
      using Continuum<dim>::log;
      using Continuum<dim>::timer;
      using Continuum<dim>::discretisation;
      using Continuum<dim>::contact;
      MPI_Comm communicator;
      /**
       * Per rank: its number of contact dofs and the first of them in the
       * state (the dofs of all ranks on every rank, rank by rank; a rank
       * computes its own, from GreenOperator::first_row on, and gathers
       * the others'); the same for the nodes (the state alpha).
       */
      std::vector<int> counts, offsets, node_counts, node_offsets;
      /** This rank's first node in the state (first dof: op.first_row). */
      unsigned int first_node = 0;
      /**
       * Per own node: its first dof among this rank's dofs (one more
       * entry: the number of own dofs).
       */
      std::vector<unsigned int> dof_start;
      physics::GreenOperator    op;
      double                    setup_seconds = 0;
      bool                      is_set_up     = false;
      /** The file the operator was read from; empty if computed. */
      std::string   operator_source;
      std::uint32_t fingerprint = 0;
      /** The H-matrix product's relative error on two test slips. */
      double compression_error = 0;
      /**
       * The H-matrices of S on all ranks together: their numbers as a
       * fraction of S's n_c^2, their low-rank and dense blocks.
       */
      double      compressed_fraction = 0;
      std::size_t low_rank_blocks = 0, dense_blocks = 0;
      /** The memory of S during the run, the largest over the ranks [MB]. */
      double operator_megabytes = 0;
      /** Per own node: radiation damping eta w [N s/m^dim]. */
      std::vector<double> damping;
      /**
       * The scene's shear stress perturbation: its spatial part as nodal
       * forces w_k Delta tau(x_k) e on this rank's dofs (zero without it)
       * and the factor g(t) (empty: none).
       */
      std::vector<double>           perturbation_forces;
      std::function<double(double)> perturbation_history;
      /** g(t) of the shear stress perturbation (0 without it). */
      double
      perturbation_factor(const double t) const
      {
        return perturbation_history ? perturbation_history(t) : 0.;
      }
      /** The scene's pore pressure and Darcy velocity (empty: none). */
      std::function<double(const Point<dim> &, double)> pore_pressure;
      std::function<std::array<double, 2>(const Point<dim> &, double)>
        darcy_velocity;
      /**
       * With a pore pressure: every node's position and |sigma_n| (all
       * ranks' nodes, for check_compression()).
       */
      std::vector<Point<dim>> all_positions;
      std::vector<double>     all_normal_stresses;
      /** The static solves of body() (made at its first call). */
      mutable std::unique_ptr<physics::StaticSolver<dim>> static_solver;
      /**
       * A split fault's body: the tied system and the factor of its
       * interior block (made at body()'s first call).
       */
      struct SplitBody
      {
        physics::GlobalSystem                    system;
        std::unique_ptr<physics::InteriorSolver> solver;
      };
      mutable std::unique_ptr<SplitBody> split_body;
      /**
       * body() of a split fault: u and v of the tied system's equilibrium
       * with the slip (rate) between the two sides, the load boundaries at
       * V t (V), untied (physics/split_fault.h).
       */
      void
                     split_body_fields(const State &state, BodyState &b) const;
      State          initial;
      mutable Vector force_work;
      /** normal_forces()'s buffers: per own node, per own dof. */
      mutable std::vector<double> normal_work, normal_change;
      /** The implicit step's scheme and fault solver. */
      std::unique_ptr<const time::TimeScheme> scheme;
      solvers::FaultSolver                    fault_solver;
      /** S_kk of this rank's nodes (taken before compression). */
      std::vector<double> S_diagonal;
    };
  } // namespace models
} // namespace rsfcycle

#endif
