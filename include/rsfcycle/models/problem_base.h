// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_models_problem_base_h
#define rsfcycle_models_problem_base_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <memory>
#include <optional>
#include <ostream>
#include <rsfcycle/la.h>
#include <rsfcycle/models/continuum.h>
#include <rsfcycle/models/explicit_step.h>
#include <rsfcycle/models/implicit_step.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/physics/body_state.h>
#include <rsfcycle/physics/contact_quadrature.h>
#include <rsfcycle/physics/discretisation.h>
#include <rsfcycle/physics/scene.h>
#include <rsfcycle/solvers/tnnmg.h>
#include <rsfcycle/time/explicit_model.h>
#include <rsfcycle/time/implicit_model.h>
#include <rsfcycle/time/model.h>
#include <rsfcycle/time/time_scheme.h>
#include <vector>

namespace rsfcycle
{
  using namespace dealii;

  /**
   * The generic solver of doc/model.md §1-4 for one scene. It owns, each a
   * member of its own class:
   *  - the discretisation (physics/discretisation.h): the Triangulation
   *    refined toward the seismogenic patch, FE_Q(1)^dim, the matrices
   *    M, C, K and the gravity load, the Dirichlet dofs;
   *  - the boundary quadrature of the sinh^-1 dissipation
   *    (physics/contact_quadrature.h): contact nodes, lumped weights,
   *    normal stress, the state distance (14);
   *  - TNNMG with its linear correction (solvers/), for `multigrid` the
   *    geometric MGTransfer hierarchy of the locally refined mesh;
   *  - the implicit step of `Solver/Time scheme` with the rate/state
   *    coupling (models/implicit_step.h);
   *  - the ParameterHandler-driven time loop, through run(): it hands itself
   *    to the Simulator (simulator/simulator.h), which builds the
   *    integrator and the writers of `Output/Writers` (the snapshots of
   *    output/snapshots.h from the body that offer() gives) from the
   *    parameters.
   * To the simulator it is a time::Model of BodyState whose steps are
   * implicit (time::ImplicitModel).
   */
  template <int dim>
  class ProblemBase : public models::Continuum<dim>,
                      public time::Model<BodyState>,
                      public time::ImplicitModel<BodyState>,
                      public time::ExplicitModel<BodyState>
  {
  public:
    using NodeInfo = typename physics::ContactQuadrature<dim>::NodeInfo;

    ProblemBase(const Parameters          &parameters,
                const physics::Scene<dim> &scene,
                std::ostream              &log);

    /** Mesh, dofs, matrices, normal stress, initial state, solvers. */
    void
    setup();

    /**
     * setup() and the whole time loop with output; with `resume`, continue
     * from the checkpoint in the run folder, appending to its files. Returns
     * false if the run was stopped by SIGINT/SIGTERM (a checkpoint was
     * written), true when it ended normally.
     */
    bool
    run(const ParameterHandler &prm, bool resume = false);

    /** The state distance (14) between two states. */
    double
    state_distance(const std::vector<double> &alpha1,
                   const std::vector<double> &alpha2) const
    {
      return contact.state_distance(alpha1, alpha2);
    }

    /**
     * The distance of two states in the time step's error estimate
     * (`Time stepping/Error norm`): (14), or the largest difference at a
     * contact node.
     */
    double
    error_distance(const std::vector<double> &alpha1,
                   const std::vector<double> &alpha2) const
    {
      return parameters.time_stepping.error_norm ==
                 TimeSteppingParameters::ErrorNorm::max ?
               contact.state_max_distance(alpha1, alpha2) :
               contact.state_distance(alpha1, alpha2);
    }

    /** Slip rate |v_T| of every contact node. */
    std::vector<double>
    slip_rates(const la::Vector &v) const;

    /**
     * Mechanical energy 1/2 v^T M v + 1/2 u^T K u - f^T u (kinetic, elastic,
     * and the potential of the body force f).
     */
    double
    energy(const BodyState &state) const;

    /** Physical vertical displacement at the scene's observation points. */
    std::vector<double>
    observed_uplift(const la::Vector &u) const;

    const std::vector<NodeInfo> &
    contact_nodes() const
    {
      return contact.nodes();
    }

    const Triangulation<dim> &
    triangulation() const
    {
      return discretisation.triangulation;
    }

    const DoFHandler<dim> &
    dofs() const
    {
      return discretisation.dof_handler;
    }

    /** @name The time::Model interface */
    /** @{ */
    BodyState
    initial_state() const override
    {
      return initial;
    }
    output::Layout
    layout() const override;
    output::Sample
    sample(const BodyState &state) const override;
    output::CheckpointIdentity
    checkpoint_identity() const override;
    /** The scene, mesh and solver lines of the log (read by test digests). */
    void
    describe(std::ostream &log) const override;
    /** The body for the snapshots of `Output/Writers` (vtu, hdf5). */
    output::Offer
    offer() override;
    solvers::StepStatistics
    take_work() override;
    std::string
    last_failure() const override;
    void
    step_accepted() override;
    /** @} */

    /** @name The time::ImplicitModel interface */
    /** @{ */
    /**
     * One implicit step of length tau from state `old` at time t, its
     * iterations started from `guess` if given; no value if the spatial
     * problem failed (no convergence, non-finite values).
     */
    std::optional<BodyState>
    step(const BodyState &old,
         double           t,
         double           tau,
         const BodyState *guess = nullptr) override;
    double
    error_distance(const BodyState &s1, const BodyState &s2) const override
    {
      return error_distance(s1.alpha, s2.alpha);
    }
    /** The velocity and the friction state (what a guess needs). */
    BodyState
    predict(const std::array<const BodyState *, 3> &states,
            const std::array<double, 3>            &weights) const override;
    double
    error_order() const override
    {
      return scheme->local_error_order();
    }
    /** @} */

    /** @name The time::ExplicitModel interface (Dynamics = dynamic) */
    /** @{ */
    double
    stable_step() const override;
    std::optional<BodyState>
    explicit_step(const BodyState &old, double t, double tau) override;
    std::string
    explicit_refusal() const override;
    void
    limit_fixed_point_iterations(const unsigned int n) override
    {
      implicit_step->limit_fixed_point_iterations(n);
    }
    /** @} */

  private:
    void
    setup_system();
    void
    setup_linear_correction();
    void
    setup_observation_points();
    void
    compute_initial_state();

    using models::Continuum<dim>::parameters;
    using models::Continuum<dim>::scene;
    using models::Continuum<dim>::log;
    using models::Continuum<dim>::timer;
    using models::Continuum<dim>::discretisation;
    using models::Continuum<dim>::contact;

    std::unique_ptr<solvers::LinearCorrection> linear_correction;
    /** Solver/Direct fallback: the direct correction, else null. */
    std::unique_ptr<solvers::LinearCorrection> fallback_correction;
    std::unique_ptr<solvers::TNNMG>            tnnmg;
    /** The time scheme of the implicit step (`Solver/Time scheme`). */
    const std::unique_ptr<const time::TimeScheme> scheme;
    std::unique_ptr<models::ImplicitStep<dim>>    implicit_step;
    /** The explicit step (Dynamics = dynamic only, else null). */
    std::unique_ptr<models::ExplicitStep<dim>> explicit_stepper;
    /** Whether the last step taken was explicit (for last_failure()). */
    bool last_explicit = false;

    BodyState initial;
    /** Contact nodes with a tensile reaction in the gravity equilibrium. */
    unsigned int n_tensile_nodes = 0;

    /** Observation points: dof indices and weights of u . vertical. */
    /** Per observation point: (local index, weight) on the owning rank. */
    std::vector<std::vector<std::pair<types::global_dof_index, double>>>
      observation_weights;
    /** Per observation point: on how many ranks it was found. */
    std::vector<double> observation_ranks;
  };
} // namespace rsfcycle

#endif
