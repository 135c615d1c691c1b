#ifndef rsfcycle_solvers_local_sor_h
#define rsfcycle_solvers_local_sor_h

#include <rsfcycle/la.h>
#include <rsfcycle/local_matrix.h>

namespace rsfcycle
{
  namespace solvers
  {
    /**
     * Gauss-Seidel (SOR) relaxation of a rank's rows (LocalMatrix) for the
     * multigrid smoother: the interface of deal.II's PreconditionSOR (which
     * takes serial vectors only), the same arithmetic. Ghost values are
     * those of the vector as given (processor-local SOR: lagged across
     * ranks).
     */
    class LocalSOR
    {
    public:
      struct AdditionalData
      {
        explicit AdditionalData(const double omega = 1.)
          : omega(omega)
        {}
        double omega;
      };

      void
      initialize(const la::LocalMatrix &matrix,
                 const AdditionalData  &data = AdditionalData())
      {
        A     = &matrix;
        omega = data.omega;
      }

      void
      clear()
      {
        A = nullptr;
      }

      void
      vmult(la::Vector &dst, const la::Vector &src) const
      {
        A->precondition_SOR(dst, src, omega);
      }

      void
      Tvmult(la::Vector &dst, const la::Vector &src) const
      {
        A->precondition_TSOR(dst, src, omega);
      }

      void
      step(la::Vector &v, const la::Vector &b) const
      {
        A->SOR_step(v, b, omega);
      }

      void
      Tstep(la::Vector &v, const la::Vector &b) const
      {
        A->TSOR_step(v, b, omega);
      }

    private:
      const la::LocalMatrix *A     = nullptr;
      double                 omega = 1;
    };
  } // namespace solvers
} // namespace rsfcycle

#endif
