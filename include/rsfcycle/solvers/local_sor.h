// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_solvers_local_sor_h
#define rsfcycle_solvers_local_sor_h

#include <deal.II/base/mg_level_object.h>
#include <deal.II/multigrid/mg_base.h>
#include <rsfcycle/la.h>
#include <rsfcycle/local_matrix.h>

namespace rsfcycle
{
  namespace solvers
  {
    /**
     * The multigrid smoother: `steps` Gauss-Seidel sweeps (forward, or
     * backward for the transpose) over each rank's rows of the level matrix
     * (LocalMatrix), the other ranks' entries as they were when the
     * smoothing began: processor-local (block Jacobi across ranks,
     * Gauss-Seidel within a rank). One exchange of ghost values per
     * smoothing, none for apply() (which starts from zero, so the frozen
     * ghosts are zero). The forward pre-smoother and the backward
     * post-smoother are adjoint, so the V-cycle stays symmetric for CG. On
     * one rank: deal.II's SOR smoother with omega = 1.
     */
    class LocalSORSmoother : public dealii::MGSmoother<la::Vector>
    {
    public:
      LocalSORSmoother(const unsigned int steps, const bool transpose)
        : dealii::MGSmoother<la::Vector>(steps, false, false, transpose)
      {}

      void
      initialize(const dealii::MGLevelObject<la::LocalMatrix> &level_matrices)
      {
        matrices = &level_matrices;
      }

      void
      clear() override
      {
        matrices = nullptr;
      }

      void
      smooth(const unsigned int level,
             la::Vector        &u,
             const la::Vector  &rhs) const override
      {
        (*matrices)[level].relax(u, rhs, this->steps, !this->transpose, false);
      }

      void
      apply(const unsigned int level,
            la::Vector        &u,
            const la::Vector  &rhs) const override
      {
        u = 0;
        (*matrices)[level].relax(u, rhs, this->steps, !this->transpose, true);
      }

    private:
      const dealii::MGLevelObject<la::LocalMatrix> *matrices = nullptr;
    };
  } // namespace solvers
} // namespace rsfcycle

#endif
