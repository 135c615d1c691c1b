// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_ids_h
#define rsfcycle_ids_h

#include <deal.II/base/types.h>

namespace rsfcycle
{
  /**
   * Boundary ids used by every scene (doc/model.md §1). Scenes set them on the
   * coarse mesh; the solver reads nothing else about the geometry.
   *  - surface: traction free;
   *  - backstop: prescribed velocity v(t) (all components);
   *  - contact: the base y = 0, u.n = 0 and rate-and-state friction;
   *  - lateral: 3D side walls across the contact, no normal velocity (free
   *    slip: z fixed);
   *  - parallel: walls parallel to the contact, no normal velocity (free
   *    slip: y fixed);
   *  - absorbing: the truncation of an unbounded body, where outgoing
   *    waves leave: the dashpots (Lysmer and Kuhlemeyer) of the traction
   *    -rho (c_p v_n n + c_s v_t) (antiplane: -rho c_s v);
   *  - creep: a part of the contact's plane y = 0 that slides at the
   *    backstop's velocity: the tangential components prescribed as on the
   *    backstop, the normal one held or free as on the contact;
   *  - fault_opposite: the other side of a fault between two deformable
   *    parts of the body (split nodes, doc/model.md §8.4): faces of the
   *    contact's plane whose nodes pair with the contact and creep nodes
   *    at the same positions. The assembly treats them as traction free;
   *    the Green's-function method ties each pair (the normal displacement
   *    continuous, the slip the jump of the tangential displacement);
   *  - backstop_opposite: prescribed velocity -v(t), the opposite plate.
   */
  namespace boundary_id
  {
    constexpr dealii::types::boundary_id surface           = 0;
    constexpr dealii::types::boundary_id backstop          = 1;
    constexpr dealii::types::boundary_id contact           = 2;
    constexpr dealii::types::boundary_id lateral           = 3;
    constexpr dealii::types::boundary_id absorbing         = 4;
    constexpr dealii::types::boundary_id creep             = 5;
    constexpr dealii::types::boundary_id parallel          = 6;
    constexpr dealii::types::boundary_id fault_opposite    = 7;
    constexpr dealii::types::boundary_id backstop_opposite = 8;
  } // namespace boundary_id

  /** Material ids: the regions of doc/model.md §5 (density, viscosity). */
  namespace material_id
  {
    constexpr dealii::types::material_id upper = 0;
    constexpr dealii::types::material_id lower = 1;
  } // namespace material_id
} // namespace rsfcycle

#endif
