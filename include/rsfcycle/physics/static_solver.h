// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_physics_static_solver_h
#define rsfcycle_physics_static_solver_h

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <memory>
#include <rsfcycle/la.h>
#include <rsfcycle/local_matrix.h>
#include <rsfcycle/physics/discretisation.h>
#include <vector>

namespace rsfcycle
{
  namespace physics
  {
    /**
     * The static equilibrium K u = f of the body with u prescribed on the
     * fixed dofs (load boundaries, hanging nodes) and on further dofs of
     * the caller's (the contact's tangential dofs): the displacement and
     * velocity of the whole body that the Green's-function method
     * (models::GreenFault) writes at output times from the fault's slip
     * and slip rate. The matrix with the prescribed rows and columns
     * replaced by the identity and its algebraic multigrid are built once;
     * every solve is one CG run (relative residual 1e-12) on N ranks.
     */
    template <int dim>
    class StaticSolver
    {
    public:
      /**
       * `prescribed`: local indices (owned) of the dofs held besides the
       * discretisation's fixed ones.
       */
      StaticSolver(const Discretisation<dim>       &discretisation,
                   const std::vector<unsigned int> &prescribed);

      /**
       * u: on entry the prescribed values (the others are ignored), on
       * exit the equilibrium with the load f (none: zero), hanging nodes
       * distributed. Throws std::runtime_error if CG does not converge.
       */
      void
      solve(la::Vector &u, const la::Vector *f = nullptr) const;

      /** CG iterations of the last solve. */
      unsigned int
      last_iterations() const
      {
        return iterations;
      }

    private:
      const Discretisation<dim>                &discretisation;
      std::vector<bool>                         held; // by local index
      dealii::TrilinosWrappers::SparseMatrix    matrix;
      dealii::TrilinosWrappers::PreconditionAMG amg;
      std::unique_ptr<la::LocalMatrix>          matrix_local;
      mutable unsigned int                      iterations = 0;
    };
  } // namespace physics
} // namespace rsfcycle

#endif
