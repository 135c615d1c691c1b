// SPDX-License-Identifier: LGPL-2.1-or-later
// Shared by the tests of GreenFault::body() (green_function_body,
// green_function_split_body): the body's displacement and velocity at the
// observation points against the operator's, which computes them
// independently (physics/green_operator.h).
#ifndef rsfcycle_tests_green_body_stations_h
#define rsfcycle_tests_green_body_stations_h

#include <algorithm>
#include <cmath>
#include <rsfcycle/models/green_fault.h>
#include <rsfcycle/physics/body_state.h>
#include <rsfcycle/physics/global_system.h>
#include <rsfcycle/physics/green_operator.h>
#include <vector>

/**
 * Whether every row p of `rows` (an observation in the body's dofs, one
 * rank's whole body) gives, applied to body.u and body.v, the operator's
 * o0 + t o1 + O s and o1 + O V at the state, to 1e-7 of the largest of
 * each.
 */
inline bool
stations_as_operator(const rsfcycle::physics::GreenOperator               &op,
                     const std::vector<rsfcycle::physics::ObservationRow> &rows,
                     const rsfcycle::models::FaultState &state,
                     const rsfcycle::BodyState          &body)
{
  double error_u = 0, error_v = 0, size_u = 0, size_v = 0;
  for (unsigned int p = 0; p < rows.size(); ++p)
    {
      double u = op.o0[p] + state.t * op.o1[p], v = op.o1[p];
      for (unsigned int k = 0; k < state.slip.size(); ++k)
        {
          u += op.O(p, k) * state.slip[k];
          v += op.O(p, k) * state.rate[k];
        }
      double u_body = 0, v_body = 0;
      for (const auto &[dof, weight] : rows[p])
        {
          u_body += weight * body.u(dof);
          v_body += weight * body.v(dof);
        }
      error_u = std::max(error_u, std::abs(u_body - u));
      error_v = std::max(error_v, std::abs(v_body - v));
      size_u  = std::max(size_u, std::abs(u));
      size_v  = std::max(size_v, std::abs(v));
    }
  return error_u < 1e-7 * size_u && error_v < 1e-7 * size_v;
}

#endif
