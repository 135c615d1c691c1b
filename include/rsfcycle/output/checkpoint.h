#ifndef rsfcycle_output_checkpoint_h
#define rsfcycle_output_checkpoint_h

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <functional>
#include <string>

namespace rsfcycle
{
  namespace output
  {
    /**
     * Write dir/checkpoint.bin through `save`: first to a temporary file,
     * then renamed, so that the previous checkpoint survives until the new
     * one is complete.
     */
    void
    write_checkpoint(
      const std::string                                            &dir,
      const std::function<void(boost::archive::binary_oarchive &)> &save);

    /**
     * Read dir/checkpoint.bin through `load`; a missing file is an
     * std::invalid_argument naming the folder.
     */
    void
    read_checkpoint(
      const std::string                                            &dir,
      const std::function<void(boost::archive::binary_iarchive &)> &load);
  } // namespace output
} // namespace rsfcycle

#endif
