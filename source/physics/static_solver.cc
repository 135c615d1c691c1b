// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/lac/solver_cg.h>
#include <rsfcycle/physics/static_solver.h>
#include <rsfcycle/solvers/amg_correction.h>
#include <stdexcept>
#include <string>

namespace rsfcycle
{
  namespace physics
  {
    template <int dim>
    StaticSolver<dim>::StaticSolver(const Discretisation<dim> &discretisation,
                                    const std::vector<unsigned int> &prescribed)
      : discretisation(discretisation)
      , held(discretisation.fixed)
    {
      for (const unsigned int i : prescribed)
        held[i] = true;
      // (the ghosts' flags of the added dofs from their owners)
      la::Vector flags;
      discretisation.reinit(flags);
      for (unsigned int i = 0;
           i < discretisation.partitioner->locally_owned_size();
           ++i)
        flags.local_element(i) = held[i];
      flags.update_ghost_values();
      for (unsigned int i = 0; i < held.size(); ++i)
        held[i] = held[i] || flags.local_element(i) != 0;

      matrix.copy_from(discretisation.stiffness_matrix);
      la::for_each_entry(matrix,
                         [&](const types::global_dof_index row,
                             const types::global_dof_index column,
                             double                       &value) {
                           if (held[discretisation.local_index(row)] ||
                               held[discretisation.local_index(column)])
                             value = (row == column) ? 1. : 0.;
                         });
      amg.initialize(
        matrix, solvers::elasticity_amg_data(discretisation.dof_components()));
      matrix_local =
        std::make_unique<la::LocalMatrix>(matrix, discretisation.partitioner);
    }


    template <int dim>
    void
    StaticSolver<dim>::solve(la::Vector &u, const la::Vector *f) const
    {
      const unsigned int n_owned =
        discretisation.partitioner->locally_owned_size();
      // the prescribed part u_p alone, and rhs = f - K u_p on the free rows,
      // u_p on the held ones (identity rows)
      la::Vector given, rhs;
      discretisation.reinit(given);
      discretisation.reinit(rhs);
      for (unsigned int i = 0; i < n_owned; ++i)
        if (held[i])
          given.local_element(i) = u.local_element(i);
      discretisation.stiffness_local.vmult(rhs, given);
      rhs *= -1.;
      if (f)
        rhs += *f;
      for (unsigned int i = 0; i < n_owned; ++i)
        if (held[i])
          rhs.local_element(i) = given.local_element(i);
      la::Vector            x(given);
      const double          norm = rhs.l2_norm();
      dealii::SolverControl control(2000, 1e-12 * norm, false, false);
      if (norm > 0)
        try
          {
            dealii::SolverCG<la::Vector>(control).solve(*matrix_local,
                                                        x,
                                                        rhs,
                                                        amg);
          }
        catch (const dealii::SolverControl::NoConvergence &failure)
          {
            throw std::runtime_error(
              "the volume displacement for the VTU output did not converge "
              "(CG with algebraic multigrid: relative residual " +
              std::to_string(failure.last_residual / norm) + " after " +
              std::to_string(failure.last_step) + " iterations)");
          }
      iterations = control.last_step();
      x.zero_out_ghost_values();
      discretisation.hanging_constraints.distribute(x);
      u = x;
    }


    template class StaticSolver<2>;
    template class StaticSolver<3>;
  } // namespace physics
} // namespace rsfcycle
