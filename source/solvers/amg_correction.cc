// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <rsfcycle/solvers/amg_correction.h>

namespace rsfcycle
{
  namespace solvers
  {
    using namespace dealii;

    struct AMGCorrection::Hierarchy
    {
      double                             key = 0;
      TrilinosWrappers::SparseMatrix     matrix;
      std::vector<std::array<double, 4>> original; // contact blocks of A
      std::vector<std::array<double, 4>> current;  // ... in the hierarchy
      std::vector<std::array<double, 4>> wanted;   // ... for this system
      TrilinosWrappers::PreconditionAMG  amg;
      bool                               initialized = false;
    };


    AMGCorrection::AMGCorrection(
      const LinearCorrectionControl   &control,
      const std::vector<unsigned int> &component_of_dof)
      : control(control)
      , component_of_dof(component_of_dof)
    {}


    AMGCorrection::~AMGCorrection() = default;


    AMGCorrection::Hierarchy &
    AMGCorrection::hierarchy(const TruncatedNewtonSystem &system)
    {
      for (const auto &h : cache)
        if (h->key == system.matrix_key)
          return *h;
      if (cache.size() >= 4)
        cache.erase(cache.begin());
      auto h = std::make_unique<Hierarchy>();
      h->key = system.matrix_key;
      // The fixed (Dirichlet, hanging) rows and columns decoupled: these are
      // the non-contact truncated dofs, constant while the key is.
      const std::vector<bool> &truncated   = *system.truncated;
      const ContactSet        &contact     = *system.contact;
      const auto              &partitioner = *system.local_A->get_partitioner();
      h->matrix.copy_from(system.assembled_A());
      const auto is_fixed = [&](const unsigned int i) {
        return truncated[i] && contact.dof_to_node[i] < 0;
      };
      la::for_each_entry(h->matrix,
                         [&](const types::global_dof_index row,
                             const types::global_dof_index column,
                             double                       &value) {
                           if (row != column &&
                               (is_fixed(partitioner.global_to_local(row)) ||
                                is_fixed(partitioner.global_to_local(column))))
                             value = 0;
                         });
      for (const ContactNode &node : contact.nodes)
        {
          std::array<double, 4> d{};
          for (unsigned int i = 0; i < node.n_dofs; ++i)
            for (unsigned int j = 0; j < node.n_dofs; ++j)
              d[node.n_dofs * i + j] =
                system.local_A->el(node.dofs[i], node.dofs[j]);
          h->original.push_back(d);
        }
      cache.push_back(std::move(h));
      return *cache.back();
    }


    /**
     * The contact blocks of the AMG matrix (contact_block_entry(), as in the
     * geometric multigrid), then the hierarchy is recomputed (the aggregates of
     * the first setup are kept: PreconditionAMG::reinit()).
     */
    void
    AMGCorrection::update(Hierarchy &h, const TruncatedNewtonSystem &system)
    {
      const ContactSet &contact = *system.contact;
      // The wanted contact blocks; the hierarchy is rebuilt only if one of
      // their diagonals differs by more than a factor 2 from the one it was
      // built with (CG with the exact operator absorbs smaller changes).
      bool changed = !h.initialized;
      h.current.resize(contact.nodes.size());
      h.wanted.resize(contact.nodes.size());
      for (unsigned int k = 0; k < contact.nodes.size(); ++k)
        {
          const unsigned int n = contact.nodes[k].n_dofs;
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              {
                const double value = contact_block_entry(
                  system, k, i, j, h.original[k][n * i + j]);
                h.wanted[k][n * i + j] = value;
                if (i == j && !(value <= 2 * h.current[k][n * i + j] &&
                                h.current[k][n * i + j] <= 2 * value))
                  changed = true;
              }
        }
      // the rebuild is collective: every rank rebuilds if one needs it
      changed =
        Utilities::MPI::max(
          static_cast<int>(changed),
          system.local_A->get_partitioner()->get_mpi_communicator()) > 0;
      if (!changed)
        return;
      const auto &partitioner = *system.local_A->get_partitioner();
      for (unsigned int k = 0; k < contact.nodes.size(); ++k)
        {
          const ContactNode &node = contact.nodes[k];
          for (unsigned int i = 0; i < node.n_dofs; ++i)
            for (unsigned int j = 0; j < node.n_dofs; ++j)
              h.matrix.set(partitioner.local_to_global(node.dofs[i]),
                           partitioner.local_to_global(node.dofs[j]),
                           h.wanted[k][node.n_dofs * i + j]);
        }
      h.current = h.wanted;
      h.matrix.compress(VectorOperation::insert);
      if (h.initialized)
        h.amg.reinit();
      else
        {
          h.amg.initialize(h.matrix, elasticity_amg_data(component_of_dof));
          h.initialized = true;
        }
    }


    TrilinosWrappers::PreconditionAMG::AdditionalData
    elasticity_amg_data(const std::vector<unsigned int> &component_of_dof)
    {
      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic              = true;
      data.higher_order_elements = false;
      data.smoother_sweeps       = 3;
      data.aggregation_threshold = 1e-4;
      unsigned int n_components  = 0;
      for (const unsigned int c : component_of_dof)
        n_components = std::max(n_components, c + 1);
      data.constant_modes.assign(n_components,
                                 std::vector<bool>(component_of_dof.size(),
                                                   false));
      for (unsigned int i = 0; i < component_of_dof.size(); ++i)
        data.constant_modes[component_of_dof[i]][i] = true;
      return data;
    }


    unsigned int
    AMGCorrection::solve(const TruncatedNewtonSystem &system,
                         const la::Vector            &rhs,
                         la::Vector                  &correction)
    {
      Hierarchy &h = hierarchy(system);
      update(h, system);
      return cg.solve(
        system,
        rhs,
        correction,
        [&h](la::Vector &dst, const la::Vector &src) { h.amg.vmult(dst, src); },
        control);
    }
  } // namespace solvers
} // namespace rsfcycle
