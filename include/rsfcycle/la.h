#ifndef rsfcycle_la_h
#define rsfcycle_la_h

#include <algorithm>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/sparse_matrix.h>
#include <vector>

namespace rsfcycle
{
  namespace la
  {
    /**
     * The vector of every field of the continuum (displacement, velocity,
     * right-hand sides, solver work vectors): deal.II's distributed vector
     * on the partitioner of the discretisation (locally owned dofs first,
     * then the ghosts of locally relevant dofs). On one rank it holds every
     * dof; kernels that index it by global dof index (operator[]) are
     * correct only on owned and ghost entries (doc/design.md, Distributed
     * runs).
     */
    using Vector = dealii::LinearAlgebra::distributed::Vector<double>;

    /**
     * Boost serialization of a vector's locally owned entries (deal.II's
     * distributed vector has none: its base class's serialize() writes
     * nothing). Loading gives a vector of as many entries on this rank
     * alone; the model moves it onto its partitioner (one rank: the same
     * layout).
     */
    template <class Archive>
    void
    save(Archive &ar, const Vector &v)
    {
      std::vector<double> values(v.begin(), v.end());
      ar                 &values;
    }

    template <class Archive>
    void
    load(Archive &ar, Vector &v)
    {
      std::vector<double> values;
      ar                 &values;
      v.reinit(values.size());
      std::copy(values.begin(), values.end(), v.begin());
    }

  } // namespace la
} // namespace rsfcycle

#endif
