// SPDX-License-Identifier: LGPL-2.1-or-later
// The outputs of the quasi-dynamic fault with the bulk's Green's functions
// (models/green_fault.h): its layout and samples for the writers, the VTU
// snapshots of the whole body, the description in log.txt.
#include <array>
#include <cmath>
#include <rsfcycle/format.h>
#include <rsfcycle/models/contact_layout.h>
#include <rsfcycle/models/continuum.h>
#include <rsfcycle/models/green_fault.h>
#include <rsfcycle/output/snapshots.h>
#include <rsfcycle/physics/split_fault.h>

namespace rsfcycle
{
  namespace models
  {
    template <int dim>
    output::Layout
    GreenFault<dim>::layout() const
    {
      auto layout          = contact_layout(scene, contact);
      layout.normal_stress = op.normal_coupling;
      return layout;
    }


    template <int dim>
    output::Sample
    GreenFault<dim>::sample(const State &state) const
    {
      // this rank's nodes (their dofs from first_row in the state of all
      // dofs, their states from first_node)
      const unsigned int  first = op.first_row;
      const unsigned int  n     = state.slip.size();
      const auto         &law   = *parameters.solver.law;
      const auto         &nodes = contact.nodes();
      const unsigned int  n_own = nodes.size();
      output::Sample      sample;
      std::vector<double> rates(n_own), stresses(n_own), log10_states(n_own),
        normal_stresses(n_own);
      // (the effective normal force, with the pore pressure and the split
      // fault's normal coupling)
      const auto         &normal = normal_forces(state.slip.data(), state.t);
      std::vector<double> pressures(pore_pressure ? n_own : 0);
      std::vector<std::array<double, 2>> darcy(darcy_velocity ? n_own : 0);
      std::vector<std::array<double, 2>> slip(n_own), rate_components(n_own);
      for (unsigned int k = 0; k < n_own; ++k)
        {
          const auto  &p          = nodes[k].params;
          const double alpha      = state.alpha[first_node + k];
          slip[k]                 = {{0., 0.}};
          std::array<double, 2> V = {{0., 0.}};
          for (unsigned int i = dof_start[k]; i < dof_start[k + 1]; ++i)
            {
              slip[k][i - dof_start[k]] = state.slip[first + i];
              V[i - dof_start[k]]       = state.rate[first + i];
            }
          rates[k]           = std::hypot(V[0], V[1]);
          rate_components[k] = V;
          if (pore_pressure)
            pressures[k] = pore_pressure(nodes[k].position, state.t);
          normal_stresses[k] = normal[k] / nodes[k].weight;
          stresses[k] =
            normal_stresses[k] * law.friction_coefficient(p, alpha, rates[k]);
          log10_states[k] = p.log_theta(alpha) / std::log(10.);
          if (darcy_velocity)
            darcy[k] = darcy_velocity(nodes[k].position, state.t);
        }
      if (pore_pressure)
        sample.pore_pressures = contact.gather(pressures);
      if (darcy_velocity)
        sample.darcy_velocities = contact.gather(darcy);
      sample.slip_rates           = contact.gather(rates);
      sample.slip                 = contact.gather(slip);
      sample.slip_rate_components = contact.gather(rate_components);
      sample.shear_stresses       = contact.gather(stresses);
      sample.normal_stresses      = contact.gather(normal_stresses);
      sample.log10_states         = contact.gather(log10_states);
      for (unsigned int p = 0; p < op.O.m(); ++p)
        {
          double u = op.o0[p] + state.t * op.o1[p], v = op.o1[p];
          for (unsigned int k = 0; k < n; ++k)
            {
              u += op.O(p, k) * state.slip[k];
              v += op.O(p, k) * state.rate[k];
            }
          sample.observations.push_back(u);
          sample.observation_rates.push_back(v);
        }
      sample.statistics = state.statistics;
      return sample;
    }


    template <int dim>
    output::Offer
    GreenFault<dim>::offer()
    {
      return this->continuum_offer("the Green's-function method",
                                   [this](const output::Record &record) {
                                     return body(record.state_as<State>());
                                   });
    }


    template <int dim>
    BodyState
    GreenFault<dim>::body(const State &state) const
    {
      TimerOutput::Scope scope(timer, "Output");
      const unsigned int first = op.first_row;
      const auto        &nodes = contact.contact_set().nodes;
      const auto        &law   = *parameters.solver.law;
      BodyState          b;
      discretisation.reinit(b.u);
      discretisation.reinit(b.v);
      discretisation.reinit(b.a);
      // the normal force with the slip's change (a split fault's)
      const auto &N = normal_forces(state.slip.data(), state.t);
      for (unsigned int k = 0; k < nodes.size(); ++k)
        {
          std::array<double, 2> slip = {{0., 0.}}, rate = {{0., 0.}};
          for (unsigned int d = 0; d < nodes[k].n_dofs; ++d)
            {
              slip[d] = state.slip[first + dof_start[k] + d];
              rate[d] = state.rate[first + dof_start[k] + d];
            }
          const double alpha = state.alpha[first_node + k];
          const double V     = std::hypot(rate[0], rate[1]);
          const double w     = contact.nodes()[k].weight;
          b.alpha.push_back(alpha);
          b.slip.push_back(std::hypot(slip[0], slip[1]));
          b.slip_rate.push_back(V);
          if (pore_pressure || op.normal_coupling)
            b.normal_stress.push_back(N[k] / w);
          b.shear_traction.push_back(
            N[k] / w *
            law.friction_coefficient(contact.nodes()[k].params, alpha, V));
        }
      if (scene.split_fault())
        {
          split_body_fields(state, b);
          return b;
        }

      // the load boundaries at V t (the load velocity is constant: check())
      discretisation.set_fixed_values(b.v, state.t);
      for (const auto &dof : discretisation.backstop_dofs)
        b.u.local_element(dof.index) = state.t * b.v.local_element(dof.index);
      for (unsigned int k = 0; k < nodes.size(); ++k)
        for (unsigned int d = 0; d < nodes[k].n_dofs; ++d)
          {
            const unsigned int i                = first + dof_start[k] + d;
            b.u.local_element(nodes[k].dofs[d]) = state.slip[i];
            b.v.local_element(nodes[k].dofs[d]) = state.rate[i];
          }
      if (!static_solver)
        {
          std::vector<unsigned int> dofs;
          for (const auto &node : nodes)
            for (unsigned int d = 0; d < node.n_dofs; ++d)
              dofs.push_back(node.dofs[d]);
          static_solver =
            std::make_unique<physics::StaticSolver<dim>>(discretisation, dofs);
        }
      static_solver->solve(b.u, &discretisation.body_force);
      static_solver->solve(b.v);
      return b;
    }


    template <int dim>
    void
    GreenFault<dim>::split_body_fields(const State &state, BodyState &b) const
    {
      if (!split_body)
        {
          // the set-up's tied system again (no observation rows), kept
          // with the factor of its interior block
          auto system =
            physics::gather_system(discretisation, contact.contact_set(), {});
          physics::tie_split_fault(discretisation, system);
          auto solver = std::make_unique<physics::InteriorSolver>(
            system, discretisation.triangulation.get_communicator());
          split_body = std::make_unique<SplitBody>(
            SplitBody{std::move(system), std::move(solver)});
        }
      const auto &system = split_body->system;
      const auto &p      = *discretisation.partitioner;
      // the contact at s (V), the fixed dofs at v_b t (v_b), the rest in
      // equilibrium; untied, this rank's dofs, the hanging ones distributed
      const auto fill = [&](const std::vector<double> &contact_values,
                            const double               t,
                            const bool                 with_force,
                            la::Vector                &u) {
        std::vector<double> x(system.n(), 0.);
        for (unsigned int i = 0; i < system.n(); ++i)
          if (system.fixed[i])
            x[i] = t * system.fixed_velocity[i];
        for (unsigned int k = 0; k < system.contact_dofs.size(); ++k)
          x[system.contact_dofs[k]] = contact_values[k];
        split_body->solver->equilibrium(system, x, with_force);
        physics::untie_split_fault(system, x);
        for (unsigned int i = 0; i < p.locally_owned_size(); ++i)
          u.local_element(i) = x[p.local_to_global(i)];
        discretisation.hanging_constraints.distribute(u);
      };
      fill(state.slip, state.t, true, b.u);
      fill(state.rate, 1., false, b.v);
    }


    template <int dim>
    void
    GreenFault<dim>::describe(std::ostream &log) const
    {
      this->describe_scene(log);
      log << "Bulk: green-function, operator " << op.n_contact() << " x "
          << op.n_contact();
      if (op.is_compressed())
        log << " as an H-matrix (tolerance "
            << parameters.solver.green_compression_tolerance
            << (parameters.solver.green_single_precision ?
                  ", stored in single precision" :
                  "")
            << ", its lower triangle: "
            << format_number(100. * compressed_fraction)
            << " % of the dense numbers, " << low_rank_blocks
            << " low-rank and " << dense_blocks
            << " dense blocks, product error " << compression_error << ")";
      else
        log << " dense";
      if (const unsigned int ranks =
            Utilities::MPI::n_mpi_processes(communicator);
          ranks > 1)
        log << " (" << op.n_rows() << " rows on rank 0 of " << ranks
            << (op.is_compressed() ?
                  "; the triangle's products " +
                    std::to_string(op.product_end - op.product_begin) +
                    " rows on rank 0" :
                  std::string())
            << ")";
      log << ", " << format_number(operator_megabytes)
          << " MB on the rank that holds most";
      if (op.normal_coupling && op.normal_negligible)
        log << ", the slip's normal stress change negligible (at most "
               "1e-10 of S: a symmetric problem) and left out";
      else if (op.normal_coupling)
        log << ", the slip's normal stress change " << op.n_rows() << " x "
            << op.n_contact()
            << (op.compressed_normal ? " as an H-matrix (" : " dense (")
            << format_number(
                 1e-6 * (op.compressed_normal ?
                           double(op.compressed_normal->memory_consumption()) :
                           8. * op.n_rows() * op.n_contact()))
            << " MB)";
      log << ", " << op.O.m() << " observation rows ";
      if (operator_source.empty())
        log << "from a Cholesky factor of " << op.n_interior << " unknowns ("
            << format_number(op.factor_megabytes) << " MB, one per node) and "
            << op.n_blocks << " block solves";
      else
        log << "read from " << operator_source;
      log << " (set-up " << format_number(setup_seconds) << " s)\n"
          << "Solver: " << parameters.solver.law->name() << " law, "
          << name_of(parameters.solver.dynamics);
      if (parameters.time_stepping.integrator ==
          TimeSteppingParameters::Integrator::implicit)
        log << ", the implicit step on the fault: " << scheme->describe()
            << ", " << name_of(parameters.solver.coupling)
            << " coupling (tolerance "
            << parameters.solver.fixed_point_tolerance
            << "), fault solver tolerance " << parameters.solver.tnnmg_tolerance
            << ", step tolerance " << parameters.time_stepping.tolerance
            << std::endl;
      else
        log << ", the fault's ODE by explicit Dormand-Prince 5(4) (ARKODE), "
               "relative tolerance "
            << parameters.time_stepping.tolerance << std::endl;
    }


    // (the class is instantiated in green_fault.cc; these members here)
    template output::Layout
    GreenFault<2>::layout() const;
    template output::Sample
    GreenFault<2>::sample(const State &) const;
    template output::Offer
    GreenFault<2>::offer();
    template BodyState
    GreenFault<2>::body(const State &) const;
    template void
    GreenFault<2>::describe(std::ostream &) const;
    template output::Layout
    GreenFault<3>::layout() const;
    template output::Sample
    GreenFault<3>::sample(const State &) const;
    template output::Offer
    GreenFault<3>::offer();
    template BodyState
    GreenFault<3>::body(const State &) const;
    template void
    GreenFault<3>::describe(std::ostream &) const;
  } // namespace models
} // namespace rsfcycle
