// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_physics_interior_solver_h
#define rsfcycle_physics_interior_solver_h

#include <deal.II/lac/full_matrix.h>
#include <rsfcycle/physics/global_system.h>
#include <rsfcycle/solvers/sparse_cholesky.h>
#include <vector>

namespace rsfcycle
{
  namespace physics
  {
    /**
     * The bulk's equilibrium in a gathered system (GlobalSystem) with the
     * contact's tangential dofs c and the fixed dofs b given: the other
     * dofs I from
     *   K_II u_I = f_I - K_Ic u_c - K_Ib u_b,
     * with a CHOLMOD factor of K_II (solvers::SparseCholesky), made once.
     * physics::compute_green_operator() takes the columns K_II^-1 K_Ic of
     * its Schur complement from it; models::GreenFault::body() the whole
     * body of a split fault, in the tied unknowns (physics/split_fault.h).
     * The factor holds all of K_II, once per node: the node's first rank
     * factorises and its other ranks solve with that factor
     * (solvers::SparseCholesky::factorize_shared()).
     */
    class InteriorSolver
    {
    public:
      /**
       * Index the dofs and factorise K_II of `system` (the same on every
       * rank of `communicator`; collective, as is the destructor).
       */
      InteriorSolver(const GlobalSystem &system, MPI_Comm communicator);

      /** The number of interior dofs, n_I. */
      unsigned int
      n_interior() const
      {
        return interior.size();
      }

      /** The position of dof i among the interior ones; -1 if not one. */
      int
      interior_index(const unsigned int i) const
      {
        return index[i];
      }

      /** The dof of interior position k. */
      unsigned int
      interior_dof(const unsigned int k) const
      {
        return interior[k];
      }

      /** The factor's size in bytes (held once per node). */
      std::size_t
      factor_bytes() const
      {
        return cholesky.memory_bytes();
      }

      /** X = K_II^-1 B for all columns of B (n_I rows). */
      void
      solve(const dealii::FullMatrix<double> &B,
            dealii::FullMatrix<double>       &X) const;

      /**
       * u (all dofs of the system): on entry the contact and the fixed
       * dofs' values (the others are ignored), on exit the interior ones
       * of the equilibrium with the system's force f (`with_force`) or
       * none.
       */
      void
      equilibrium(const GlobalSystem  &system,
                  std::vector<double> &u,
                  bool                 with_force) const;

    private:
      std::vector<int>          index;
      std::vector<unsigned int> interior;
      solvers::SparseCholesky   cholesky;
    };
  } // namespace physics
} // namespace rsfcycle

#endif
