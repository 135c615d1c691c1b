// SPDX-License-Identifier: LGPL-2.1-or-later
#pragma once

#include <string>

namespace rsfcycle
{
  /**
   * Which program wrote a run folder: the version of the source, the git
   * commit it was built from (taken at every build by source/version.cmake,
   * "-dirty" when the working tree had changes), the deal.II it was
   * compiled against and the build type. `rsfcycle --version` prints them,
   * log.txt and parameters.prm start with them, checkpoint and SEAS file
   * headers carry them.
   */
  namespace version
  {
    /** The version of the source, as in CMakeLists.txt's project(). */
    extern const char *const number;
    /** `git describe --always --dirty` of the source tree at build time. */
    extern const char *const commit;
    /** Release or Debug. */
    extern const char *const build_type;

    /**
     * One line: "rsfcycle 0.1.0, commit abc1234, deal.II 9.4.1, Release".
     */
    std::string
    describe();
  } // namespace version
} // namespace rsfcycle
