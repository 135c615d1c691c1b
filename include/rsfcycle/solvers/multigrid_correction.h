// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_solvers_multigrid_correction_h
#define rsfcycle_solvers_multigrid_correction_h

#include <array>
#include <boost/serialization/array.hpp>
#include <deal.II/base/mg_level_object.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/multigrid/mg_constrained_dofs.h>
#include <deal.II/multigrid/mg_transfer.h>
#include <functional>
#include <memory>
#include <rsfcycle/la.h>
#include <rsfcycle/local_matrix.h>
#include <rsfcycle/solvers/projected_cg.h>
#include <rsfcycle/solvers/spatial_problem.h>
#include <vector>

namespace rsfcycle
{
  namespace solvers
  {
    /**
     * The geometric multigrid linear correction of TNNMG (doc/model.md §4.2
     * step 3) on the levels of the locally refined mesh (local smoothing as
     * in deal.II's step-16: MGTransferPrebuilt, MGConstrainedDoFs, edge
     * matrices at refinement edges).
     *
     * Level operators. The level mass, viscosity and stiffness matrices are
     * assembled once per mesh; for each step matrix (matrix_key) the level
     * step matrices are their linear combination (cached for a few keys, no
     * reassembly). Per TNNMG iteration only the diagonal blocks of the
     * contact vertices change on every level where the vertex exists:
     *  - a non-truncated node adds its friction Hessian block, scaled by the
     *    ratio of the vertex' lumped weight on that level to its weight on
     *    the active mesh (the level's own lumped quadrature);
     *  - a truncated node gets its diagonal multiplied by
     *    (1 + truncation_penalty), so
     *    that smoother and coarse solve keep its correction at ~0 on every
     *    level (the truncation seen by the whole hierarchy).
     * The entries are restored exactly before the next change.
     *
     * Use. The symmetric V(nu, nu)-cycle with Gauss-Seidel smoothing
     * (forward before, backward after the coarse correction) preconditions
     * CG on the truncated system (ProjectedCG), which stops after
     * LinearCorrectionControl::max_cycles cycles or a relative residual
     * reduction of LinearCorrectionControl::tolerance. The CG acceleration
     * makes the correction robust where the rediscretised coarse levels are
     * not Galerkin-consistent with the truncation.
     */
    template <int dim>
    class MultigridCorrection : public LinearCorrection
    {
    public:
      using LevelCellIterator =
        typename dealii::DoFHandler<dim>::level_cell_iterator;

      /** Mass, viscosity and stiffness matrix of one (level) cell. */
      using CellMatrices =
        std::function<void(const LevelCellIterator &,
                           std::array<dealii::FullMatrix<double>, 3> &)>;

      /** The factors of M, C, K in the step matrix with a given key. */
      using Coefficients = std::function<std::array<double, 3>(double)>;

      /** Homogeneous Dirichlet components of one boundary. */
      struct DirichletBoundary
      {
        dealii::types::boundary_id id;
        dealii::ComponentMask      components;
      };

      /**
       * Where a contact node lives: its vertex' position, the vector
       * components of its dofs (in the order of ContactNode::dofs) and its
       * lumped weight on the active mesh. The constructor takes the nodes of
       * all ranks, rank by rank (each rank's in the order of its
       * ContactSet).
       */
      struct ContactVertex
      {
        dealii::Point<dim>          position;
        std::array<unsigned int, 2> components{};
        unsigned int                n_components = 0;
        double                      weight       = 0;

        /** For gathering over ranks. */
        template <class Archive>
        void
        serialize(Archive &ar, const unsigned int)
        {
          ar &position &components &n_components &weight;
        }
      };

      struct Settings
      {
        unsigned int smoothing_steps = 3;
        /** Coarse levels of at least this many dofs keep their factor
         * while the contact blocks stay close (`Coarse factor reuse
         * size`). */
        unsigned int            coarse_reuse_size = 10000;
        LinearCorrectionControl control;
      };

      /**
       * The DoFHandler must have its level dofs distributed. contact_id is
       * the boundary that carries the friction.
       */
      MultigridCorrection(const dealii::DoFHandler<dim>        &dof_handler,
                          const std::vector<DirichletBoundary> &dirichlet,
                          dealii::types::boundary_id            contact_id,
                          const std::vector<ContactVertex> &contact_vertices,
                          const CellMatrices               &cell_matrices,
                          const Coefficients               &coefficients,
                          const Settings                   &settings);
      ~MultigridCorrection() override;

      unsigned int
      solve(const TruncatedNewtonSystem &system,
            const la::Vector            &rhs,
            la::Vector                  &correction) override;

      /** Number of levels and dofs per level (for logs). */
      std::vector<dealii::types::global_dof_index>
      level_sizes() const;

      /** The coarse level's factorisations so far (for logs and tests). */
      unsigned int
      coarse_factorisations() const
      {
        return n_coarse_factorisations;
      }

    private:
      struct LevelOperators;
      LevelOperators &
      operators(double key);

      /** Put the Hessian/truncation of `system` into the level matrices. */
      void
      update_contact_blocks(LevelOperators              &ops,
                            const TruncatedNewtonSystem &system);

      const dealii::DoFHandler<dim> &dof_handler;
      Coefficients                   coefficients;
      Settings                       settings;

      dealii::MGConstrainedDoFs              mg_constrained_dofs;
      dealii::MGTransferPrebuilt<la::Vector> transfer;

      unsigned int n_levels = 0;
      MPI_Comm     communicator;
      /** Owned level dofs and, as ghosts, the columns of their rows. */
      std::vector<std::shared_ptr<const dealii::Utilities::MPI::Partitioner>>
        level_partitioners;
      /** Level M, C, K and their interface (edge) parts, the rank's rows. */
      std::array<dealii::MGLevelObject<la::LocalMatrix>, 3> level_matrices,
        interface_matrices;

      /** One contact dof block on one level (owned level dofs, local). */
      struct LevelContactBlock
      {
        unsigned int                node = 0; // in contact_vertices
        std::array<unsigned int, 2> dofs{};
        unsigned int                n_dofs = 0;
        double                      scale  = 1;
      };
      std::vector<std::vector<LevelContactBlock>> contact_blocks; // by level
      /**
       * Per contact node of all ranks: truncated (1/0) and its Hessian
       * block, gathered per solve.
       */
      std::vector<std::array<double, 5>> node_data, own_data;

      /**
       * A coarse factor is kept while every level-0 contact block's
       * diagonal is within this fraction of the value it was factorised
       * with.
       */
      static constexpr double coarse_refresh_ratio    = 0.5;
      unsigned int            n_coarse_factorisations = 0;

      std::vector<std::unique_ptr<LevelOperators>> cache;
      ProjectedCG                                  cg;
    };
  } // namespace solvers
} // namespace rsfcycle

#endif
