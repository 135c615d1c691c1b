// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_parameter_file_h
#define rsfcycle_parameter_file_h

#include <deal.II/base/parameter_handler.h>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace rsfcycle
{
  /**
   * A path written in a parameter file, made absolute: a relative path is
   * looked up in the folder of the parameter file (`folder`) first, then
   * in the working directory. A path found in neither throws
   * std::invalid_argument: "WHAT = PATH: no such file beside the parameter
   * file (A) or in the working directory (B)".
   */
  std::filesystem::path
  resolve_input_path(const std::filesystem::path &path,
                     const std::filesystem::path &folder,
                     const std::string           &what);

  /**
   * Read a parameter file into prm with the paths in it resolved by
   * resolve_input_path(), so that a `.prm` runs from any working
   * directory:
   * - `include FILE` at the top level (outside any subsection), in the
   *   file and in the files it includes, relative to the including file;
   * - the input-file entries `file_entries` (subsection, entry), such as
   *   `Mesh file/File`, relative to the file that set them (the main file
   *   or an included one), and written back into prm as absolute paths
   *   (parameters.prm in the run folder records them, so --resume works
   *   from anywhere). Empty entries are left empty.
   * Error messages keep the line numbers of the file they name.
   */
  void
  parse_parameter_file(
    dealii::ParameterHandler                               &prm,
    const std::string                                      &file,
    const std::vector<std::pair<std::string, std::string>> &file_entries);
} // namespace rsfcycle

#endif
