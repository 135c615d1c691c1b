// SPDX-License-Identifier: LGPL-2.1-or-later
#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <limits>
#include <map>
#include <rsfcycle/format.h>
#include <rsfcycle/friction/local_solve.h>
#include <rsfcycle/models/explicit_step.h>
#include <rsfcycle/physics/split_fault.h>

namespace rsfcycle
{
  namespace models
  {
    namespace
    {
      /**
       * The largest eigenvalue of K_e x = lambda M_L,e x over this rank's
       * cells, with M_L,e the row sums of the cell's mass matrix, and the
       * smallest cell diameter (both over all ranks).
       */
      template <int dim>
      std::pair<double, double>
      largest_cell_eigenvalue(const physics::Discretisation<dim> &d)
      {
        using namespace dealii;
        const auto       &fe = d.fe;
        const QGauss<dim> quadrature(fe.degree + 1);
        FEValues<dim>     fe_values(
          fe, quadrature, update_values | update_gradients | update_JxW_values);
        const unsigned int                n = fe.n_dofs_per_cell();
        std::array<FullMatrix<double>, 3> matrices;
        for (auto &matrix : matrices)
          matrix.reinit(n, n);
        Vector<double>      force(n);
        double              lambda = 0, h = std::numeric_limits<double>::max();
        std::vector<double> scale(n);
        for (const auto &cell : d.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              h = std::min(h, cell->diameter());
              d.cell_matrices(cell, fe_values, matrices, force);
              for (unsigned int i = 0; i < n; ++i)
                {
                  double row = 0;
                  for (unsigned int j = 0; j < n; ++j)
                    row += matrices[0](i, j);
                  scale[i] = 1 / std::sqrt(row);
                }
              LAPACKFullMatrix<double> A(n, n);
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  A(i, j) = matrices[2](i, j) * scale[i] * scale[j];
              A.compute_eigenvalues();
              for (unsigned int i = 0; i < n; ++i)
                lambda = std::max(lambda, A.eigenvalue(i).real());
            }
        const MPI_Comm comm = d.triangulation.get_communicator();
        return {Utilities::MPI::max(lambda, comm),
                Utilities::MPI::min(h, comm)};
      }
    } // namespace


    template <int dim>
    ExplicitStep<dim>::ExplicitStep(
      const physics::Discretisation<dim>               &discretisation,
      const physics::ContactQuadrature<dim>            &contact,
      const friction::Law                              &law,
      std::function<double(const dealii::Point<dim> &)> along_base,
      const bool                                        two_stages)
      : discretisation(discretisation)
      , contact(contact)
      , law(law)
      , along_base(std::move(along_base))
      , potentials(contact.potentials(law))
      , load(discretisation.body_force)
      , p(two_stages ? 0.54 : 0.)
    {
      load += discretisation.prestress_force;
      const la::LocalMatrix &M = discretisation.mass_local;
      const la::LocalMatrix &C = discretisation.viscosity_local;
      const unsigned int     n = M.m();
      // a split fault's pairs (slip and mean): their partners' local index
      const auto &tie = discretisation.fault_tie;
      if (!tie.empty())
        {
          partner.assign(n, dealii::numbers::invalid_unsigned_int);
          for (unsigned int i = 0; i < n; ++i)
            {
              const auto g = discretisation.partitioner->local_to_global(i);
              if (tie.kind[g] == physics::tie_slip ||
                  tie.kind[g] == physics::tie_mean)
                partner[i] = discretisation.local_index(tie.partner[g]);
            }
          mass_coupling.assign(n, 0.);
          damping_coupling.assign(n, 0.);
          discretisation.reinit(mass_diagonal);
          discretisation.reinit(damping_diagonal);
          discretisation.reinit(rho_pairs);
        }
      const auto paired = [&](const unsigned int i) {
        return !partner.empty() &&
               partner[i] != dealii::numbers::invalid_unsigned_int;
      };
      mass.assign(n, 0.);
      damping.assign(n, 0.);
      for (unsigned int i = 0; i < n; ++i)
        {
          // (a pair's coupling stays out of the lumped mass)
          for (unsigned int j = M.row_begin(i); j < M.row_end(i); ++j)
            if (paired(i) && M.column(j) == partner[i])
              mass_coupling[i] = M.value(j);
            else
              mass[i] += M.value(j);
          for (unsigned int j = C.row_begin(i); j < C.row_end(i); ++j)
            {
              damped = damped || C.value(j) != 0;
              if (C.column(j) == i)
                damping[i] = C.value(j);
              else if (paired(i) && C.column(j) == partner[i])
                damping_coupling[i] = C.value(j);
            }
        }
      on_contact.assign(n, false);
      for (const auto &node : contact.contact_set().nodes)
        for (unsigned int l = 0; l < node.n_dofs; ++l)
          on_contact[node.dofs[l]] = true;
      if (!tie.empty())
        {
          for (unsigned int i = 0; i < n; ++i)
            {
              mass_diagonal.local_element(i)    = mass[i];
              damping_diagonal.local_element(i) = damping[i];
              // the pairs' free dofs off the contact, by kind
              const auto kind =
                tie.kind[discretisation.partitioner->local_to_global(i)];
              if (paired(i) && !discretisation.fixed[i] && !on_contact[i])
                (kind == physics::tie_slip ? free_slips : free_means)
                  .push_back(i);
            }
          mass_diagonal.update_ghost_values();
          damping_diagonal.update_ghost_values();
        }
      damped = dealii::Utilities::MPI::logical_or(
        damped, discretisation.triangulation.get_communicator());
      find_blocks();
      discretisation.reinit(damping_force);
      const auto [lambda, h] = largest_cell_eigenvalue(discretisation);
      // the largest omega tau of a stable step: central differences' 2;
      // Noh and Bathe's p = 0.54 scheme: 3.745029, where the spectral
      // radius of its amplification matrix for u'' = -omega^2 u reaches 1
      // (bisection on the 3 x 3 matrix; test explicit_shear_wave)
      stable = (p > 0 ? 3.745029 : 2.) / std::sqrt(lambda);
      h_min  = h;
    }


    template <int dim>
    std::optional<BodyState>
    ExplicitStep<dim>::operator()(const BodyState &old,
                                  const double     t,
                                  const double     tau)
    {
      if (p == 0)
        {
          la::Vector v_star = old.v;
          v_star.add(tau / 2, old.a);
          return stage(old, v_star, t, tau, 2 / tau, 0);
        }
      // Noh and Bathe (2013): central differences over p tau, then the
      // rest with the velocity from the three accelerations
      const double q1 = (1 - 2 * p) / (2 * p * (1 - p)), q2 = 0.5 - p * q1,
                   q0    = 0.5 - q1 - q2;
      const double tau_1 = p * tau, tau_2 = (1 - p) * tau;
      la::Vector   v_base = old.v;
      v_base.add(tau_1 / 2, old.a);
      const auto middle = stage(old, v_base, t, tau_1, 2 / tau_1, 0);
      if (!middle)
        return {};
      v_base = middle->v;
      v_base.add(tau_2 * q0, old.a, tau_2 * (0.5 + q1), middle->a);
      return stage(*middle, v_base, t + tau_1, tau_2, 1 / (tau_2 * q2), 1);
    }


    template <int dim>
    std::optional<BodyState>
    ExplicitStep<dim>::stage(const BodyState   &old,
                             const la::Vector  &v_star,
                             const double       t,
                             const double       tau,
                             const double       kappa,
                             const unsigned int slot)
    {
      BodyState next;
      next.u = old.u;
      next.u.add(tau, old.v, tau * tau / 2, old.a);

      // r = f - K u_{n+1} - C v*, the force without friction
      la::Vector r;
      r.reinit(load, true);
      discretisation.stiffness_local.residual(r, next.u, load);
      if (damped)
        {
          discretisation.viscosity_local.vmult(damping_force, v_star);
          r -= damping_force;
        }
      const unsigned int n = mass.size();

      const bool split = !partner.empty();
      if (split)
        pair_right_hand_sides(r, v_star, kappa);
      next.v = v_star;
      for (unsigned int i = 0; i < n; ++i)
        if (single[i])
          next.v.local_element(i) +=
            r.local_element(i) / (kappa * mass[i] + damping[i]);
      solve_blocks(r, kappa, slot, next.v);

      // a split fault's normal stress: the + side's reaction at u_{n+1}
      const auto &nodes = contact.contact_set().nodes;
      if (!discretisation.fault_tie.normal_of.empty())
        {
          // the + side's inertia from the last acceleration (the new one
          // needs the friction that needs this stress)
          if (!physics::split_normal_stresses(
                discretisation, contact, next.u, &old.a, next.normal_stress))
            {
              failure = "t = " + format_number(t + tau) + " s, explicit step " +
                        format_number(tau) +
                        " s: a fault node lost its compression (the normal "
                        "stress changed by the slip is not positive)";
              return {};
            }
          for (unsigned int k = 0; k < nodes.size(); ++k)
            potentials[k].normal_force =
              next.normal_stress[k] * contact.nodes()[k].weight;
        }

      // the contact: the state from the old slip rate, then from the mean
      std::vector<double> alpha(old.alpha.size());
      update_states(old, old.v, tau, alpha);
      solve_contact(r, v_star, alpha, kappa, next.v, nullptr);
      update_states(old, next.v, tau, alpha);
      solve_contact(r, v_star, alpha, kappa, next.v, &next.shear_traction);
      update_states(old, next.v, tau, alpha);
      next.alpha = std::move(alpha);

      discretisation.set_fixed_values(next.v, t + tau);
      if (split)
        solve_pairs(kappa, next.v);
      next.v.zero_out_ghost_values();
      discretisation.hanging_constraints.distribute(next.v);
      next.a = next.v;
      next.a -= v_star;
      next.a *= kappa;

      if (!finite(next, t, tau))
        return {};
      return next;
    }


    template <int dim>
    bool
    ExplicitStep<dim>::finite(const BodyState &next,
                              const double     t,
                              const double     tau)
    {
      // every rank rejects the step alike
      const auto  &nodes = contact.contact_set().nodes;
      const double norms = next.u.l2_norm() + next.v.l2_norm();
      std::string  bad_state;
      for (unsigned int k = 0; k < nodes.size() && bad_state.empty(); ++k)
        if (!std::isfinite(next.alpha[k]))
          bad_state = format_number(along_base(contact.nodes()[k].position));
      const MPI_Comm comm = discretisation.triangulation.get_communicator();
      if (std::isfinite(norms) &&
          dealii::Utilities::MPI::max(bad_state.empty() ? 0 : 1, comm) == 0)
        return true;
      failure = "t = " + format_number(t + tau) + " s, explicit step " +
                format_number(tau) + " s: non-finite " +
                (std::isfinite(norms) ?
                   "friction state" +
                     (bad_state.empty() ?
                        std::string(" on another rank") :
                        " at the base node at s = " + bad_state + " m") :
                   std::string("displacement or velocity"));
      return false;
    }


    template <int dim>
    void
    ExplicitStep<dim>::solve_contact(const la::Vector          &r,
                                     const la::Vector          &v_star,
                                     const std::vector<double> &alpha,
                                     const double               kappa,
                                     la::Vector                &v,
                                     std::vector<double>       *traction)
    {
      const auto &nodes = contact.contact_set().nodes;
      if (traction)
        traction->assign(nodes.size(), 0.);
      for (unsigned int k = 0; k < nodes.size(); ++k)
        {
          potentials[k].set_state(alpha[k]);
          std::array<double, 2> a{}, rho{}, guess{};
          for (unsigned int l = 0; l < nodes[k].n_dofs; ++l)
            {
              const auto i = nodes[k].dofs[l];
              a[l]         = kappa * mass[i] + damping[i];
              rho[l]   = r.local_element(i) + a[l] * v_star.local_element(i);
              guess[l] = v.local_element(i);
              if (!partner.empty() &&
                  partner[i] != dealii::numbers::invalid_unsigned_int)
                {
                  // the pair's mean eliminated
                  const auto [a_pair, rho_pair] = condensed(i, kappa);
                  a[l] -= a_pair;
                  rho[l] = rho_pairs.local_element(i) - rho_pair;
                }
            }
          std::array<double, 2> x{};
          if (nodes[k].n_dofs == 1)
            {
              const std::array<double, 1> g{{guess[0]}};
              x[0] = friction::solve_local_problem<1>({{a[0]}},
                                                      {{rho[0]}},
                                                      potentials[k],
                                                      &g)
                       .x[0];
            }
          else
            x = friction::solve_local_problem<2>({{a[0], 0., 0., a[1]}},
                                                 rho,
                                                 potentials[k],
                                                 &guess)
                  .x;
          double f2 = 0;
          for (unsigned int l = 0; l < nodes[k].n_dofs; ++l)
            {
              v.local_element(nodes[k].dofs[l]) = x[l];
              f2 += std::pow(rho[l] - a[l] * x[l], 2);
            }
          if (traction)
            (*traction)[k] = std::sqrt(f2) / contact.nodes()[k].weight;
        }
    }


    template <int dim>
    void
    ExplicitStep<dim>::find_blocks()
    {
      // the free dofs off the contact and the pairs, joined where C couples
      // two of them (union-find): a vertex's dashpot on a face not aligned
      // with the axes joins the vertex's components
      const la::LocalMatrix &C = discretisation.viscosity_local;
      const unsigned int     n = mass.size();
      std::vector<bool>      free(n);
      for (unsigned int i = 0; i < n; ++i)
        free[i] = !discretisation.fixed[i] && !on_contact[i] &&
                  (partner.empty() ||
                   partner[i] == dealii::numbers::invalid_unsigned_int);
      std::vector<unsigned int> root(n);
      for (unsigned int i = 0; i < n; ++i)
        root[i] = i;
      const auto find = [&root](unsigned int i) {
        while (root[i] != i)
          i = root[i] = root[root[i]];
        return i;
      };
      for (unsigned int i = 0; i < n; ++i)
        if (free[i])
          for (unsigned int j = C.row_begin(i); j < C.row_end(i); ++j)
            if (const unsigned int c = C.column(j);
                c != i && c < n && free[c] && C.value(j) != 0)
              root[find(i)] = find(c);
      std::map<unsigned int, std::vector<unsigned int>> components;
      for (unsigned int i = 0; i < n; ++i)
        if (free[i])
          components[find(i)].push_back(i);
      single.assign(n, false);
      std::size_t largest = 1;
      for (auto &[r, dofs] : components)
        if (dofs.size() == 1)
          single[dofs[0]] = true;
        else
          {
            largest = std::max(largest, dofs.size());
            Block block;
            block.dofs = dofs;
            block.damping.reinit(dofs.size(), dofs.size());
            for (unsigned int k = 0; k < dofs.size(); ++k)
              for (unsigned int j = C.row_begin(dofs[k]);
                   j < C.row_end(dofs[k]);
                   ++j)
                for (unsigned int l = 0; l < dofs.size(); ++l)
                  if (C.column(j) == dofs[l])
                    block.damping(k, l) = C.value(j);
            blocks.push_back(std::move(block));
          }
      const MPI_Comm comm = discretisation.triangulation.get_communicator();
      if (dealii::Utilities::MPI::max(static_cast<unsigned int>(largest),
                                      comm) > (dim == 3 ? 3u : 2u))
        refused = "the damping matrix C couples the dofs of different nodes "
                  "(Kelvin-Voigt viscosity); the explicit step needs C "
                  "lumped at the nodes";
    }


    template <int dim>
    void
    ExplicitStep<dim>::solve_blocks(const la::Vector  &r,
                                    const double       kappa,
                                    const unsigned int slot,
                                    la::Vector        &v)
    {
      // (kappa M_L + C)^-1 of every block, one per stage of a step,
      // inverted again only when the step changes (the last step before
      // End time, or a new Courant step)
      if (kappa != blocks_kappa[slot])
        {
          for (auto &block : blocks)
            {
              block.inverse[slot] = block.damping;
              for (unsigned int k = 0; k < block.dofs.size(); ++k)
                block.inverse[slot](k, k) += kappa * mass[block.dofs[k]];
              block.inverse[slot].gauss_jordan();
            }
          blocks_kappa[slot] = kappa;
        }
      for (const auto &block : blocks)
        for (unsigned int k = 0; k < block.dofs.size(); ++k)
          for (unsigned int l = 0; l < block.dofs.size(); ++l)
            v.local_element(block.dofs[k]) +=
              block.inverse[slot](k, l) * r.local_element(block.dofs[l]);
    }


    template <int dim>
    void
    ExplicitStep<dim>::pair_right_hand_sides(const la::Vector &r,
                                             const la::Vector &v_star,
                                             const double      kappa)
    {
      v_star.update_ghost_values();
      for (unsigned int i = 0; i < partner.size(); ++i)
        if (partner[i] != dealii::numbers::invalid_unsigned_int)
          rho_pairs.local_element(i) =
            r.local_element(i) +
            (kappa * mass[i] + damping[i]) * v_star.local_element(i) +
            (kappa * mass_coupling[i] + damping_coupling[i]) *
              v_star.local_element(partner[i]);
      rho_pairs.update_ghost_values();
    }


    template <int dim>
    std::pair<double, double>
    ExplicitStep<dim>::condensed(const unsigned int i, const double kappa) const
    {
      const unsigned int j    = partner[i];
      const double       a_ij = kappa * mass_coupling[i] + damping_coupling[i];
      const double       a_jj = kappa * mass_diagonal.local_element(j) +
                          damping_diagonal.local_element(j);
      return {a_ij * a_ij / a_jj, a_ij * rho_pairs.local_element(j) / a_jj};
    }


    template <int dim>
    void
    ExplicitStep<dim>::solve_pairs(const double kappa, la::Vector &v) const
    {
      // a free slip off the contact (none in the shipped meshes) first,
      // then every free mean from its slip (ghosts exchanged between)
      for (const unsigned int i : free_slips)
        {
          const auto [a_pair, rho_pair] = condensed(i, kappa);
          v.local_element(i) = (rho_pairs.local_element(i) - rho_pair) /
                               (kappa * mass[i] + damping[i] - a_pair);
        }
      v.update_ghost_values();
      for (const unsigned int i : free_means)
        v.local_element(i) = (rho_pairs.local_element(i) -
                              (kappa * mass_coupling[i] + damping_coupling[i]) *
                                v.local_element(partner[i])) /
                             (kappa * mass[i] + damping[i]);
    }


    template <int dim>
    void
    ExplicitStep<dim>::update_states(const BodyState     &old,
                                     const la::Vector    &v,
                                     const double         tau,
                                     std::vector<double> &alpha) const
    {
      const auto &nodes = contact.contact_set().nodes;
      for (unsigned int k = 0; k < nodes.size(); ++k)
        {
          double v2 = 0;
          for (unsigned int l = 0; l < nodes[k].n_dofs; ++l)
            {
              const auto dof = nodes[k].dofs[l];
              v2 +=
                std::pow((old.v.local_element(dof) + v.local_element(dof)) / 2,
                         2);
            }
          alpha[k] = law.update_state(contact.nodes()[k].params,
                                      old.alpha[k],
                                      std::sqrt(v2),
                                      tau);
        }
    }


    template class ExplicitStep<2>;
    template class ExplicitStep<3>;
  } // namespace models
} // namespace rsfcycle
