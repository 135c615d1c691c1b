// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_physics_global_system_h
#define rsfcycle_physics_global_system_h

#include <cstddef>
#include <deal.II/base/types.h>
#include <rsfcycle/physics/discretisation.h>
#include <rsfcycle/physics/scene.h>
#include <rsfcycle/solvers/spatial_problem.h>
#include <utility>
#include <vector>

namespace rsfcycle
{
  namespace physics
  {

    /**
     * The assembled elastic system of a Discretisation gathered onto every
     * rank, in the global dof numbering: what the fault's Green's functions
     * are computed from (physics/green_operator.h). On one rank it is the
     * rank's own matrices; on N ranks every rank holds all of it (the
     * set-up's memory does not fall with N; the operator's does).
     */
    struct GlobalSystem
    {
      /** The stiffness K in compressed rows. */
      std::vector<std::size_t>  row_start;
      std::vector<unsigned int> columns;
      std::vector<double>       values;
      /** Per dof: prescribed (Dirichlet, hanging), f, v_b. */
      std::vector<bool> fixed;
      /** The body force and the shear prestress as nodal forces [N]. */
      std::vector<double> force;
      /** The prescribed velocity of the fixed dofs [m/s] (load). */
      std::vector<double> fixed_velocity;
      /**
       * The contact's tangential dofs (one per contact node in 2D, up to
       * two in 3D, a node's together), the nodes of rank 0 first (in its
       * own order), then those of rank 1, ...
       */
      std::vector<unsigned int> contact_dofs;
      /** First contact dof of every rank, then the number of dofs. */
      std::vector<unsigned int> rank_offsets;
      /** The observation rows (every point once). */
      std::vector<ObservationRow> observations;
      /**
       * With a split fault (physics/split_fault.h) in plane strain or 3D:
       * per contact dof (in the order of contact_dofs), the compressive
       * normal force on its node as a row of the unknowns, the force with
       * which the fault's - side pushes on the + side against the + side's
       * outward normal [N/m^(3-dim)]; empty otherwise.
       */
      std::vector<ObservationRow> normal_rows;
      /**
       * With a split fault, tied (physics/split_fault.h): per dof, its part
       * in the tie (physics::TieKind) and its partner dof on the fault's
       * other side, what untie_split_fault() maps the tied unknowns back
       * with; empty otherwise.
       */
      std::vector<unsigned char> tie_kind;
      std::vector<unsigned int>  tie_partner;

      unsigned int
      n() const
      {
        return fixed.size();
      }
      std::size_t
      row_begin(const unsigned int i) const
      {
        return row_start[i];
      }
      std::size_t
      row_end(const unsigned int i) const
      {
        return row_start[i + 1];
      }
    };

    /**
     * The rows of the scene's observation points: the physical vertical
     * displacement (antiplane: the out-of-plane one) interpolated in the
     * cell around each point, in global dof indices; empty for a point
     * whose cell this rank does not own (gather_system() picks the
     * owner's; the volume path sums over the ranks).
     */
    template <int dim>
    std::vector<ObservationRow>
    observation_rows(const Discretisation<dim> &discretisation,
                     const Scene<dim>          &scene,
                     bool                       antiplane);

    /**
     * Gather the stiffness, the fixed dofs, the loads and the contact dofs
     * of `contact` onto every rank, and the observation rows: `local_rows`
     * holds one row per observation point, empty on the ranks that do not
     * own the point's cell; the first rank's non-empty row is taken.
     * Throws std::invalid_argument for a contact node with two tangential
     * dofs (3D) and for a point no rank owns.
     */
    template <int dim>
    GlobalSystem
    gather_system(const Discretisation<dim>         &discretisation,
                  const solvers::ContactSet         &contact,
                  const std::vector<ObservationRow> &local_rows);
  } // namespace physics
} // namespace rsfcycle

#endif
