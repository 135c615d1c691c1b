// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_solvers_step_statistics_h
#define rsfcycle_solvers_step_statistics_h

namespace rsfcycle
{
  namespace solvers
  {
    /** Counts of the algebraic solvers for one time step: fixed-point
     * iterations of the rate/state coupling, TNNMG iterations and linear
     * (multigrid) iterations. */
    struct StepStatistics
    {
      unsigned int fixed_point_iterations = 0;
      unsigned int tnnmg_iterations       = 0;
      unsigned int linear_iterations      = 0;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &fixed_point_iterations &tnnmg_iterations &linear_iterations;
      }
    };
  } // namespace solvers
} // namespace rsfcycle

#endif
