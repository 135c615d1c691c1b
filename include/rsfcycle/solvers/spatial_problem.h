// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_solvers_spatial_problem_h
#define rsfcycle_solvers_spatial_problem_h

#include <array>
#include <cmath>
#include <deal.II/base/types.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <functional>
#include <rsfcycle/friction/local_solve.h>
#include <rsfcycle/la.h>
#include <rsfcycle/local_matrix.h>
#include <vector>

namespace rsfcycle
{
  namespace solvers
  {
    using dealii::types::global_dof_index;

    /**
     * One contact node: the tangential degrees of freedom of one base vertex
     * that are free (1 in 2D; 2 in 3D, or 1 where a 3D base vertex also lies
     * on a free-slip wall), as local indices of the vectors (a rank has the
     * nodes whose dofs it owns). Its normal component is fixed (u.n = 0).
     */
    struct ContactNode
    {
      std::array<unsigned int, 2> dofs{};
      unsigned int                n_dofs = 0;
    };

    /**
     * |(v_T)| of one node, without forming squares (slip rates of stuck nodes
     * can be ~1e-160 m/s, whose square underflows).
     */
    inline double
    tangential_norm(const ContactNode &node, const la::Vector &v)
    {
      return node.n_dofs == 1 ? std::abs(v.local_element(node.dofs[0])) :
                                std::hypot(v.local_element(node.dofs[0]),
                                           v.local_element(node.dofs[1]));
    }

    /**
     * The contact nodes of a rank and, per local index (owned, then
     * ghosts), the node it belongs to (-1 if none). Built once per mesh.
     */
    struct ContactSet
    {
      std::vector<ContactNode> nodes;
      std::vector<int>         dof_to_node;

      void
      build_index(const unsigned int n_local)
      {
        dof_to_node.assign(n_local, -1);
        for (unsigned int i = 0; i < nodes.size(); ++i)
          for (unsigned int k = 0; k < nodes[i].n_dofs; ++k)
            dof_to_node[nodes[i].dofs[k]] = static_cast<int>(i);
      }
    };

    /**
     * The spatial problem (15) for a fixed state, as a convex minimisation
     * (doc/model.md §4.2):
     *   min J(v) = 1/2 v^T A v - r^T v + sum_i phi_i(|v_{T_i}|)
     * over all v whose entries marked `fixed` (Dirichlet values, hanging
     * nodes) keep the values they have on entry.
     */
    struct SpatialProblem
    {
      /** The rank's rows of A. */
      const la::LocalMatrix *local_A = nullptr;
      /** A assembled as a Trilinos matrix (algebraic multigrid). */
      std::function<const dealii::TrilinosWrappers::SparseMatrix &()>
                                                  assembled_A;
      const la::Vector                           *rhs        = nullptr;
      const std::vector<bool>                    *fixed      = nullptr;
      const ContactSet                           *contact    = nullptr;
      const std::vector<friction::NodePotential> *potentials = nullptr;
      /** Passed on to TruncatedNewtonSystem::matrix_key. */
      double matrix_key = 0;
    };

    /**
     * The truncated Newton system of one TNNMG iteration (doc/model.md §4.2
     * step 3): (A + H) c = rhs on the components not truncated; c = 0 on the
     * truncated ones. H is block diagonal with one d x d block (row-major)
     * per contact node; blocks of truncated nodes are zero.
     */
    struct TruncatedNewtonSystem
    {
      const la::LocalMatrix *local_A = nullptr;
      std::function<const dealii::TrilinosWrappers::SparseMatrix &()>
                                                assembled_A;
      const ContactSet                         *contact       = nullptr;
      const std::vector<std::array<double, 4>> *node_hessians = nullptr;
      /** By local index (owned, then ghosts). */
      const std::vector<bool> *truncated = nullptr;
      /**
       * Identifies the content of A (here: the step size tau), so that a
       * correction may cache what it derives from A. Entries of `truncated`
       * that are not contact dofs (the fixed dofs) must not change while A
       * keeps its key.
       */
      double matrix_key = 0;
    };

    /**
     * The linear correction of TNNMG behind one interface, so that the
     * sparse direct solve, algebraic and geometric multigrid plug in without
     * touching the TNNMG step.
     */
    class LinearCorrection
    {
    public:
      virtual ~LinearCorrection() = default;

      /**
       * Solve the truncated system approximately; return the number of
       * inner iterations (multigrid cycles; 1 for a direct solve).
       */
      virtual unsigned int
      solve(const TruncatedNewtonSystem &system,
            const la::Vector            &rhs,
            la::Vector                  &correction) = 0;

      /**
       * Drop what depends on the history of earlier solves rather than on
       * the step matrix alone (called when a checkpoint is written, so that
       * a resumed run solves as the uninterrupted one).
       */
      virtual void
      forget()
      {}
    };
  } // namespace solvers
} // namespace rsfcycle

#endif
