#ifndef rsfcycle_problem_base_h
#define rsfcycle_problem_base_h

#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <memory>
#include <optional>
#include <ostream>
#include <rsfcycle/friction/rate_state.h>
#include <rsfcycle/output/events.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/scenes/scene.h>
#include <rsfcycle/solvers/tnnmg.h>
#include <vector>

namespace rsfcycle
{
  using namespace dealii;

  /** Counts of the algebraic solver for one time step (one spatial problem). */
  struct StepStatistics
  {
    unsigned int fixed_point_iterations = 0;
    unsigned int tnnmg_iterations       = 0;
    unsigned int linear_iterations      = 0;
  };

  /**
   * The state of the body at one time: displacement, velocity, acceleration
   * (all dofs) and the friction state alpha = log(theta V* / L) per contact
   * node, with what the step that produced it cost.
   */
  struct BodyState
  {
    Vector<double>      u, v, a;
    std::vector<double> alpha;
    std::vector<double> shear_traction; // |friction force| / w per node [Pa]
    StepStatistics      statistics;

    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &u &v &a &alpha &shear_traction;
      ar &statistics.fixed_point_iterations &statistics
        .tnnmg_iterations                   &statistics.linear_iterations;
    }
  };

  /**
   * The generic solver of MODEL.md §1-4 for one scene: owns the locally
   * refined Triangulation, FE_Q(1)^dim, the mass, viscosity and stiffness
   * matrices (assembled once), the lumped contact quadrature and the normal
   * stress, and advances the body by Newmark steps (15) whose spatial
   * problems are solved by TNNMG inside the rate/state fixed-point
   * iteration (18). The time loop with step doubling, output and progress
   * is run().
   */
  template <int dim>
  class ProblemBase
  {
  public:
    ProblemBase(const Parameters         &parameters,
                const scenes::Scene<dim> &scene,
                std::ostream             &log);
    ~ProblemBase();

    /** Mesh, dofs, matrices, normal stress, initial state. */
    void
    setup();

    /**
     * setup() and the whole time loop with output; with `resume`, continue
     * from the checkpoint in the run folder, appending to its files. Returns
     * false if the run was stopped by SIGINT/SIGTERM (a checkpoint was
     * written), true when it reached the end time.
     */
    bool
    run(const ParameterHandler &prm, bool resume = false);

    /**
     * One Newmark step of length tau from state `old` at time t; no value
     * if the spatial problem failed (no convergence, non-finite values).
     */
    std::optional<BodyState>
    newmark_step(const BodyState &old, double t, double tau);

    /** The state distance (14) between two states. */
    double
    state_distance(const std::vector<double> &alpha1,
                   const std::vector<double> &alpha2) const;

    /** Slip rate |v_T| of every contact node. */
    std::vector<double>
    slip_rates(const Vector<double> &v) const;

    /** The initial state (gravity equilibrium, v = a = 0, alpha_0). */
    const BodyState &
    initial_state() const
    {
      return initial;
    }

    /**
     * Mechanical energy 1/2 v^T M v + 1/2 u^T K u - f^T u (kinetic, elastic,
     * and the potential of the body force f).
     */
    double
    energy(const BodyState &state) const;

    /** Physical vertical displacement at the scene's observation points. */
    std::vector<double>
    observed_uplift(const Vector<double> &u) const;

    /** Contact node k: position, lumped weight, normal force. */
    struct NodeInfo
    {
      Point<dim>              position;
      double                  weight       = 0;
      double                  normal_force = 0;
      friction::Parameters    params;
      types::global_dof_index scalar_dof = 0;
      types::global_dof_index normal_dof = 0;
    };

    const std::vector<NodeInfo> &
    contact_nodes() const
    {
      return node_info;
    }

    const Triangulation<dim> &
    triangulation() const
    {
      return tria;
    }

    const DoFHandler<dim> &
    dofs() const
    {
      return dof_handler;
    }

  private:
    /** What the time loop carries from step to step; a checkpoint. */
    struct RunState
    {
      explicit RunState(output::EventDetector events)
        : events(std::move(events))
      {}
      BodyState             state;
      double                t               = 0;
      double                tau             = 0;
      unsigned int          step            = 0;
      unsigned int          max_fixed_point = 0;
      unsigned long         total_problems  = 0;
      double                min_dt = 1e300, max_dt = 0;
      double                last_output = 0, last_profile = 0;
      output::EventDetector events;
      long long series_bytes = 0, profile_bytes = 0, catalogue_bytes = 0;
      bool      has_candidate = false; // the step controller's next step
      BodyState candidate;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &state &t &tau &step &max_fixed_point &total_problems &min_dt &max_dt
          &last_output &last_profile &events &series_bytes &profile_bytes
            &catalogue_bytes &has_candidate;
        if (has_candidate)
          ar &candidate;
      }
    };

    void
    write_checkpoint(const std::string &dir, const RunState &run_state) const;
    void
    read_checkpoint(const std::string &dir, RunState &run_state);

    /** Where the first non-finite velocity is (for diagnoses). */
    std::string
    first_non_finite(const Vector<double> &v) const;

    /** Iterations of all spatial problems since the last accepted step. */
    StepStatistics work;

    /** Why the last spatial problem failed (diagnosis on step underflow). */
    std::string last_failure;

    void
    make_grid();
    void
    setup_system();
    void
    assemble_matrices();
    template <class Iterator>
    void
    cell_matrices(const Iterator                    &cell,
                  FEValues<dim>                     &fe_values,
                  std::array<FullMatrix<double>, 3> &matrices,
                  Vector<double>                    &cell_force) const;
    void
    setup_linear_correction();
    void
    setup_contact();
    void
    compute_initial_state();
    void
    set_fixed_values(Vector<double> &v, double t) const;
    const SparseMatrix<double> &
    step_matrix(double tau);
    void
    output_results(const BodyState &state, double t);

    const Parameters         &parameters;
    const scenes::Scene<dim> &scene;
    std::ostream             &log;
    TimerOutput               timer;

    Triangulation<dim>        tria;
    FESystem<dim>             fe;
    DoFHandler<dim>           dof_handler;
    FE_Q<dim>                 scalar_fe;
    DoFHandler<dim>           scalar_dof_handler;
    AffineConstraints<double> hanging_constraints;
    AffineConstraints<double> scalar_constraints;

    SparsityPattern      sparsity_pattern;
    SparseMatrix<double> mass_matrix, viscosity_matrix, stiffness_matrix;
    Vector<double>       body_force;

    /** Dofs whose value is prescribed (Dirichlet, hanging nodes). */
    std::vector<bool> fixed;
    /** Backstop dofs with their component (inhomogeneous Dirichlet). */
    std::vector<std::pair<types::global_dof_index, unsigned int>> backstop_dofs;

    solvers::ContactSet   contact;
    std::vector<NodeInfo> node_info;
    double                contact_area = 0;
    friction::StateLaw    state_law;

    /** Step matrices for the last few step sizes (A depends on tau only). */
    std::vector<std::pair<double, std::unique_ptr<SparseMatrix<double>>>>
      step_matrices;

    std::unique_ptr<solvers::LinearCorrection> linear_correction;
    std::unique_ptr<solvers::TNNMG>            tnnmg;

    BodyState initial;

    /** Observation points: dof indices and weights of u . vertical. */
    std::vector<std::vector<std::pair<types::global_dof_index, double>>>
      observation_weights;

    std::vector<std::pair<double, std::string>> pvd_records;
    unsigned int                                n_snapshots = 0;
  };
} // namespace rsfcycle

#endif
