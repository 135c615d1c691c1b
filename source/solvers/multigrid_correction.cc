// SPDX-License-Identifier: LGPL-2.1-or-later
#include <algorithm>
#include <cmath>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/multigrid/mg_coarse.h>
#include <deal.II/multigrid/mg_matrix.h>
#include <deal.II/multigrid/mg_smoother.h>
#include <deal.II/multigrid/mg_tools.h>
#include <deal.II/multigrid/multigrid.h>
#include <map>
#include <rsfcycle/solvers/coarse_direct.h>
#include <rsfcycle/solvers/local_sor.h>
#include <rsfcycle/solvers/multigrid_correction.h>

namespace rsfcycle
{
  namespace solvers
  {
    using namespace dealii;


    /**
     * The level step matrices of one matrix key and the multigrid objects
     * that refer to them (their addresses must stay fixed: held by
     * unique_ptr).
     */
    template <int dim>
    struct MultigridCorrection<dim>::LevelOperators
    {
      double key = 0;
      /** The level step matrices and their interface parts. */
      MGLevelObject<la::LocalMatrix> local_matrices, local_interface;
      /** Original diagonal blocks of the contact blocks, by level. */
      std::vector<std::vector<std::array<double, 4>>> original;

      CoarseDirect coarse;
      /**
       * The diagonal entries of the level-0 contact blocks that `coarse`
       * was factorised with (empty before the first factorisation).
       */
      std::vector<std::array<double, 2>> factorised_diagonal;
      bool                               factorised = false;
      mg::Matrix<la::Vector>             mg_matrix;
      mg::Matrix<la::Vector>             mg_interface_up;
      mg::Matrix<la::Vector>             mg_interface_down;
      /** Forward Gauss-Seidel before, backward after: the V-cycle is
       * symmetric (needed by CG; alternating sweeps with an odd count of
       * them would not be). */
      std::unique_ptr<LocalSORSmoother>      pre_smoother, post_smoother;
      std::unique_ptr<Multigrid<la::Vector>> multigrid;
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
      n_levels = dof_handler.get_triangulation().n_global_levels();

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

      // Level sparsity patterns and matrices (Trilinos, so that the rows a
      // rank adds to on its level cells go to their owners), kept as the
      // rank's rows.
      communicator = dof_handler.get_communicator();
      level_partitioners.resize(n_levels);
      std::array<MGLevelObject<TrilinosWrappers::SparseMatrix>, 3> assembled,
        assembled_interface;
      for (unsigned int m = 0; m < 3; ++m)
        {
          assembled[m].resize(0, n_levels - 1);
          assembled_interface[m].resize(0, n_levels - 1);
          level_matrices[m].resize(0, n_levels - 1);
          interface_matrices[m].resize(0, n_levels - 1);
        }
      std::vector<AffineConstraints<double>> level_constraints(n_levels);
      for (unsigned int level = 0; level < n_levels; ++level)
        {
          const IndexSet &owned = dof_handler.locally_owned_mg_dofs(level);
          const IndexSet  relevant =
            DoFTools::extract_locally_relevant_level_dofs(dof_handler, level);
          DynamicSparsityPattern dsp(relevant);
          MGTools::make_sparsity_pattern(dof_handler, dsp, level);
          SparsityTools::distribute_sparsity_pattern(dsp,
                                                     owned,
                                                     communicator,
                                                     relevant);
          DynamicSparsityPattern interface_dsp(relevant);
          MGTools::make_interface_sparsity_pattern(dof_handler,
                                                   mg_constrained_dofs,
                                                   interface_dsp,
                                                   level);
          SparsityTools::distribute_sparsity_pattern(interface_dsp,
                                                     owned,
                                                     communicator,
                                                     relevant);
          const IndexSet ghosts = la::matrix_ghosts(dsp, owned, relevant);
          level_partitioners[level] =
            std::make_shared<Utilities::MPI::Partitioner>(owned,
                                                          ghosts,
                                                          communicator);
          for (unsigned int m = 0; m < 3; ++m)
            {
              assembled[m][level].reinit(owned, owned, dsp, communicator);
              assembled_interface[m][level].reinit(owned,
                                                   owned,
                                                   interface_dsp,
                                                   communicator);
            }
          level_constraints[level].reinit(relevant);
          level_constraints[level].add_lines(
            mg_constrained_dofs.get_refinement_edge_indices(level));
          level_constraints[level].add_lines(
            mg_constrained_dofs.get_boundary_indices(level));
          level_constraints[level].close();
        }

      // Assembly on the rank's cells of every level.
      const unsigned int n_cell_dofs = dof_handler.get_fe().n_dofs_per_cell();
      std::array<FullMatrix<double>, 3> cell{{FullMatrix<double>(n_cell_dofs),
                                              FullMatrix<double>(n_cell_dofs),
                                              FullMatrix<double>(n_cell_dofs)}};
      FullMatrix<double>                cell_interface(n_cell_dofs);
      std::vector<types::global_dof_index> indices(n_cell_dofs);
      for (const auto &level_cell : dof_handler.mg_cell_iterators())
        {
          if (!level_cell->is_locally_owned_on_level())
            continue;
          const unsigned int level = level_cell->level();
          for (auto &matrix : cell)
            matrix = 0;
          cell_matrices(level_cell, cell);
          level_cell->get_mg_dof_indices(indices);
          for (unsigned int m = 0; m < 3; ++m)
            {
              level_constraints[level].distribute_local_to_global(
                cell[m], indices, assembled[m][level]);
              cell_interface = 0;
              for (unsigned int i = 0; i < n_cell_dofs; ++i)
                for (unsigned int j = 0; j < n_cell_dofs; ++j)
                  if (mg_constrained_dofs.is_interface_matrix_entry(level,
                                                                    indices[i],
                                                                    indices[j]))
                    cell_interface(i, j) = cell[m](i, j);
              assembled_interface[m][level].add(indices, cell_interface);
            }
        }
      for (unsigned int level = 0; level < n_levels; ++level)
        for (unsigned int m = 0; m < 3; ++m)
          {
            assembled[m][level].compress(VectorOperation::add);
            assembled_interface[m][level].compress(VectorOperation::add);
            level_matrices[m][level].initialize(assembled[m][level],
                                                level_partitioners[level]);
            interface_matrices[m][level].initialize(
              assembled_interface[m][level], level_partitioners[level]);
          }

      // The contact blocks on every level, with the level's lumped weights
      // (contact nodes found by position: vertex numbers differ between
      // ranks).
      const auto less = [](const Point<dim> &a, const Point<dim> &b) {
        for (unsigned int d = 0; d < dim; ++d)
          if (a[d] != b[d])
            return a[d] < b[d];
        return false;
      };
      std::map<Point<dim>, unsigned int, decltype(less)> node_at(less);
      for (unsigned int k = 0; k < contact_vertices.size(); ++k)
        node_at[contact_vertices[k].position] = k;
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
          if (!level_cell->is_locally_owned_on_level())
            continue;
          const unsigned int level = level_cell->level();
          const auto        &owned = dof_handler.locally_owned_mg_dofs(level);
          for (const unsigned int f : level_cell->face_indices())
            {
              const auto face = level_cell->face(f);
              if (!face->at_boundary() || face->boundary_id() != contact_id)
                continue;
              for (const unsigned int v : face->vertex_indices())
                {
                  const auto found = node_at.find(face->vertex(v));
                  if (found == node_at.end())
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
                      if (!owned.is_element(dof) ||
                          mg_constrained_dofs.is_boundary_index(level, dof) ||
                          mg_constrained_dofs.at_refinement_edge(level, dof))
                        {
                          usable = false;
                          break;
                        }
                      block.dofs[block.n_dofs++] =
                        level_partitioners[level]->global_to_local(dof);
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
      for (unsigned int l = 0; l < n_levels; ++l)
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

      auto ops                      = std::make_unique<LevelOperators>();
      ops->key                      = key;
      const std::array<double, 3> c = coefficients(key);
      ops->local_matrices.resize(0, n_levels - 1);
      ops->local_interface.resize(0, n_levels - 1);
      ops->original.resize(n_levels);
      for (unsigned int level = 0; level < n_levels; ++level)
        {
          ops->local_matrices[level].combine(
            {{c[0], &level_matrices[0][level]},
             {c[1], &level_matrices[1][level]},
             {c[2], &level_matrices[2][level]}});
          ops->local_interface[level].combine(
            {{c[0], &interface_matrices[0][level]},
             {c[1], &interface_matrices[1][level]},
             {c[2], &interface_matrices[2][level]}});
          for (const auto &block : contact_blocks[level])
            {
              std::array<double, 4> d{};
              for (unsigned int i = 0; i < block.n_dofs; ++i)
                for (unsigned int j = 0; j < block.n_dofs; ++j)
                  d[block.n_dofs * i + j] =
                    ops->local_matrices[level].el(block.dofs[i], block.dofs[j]);
              ops->original[level].push_back(d);
            }
        }
      ops->mg_matrix.initialize(ops->local_matrices);
      ops->mg_interface_up.initialize(ops->local_interface);
      ops->mg_interface_down.initialize(ops->local_interface);
      ops->pre_smoother =
        std::make_unique<LocalSORSmoother>(settings.smoothing_steps, false);
      ops->post_smoother =
        std::make_unique<LocalSORSmoother>(settings.smoothing_steps, true);
      ops->pre_smoother->initialize(ops->local_matrices);
      ops->post_smoother->initialize(ops->local_matrices);
      ops->multigrid =
        std::make_unique<Multigrid<la::Vector>>(ops->mg_matrix,
                                                ops->coarse,
                                                transfer,
                                                *ops->pre_smoother,
                                                *ops->post_smoother);
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
      // The truncation and Hessian of every rank's contact nodes: a level
      // dof may belong to another rank than the node's active dofs.
      const ContactSet &contact = *system.contact;
      own_data.resize(contact.nodes.size());
      for (unsigned int k = 0; k < contact.nodes.size(); ++k)
        {
          own_data[k][0] =
            (*system.truncated)[contact.nodes[k].dofs[0]] ? 1. : 0.;
          for (unsigned int i = 0; i < 4; ++i)
            own_data[k][1 + i] = (*system.node_hessians)[k][i];
        }
      node_data = la::all_gather(communicator, own_data);

      for (unsigned int level = 0; level < contact_blocks.size(); ++level)
        for (unsigned int b = 0; b < contact_blocks[level].size(); ++b)
          {
            const LevelContactBlock     &block = contact_blocks[level][b];
            const std::array<double, 4> &d     = ops.original[level][b];
            const std::array<double, 5> &data  = node_data[block.node];
            const unsigned int           n     = block.n_dofs;
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                ops.local_matrices[level].entry(block.dofs[i], block.dofs[j]) =
                  (data[0] != 0) ?
                    ((i == j) ? d[n * i + j] * (1. + truncation_penalty) :
                                d[n * i + j]) :
                    d[n * i + j] + block.scale * data[1 + n * i + j];
          }

      // The coarse matrix, whole on every rank. A large one (Coarse factor
      // reuse size) is factorised again only when a contact block's
      // diagonal moved by more than half of the value
      // the factor holds: the coarse solve is a preconditioner, and a
      // factor whose contact blocks are within that ratio of the current
      // ones is spectrally equivalent to the current coarse matrix (the
      // contact blocks are a block-diagonal, positive semi-definite
      // addition). Truncation (a factor 1 + 1e8) or a new step matrix
      // always refactorises; the friction Hessians of successive TNNMG
      // iterations and fixed-point iterations usually do not.
      const std::vector<LevelContactBlock> &coarse_blocks = contact_blocks[0];
      bool                                  refactorise =
        !ops.factorised || dof_handler.n_dofs(0) < settings.coarse_reuse_size;
      for (unsigned int b = 0; b < coarse_blocks.size() && !refactorise; ++b)
        for (unsigned int i = 0; i < coarse_blocks[b].n_dofs; ++i)
          {
            const unsigned int dof  = coarse_blocks[b].dofs[i];
            const double       now  = ops.local_matrices[0].el(dof, dof);
            const double       then = ops.factorised_diagonal[b][i];
            if (std::abs(now - then) > coarse_refresh_ratio * std::abs(then))
              refactorise = true;
          }
      if (Utilities::MPI::logical_or(refactorise, communicator))
        {
          ops.coarse.initialize(ops.local_matrices[0],
                                dof_handler.n_dofs(0),
                                communicator);
          ops.factorised = true;
          ops.factorised_diagonal.assign(coarse_blocks.size(), {});
          for (unsigned int b = 0; b < coarse_blocks.size(); ++b)
            for (unsigned int i = 0; i < coarse_blocks[b].n_dofs; ++i)
              ops.factorised_diagonal[b][i] =
                ops.local_matrices[0].el(coarse_blocks[b].dofs[i],
                                         coarse_blocks[b].dofs[i]);
          ++n_coarse_factorisations;
        }
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
