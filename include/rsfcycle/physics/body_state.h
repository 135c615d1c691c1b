// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_physics_body_state_h
#define rsfcycle_physics_body_state_h

#include <boost/serialization/split_member.hpp>
#include <boost/serialization/vector.hpp>
#include <rsfcycle/la.h>
#include <rsfcycle/solvers/step_statistics.h>
#include <vector>

namespace rsfcycle
{
  /**
   * The state of the body at one time: displacement, velocity, acceleration
   * (all dofs) and the friction state alpha = log(theta V* / L) per contact
   * node, with the friction force of the step that produced it and what
   * that step cost.
   */
  struct BodyState
  {
    la::Vector          u, v, a;
    std::vector<double> alpha;
    std::vector<double> shear_traction; // |friction force| / w per node [Pa]
    solvers::StepStatistics statistics;
    /**
     * The effective normal stress per node where it changes in time (a
     * pore pressure) [Pa]; empty: the contact's constant one. Made for
     * the output, not kept in checkpoints.
     */
    std::vector<double> normal_stress;
    /**
     * The slip and slip rate per node (magnitudes) [m, m/s] where the
     * contact's displacement is not the slip (the Green's-function method:
     * a split fault's two sides move); empty: the contact dofs' tangential
     * displacement and velocity. Made for the output, not kept in
     * checkpoints.
     */
    std::vector<double> slip, slip_rate;

    template <class Archive>
    void
    save(Archive &ar, const unsigned int) const
    {
      la::save(ar, u);
      la::save(ar, v);
      la::save(ar, a);
      ar &alpha &shear_traction &statistics;
    }

    template <class Archive>
    void
    load(Archive &ar, const unsigned int)
    {
      la::load(ar, u);
      la::load(ar, v);
      la::load(ar, a);
      ar &alpha &shear_traction &statistics;
    }

    BOOST_SERIALIZATION_SPLIT_MEMBER()
  };
} // namespace rsfcycle

#endif
