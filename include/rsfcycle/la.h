// SPDX-License-Identifier: LGPL-2.1-or-later
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
#include <type_traits>
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

    /**
     * The entries of every rank's `local` concatenated rank by rank, on
     * every rank (MPI_Allgatherv of raw doubles: deal.II's all_gather
     * serialises and compresses, which costs more than the gather itself
     * for the per-iteration node data). T is double or an array of doubles.
     */
    template <typename T>
    std::vector<T>
    all_gather(const MPI_Comm &comm, const std::vector<T> &local)
    {
      static_assert(std::is_trivially_copyable<T>::value &&
                      sizeof(T) % sizeof(double) == 0,
                    "gathered as doubles");
      constexpr int per  = sizeof(T) / sizeof(double);
      const int     size = dealii::Utilities::MPI::n_mpi_processes(comm);
      if (size == 1)
        return local;
      const int        count = per * static_cast<int>(local.size());
      std::vector<int> counts(size), offsets(size, 0);
      MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
      for (int r = 1; r < size; ++r)
        offsets[r] = offsets[r - 1] + counts[r - 1];
      std::vector<T> all((offsets.back() + counts.back()) / per);
      MPI_Allgatherv(local.data(),
                     count,
                     MPI_DOUBLE,
                     all.data(),
                     counts.data(),
                     offsets.data(),
                     MPI_DOUBLE,
                     comm);
      return all;
    }
  } // namespace la
} // namespace rsfcycle

#endif
