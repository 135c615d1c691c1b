// SPDX-License-Identifier: LGPL-2.1-or-later
#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <limits>
#include <rsfcycle/format.h>
#include <rsfcycle/friction/local_solve.h>
#include <rsfcycle/models/explicit_step.h>

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
      std::function<double(const dealii::Point<dim> &)> along_base)
      : discretisation(discretisation)
      , contact(contact)
      , law(law)
      , along_base(std::move(along_base))
      , potentials(contact.potentials(law))
      , load(discretisation.body_force)
    {
      load += discretisation.prestress_force;
      const la::LocalMatrix &M = discretisation.mass_local;
      const la::LocalMatrix &C = discretisation.viscosity_local;
      const unsigned int     n = M.m();
      mass.assign(n, 0.);
      damping.assign(n, 0.);
      bool diagonal = true;
      for (unsigned int i = 0; i < n; ++i)
        {
          for (unsigned int j = M.row_begin(i); j < M.row_end(i); ++j)
            mass[i] += M.value(j);
          for (unsigned int j = C.row_begin(i); j < C.row_end(i); ++j)
            if (C.column(j) == i)
              damping[i] = C.value(j);
            else if (C.value(j) != 0 && !discretisation.fixed[i])
              diagonal = false;
        }
      on_contact.assign(n, false);
      for (const auto &node : contact.contact_set().nodes)
        for (unsigned int l = 0; l < node.n_dofs; ++l)
          on_contact[node.dofs[l]] = true;
      const MPI_Comm comm = discretisation.triangulation.get_communicator();
      if (dealii::Utilities::MPI::max(discretisation.fault_tie.empty() ? 0 : 1,
                                      comm) > 0)
        refused = "a fault-opposite side (Boundary roles) has no explicit "
                  "step yet (its tied unknowns have no lumped mass)";
      else if (dealii::Utilities::MPI::min(diagonal ? 1 : 0, comm) == 0)
        refused = "the damping matrix C is not diagonal (Kelvin-Voigt "
                  "viscosity, or an absorbing face not aligned with the "
                  "axes); the explicit step needs a lumped C";
      const auto [lambda, h] = largest_cell_eigenvalue(discretisation);
      stable                 = 2 / std::sqrt(lambda);
      h_min                  = h;
    }


    template <int dim>
    std::optional<BodyState>
    ExplicitStep<dim>::operator()(const BodyState &old,
                                  const double     t,
                                  const double     tau)
    {
      BodyState next;
      next.u = old.u;
      next.u.add(tau, old.v, tau * tau / 2, old.a);
      la::Vector v_star = old.v;
      v_star.add(tau / 2, old.a);

      // r = f - K u_{n+1} - C v*, the force without friction
      la::Vector r;
      r.reinit(load, true);
      discretisation.stiffness_local.residual(r, next.u, load);
      const unsigned int n = mass.size();
      for (unsigned int i = 0; i < n; ++i)
        r.local_element(i) -= damping[i] * v_star.local_element(i);

      next.v = v_star;
      for (unsigned int i = 0; i < n; ++i)
        if (!discretisation.fixed[i] && !on_contact[i])
          next.v.local_element(i) +=
            r.local_element(i) / (2 * mass[i] / tau + damping[i]);

      // the contact: the state from the old slip rate, then from the mean
      std::vector<double> alpha(old.alpha.size());
      const auto         &nodes = contact.contact_set().nodes;
      for (unsigned int k = 0; k < nodes.size(); ++k)
        {
          double v2 = 0;
          for (unsigned int l = 0; l < nodes[k].n_dofs; ++l)
            v2 += std::pow(old.v.local_element(nodes[k].dofs[l]), 2);
          alpha[k] = law.update_state(contact.nodes()[k].params,
                                      old.alpha[k],
                                      std::sqrt(v2),
                                      tau);
        }
      solve_contact(r, v_star, alpha, tau, next.v, nullptr);
      update_states(old, next.v, tau, alpha);
      solve_contact(r, v_star, alpha, tau, next.v, &next.shear_traction);
      update_states(old, next.v, tau, alpha);
      next.alpha = std::move(alpha);

      discretisation.set_fixed_values(next.v, t + tau);
      next.v.zero_out_ghost_values();
      discretisation.hanging_constraints.distribute(next.v);
      next.a = next.v;
      next.a -= v_star;
      next.a *= 2 / tau;

      // every rank rejects the step alike
      const double norms = next.u.l2_norm() + next.v.l2_norm();
      std::string  bad_state;
      for (unsigned int k = 0; k < nodes.size() && bad_state.empty(); ++k)
        if (!std::isfinite(next.alpha[k]))
          bad_state = format_number(along_base(contact.nodes()[k].position));
      const MPI_Comm comm = discretisation.triangulation.get_communicator();
      if (!std::isfinite(norms) ||
          dealii::Utilities::MPI::max(bad_state.empty() ? 0 : 1, comm) > 0)
        {
          failure = "t = " + format_number(t + tau) + " s, explicit step " +
                    format_number(tau) + " s: non-finite " +
                    (std::isfinite(norms) ?
                       "friction state" +
                         (bad_state.empty() ?
                            std::string(" on another rank") :
                            " at the base node at s = " + bad_state + " m") :
                       std::string("displacement or velocity"));
          return {};
        }
      return next;
    }


    template <int dim>
    void
    ExplicitStep<dim>::solve_contact(const la::Vector          &r,
                                     const la::Vector          &v_star,
                                     const std::vector<double> &alpha,
                                     const double               tau,
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
              a[l]         = 2 * mass[i] / tau + damping[i];
              rho[l]   = r.local_element(i) + a[l] * v_star.local_element(i);
              guess[l] = v.local_element(i);
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
