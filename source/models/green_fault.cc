// SPDX-License-Identifier: LGPL-2.1-or-later
// The quasi-dynamic fault with the bulk's Green's functions
// (models/green_fault.h, doc/model.md §8.1).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <deal.II/grid/tria.h>
#include <limits>
#include <rsfcycle/format.h>
#include <rsfcycle/ids.h>
#include <rsfcycle/models/green_fault.h>
#include <rsfcycle/output/files.h>
#include <rsfcycle/physics/split_fault.h>
#include <rsfcycle/simulator/simulator.templates.h>
#include <rsfcycle/time/integrator.h>
#include <rsfcycle/time/schemes.h>
#include <stdexcept>

namespace rsfcycle
{
  namespace models
  {
    namespace
    {
      const std::string refused = "Solver/Bulk = green-function: ";
      /** The operator's file in the run folder. */
      const std::string operator_file = "green-operator.bin";
    } // namespace


    template <int dim>
    void
    GreenFault<dim>::check(const Parameters          &parameters,
                           const physics::Scene<dim> &scene)
    {
      if (!scene.normal_stress())
        throw std::invalid_argument(
          refused + "needs a prescribed normal stress (Friction/Normal "
                    "stress); the normal stress of the gravity equilibrium "
                    "changes with slip");
      if (const auto viscous = viscous_material(scene))
        throw std::invalid_argument(
          refused + "needs an elastic bulk (Materials: material " +
          std::to_string(viscous->first) + " has shear viscosity " +
          format_number(viscous->second.shear_viscosity) + ", bulk viscosity " +
          format_number(viscous->second.bulk_viscosity) +
          "; Kelvin-Voigt viscosity is not a Green's function of the "
          "slip)");
      if (scene.split_fault() && scene.gravity().norm() != 0)
        throw std::invalid_argument(
          refused + "with a fault-opposite side (Boundary roles) needs "
                    "Gravity = 0 (the initial slip of a split fault under "
                    "gravity is not implemented yet)");
      const double t_end = parameters.run.end_time;
      if ((scene.backstop_velocity(0.) - scene.backstop_velocity(t_end))
            .norm() != 0)
        throw std::invalid_argument(
          refused + "needs a load velocity constant in time (Ramp time = "
                    "0): the loading response is affine in t");
    }


    template <int dim>
    GreenFault<dim>::GreenFault(const Parameters          &parameters,
                                const physics::Scene<dim> &scene,
                                std::ostream              &log)
      : Continuum<dim>(parameters, scene, log, true)
      , communicator(discretisation.triangulation.get_communicator())
      , scheme(time::make_scheme(parameters.solver, false))
      , fault_solver(parameters.solver.max_tnnmg_iterations,
                     parameters.solver.truncation_ratio)
    {
      check(parameters, scene);
    }


    template <int dim>
    void
    GreenFault<dim>::setup(const bool resume)
    {
      const auto start = std::chrono::steady_clock::now();
      {
        TimerOutput::Scope scope(timer, "Setup");
        discretisation.make_grid();
        discretisation.setup_system();
        discretisation.setup_boundary_conditions();
        this->setup_contact();
        discretisation.assemble_matrices();
        contact.set_normal_forces(scene.normal_stress());
        pore_pressure  = scene.pore_pressure();
        darcy_velocity = scene.darcy_velocity();
        if (pore_pressure)
          {
            std::vector<Point<dim>> positions;
            std::vector<double>     stresses;
            for (const auto &node : contact.nodes())
              {
                positions.push_back(node.position);
                stresses.push_back(node.normal_force / node.weight);
              }
            all_positions       = la::all_gather(communicator, positions);
            all_normal_stresses = la::all_gather(communicator, stresses);
          }
      }

      // The radiation damping eta w_k of every node is the diagonal of C on
      // the contact; anything else in C (dashpots, viscosity) is refused.
      const auto       &C     = discretisation.viscosity_local;
      const auto       &nodes = contact.contact_set().nodes;
      std::vector<bool> on_contact(C.m(), false);
      for (const auto &node : nodes)
        for (unsigned int d = 0; d < node.n_dofs; ++d)
          on_contact[node.dofs[d]] = true;
      // (the rows and columns of fixed dofs do not enter: their values
      // are prescribed, and constrained rows carry a diagonal)
      // (a refusal on one rank is made on every rank: the first rank's)
      const auto &fixed = discretisation.fixed;
      std::string refusal;
      for (unsigned int i = 0; i < C.m(); ++i)
        for (unsigned int e = C.row_begin(i); e < C.row_end(i); ++e)
          if (C.value(e) != 0 && !fixed[i] && !fixed[C.column(e)] &&
              !(on_contact[i] && C.column(e) == i))
            refusal = refused +
                      "the bulk has dashpots (Boundary roles: absorbing) "
                      "or viscosity; only radiation damping on the "
                      "contact is allowed";
      damping.assign(nodes.size(), 0.);
      dof_start.assign(1, 0);
      for (unsigned int k = 0; k < nodes.size(); ++k)
        {
          dof_start.push_back(dof_start.back() + nodes[k].n_dofs);
          const unsigned int i = nodes[k].dofs[0];
          for (unsigned int e = C.row_begin(i); e < C.row_end(i); ++e)
            if (C.column(e) == i)
              damping[k] = C.value(e);
          if (contact.nodes()[k].params.cohesion != 0)
            refusal = refused + "needs Friction/Cohesion = 0 (the cohesion "
                                "makes the fault's ODE non-smooth at V = 0)";
          if (!(damping[k] > 0))
            refusal =
              refused + "needs radiation damping > 0 on every contact node";
        }
      for (const auto &r : Utilities::MPI::all_gather(communicator, refusal))
        if (!r.empty())
          throw std::invalid_argument(r);

      // the shear stress perturbation's nodal forces, lumped as the
      // prestress's (physics::Discretisation::add_contact_terms)
      perturbation_forces.assign(dof_start.back(), 0.);
      perturbation_history = scene.shear_perturbation_history();
      if (const auto perturbation = scene.shear_perturbation())
        for (unsigned int k = 0; k < nodes.size(); ++k)
          {
            const auto          &node     = contact.nodes()[k];
            const Tensor<1, dim> traction = perturbation(node.position);
            for (unsigned int d = 0; d < nodes[k].n_dofs; ++d)
              perturbation_forces[dof_start[k] + d] =
                node.weight * traction[node.components[d]];
          }

      {
        TimerOutput::Scope scope(timer, "Green's function operator");
        // (the gathered system is the set-up's; it goes at the scope's end)
        auto system = physics::gather_system(
          discretisation,
          contact.contact_set(),
          physics::observation_rows(discretisation,
                                    scene,
                                    parameters.run.antiplane));
        if (scene.split_fault())
          physics::tie_split_fault(discretisation, system);
        fingerprint = physics::operator_fingerprint(system);
        // every rank's dofs and nodes in the state: counts and offsets of
        // the gathers
        counts.clear();
        offsets.clear();
        for (unsigned int r = 0; r + 1 < system.rank_offsets.size(); ++r)
          {
            offsets.push_back(system.rank_offsets[r]);
            counts.push_back(system.rank_offsets[r + 1] -
                             system.rank_offsets[r]);
          }
        node_counts =
          Utilities::MPI::all_gather(communicator,
                                     static_cast<int>(nodes.size()));
        node_offsets.assign(1, 0);
        for (unsigned int r = 0; r + 1 < node_counts.size(); ++r)
          node_offsets.push_back(node_offsets.back() + node_counts[r]);
        first_node =
          node_offsets[Utilities::MPI::this_mpi_process(communicator)];
        const unsigned int first =
          system.rank_offsets[Utilities::MPI::this_mpi_process(communicator)];
        operator_source =
          resume ? parameters.run.output_directory + "/" + operator_file :
                   parameters.solver.green_operator_file;
        if (operator_source.empty())
          op = physics::compute_green_operator(system, communicator);
        else
          op =
            physics::read_green_operator(operator_source,
                                         resume ? "--resume" :
                                                  "Solver/Green operator file",
                                         fingerprint,
                                         discretisation.dof_handler.n_dofs(),
                                         system.contact_dofs.size(),
                                         system.observations.size(),
                                         first,
                                         dof_start.back(),
                                         communicator);
      }

      // what the implicit step needs of S
      S_diagonal.clear();
      for (unsigned int i = 0; i < op.n_rows(); ++i)
        S_diagonal.push_back(op.S(i, op.first_row + i));

      // S as an H-matrix: asked for, or automatic from 1000 contact nodes
      // on (below, compression gains nothing: benchmarks/green-function)
      {
        using Storage      = SolverParameters::GreenStorage;
        const auto storage = parameters.solver.green_storage;
        if (storage == Storage::h_matrix ||
            (storage == Storage::automatic && op.n_contact() >= 1000))
          {
            TimerOutput::Scope  scope(timer, "Green's function compression");
            std::vector<double> points;
            // (a node's dofs at its position)
            for (unsigned int k = 0; k < nodes.size(); ++k)
              for (unsigned int i = 0; i < nodes[k].n_dofs; ++i)
                for (unsigned int d = 0; d < dim; ++d)
                  points.push_back(contact.nodes()[k].position[d]);
            compression_error = Utilities::MPI::max(
              op.compress(
                la::all_gather(communicator, points),
                dim,
                parameters.solver.green_compression_tolerance,
                communicator,
                parameters.solver.green_single_precision ?
                  solvers::HierarchicalMatrix::Precision::single_precision :
                  solvers::HierarchicalMatrix::Precision::double_precision),
              communicator);
            compressed_fraction =
              Utilities::MPI::sum(double(op.stored_entries()), communicator) /
              (double(op.n_contact()) * op.n_contact());
            low_rank_blocks =
              Utilities::MPI::sum(op.n_low_rank_blocks(), communicator);
            dense_blocks =
              Utilities::MPI::sum(op.n_dense_blocks(), communicator);
          }
        // what the run keeps of S on the rank that keeps most
        // (and of N, with a split fault's normal coupling)
        const double dense = 8. * op.n_rows() * op.n_contact();
        operator_megabytes = Utilities::MPI::max(
          1e-6 *
            ((op.is_compressed() ? double(op.memory_consumption()) : dense) +
             (op.normal_coupling && !op.normal_negligible ?
                (op.compressed_normal ?
                   double(op.compressed_normal->memory_consumption()) :
                   dense) :
                0.)),
          communicator);
      }

      // The initial slip is the volume path's: the tangential displacement
      // of the gravity equilibrium on a frictionless contact (zero without
      // gravity); the traction is then the shear prestress alone.
      {
        TimerOutput::Scope scope(timer, "Gravity equilibrium");
        // (a split fault starts without slip: check() refuses gravity)
        la::Vector u;
        discretisation.reinit(u);
        if (!scene.split_fault())
          u = discretisation.gravity_equilibrium().first;
        std::vector<double> slip, alpha;
        for (unsigned int k = 0; k < nodes.size(); ++k)
          {
            for (unsigned int d = 0; d < nodes[k].n_dofs; ++d)
              slip.push_back(u.local_element(nodes[k].dofs[d]));
            alpha.push_back(scene.initial_state(contact.nodes()[k].position));
          }
        // the state of all nodes on every rank, rank by rank
        initial.slip  = la::all_gather(communicator, slip);
        initial.alpha = la::all_gather(communicator, alpha);
      }
      initial.t = 0;
      initial.rate.resize(initial.slip.size());
      force_work.reinit(dof_start.back());
      slip_rates(initial.slip.data(),
                 initial.alpha.data(),
                 0.,
                 initial.rate.data());
      setup_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
      is_set_up = true;
    }


    /**
     * The balance F - c V = N mu(|V|, alpha) sign V of node k for V: V has
     * the sign of F, and G(x) = N mu(e^x) + c e^x - |F| increases in
     * x = log |V|. Newton in x from the solution without damping
     * (V = 2 V_theta sinh(|F| / (a N)) for the regularised law), kept in
     * the bracket [x_lo, x_hi] (x_hi = log(|F| / c), where G >= 0), with
     * bisection when a step leaves it; converged at |dx| < 1e-12.
     */
    template <int dim>
    double
    GreenFault<dim>::slip_rate(const unsigned int k,
                               const double       force,
                               const double       alpha,
                               const double       N) const
    {
      if (!(N > 0))
        return std::numeric_limits<double>::quiet_NaN();
      const double T = std::abs(force);
      if (T == 0)
        return 0;
      const auto          &node = contact.nodes()[k];
      const auto          &p    = node.params;
      const friction::Law &law  = *parameters.solver.law;
      const double         c    = damping[k];
      const double         term = law.state_term(p, alpha);
      double               x_hi = std::log(T / c);
      double               x_lo = -std::numeric_limits<double>::infinity();
      const double         y    = T / (p.a * N);
      // log(2 V_theta sinh y), V_theta = exp(term)
      double x = term + (y > 20 ? y : std::log(2 * std::sinh(y)));
      x        = std::min(x, x_hi);
      for (unsigned int iteration = 0; iteration < 200; ++iteration)
        {
          const double V  = std::exp(x);
          const auto   cd = law.coefficient_and_derivative(p, term, V);
          const double G  = N * cd.mu + c * V - T;
          if (G == 0)
            break;
          (G > 0 ? x_hi : x_lo) = x;
          const double slope    = V * (N * cd.derivative + c);
          double       x_new    = x - G / slope;
          if (!(x_new > x_lo && x_new < x_hi))
            x_new = std::isfinite(x_lo) ? 0.5 * (x_lo + x_hi) : x - 20;
          const bool done = std::abs(x_new - x) < 1e-12 ||
                            x_hi - x_lo < 1e-12 * std::max(1., std::abs(x));
          x = x_new;
          if (done)
            break;
        }
      return std::copysign(std::exp(x), force);
    }


    template <int dim>
    double
    GreenFault<dim>::normal_force(const unsigned int k, const double t) const
    {
      const auto &node = contact.nodes()[k];
      if (!pore_pressure)
        return node.normal_force;
      return node.normal_force - node.weight * pore_pressure(node.position, t);
    }


    template <int dim>
    const std::vector<double> &
    GreenFault<dim>::normal_forces(const double *s, const double t) const
    {
      normal_work.resize(damping.size());
      if (op.normal_coupling)
        {
          normal_change.resize(op.n_rows());
          op.apply_normal(s, t, normal_change.data());
        }
      for (unsigned int k = 0; k < damping.size(); ++k)
        normal_work[k] =
          normal_force(k, t) +
          (op.normal_coupling ? normal_change[dof_start[k]] : 0.);
      return normal_work;
    }


    template <int dim>
    void
    GreenFault<dim>::slip_rates(const double *s,
                                const double *alpha,
                                const double  t,
                                double       *V,
                                double       *alpha_rate) const
    {
      const unsigned int first = op.first_row;
      const auto        &law   = *parameters.solver.law;
      op.apply(s, force_work.begin());
      const auto  &N = normal_forces(s, t);
      const double g = perturbation_factor(t);
      for (unsigned int k = 0; k < damping.size(); ++k)
        {
          // the node's force F = g0 + t g1 - S s + g(t) P on its dofs (P the
          // perturbation's forces); with two, the slip rate has the
          // direction of F (free rake) and the balance holds for its length
          const unsigned int i0 = dof_start[k], n_dofs = dof_start[k + 1] - i0;
          const unsigned int node = first_node + k;
          std::array<double, 2> F = {{0., 0.}};
          for (unsigned int d = 0; d < n_dofs; ++d)
            F[d] = op.g0[i0 + d] + t * op.g1[i0 + d] - force_work[i0 + d] +
                   g * perturbation_forces[i0 + d];
          double speed;
          if (n_dofs == 1)
            {
              V[first + i0] = slip_rate(k, F[0], alpha[node], N[k]);
              speed         = std::abs(V[first + i0]);
            }
          else
            {
              const double length = std::hypot(F[0], F[1]);
              speed               = slip_rate(k, length, alpha[node], N[k]);
              for (unsigned int d = 0; d < 2; ++d)
                V[first + i0 + d] = length > 0 ? speed * F[d] / length : 0.;
            }
          if (alpha_rate)
            alpha_rate[node] =
              law.state_rate(contact.nodes()[k].params, alpha[node], speed);
        }
      gather_in_place(V);
      if (alpha_rate)
        gather_in_place(alpha_rate, true);
      if (pore_pressure)
        for (unsigned int j = 0; j < op.n_contact(); ++j)
          if (!std::isfinite(V[j]))
            {
              check_compression(t);
              break;
            }
    }


    template <int dim>
    void
    GreenFault<dim>::check_compression(const double t) const
    {
      unsigned int weakest = 0;
      double       least   = std::numeric_limits<double>::infinity();
      for (unsigned int j = 0; j < all_positions.size(); ++j)
        {
          const double sigma =
            all_normal_stresses[j] - pore_pressure(all_positions[j], t);
          if (!(sigma >= least))
            {
              least   = sigma;
              weakest = j;
            }
        }
      if (!(least > 0))
        {
          // in 2D the place along the contact; in 3D the node's position
          const Point<dim> &node = all_positions[weakest];
          std::string where = format_number(scene.along_base_coordinate(node)) +
                              " m along the contact";
          if (dim == 3)
            where = "(x, y, z) = (" + format_number(node[0]) + ", " +
                    format_number(node[1]) + ", " +
                    format_number(node[dim - 1]) + ") m";
          throw time::CompressionLost(
            "at t = " + format_number(t) +
            " s the pore pressure left the fault node at " + where +
            " without compression: sigma_n - p = " + format_number(least) +
            " Pa (p = " + format_number(pore_pressure(node, t)) +
            " Pa); rate-and-state friction needs sigma_n - p > 0");
        }
    }


    template <int dim>
    void
    GreenFault<dim>::gather_in_place(double *values, const bool nodes) const
    {
      if (counts.size() > 1)
        MPI_Allgatherv(MPI_IN_PLACE,
                       0,
                       MPI_DATATYPE_NULL,
                       values,
                       nodes ? node_counts.data() : counts.data(),
                       nodes ? node_offsets.data() : offsets.data(),
                       MPI_DOUBLE,
                       communicator);
    }


    template <int dim>
    int
    GreenFault<dim>::ode_rhs(const double t, const Vector &y, Vector &dy) const
    {
      TimerOutput::Scope scope(timer, "Fault right-hand side");
      const unsigned int n = op.n_contact();
      slip_rates(y.begin(), y.begin() + n, t, dy.begin(), dy.begin() + n);
      bool finite = true;
      for (unsigned int j = 0; j < dy.size(); ++j)
        finite = finite && std::isfinite(dy[j]);
      return finite ? 0 : 1;
    }


    template <int dim>
    typename GreenFault<dim>::Vector
    GreenFault<dim>::to_ode(const State &state) const
    {
      // the slip of every dof, then the state of every node
      const unsigned int n = state.slip.size();
      Vector             y(n + state.alpha.size());
      std::copy(state.slip.begin(), state.slip.end(), y.begin());
      std::copy(state.alpha.begin(), state.alpha.end(), y.begin() + n);
      return y;
    }


    template <int dim>
    FaultState
    GreenFault<dim>::from_ode(const Vector &y, const double t) const
    {
      const unsigned int n = op.n_contact();
      State              state;
      state.t = t;
      state.slip.assign(y.begin(), y.begin() + n);
      state.alpha.assign(y.begin() + n, y.end());
      state.rate.resize(n);
      slip_rates(state.slip.data(), state.alpha.data(), t, state.rate.data());
      return state;
    }


    template <int dim>
    typename GreenFault<dim>::Vector
    GreenFault<dim>::ode_absolute_tolerances(const double relative) const
    {
      // rtol L for the slip of each of a node's dofs, rtol for its state
      std::vector<double> L, L_dofs;
      for (unsigned int k = 0; k < damping.size(); ++k)
        {
          L.push_back(contact.nodes()[k].params.L);
          for (unsigned int i = dof_start[k]; i < dof_start[k + 1]; ++i)
            L_dofs.push_back(L.back());
        }
      L      = la::all_gather(communicator, L);
      L_dofs = la::all_gather(communicator, L_dofs);
      Vector a(L_dofs.size() + L.size());
      for (unsigned int j = 0; j < L_dofs.size(); ++j)
        a[j] = relative * L_dofs[j];
      for (unsigned int k = 0; k < L.size(); ++k)
        a[L_dofs.size() + k] = relative;
      return a;
    }


    template <int dim>
    output::CheckpointIdentity
    GreenFault<dim>::checkpoint_identity() const
    {
      return {parameters.run.scene + " (green-function)",
              dim,
              discretisation.dof_handler.n_dofs(),
              Utilities::MPI::n_mpi_processes(communicator)};
    }


    template <int dim>
    bool
    GreenFault<dim>::run(const ParameterHandler &prm, const bool resume)
    {
      if (!is_set_up)
        setup(resume);
      if (!resume)
        {
          output::write_parameters(parameters.run.output_directory, prm);
          physics::write_green_operator(parameters.run.output_directory + "/" +
                                          operator_file,
                                        op,
                                        fingerprint,
                                        discretisation.dof_handler.n_dofs(),
                                        communicator);
        }
      if (op.is_compressed())
        op.release_dense();
      Simulator<State> simulator(parameters, *this, log, timer);
      return !simulator.run(resume).interrupted;
    }


    template class GreenFault<2>;
    template class GreenFault<3>;
  } // namespace models

  template class Simulator<models::FaultState>;
} // namespace rsfcycle
