// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/multigrid/mg_tools.h>
#include <map>
#include <rsfcycle/format.h>
#include <rsfcycle/ids.h>
#include <rsfcycle/models/contact_layout.h>
#include <rsfcycle/models/continuum.h>
#include <rsfcycle/models/problem_base.h>
#include <rsfcycle/output/files.h>
#include <rsfcycle/output/snapshots.h>
#include <rsfcycle/physics/global_system.h>
#include <rsfcycle/physics/split_fault.h>
#include <rsfcycle/simulator/simulator.templates.h>
#include <rsfcycle/solvers/amg_correction.h>
#include <rsfcycle/solvers/direct_correction.h>
#include <rsfcycle/solvers/multigrid_correction.h>
#include <rsfcycle/solvers/reused_factor_correction.h>
#include <rsfcycle/time/schemes.h>

namespace rsfcycle
{
  template <int dim>
  ProblemBase<dim>::ProblemBase(const Parameters          &parameters,
                                const physics::Scene<dim> &scene,
                                std::ostream              &log)
    : models::Continuum<dim>(parameters,
                             scene,
                             log,
                             parameters.solver.dynamics ==
                               SolverParameters::Dynamics::quasi_dynamic,
                             parameters.solver.lumped_mass)
    , scheme(time::make_scheme(parameters.solver,
                               parameters.solver.dynamics ==
                                 SolverParameters::Dynamics::dynamic))
  {}


  /** The discretisation and the contact quadrature on it. */
  template <int dim>
  void
  ProblemBase<dim>::setup_system()
  {
    discretisation.make_grid();
    discretisation.setup_system();
    discretisation.setup_boundary_conditions();
    discretisation.assemble_matrices();
    if (scene.split_fault())
      discretisation.tie_fault_sides();
    this->setup_contact();
  }


  namespace
  {
    /**
     * Geometric multigrid on the levels of the discretisation: its
     * prescribed components held at zero, the contact vertices with their
     * lumped weights, the level cell matrices and the step matrix's
     * coefficients of the time scheme.
     */
    template <int dim>
    std::unique_ptr<solvers::LinearCorrection>
    make_multigrid(const physics::Discretisation<dim>     &discretisation,
                   const physics::ContactQuadrature<dim>  &contact,
                   const SolverParameters                 &solver,
                   const time::TimeScheme                 &scheme,
                   const solvers::LinearCorrectionControl &control)
    {
      using MG = solvers::MultigridCorrection<dim>;
      std::vector<typename MG::DirichletBoundary> dirichlet;
      for (const auto &[id, mask] : discretisation.prescribed_components())
        dirichlet.push_back({id, mask});
      const auto       &fe = discretisation.fe;
      const QGauss<dim> quadrature(fe.degree + 1);
      auto              fe_values = std::make_shared<FEValues<dim>>(
        fe, quadrature, update_values | update_gradients | update_JxW_values);
      auto       force = std::make_shared<Vector<double>>(fe.n_dofs_per_cell());
      const auto level_cell_matrices =
        [&discretisation,
         fe_values,
         force](const typename MG::LevelCellIterator &cell,
                std::array<FullMatrix<double>, 3>    &matrices) {
          discretisation.cell_matrices(cell, *fe_values, matrices, *force);
        };
      const auto coefficients =
        [&scheme,
         inertia = solver.dynamics ==
                   SolverParameters::Dynamics::dynamic](const double tau) {
          return time::step_coefficients(scheme, tau, inertia);
        };
      typename MG::Settings settings;
      settings.smoothing_steps   = solver.smoothing_steps;
      settings.coarse_reuse_size = solver.coarse_reuse_size;
      settings.control           = control;
      return std::make_unique<MG>(discretisation.dof_handler,
                                  dirichlet,
                                  boundary_id::contact,
                                  contact.multigrid_vertices(),
                                  level_cell_matrices,
                                  coefficients,
                                  settings);
    }
  } // namespace


  /** The linear correction named in the parameters, and TNNMG with it. */
  template <int dim>
  void
  ProblemBase<dim>::setup_linear_correction()
  {
    const auto                      &solver = parameters.solver;
    solvers::LinearCorrectionControl control;
    control.max_cycles = solver.correction_cycles;
    control.tolerance  = solver.correction_tolerance;
    using Correction   = SolverParameters::LinearCorrection;
    switch (solver.linear_correction)
      {
        case Correction::direct:
          if (solver.direct_factor_reuse)
            linear_correction =
              std::make_unique<solvers::ReusedFactorCorrection>(control);
          else
            linear_correction = std::make_unique<solvers::DirectCorrection>();
          break;
        case Correction::amg:
          linear_correction = std::make_unique<solvers::AMGCorrection>(
            control, discretisation.dof_components());
          break;
        case Correction::multigrid:
          linear_correction =
            make_multigrid(discretisation, contact, solver, *scheme, control);
          break;
      }

    solvers::TNNMGControl tnnmg_control;
    tnnmg_control.max_iterations   = solver.max_tnnmg_iterations;
    tnnmg_control.truncation_ratio = solver.truncation_ratio;
    if (solver.direct_fallback &&
        solver.linear_correction != Correction::direct)
      fallback_correction = std::make_unique<solvers::DirectCorrection>();
    tnnmg = std::make_unique<solvers::TNNMG>(*linear_correction,
                                             tnnmg_control,
                                             fallback_correction.get());
    tnnmg->set_timer(&timer);
  }


  /**
   * The initial displacement: static equilibrium under gravity with a
   * frictionless base (normal component fixed) and a fixed backstop. The
   * normal force of each contact node, w_i |sigma_n,i|, is the magnitude of
   * its normal reaction force, the residual K u - f of the y component.
   */
  template <int dim>
  void
  ProblemBase<dim>::compute_initial_state()
  {
    const auto [u, reaction] = discretisation.gravity_equilibrium();
    if (const auto normal_stress = scene.normal_stress())
      contact.set_normal_forces(normal_stress);
    else if (parameters.run.antiplane)
      throw std::logic_error("antiplane without a prescribed normal stress "
                             "(the scene must refuse it)");
    else
      n_tensile_nodes = contact.set_normal_forces(reaction);
    for (const auto &node : contact.nodes())
      if (!std::isfinite(node.normal_force))
        throw std::runtime_error(
          "non-finite normal stress (gravity equilibrium or prescribed) at "
          "the base "
          "node at s = " +
          format_number(scene.along_base_coordinate(node.position)) + " m");

    initial.u = u;
    discretisation.reinit(initial.v);
    discretisation.reinit(initial.a);
    initial.alpha.clear();
    for (const auto &node : contact.nodes())
      initial.alpha.push_back(scene.initial_state(node.position));
    initial.shear_traction.assign(contact.n_nodes(), 0.);
  }


  /**
   * Observation points: u . vertical as a weighted sum of dofs, on the rank
   * that owns the cell around the point (on a rank boundary: each rank that
   * finds the point in one of its cells; the values are averaged).
   */
  template <int dim>
  void
  ProblemBase<dim>::setup_observation_points()
  {
    // the points' rows in global indices (on the ranks owning their cells),
    // the same as the Green's-function method's
    observation_weights.clear();
    std::vector<double> found;
    for (const auto &row : physics::observation_rows(discretisation,
                                                     scene,
                                                     parameters.run.antiplane))
      {
        std::vector<std::pair<types::global_dof_index, double>> w;
        for (const auto &[j, weight] :
             discretisation.fault_tie.empty() ?
               row :
               physics::tie_row(discretisation.fault_tie, row))
          w.emplace_back(discretisation.local_index(j), weight);
        found.push_back(w.empty() ? 0. : 1.);
        observation_weights.push_back(w);
      }
    observation_ranks.resize(found.size());
    Utilities::MPI::sum(found,
                        discretisation.triangulation.get_communicator(),
                        observation_ranks);
  }


  template <int dim>
  void
  ProblemBase<dim>::setup()
  {
    {
      TimerOutput::Scope scope(timer, "Setup");
      setup_system();
    }
    {
      TimerOutput::Scope scope(timer, "Gravity equilibrium");
      compute_initial_state();
    }
    {
      TimerOutput::Scope scope(timer, "Linear correction setup");
      setup_linear_correction();
    }
    if (parameters.solver.linear_correction !=
        SolverParameters::LinearCorrection::amg)
      discretisation.release_assembled_matrices();
    setup_observation_points();
    la::load_partitioner() = discretisation.partitioner;
    implicit_step          = std::make_unique<models::ImplicitStep<dim>>(
      parameters.solver,
      *scheme,
      discretisation,
      contact,
      *tnnmg,
      [this](const Point<dim> &p) { return scene.along_base_coordinate(p); });
    implicit_step->set_timer(&timer);
    if (parameters.solver.dynamics == SolverParameters::Dynamics::dynamic)
      {
        TimerOutput::Scope scope(timer, "Explicit step setup");
        explicit_stepper = std::make_unique<models::ExplicitStep<dim>>(
          discretisation,
          contact,
          *parameters.solver.law,
          [this](const Point<dim> &p) {
            return scene.along_base_coordinate(p);
          },
          parameters.time_stepping.explicit_scheme ==
            TimeSteppingParameters::ExplicitScheme::noh_bathe);
      }
  }


  template <int dim>
  double
  ProblemBase<dim>::stable_step() const
  {
    return explicit_stepper ? explicit_stepper->stable_step() : 0.;
  }


  template <int dim>
  std::optional<BodyState>
  ProblemBase<dim>::explicit_step(const BodyState &old,
                                  const double     t,
                                  const double     tau)
  {
    TimerOutput::Scope scope(timer, "Explicit step");
    last_explicit = true;
    return (*explicit_stepper)(old, t, tau);
  }


  template <int dim>
  std::string
  ProblemBase<dim>::explicit_refusal() const
  {
    if (!explicit_stepper)
      return "needs Solver/Dynamics = dynamic (the explicit step is the "
             "wave equation's)";
    return explicit_stepper->refusal();
  }


  template <int dim>
  double
  ProblemBase<dim>::energy(const BodyState &state) const
  {
    return 0.5 * discretisation.mass_local.matrix_norm_square(state.v) +
           0.5 * discretisation.stiffness_local.matrix_norm_square(state.u) -
           discretisation.body_force * state.u;
  }


  template <int dim>
  std::vector<double>
  ProblemBase<dim>::observed_uplift(const la::Vector &u) const
  {
    // Hanging-node values are set in u (distribute), so the interpolation
    // may use any dof of the cell.
    std::vector<double> values;
    const double       *entries = discretisation.stiffness_local.ghosted(u);
    for (const auto &w : observation_weights)
      {
        double value = 0;
        for (const auto &[i, weight] : w)
          value += weight * entries[i];
        values.push_back(value);
      }
    discretisation.stiffness_local.release(u);
    Utilities::MPI::sum(values,
                        discretisation.triangulation.get_communicator(),
                        values);
    for (unsigned int k = 0; k < values.size(); ++k)
      values[k] /= observation_ranks[k];
    return values;
  }


  template <int dim>
  std::optional<BodyState>
  ProblemBase<dim>::step(const BodyState &old,
                         const double     t,
                         const double     tau,
                         const BodyState *guess)
  {
    last_explicit = false;
    return (*implicit_step)(old, t, tau, guess);
  }


  template <int dim>
  BodyState
  ProblemBase<dim>::predict(const std::array<const BodyState *, 3> &s,
                            const std::array<double, 3>            &w) const
  {
    BodyState p;
    p.v.reinit(s[2]->v);
    for (unsigned int i = 0; i < 3; ++i)
      p.v.add(w[i], s[i]->v);
    p.alpha.assign(s[2]->alpha.size(), 0.);
    for (unsigned int k = 0; k < p.alpha.size(); ++k)
      p.alpha[k] =
        w[0] * s[0]->alpha[k] + w[1] * s[1]->alpha[k] + w[2] * s[2]->alpha[k];
    return p;
  }


  template <int dim>
  std::vector<double>
  ProblemBase<dim>::slip_rates(const la::Vector &v) const
  {
    return contact.slip_rates(v);
  }


  template <int dim>
  output::Layout
  ProblemBase<dim>::layout() const
  {
    output::Layout layout = models::contact_layout(scene, contact);
    layout.normal_stress  = !discretisation.fault_tie.normal_of.empty();
    return layout;
  }


  template <int dim>
  output::Sample
  ProblemBase<dim>::sample(const BodyState &state) const
  {
    output::Sample            sample;
    const std::vector<double> rates = contact.slip_rates(state.v);
    sample.slip_rates               = contact.gather(rates);
    sample.slip = contact.gather(contact.tangential_displacement(state.u));
    sample.observations = observed_uplift(state.u);
    sample.statistics   = state.statistics;
    if (parameters.output.seas.enabled())
      {
        // the friction stress |sigma_n| mu(V, alpha) + C of the accepted
        // state, and log10 theta
        std::vector<double> stresses, log10_states;
        const auto         &nodes = contact.nodes();
        // a split fault: the normal stress changed by the slip (a resumed
        // state has none yet: from its displacement)
        const bool split_normal = !discretisation.fault_tie.normal_of.empty();
        std::vector<double> normal = state.normal_stress;
        if (split_normal && Utilities::MPI::max(normal.empty() ? 0 : 1,
                                                discretisation.triangulation
                                                  .get_communicator()) == 0)
          physics::split_normal_stresses(
            discretisation,
            contact,
            state.u,
            parameters.solver.dynamics == SolverParameters::Dynamics::dynamic ?
              &state.a :
              nullptr,
            normal);
        for (unsigned int k = 0; k < nodes.size(); ++k)
          {
            const auto  &p = nodes[k].params;
            const double normal_stress =
              split_normal ? normal[k] :
                             nodes[k].normal_force / nodes[k].weight;
            stresses.push_back(normal_stress *
                                 parameters.solver.law->friction_coefficient(
                                   p, state.alpha[k], rates[k]) +
                               (rates[k] > 0 ? p.cohesion : 0.));
            log10_states.push_back(p.log_theta(state.alpha[k]) / std::log(10.));
          }
        sample.shear_stresses = contact.gather(stresses);
        sample.slip_rate_components =
          contact.gather(contact.tangential_displacement(state.v));
        sample.log10_states      = contact.gather(log10_states);
        sample.observation_rates = observed_uplift(state.v);
        if (split_normal)
          sample.normal_stresses = contact.gather(normal);
      }
    return sample;
  }


  template <int dim>
  solvers::StepStatistics
  ProblemBase<dim>::take_work()
  {
    return implicit_step->take_work();
  }


  template <int dim>
  void
  ProblemBase<dim>::step_accepted()
  {
    linear_correction->forget();
    if (fallback_correction)
      fallback_correction->forget();
  }


  template <int dim>
  std::string
  ProblemBase<dim>::last_failure() const
  {
    return last_explicit ? explicit_stepper->last_failure() :
                           implicit_step->last_failure();
  }


  template <int dim>
  output::CheckpointIdentity
  ProblemBase<dim>::checkpoint_identity() const
  {
    return {parameters.run.scene,
            dim,
            discretisation.dof_handler.n_dofs(),
            Utilities::MPI::n_mpi_processes(
              discretisation.triangulation.get_communicator())};
  }


  template <int dim>
  output::Offer
  ProblemBase<dim>::offer()
  {
    // a split fault: the fault's slip and slip rate from the tied unknowns,
    // the body's displacement and velocity untied (both sides)
    std::function<BodyState(const output::Record &)> body;
    if (!discretisation.fault_tie.empty())
      body = [this](const output::Record &record) {
        BodyState   state = record.state_as<BodyState>();
        const auto &nodes = contact.contact_set().nodes;
        state.slip.resize(nodes.size());
        for (unsigned int k = 0; k < nodes.size(); ++k)
          state.slip[k] = solvers::tangential_norm(nodes[k], state.u);
        state.slip_rate = contact.slip_rates(state.v);
        for (la::Vector *field : {&state.u, &state.v})
          {
            physics::untie_split_fault(discretisation.fault_tie, *field);
            discretisation.hanging_constraints.distribute(*field);
          }
        return state;
      };
    return this->continuum_offer("the volume method", body);
  }


  template <int dim>
  void
  ProblemBase<dim>::describe(std::ostream &log) const
  {
    const auto &tria = discretisation.triangulation;
    this->describe_scene(log);
    double h_min = 1e300, h_max = 0;
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          h_min = std::min(h_min, cell->diameter());
          h_max = std::max(h_max, cell->diameter());
        }
    h_min = Utilities::MPI::min(h_min, tria.get_communicator());
    h_max = Utilities::MPI::max(h_max, tria.get_communicator());
    if (const unsigned int n_ranks =
          Utilities::MPI::n_mpi_processes(tria.get_communicator());
        n_ranks > 1)
      log << "MPI ranks: " << n_ranks << "\n";
    log << "Cell diameters: " << h_min << " m to " << h_max << " m\n";
    log << "Gravity equilibrium: CG with algebraic multigrid, "
        << discretisation.gravity_iterations << " iterations\n";
    const auto &solver = parameters.solver;
    log << "Solver: " << name_of(solver.coupling) << " coupling, "
        << name_of(solver.linear_correction) << " linear correction"
        << (fallback_correction ? " (direct fallback), " : ", ")
        << solver.law->name() << " law, " << name_of(solver.dynamics) << ", "
        << scheme->describe() << std::endl;
    using Integrator = TimeSteppingParameters::Integrator;
    if (explicit_stepper && explicit_stepper->refusal().empty() &&
        (parameters.time_stepping.integrator == Integrator::explicit_steps ||
         parameters.time_stepping.integrator == Integrator::implicit_explicit))
      log << "Explicit step: "
          << parameters.time_stepping.courant_number *
               explicit_stepper->stable_step()
          << " s, Courant number " << parameters.time_stepping.courant_number
          << " x the stable step " << explicit_stepper->stable_step()
          << " s of " << name_of(parameters.time_stepping.explicit_scheme)
          << " ("
          << (parameters.time_stepping.explicit_scheme ==
                  TimeSteppingParameters::ExplicitScheme::noh_bathe ?
                "3.745" :
                "2")
          << "/omega_max, omega_max^2 the largest cell eigenvalue of the "
             "lumped mass and the stiffness; smallest cell "
          << explicit_stepper->smallest_cell() << " m)" << std::endl;
    if (const auto *mg =
          dynamic_cast<const solvers::MultigridCorrection<dim> *>(
            linear_correction.get()))
      {
        log << "Multigrid: " << mg->level_sizes().size()
            << " levels, dofs per level:";
        for (const auto n : mg->level_sizes())
          log << ' ' << n;
        log << std::endl;
        if (Utilities::MPI::n_mpi_processes(tria.get_communicator()) > 1)
          // the cost of a level-by-level cycle over its cost if every level
          // were split evenly (deal.II's estimate: cells per level and rank)
          log << "Multigrid workload imbalance over the ranks: "
              << MGTools::workload_imbalance(tria) << std::endl;
      }
    // The step-size control sees the solver's error too (BP1 at 50 m, both
    // tolerances 1e-6: 5e4 s steps between events; TNNMG 1e-9: 4e5 - 8e5 s)
    if (parameters.time_stepping.adaptive &&
        parameters.solver.tnnmg_tolerance >
          0.1 * parameters.time_stepping.tolerance)
      log << "Warning: Solver/TNNMG tolerance = "
          << parameters.solver.tnnmg_tolerance
          << " is above a tenth of Time stepping/Tolerance = "
          << parameters.time_stepping.tolerance
          << ": the step-size control will see the solver's error and take "
             "smaller steps than the scheme needs."
          << std::endl;
    if (n_tensile_nodes > 0)
      log << "Warning: " << n_tensile_nodes
          << " contact nodes carry a tensile normal reaction in the gravity "
             "equilibrium; their magnitude is used."
          << std::endl;
  }


  template <int dim>
  bool
  ProblemBase<dim>::run(const ParameterHandler &prm, const bool resume)
  {
    if (!resume)
      output::write_parameters(parameters.run.output_directory, prm);
    setup();
    Simulator<BodyState> simulator(parameters, *this, log, timer);
    return !simulator.run(resume).interrupted;
  }

  template class ProblemBase<2>;
  template class ProblemBase<3>;
} // namespace rsfcycle

namespace rsfcycle
{
  template class Simulator<BodyState>;
} // namespace rsfcycle
