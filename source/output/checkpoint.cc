#include <filesystem>
#include <fstream>
#include <rsfcycle/output/checkpoint.h>
#include <stdexcept>

namespace rsfcycle
{
  namespace output
  {
    void
    write_checkpoint(
      const std::string                                            &dir,
      const std::function<void(boost::archive::binary_oarchive &)> &save)
    {
      const std::string tmp = dir + "/checkpoint.tmp";
      {
        std::ofstream                   out(tmp, std::ios::binary);
        boost::archive::binary_oarchive archive(out);
        save(archive);
        out.flush();
        if (!out)
          throw std::runtime_error("cannot write the checkpoint " + tmp);
      }
      std::filesystem::rename(tmp, dir + "/checkpoint.bin");
    }


    void
    read_checkpoint(
      const std::string                                            &dir,
      const std::function<void(boost::archive::binary_iarchive &)> &load)
    {
      std::ifstream in(dir + "/checkpoint.bin", std::ios::binary);
      if (!in)
        throw std::invalid_argument("--resume " + dir +
                                    ": no checkpoint.bin in this folder");
      boost::archive::binary_iarchive archive(in);
      load(archive);
    }
  } // namespace output
} // namespace rsfcycle
