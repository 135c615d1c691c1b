// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_output_checkpoint_h
#define rsfcycle_output_checkpoint_h

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <cstdint>
#include <functional>
#include <string>

namespace rsfcycle
{
  namespace output
  {
    /**
     * The checkpoint format this program writes and reads. Increase it
     * whenever the header or anything serialised changes (the simulator's
     * LoopState, the integrator's memory, a writer's save()): a checkpoint
     * of another format is refused on resume, never misread. Format 3: the
     * writers keep their own times and file sizes; format 4: the SEAS files'
     * time-step statistics, the events' moments.
     */
    constexpr std::uint32_t checkpoint_format = 4;

    /**
     * What a checkpoint was written for, given by the model: its scene, the
     * dimension of its mesh (0 for a model without one), its number of
     * unknowns (degrees of freedom, or the size of the state) and the
     * number of MPI ranks that wrote it. Resuming refuses a checkpoint whose
     * identity differs from the run's.
     */
    struct CheckpointIdentity
    {
      std::string   scene;
      std::uint32_t dimension  = 0;
      std::uint64_t n_unknowns = 0;
      std::uint32_t n_ranks    = 1;
    };

    /**
     * Write dir/checkpoint.bin: a header (magic "rsfcycle", format and
     * program version, the identity, payload size, CRC32 of the payload
     * and of the header; doc/checkpoints.md) followed by the Boost binary
     * archive that `save` fills. The file is written to checkpoint.tmp and
     * synced, the previous checkpoint is kept as checkpoint.bin.prev, the
     * new one renamed to checkpoint.bin and the folder synced: at every
     * moment checkpoint.bin is a complete checkpoint, also after a power
     * loss. A failed write is a std::runtime_error naming the file and the
     * reason; the last checkpoint stays as it was.
     */
    void
    write_checkpoint(
      const std::string                                            &dir,
      const CheckpointIdentity                                     &identity,
      const std::function<void(boost::archive::binary_oarchive &)> &save);

    /**
     * Read dir/checkpoint.bin through `load` after checking it against
     * `identity`: a missing, truncated, damaged (checksum) file, another
     * format, scene, dimension, number of ranks or unknowns is an
     * std::invalid_argument of one line, "dir/checkpoint.bin: what is
     * wrong", which also says whether checkpoint.bin.prev is intact and how
     * to use it. Nothing is read into the run before all checks passed.
     */
    void
    read_checkpoint(
      const std::string                                            &dir,
      const CheckpointIdentity                                     &identity,
      const std::function<void(boost::archive::binary_iarchive &)> &load);
  } // namespace output
} // namespace rsfcycle

#endif
