// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_solvers_direct_correction_h
#define rsfcycle_solvers_direct_correction_h

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>
#include <memory>
#include <rsfcycle/solvers/spatial_problem.h>
#include <vector>

namespace rsfcycle
{
  namespace solvers
  {
    /**
     * Exact (sparse direct) linear correction. The Newton matrix differs
     * from A only in the contact block, so the free non-contact unknowns I
     * are eliminated once per step matrix: CHOLMOD factorises A_II (a sparse
     * Cholesky factor, solvers/sparse_cholesky.h), and the dense Schur
     * complement S = A_cc - A_cI A_II^{-1} A_Ic of all contact dofs c is
     * L_cc L_cc^T from a second factorisation of A in A_II's order with the
     * contact dofs last (SparseCholesky::schur_complement(), which is then
     * freed). Each TNNMG iteration then costs two sparse back-substitutions
     * (before and after) and one dense solve with S_aa + H_aa on the active
     * (non-truncated) contact dofs a. The factorisations of the
     * last few step matrices are cached by TruncatedNewtonSystem::matrix_key.
     * Meant for 2D and small 3D meshes (S is dense).
     */
    class DirectCorrection : public LinearCorrection
    {
    public:
      DirectCorrection();
      ~DirectCorrection() override;

      unsigned int
      solve(const TruncatedNewtonSystem &system,
            const la::Vector            &rhs,
            la::Vector                  &correction) override;

    private:
      struct Factorization;
      const Factorization &
      factorization(const TruncatedNewtonSystem &system);

      /**
       * S_aa + H_aa into S: f's Schur complement on the active contact dofs
       * (their positions in contact_dofs; active_position: each contact
       * dof's position among them, -1 if truncated) and the friction's
       * Hessian blocks of the active nodes.
       */
      void
      contact_matrix(const Factorization              &f,
                     const TruncatedNewtonSystem      &system,
                     const std::vector<unsigned int>  &active,
                     const std::vector<int>           &active_position,
                     dealii::LAPACKFullMatrix<double> &S) const;

      std::vector<std::unique_ptr<Factorization>> cache;
      std::vector<global_dof_index>               interior, contact_dofs;
      std::vector<int> interior_index; // dof -> index in interior, or -1
      std::vector<int> contact_index;  // dof -> index in contact_dofs, or -1
      dealii::Vector<double>           b_I, y;       // work vectors of solve()
      dealii::LAPACKFullMatrix<double> contact_work; // S_aa + H_aa, factorised
    };
  } // namespace solvers
} // namespace rsfcycle

#endif
