// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_physics_split_fault_h
#define rsfcycle_physics_split_fault_h

#include <rsfcycle/physics/contact_quadrature.h>
#include <rsfcycle/physics/discretisation.h>
#include <rsfcycle/physics/global_system.h>

namespace rsfcycle
{
  namespace physics
  {
    /**
     * Tie the two sides of a split fault (doc/model.md §8.4) in a gathered
     * system: every node of the contact and creep faces (the + side) pairs
     * with the node of a fault-opposite face (the - side) at the same
     * position, and the system is rewritten in new unknowns, u = T u~,
     * K~ = T^T K T, f~ = T^T f, the observation rows as rows of u~. Per pair
     * and tangential component, with a the + dof and b the - dof:
     *   u_a = m + s/2,  u_b = m - s/2,
     * the slip s = u_a - u_b in a's place (the contact dof, so the Schur
     * complement of physics/green_operator.h is the fault's in the slip)
     * and the mean m in b's. The nodal force on a (the shear prestress:
     * the system's force without gravity) is the fault's internal
     * traction, so it acts on b too, opposite: s takes it whole, m none. The
     * normal dofs c (+) and d (-) become one, u_c = u_d = w in c's place; d is
     * left fixed at zero with a unit diagonal and no coupling. Prescribed dofs:
     * a creep (or load) dof a with a free b prescribes the slip at twice a's
     * velocity (the two plates' difference, +v - (-v)) and leaves m free; a and
     * b both prescribed give s and m from their two velocities; a normal
     * prescribed on either side prescribes w. Pairs of hanging dofs are
     * left as they are (their parents are paired).
     *
     * Throws std::invalid_argument naming Mesh file/Boundary roles for a
     * node without a partner on the other side, a node hanging on one side
     * only (the sides refined differently) and a free contact dof whose
     * partner is prescribed.
     */
    /**
     * Refine the two sides of a split fault alike: after a refinement
     * cycle, a fault face (contact, creep or fault-opposite) whose centre is
     * a vertex of the other side's fault faces (that side is finer there:
     * the refinement law measures each side's own cells, and the mesh
     * smoothing adds cells on one side) is refined, until no face is, on
     * every rank. Meshes of the two sides that differ (unstructured ones)
     * then still pair node for node.
     */
    template <int dim>
    void
    refine_fault_sides_alike(Triangulation<dim> &triangulation);

    template <int dim>
    void
    tie_split_fault(const Discretisation<dim> &discretisation,
                    GlobalSystem              &system);

    /**
     * The pairs of the two sides (FaultTie) of a discretisation with n dofs,
     * found by position across the ranks; the refusals above.
     */
    template <int dim>
    FaultTie
    pair_fault_sides(const Discretisation<dim> &discretisation, unsigned int n);

    /** A = T^T A T of a matrix in compressed rows, global numbering. */
    void
    tie_matrix(const FaultTie            &tie,
               std::vector<std::size_t>  &row_start,
               std::vector<unsigned int> &columns,
               std::vector<double>       &values);

    /**
     * f~ = T^T f of nodal forces whose + tangential part is the shear
     * prestress (the fault's internal traction, acting on both sides).
     */
    std::vector<double>
    tie_force(const FaultTie &tie, const std::vector<double> &force);

    /**
     * The prescribed dofs (`fixed`) and their prescribed values (velocities,
     * or factors of the load velocity) in the tied unknowns: a + tangential
     * dof with a free partner prescribes the slip at twice its value (the
     * plates' difference), with a prescribed one the difference and the
     * mean; a prescribed normal on either side prescribes the shared one,
     * the - normal is fixed at zero. Throws std::invalid_argument for a
     * prescribed - dof whose + partner is free.
     */
    void
    tie_prescribed(const FaultTie      &tie,
                   std::vector<bool>   &fixed,
                   std::vector<double> &values);

    /** A row of the untied dofs as a row of the tied unknowns. */
    ObservationRow
    tie_row(const FaultTie &tie, const ObservationRow &row);

    /**
     * Per contact dof a, the compressive normal force on its node as a row
     * of the tied unknowns, -n (K u)_c of the untied stiffness's row c (the
     * + side's cells alone); empty without a normal component.
     */
    std::vector<ObservationRow>
    normal_force_rows(const FaultTie                  &tie,
                      const std::vector<std::size_t>  &row_start,
                      const std::vector<unsigned int> &columns,
                      const std::vector<double>       &values,
                      const std::vector<unsigned int> &contact_dofs);

    /**
     * A split fault's normal stress per contact node of this rank at the
     * displacement u and, with inertia, the acceleration a: the normal
     * force on the + side's face, (w_k sigma_0 + n_k . u + m_k . a) / w_k
     * [Pa] (Discretisation::fault_normal_rows n_k: the + side's elastic
     * reaction; fault_normal_inertia_rows m_k: its mass times the
     * acceleration, which a wave crossing the fault makes as large as the
     * elastic part), into `stresses`; a = nullptr: quasi-static (no
     * inertia). False if a node of any rank is not in compression
     * (collective).
     */
    template <int dim>
    bool
    split_normal_stresses(const Discretisation<dim>    &discretisation,
                          const ContactQuadrature<dim> &contact,
                          const la::Vector             &u,
                          const la::Vector             *a,
                          std::vector<double>          &stresses);

    /** A dof's part in the tie of a split fault (GlobalSystem::tie_kind). */
    enum TieKind : unsigned char
    {
      tie_none,
      tie_slip,   // tangential, + side: becomes s
      tie_mean,   // tangential, - side: becomes m
      tie_normal, // normal, + side: becomes w
      tie_gone    // normal, - side: eliminated
    };

    /**
     * The displacement u = T u~ of the untied dofs from the tied unknowns
     * u~ of a system that tie_split_fault() rewrote (all dofs, in place):
     * u_a = m + s/2 and u_b = m - s/2 of every tangential pair, the normal
     * w on both sides.
     */
    void
    untie_split_fault(const GlobalSystem &system, std::vector<double> &u);

    /**
     * The same for a vector of the volume method: u = T u~ on the rank's
     * paired dofs (partners on other ranks read as ghosts), then the ghosts
     * updated; pairs of hanging dofs are left to
     * hanging_constraints.distribute().
     */
    void
    untie_split_fault(const FaultTie &tie, la::Vector &u);
  } // namespace physics
} // namespace rsfcycle

#endif
