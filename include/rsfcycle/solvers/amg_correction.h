// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_solvers_amg_correction_h
#define rsfcycle_solvers_amg_correction_h

#include <deal.II/lac/trilinos_precondition.h>
#include <memory>
#include <rsfcycle/la.h>
#include <rsfcycle/solvers/projected_cg.h>
#include <rsfcycle/solvers/spatial_problem.h>
#include <vector>

namespace rsfcycle
{
  namespace solvers
  {
    /**
     * Algebraic multigrid (Trilinos ML) as the linear correction, for
     * comparison and as a fall-back: one AMG hierarchy per step matrix
     * (cached by matrix_key; the fixed rows and columns decoupled), whose
     * contact blocks get the friction Hessian and the truncation of the
     * TNNMG iteration (the hierarchy is recomputed on the aggregates of its
     * first setup when a contact diagonal changed by more than a factor 2
     * since), used as preconditioner of CG on the truncated system
     * (ProjectedCG), which sees the exact operator.
     */
    /**
     * Trilinos ML settings for an elasticity matrix: elliptic, one constant
     * (translation) mode per displacement component (`component_of_dof`:
     * the component of every dof).
     */
    dealii::TrilinosWrappers::PreconditionAMG::AdditionalData
    elasticity_amg_data(const std::vector<unsigned int> &component_of_dof);

    class AMGCorrection : public LinearCorrection
    {
    public:
      /**
       * component_of_dof: the vector component of every dof (the
       * translations are AMG's near-null space).
       */
      AMGCorrection(const LinearCorrectionControl   &control,
                    const std::vector<unsigned int> &component_of_dof);
      ~AMGCorrection() override;

      unsigned int
      solve(const TruncatedNewtonSystem &system,
            const la::Vector            &rhs,
            la::Vector                  &correction) override;

    private:
      struct Hierarchy;
      Hierarchy &
      hierarchy(const TruncatedNewtonSystem &system);
      void
      update(Hierarchy &h, const TruncatedNewtonSystem &system);

      LinearCorrectionControl                 control;
      std::vector<unsigned int>               component_of_dof;
      std::vector<std::unique_ptr<Hierarchy>> cache;
      ProjectedCG                             cg;
    };
  } // namespace solvers
} // namespace rsfcycle

#endif
