// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_physics_contact_quadrature_h
#define rsfcycle_physics_contact_quadrature_h

#include <array>
#include <deal.II/base/mpi.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>
#include <functional>
#include <rsfcycle/friction/local_solve.h>
#include <rsfcycle/la.h>
#include <rsfcycle/solvers/multigrid_correction.h>
#include <rsfcycle/solvers/spatial_problem.h>
#include <vector>

namespace rsfcycle
{
  namespace physics
  {
    using namespace dealii;

    /**
     * The boundary quadrature of the friction term (doc/model.md §2, the
     * sinh^-1 dissipation): the contact nodes (the base vertices with a
     * free tangential component), their lumped (trapezoidal, vertex)
     * weights w_i condensed onto the non-hanging nodes so that the friction
     * potential j(v) = sum_i w_i [|sigma_n,i| int_0^|v_i| mu + C |v_i|]
     * stays node-wise separable (13), the normal force w_i |sigma_n,i| and
     * the friction parameters of every node, and the quantities defined by
     * the quadrature: the state distance (14), slip rates, slips.
     */
    template <int dim>
    class ContactQuadrature
    {
    public:
      /** Contact node k: position, lumped weight, normal force. */
      struct NodeInfo
      {
        Point<dim> position;
        /** The material of a cell at the node (its shear modulus). */
        types::material_id      material     = 0;
        double                  weight       = 0;
        double                  normal_force = 0;
        friction::Parameters    params;
        types::global_dof_index scalar_dof = 0;
        types::global_dof_index normal_dof = 0;
        /** The displacement component of each tangential dof. */
        std::array<unsigned int, 2> components{};
      };

      /**
       * The contact nodes of the faces with boundary id `contact` whose
       * dofs this rank owns, with the friction parameters given by
       * `parameters_at` at each node's position. `fixed` marks the dofs
       * (by local index of `partitioner`) that are not unknowns.
       */
      void
      setup(const DoFHandler<dim>             &dof_handler,
            const DoFHandler<dim>             &scalar_dof_handler,
            const AffineConstraints<double>   &hanging_constraints,
            const Utilities::MPI::Partitioner &partitioner,
            const std::vector<bool>           &fixed,
            const std::function<friction::Parameters(const Point<dim> &)>
              &parameters_at);

      /**
       * Normal forces |r_i| from the reaction r = K u - f of the gravity
       * equilibrium at each node's normal dof. Returns the number of nodes
       * whose reaction has the opposite sign of the total (tensile).
       */
      unsigned int
      set_normal_forces(const la::Vector &reaction);

      /** Normal forces w_i |sigma_n(x_i)| from a prescribed normal stress. */
      void
      set_normal_forces(
        const std::function<double(const Point<dim> &)> &normal_stress);

      /** The state distance (14) between two states (all ranks). */
      double
      state_distance(const std::vector<double> &alpha1,
                     const std::vector<double> &alpha2) const;

      /** max_k |alpha1_k - alpha2_k| over the contact nodes (all ranks). */
      double
      state_max_distance(const std::vector<double> &alpha1,
                         const std::vector<double> &alpha2) const;

      /** Slip rate |v_T| of every contact node. */
      std::vector<double>
      slip_rates(const la::Vector &v) const;

      /** Tangential displacement (up to 2 components) of every node. */
      std::vector<std::array<double, 2>>
      tangential_displacement(const la::Vector &u) const;

      /**
       * The node potentials phi_i of (13) of the friction law `law` with the
       * state alpha not yet set (the cohesion force w_i C_i from the node's
       * parameters).
       */
      std::vector<friction::NodePotential>
      potentials(const friction::Law &law) const;

      const std::vector<NodeInfo> &
      nodes() const
      {
        return node_info;
      }

      /** The contact dofs per node, for the solvers. */
      const solvers::ContactSet &
      contact_set() const
      {
        return contact;
      }

      /** The contact nodes of this rank. */
      unsigned int
      n_nodes() const
      {
        return node_info.size();
      }

      /** The contact nodes of all ranks. */
      unsigned int
      n_global_nodes() const
      {
        return order.size();
      }

      /**
       * A value per node of this rank, gathered from all ranks onto every
       * rank in the order of the nodes' positions (lexicographic in the
       * coordinates, x first, the last coordinate last), which does not
       * depend on the number of ranks.
       */
      template <typename T>
      std::vector<T>
      gather(const std::vector<T> &local) const
      {
        const std::vector<T> all = la::all_gather(communicator, local);
        std::vector<T>       sorted(all.size());
        for (unsigned int k = 0; k < order.size(); ++k)
          sorted[k] = all[order[k]];
        return sorted;
      }

      /**
       * The contact nodes of all ranks, rank by rank, as the geometric
       * multigrid finds them on its levels: position, lumped weight and the
       * components of their dofs (collective).
       */
      std::vector<typename solvers::MultigridCorrection<dim>::ContactVertex>
      multigrid_vertices() const;

    private:
      solvers::ContactSet   contact;
      std::vector<NodeInfo> node_info;
      double                area         = 0;
      MPI_Comm              communicator = MPI_COMM_SELF;
      unsigned int          n_ranks      = 1;
      /** Sorted position k -> index in the rank-by-rank list. */
      std::vector<unsigned int> order;
    };
  } // namespace physics
} // namespace rsfcycle

#endif
