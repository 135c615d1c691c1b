// SPDX-License-Identifier: LGPL-2.1-or-later
// Checks the checkpoint format (output/checkpoint.h, doc/checkpoints.md)
// through write_checkpoint and read_checkpoint on files in the folder
// "run":
//  - a checkpoint reads back what was written; a second one keeps the
//    first as checkpoint.bin.prev (bitwise);
//  - every kind of mismatch is refused with its one-line message naming
//    the file: missing, truncated, damaged payload, damaged header, bytes
//    appended, another format version, not a checkpoint, a checkpoint of
//    the format before headers, another scene, dimension, number of MPI
//    ranks (in both directions) or unknowns;
//  - the message says that checkpoint.bin.prev is intact where it is, and
//    nothing about it where it is damaged too;
//  - a refused checkpoint leaves both files as they were;
//  - a write into a missing folder is one line naming the file and the
//    system's reason.
// The program version in messages is printed as X.
#include "tests.h"

#include <boost/serialization/vector.hpp>
#include <filesystem>
#include <regex>
#include <rsfcycle/output/checkpoint.h>
#include <sstream>
#include <vector>

using namespace rsfcycle::output;

namespace
{
  const std::string dir = "run", bin = "run/checkpoint.bin",
                    prev = "run/checkpoint.bin.prev";

  std::string
  read_file(const std::string &path)
  {
    std::ifstream      in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
  }

  void
  write_bytes(const std::string &path, const std::string &bytes)
  {
    std::ofstream(path, std::ios::binary) << bytes;
  }

  /** A checkpoint of 200 doubles of value x. */
  void
  write(const CheckpointIdentity &identity,
        const double              x,
        const std::string        &folder = dir)
  {
    write_checkpoint(folder,
                     identity,
                     [x](boost::archive::binary_oarchive &ar) {
                       const std::vector<double> values(200, x);
                       ar << values;
                     });
  }

  /** The value read back, or the message of the refusal. */
  std::string
  resume(const CheckpointIdentity &identity, const std::string &folder = dir)
  {
    try
      {
        std::vector<double> values;
        read_checkpoint(folder,
                        identity,
                        [&](boost::archive::binary_iarchive &ar) {
                          ar >> values;
                        });
        return "read " + std::to_string(values.size()) + " values " +
               std::to_string(static_cast<int>(values[0]));
      }
    catch (const std::exception &error)
      {
        return std::regex_replace(error.what(),
                                  std::regex("rsfcycle [0-9][0-9.]*"),
                                  "rsfcycle X");
      }
  }
} // namespace


int
main()
{
  initlog();
  std::filesystem::remove_all(dir);
  std::filesystem::remove_all("ranks");
  std::filesystem::create_directories(dir);
  const CheckpointIdentity wedge{"wedge", 2, 1050, 1};

  dealii::deallog << "missing: " << resume(wedge) << std::endl;
  write(wedge, 1);
  dealii::deallog << "first: " << resume(wedge) << std::endl;
  const std::string first = read_file(bin);
  write(wedge, 2);
  dealii::deallog << "second: " << resume(wedge) << std::endl;
  dealii::deallog << "size " << read_file(bin).size()
                  << ", previous kept bitwise: "
                  << (read_file(prev) == first ? "yes" : "no") << std::endl;

  // identity: the previous checkpoint has the same, so no hint
  CheckpointIdentity other = wedge;
  other.scene              = "spring-slider";
  dealii::deallog << "scene: " << resume(other) << std::endl;
  other           = wedge;
  other.dimension = 3;
  dealii::deallog << "dimension: " << resume(other) << std::endl;
  other         = wedge;
  other.n_ranks = 4;
  dealii::deallog << "ranks: " << resume(other) << std::endl;
  std::filesystem::create_directories("ranks");
  write(other, 1, "ranks");
  dealii::deallog << "written on 4 ranks: " << resume(wedge, "ranks")
                  << std::endl;
  other            = wedge;
  other.n_unknowns = 8070;
  dealii::deallog << "unknowns: " << resume(other) << std::endl;

  // damage to checkpoint.bin, the previous one intact
  const std::string good = read_file(bin);
  const auto damaged = [&](const std::string &label, const std::string &bytes) {
    write_bytes(bin, bytes);
    const std::string before = read_file(bin) + read_file(prev);
    dealii::deallog << label << ": " << resume(wedge) << std::endl;
    if (read_file(bin) + read_file(prev) != before)
      dealii::deallog << "  the files changed" << std::endl;
  };
  damaged("truncated", good.substr(0, 1000));
  damaged("truncated header", good.substr(0, 50));
  damaged("empty", "");
  std::string bytes = good;
  for (unsigned int i = 0; i < 64; ++i)
    bytes[bytes.size() / 2 + i] ^= 0x5a;
  damaged("payload", bytes);
  bytes = good;
  bytes[64] ^= 1; // the number of unknowns
  damaged("header", bytes);
  damaged("appended", good + "x");
  bytes    = good;
  bytes[8] = rsfcycle::output::checkpoint_format + 1; // another format
  damaged("format", bytes);
  damaged("not a checkpoint", "time_s,step_size_s\n1,2\n");
  {
    std::ostringstream old;
    {
      boost::archive::binary_oarchive archive(old);
      archive << std::vector<double>(3, 1.);
    }
    damaged("headerless", old.str());
  }

  // both damaged: no hint
  write_bytes(prev, good.substr(0, 500));
  damaged("both truncated", good.substr(0, 1000));
  write_bytes(prev, good);
  std::filesystem::remove(bin);
  dealii::deallog << "missing, previous intact: " << resume(wedge) << std::endl;

  // a failed write: one line naming the file and the reason
  try
    {
      write_checkpoint("no-such-folder",
                       wedge,
                       [](boost::archive::binary_oarchive &) {});
    }
  catch (const std::exception &error)
    {
      dealii::deallog << "write: " << error.what() << std::endl;
    }
}
