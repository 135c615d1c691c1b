// SPDX-License-Identifier: LGPL-2.1-or-later
#include <cmath>
#include <rsfcycle/solvers/projected_cg.h>

namespace rsfcycle
{
  namespace solvers
  {
    using dealii::Vector;

    void
    truncated_newton_vmult(const TruncatedNewtonSystem &system,
                           const la::Vector            &x,
                           la::Vector                  &y)
    {
      system.local_A->vmult(y, x);
      const ContactSet &contact = *system.contact;
      for (unsigned int k = 0; k < contact.nodes.size(); ++k)
        {
          const ContactNode &node = contact.nodes[k];
          const auto        &H    = (*system.node_hessians)[k];
          for (unsigned int i = 0; i < node.n_dofs; ++i)
            for (unsigned int j = 0; j < node.n_dofs; ++j)
              y.local_element(node.dofs[i]) +=
                H[node.n_dofs * i + j] * x.local_element(node.dofs[j]);
        }
      const std::vector<bool> &truncated = *system.truncated;
      for (unsigned int i = 0; i < y.locally_owned_size(); ++i)
        if (truncated[i])
          y.local_element(i) = 0;
    }


    unsigned int
    ProjectedCG::solve(const TruncatedNewtonSystem   &system,
                       const la::Vector              &rhs,
                       la::Vector                    &x,
                       const Preconditioner          &preconditioner,
                       const LinearCorrectionControl &control)
    {
      const std::vector<bool> &truncated = *system.truncated;
      const auto               project   = [&](la::Vector &w) {
        for (unsigned int i = 0; i < w.locally_owned_size(); ++i)
          if (truncated[i])
            w.local_element(i) = 0;
      };
      if (r.size() != rhs.size())
        {
          r.reinit(rhs);
          z.reinit(rhs);
          p.reinit(rhs);
          q.reinit(rhs);
        }
      x = 0;
      r = rhs;
      project(r);
      const double r0 = r.l2_norm();
      reduction       = 0;
      if (!(r0 > 0))
        return 0;

      unsigned int cycles = 0;
      double       rz     = 0;
      while (cycles < control.max_cycles)
        {
          preconditioner(z, r);
          ++cycles;
          project(z);
          const double rz_new = r * z;
          if (!(rz_new > 0))
            break; // no descent left (or a non-finite preconditioner)
          if (cycles == 1)
            p = z;
          else
            p.sadd(rz_new / rz, z);
          rz = rz_new;
          truncated_newton_vmult(system, p, q);
          const double pq = p * q;
          if (!(pq > 0))
            break;
          const double alpha = rz / pq;
          x.add(alpha, p);
          r.add(-alpha, q);
          if (r.l2_norm() <= control.tolerance * r0)
            break;
        }
      reduction = r.l2_norm() / r0;
      return cycles;
    }
  } // namespace solvers
} // namespace rsfcycle
