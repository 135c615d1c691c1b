#include <algorithm>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/householder.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/multigrid/mg_coarse.h>
#include <deal.II/multigrid/mg_matrix.h>
#include <deal.II/multigrid/mg_smoother.h>
#include <deal.II/multigrid/mg_tools.h>
#include <deal.II/multigrid/multigrid.h>
#include <map>
#include <rsfcycle/solvers/local_sor.h>
#include <rsfcycle/solvers/multigrid_correction.h>

namespace rsfcycle
{
  namespace solvers
  {
    using namespace dealii;

    namespace
    {
      /**
       * The coarse level by Householder least squares (deal.II's
       * MGCoarseGridHouseholder, which takes serial vectors only): the
       * coarse level is whole on every rank.
       */
      class CoarseHouseholder : public MGCoarseGridBase<la::Vector>
      {
      public:
        void
        initialize(const FullMatrix<double> &matrix)
        {
          householder.initialize(matrix);
        }

        void
        operator()(const unsigned int,
                   la::Vector       &dst,
                   const la::Vector &src) const override
        {
          // buffers kept: the coarse solve runs in every V-cycle
          b.reinit(src.size(), true);
          x.reinit(dst.size(), true);
          std::copy(src.begin(), src.end(), b.begin());
          householder.least_squares(x, b);
          std::copy(x.begin(), x.end(), dst.begin());
        }

      private:
        Householder<double>    householder;
        mutable Vector<double> b, x;
      };
    } // namespace


    /**
     * The level step matrices of one matrix key and the multigrid objects
     * that refer to them (their addresses must stay fixed: held by
     * unique_ptr).
     */
    template <int dim>
    struct MultigridCorrection<dim>::LevelOperators
    {
      double                              key = 0;
      MGLevelObject<SparseMatrix<double>> matrices, interface;
      /** The same, read in place by the cycle (distributed vectors). */
      MGLevelObject<la::LocalMatrix> local_matrices, local_interface;
      /** Original diagonal blocks of the contact blocks, by level. */
      std::vector<std::vector<std::array<double, 4>>> original;

      FullMatrix<double>     coarse_matrix;
      CoarseHouseholder      coarse;
      mg::Matrix<la::Vector> mg_matrix;
      mg::Matrix<la::Vector> mg_interface_up;
      mg::Matrix<la::Vector> mg_interface_down;
      using Smoother = LocalSOR;
      /** Forward Gauss-Seidel before, backward after: the V-cycle is
       * symmetric (needed by CG; alternating sweeps with an odd count of
       * them would not be). */
      mg::SmootherRelaxation<Smoother, la::Vector> pre_smoother, post_smoother;
      std::unique_ptr<Multigrid<la::Vector>>       multigrid;
      std::unique_ptr<
        PreconditionMG<dim, la::Vector, MGTransferPrebuilt<la::Vector>>>
        preconditioner;
    };


    template <int dim>
    MultigridCorrection<dim>::MultigridCorrection(
      const DoFHandler<dim>                &dof_handler,
      const std::vector<DirichletBoundary> &dirichlet,
      const types::boundary_id              contact_id,
      const std::vector<ContactVertex>     &contact_vertices,
      const CellMatrices                   &cell_matrices,
      const Coefficients                   &coefficients,
      const Settings                       &settings)
      : dof_handler(dof_handler)
      , coefficients(coefficients)
      , settings(settings)
    {
      const unsigned int n_levels =
        dof_handler.get_triangulation().n_global_levels();

      // Level constraints: refinement edges and the Dirichlet components.
      mg_constrained_dofs.initialize(dof_handler);
      for (const auto &boundary : dirichlet)
        {
          std::vector<IndexSet> indices(n_levels);
          MGTools::make_boundary_list(dof_handler,
                                      std::set<types::boundary_id>{boundary.id},
                                      indices,
                                      boundary.components);
          for (unsigned int level = 0; level < n_levels; ++level)
            mg_constrained_dofs.add_boundary_indices(dof_handler,
                                                     level,
                                                     indices[level]);
        }
      transfer.initialize_constraints(mg_constrained_dofs);
      transfer.build(dof_handler);

      // Level sparsity patterns and matrices.
      patterns.resize(0, n_levels - 1);
      interface_patterns.resize(0, n_levels - 1);
      for (unsigned int m = 0; m < 3; ++m)
        {
          level_matrices[m].resize(0, n_levels - 1);
          interface_matrices[m].resize(0, n_levels - 1);
        }
      std::vector<AffineConstraints<double>> level_constraints(n_levels);
      for (unsigned int level = 0; level < n_levels; ++level)
        {
          const types::global_dof_index n = dof_handler.n_dofs(level);
          DynamicSparsityPattern        dsp(n, n);
          MGTools::make_sparsity_pattern(dof_handler, dsp, level);
          patterns[level].copy_from(dsp);
          DynamicSparsityPattern interface_dsp(n, n);
          MGTools::make_interface_sparsity_pattern(dof_handler,
                                                   mg_constrained_dofs,
                                                   interface_dsp,
                                                   level);
          interface_patterns[level].copy_from(interface_dsp);
          for (unsigned int m = 0; m < 3; ++m)
            {
              level_matrices[m][level].reinit(patterns[level]);
              interface_matrices[m][level].reinit(interface_patterns[level]);
            }
          level_constraints[level].reinit(
            DoFTools::extract_locally_relevant_level_dofs(dof_handler, level));
          level_constraints[level].add_lines(
            mg_constrained_dofs.get_refinement_edge_indices(level));
          level_constraints[level].add_lines(
            mg_constrained_dofs.get_boundary_indices(level));
          level_constraints[level].close();
        }

      // Assembly on every cell of every level.
      const unsigned int n_cell_dofs = dof_handler.get_fe().n_dofs_per_cell();
      std::array<FullMatrix<double>, 3> cell({FullMatrix<double>(n_cell_dofs),
                                              FullMatrix<double>(n_cell_dofs),
                                              FullMatrix<double>(n_cell_dofs)});
      std::vector<types::global_dof_index> indices(n_cell_dofs);
      for (const auto &level_cell : dof_handler.mg_cell_iterators())
        {
          const unsigned int level = level_cell->level();
          for (auto &matrix : cell)
            matrix = 0;
          cell_matrices(level_cell, cell);
          level_cell->get_mg_dof_indices(indices);
          for (unsigned int m = 0; m < 3; ++m)
            {
              level_constraints[level].distribute_local_to_global(
                cell[m], indices, level_matrices[m][level]);
              for (unsigned int i = 0; i < n_cell_dofs; ++i)
                for (unsigned int j = 0; j < n_cell_dofs; ++j)
                  if (mg_constrained_dofs.is_interface_matrix_entry(level,
                                                                    indices[i],
                                                                    indices[j]))
                    interface_matrices[m][level].add(indices[i],
                                                     indices[j],
                                                     cell[m](i, j));
            }
        }

      // The contact blocks on every level, with the level's lumped weights.
      std::map<unsigned int, unsigned int> node_of_vertex;
      for (unsigned int k = 0; k < contact_vertices.size(); ++k)
        node_of_vertex[contact_vertices[k].vertex] = k;
      contact_blocks.assign(n_levels, {});
      std::vector<std::map<unsigned int, double>> level_weight(n_levels);
      for (const auto &level_cell : dof_handler.mg_cell_iterators())
        for (const unsigned int f : level_cell->face_indices())
          {
            const auto face = level_cell->face(f);
            if (!face->at_boundary() || face->boundary_id() != contact_id)
              continue;
            for (const unsigned int v : face->vertex_indices())
              level_weight[level_cell->level()][face->vertex_index(v)] +=
                face->measure() / face->n_vertices();
          }
      for (const auto &level_cell : dof_handler.mg_cell_iterators())
        {
          const unsigned int level = level_cell->level();
          for (const unsigned int f : level_cell->face_indices())
            {
              const auto face = level_cell->face(f);
              if (!face->at_boundary() || face->boundary_id() != contact_id)
                continue;
              for (const unsigned int v : face->vertex_indices())
                {
                  const auto found = node_of_vertex.find(face->vertex_index(v));
                  if (found == node_of_vertex.end())
                    continue; // hanging on the active mesh: no friction data
                  const ContactVertex &cv = contact_vertices[found->second];
                  LevelContactBlock    block;
                  block.node = found->second;
                  block.scale =
                    level_weight[level][face->vertex_index(v)] / cv.weight;
                  bool usable = true;
                  for (unsigned int c = 0; c < cv.n_components; ++c)
                    {
                      const auto dof =
                        face->mg_vertex_dof_index(level, v, cv.components[c]);
                      if (mg_constrained_dofs.is_boundary_index(level, dof) ||
                          mg_constrained_dofs.at_refinement_edge(level, dof))
                        usable = false;
                      block.dofs[block.n_dofs++] = dof;
                    }
                  if (!usable)
                    continue;
                  bool known = false;
                  for (const auto &b : contact_blocks[level])
                    known = known || (b.dofs[0] == block.dofs[0]);
                  if (!known)
                    contact_blocks[level].push_back(block);
                }
            }
        }
    }


    template <int dim>
    MultigridCorrection<dim>::~MultigridCorrection() = default;


    template <int dim>
    std::vector<types::global_dof_index>
    MultigridCorrection<dim>::level_sizes() const
    {
      std::vector<types::global_dof_index> sizes;
      for (unsigned int l = 0; l < patterns.n_levels(); ++l)
        sizes.push_back(dof_handler.n_dofs(l));
      return sizes;
    }


    template <int dim>
    typename MultigridCorrection<dim>::LevelOperators &
    MultigridCorrection<dim>::operators(const double key)
    {
      for (const auto &ops : cache)
        if (ops->key == key)
          return *ops;
      if (cache.size() >= 4)
        cache.erase(cache.begin());

      auto ops                            = std::make_unique<LevelOperators>();
      ops->key                            = key;
      const std::array<double, 3> c       = coefficients(key);
      const unsigned int          n_level = patterns.n_levels();
      ops->matrices.resize(0, n_level - 1);
      ops->interface.resize(0, n_level - 1);
      ops->original.resize(n_level);
      for (unsigned int level = 0; level < n_level; ++level)
        {
          ops->matrices[level].reinit(patterns[level]);
          ops->interface[level].reinit(interface_patterns[level]);
          for (unsigned int m = 0; m < 3; ++m)
            if (c[m] != 0)
              {
                ops->matrices[level].add(c[m], level_matrices[m][level]);
                ops->interface[level].add(c[m], interface_matrices[m][level]);
              }
          for (const auto &block : contact_blocks[level])
            {
              std::array<double, 4> d{};
              for (unsigned int i = 0; i < block.n_dofs; ++i)
                for (unsigned int j = 0; j < block.n_dofs; ++j)
                  d[block.n_dofs * i + j] =
                    ops->matrices[level].el(block.dofs[i], block.dofs[j]);
              ops->original[level].push_back(d);
            }
        }
      ops->local_matrices.resize(0, n_level - 1);
      ops->local_interface.resize(0, n_level - 1);
      for (unsigned int level = 0; level < n_level; ++level)
        {
          ops->local_matrices[level].initialize(ops->matrices[level]);
          ops->local_interface[level].initialize(ops->interface[level]);
        }
      ops->mg_matrix.initialize(ops->local_matrices);
      ops->mg_interface_up.initialize(ops->local_interface);
      ops->mg_interface_down.initialize(ops->local_interface);
      for (auto *smoother : {&ops->pre_smoother, &ops->post_smoother})
        {
          smoother->initialize(
            ops->local_matrices,
            typename LevelOperators::Smoother::AdditionalData(1.0));
          smoother->set_steps(settings.smoothing_steps);
        }
      ops->post_smoother.set_transpose(true);
      ops->multigrid =
        std::make_unique<Multigrid<la::Vector>>(ops->mg_matrix,
                                                ops->coarse,
                                                transfer,
                                                ops->pre_smoother,
                                                ops->post_smoother);
      ops->multigrid->set_edge_matrices(ops->mg_interface_down,
                                        ops->mg_interface_up);
      ops->preconditioner = std::make_unique<
        PreconditionMG<dim, la::Vector, MGTransferPrebuilt<la::Vector>>>(
        dof_handler, *ops->multigrid, transfer);
      cache.push_back(std::move(ops));
      return *cache.back();
    }


    template <int dim>
    void
    MultigridCorrection<dim>::update_contact_blocks(
      LevelOperators              &ops,
      const TruncatedNewtonSystem &system)
    {
      for (unsigned int level = 0; level < contact_blocks.size(); ++level)
        for (unsigned int b = 0; b < contact_blocks[level].size(); ++b)
          {
            const LevelContactBlock     &block = contact_blocks[level][b];
            const std::array<double, 4> &d     = ops.original[level][b];
            const unsigned int           n     = block.n_dofs;
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                ops.matrices[level].set(
                  block.dofs[i],
                  block.dofs[j],
                  contact_block_entry(
                    system, block.node, i, j, d[n * i + j], block.scale));
          }
      ops.coarse_matrix.copy_from(ops.matrices[0]);
      ops.coarse.initialize(ops.coarse_matrix);
    }


    template <int dim>
    unsigned int
    MultigridCorrection<dim>::solve(const TruncatedNewtonSystem &system,
                                    const la::Vector            &rhs,
                                    la::Vector                  &correction)
    {
      LevelOperators &ops = operators(system.matrix_key);
      update_contact_blocks(ops, system);
      return cg.solve(
        system,
        rhs,
        correction,
        [&ops](la::Vector &dst, const la::Vector &src) {
          ops.preconditioner->vmult(dst, src);
        },
        settings.control);
    }


    template class MultigridCorrection<2>;
    template class MultigridCorrection<3>;
  } // namespace solvers
} // namespace rsfcycle
