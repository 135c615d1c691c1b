#ifndef rsfcycle_la_h
#define rsfcycle_la_h

#include <algorithm>
#include <deal.II/base/mpi.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/sparse_matrix.h>
#include <memory>
#include <stdexcept>
#include <string>
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
     * The layout that loaded vectors get (set by the model before a
     * checkpoint is read): its owned entries must be as many as were saved.
     */
    inline std::shared_ptr<const dealii::Utilities::MPI::Partitioner> &
    load_partitioner()
    {
      static std::shared_ptr<const dealii::Utilities::MPI::Partitioner> p;
      return p;
    }

    /**
     * Boost serialization of a vector's locally owned entries (deal.II's
     * distributed vector has none: its base class's serialize() writes
     * nothing). Loading puts them on load_partitioner() (or, if none is
     * set, on a vector of this rank alone).
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
      const auto         &partitioner = load_partitioner();
      if (partitioner && partitioner->locally_owned_size() == values.size())
        v.reinit(partitioner);
      else if (partitioner)
        throw std::invalid_argument(
          "checkpoint: " + std::to_string(values.size()) +
          " entries of a vector where this rank owns " +
          std::to_string(partitioner->locally_owned_size()));
      else
        v.reinit(values.size());
      std::copy(values.begin(), values.end(), v.begin());
    }

  } // namespace la
} // namespace rsfcycle

#endif
