// SPDX-License-Identifier: LGPL-2.1-or-later
#include <fstream>
#include <rsfcycle/parameter_file.h>
#include <sstream>
#include <stdexcept>

namespace rsfcycle
{
  namespace fs = std::filesystem;

  fs::path
  resolve_input_path(const fs::path    &path,
                     const fs::path    &folder,
                     const std::string &what)
  {
    if (path.is_absolute())
      {
        if (!fs::exists(path))
          throw std::invalid_argument(what + " = " + path.string() +
                                      ": no such file");
        return path;
      }
    const fs::path beside = (fs::absolute(folder) / path).lexically_normal();
    const fs::path here   = fs::absolute(path).lexically_normal();
    if (fs::exists(beside))
      return beside;
    if (fs::exists(here))
      return here;
    throw std::invalid_argument(
      what + " = " + path.string() +
      ": no such file beside the parameter file (" + beside.string() +
      ") or in the working directory (" + here.string() + ")");
  }


  namespace
  {
    std::string
    trimmed(const std::string &line)
    {
      const auto first = line.find_first_not_of(" \t\r");
      if (first == std::string::npos)
        return "";
      return line.substr(first, line.find_last_not_of(" \t\r") - first + 1);
    }

    /**
     * Parse `file` into prm, one piece between top-level `include` lines at
     * a time (each piece preceded by as many empty lines as come before it,
     * so that deal.II's messages give the file's own line numbers), and
     * the included files recursively in their place. After each piece,
     * `parsed(folder of file)`.
     */
    template <typename Parsed>
    void
    parse_with_includes(dealii::ParameterHandler &prm,
                        const fs::path           &file,
                        const unsigned int        depth,
                        const Parsed             &parsed)
    {
      if (depth > 16)
        throw std::invalid_argument("include in " + file.string() +
                                    ": more than 16 levels (a cycle?)");
      std::ifstream input(file);
      if (!input)
        throw std::invalid_argument("parameter file " + file.string() +
                                    " cannot be read");
      std::string  piece, line;
      unsigned int line_number = 0, nesting = 0;
      const auto   parse_piece = [&]() {
        std::istringstream text(piece);
        prm.parse_input(text, file.string(), "", false);
        parsed(file.parent_path());
        piece = std::string(line_number, '\n');
      };
      while (std::getline(input, line))
        {
          ++line_number;
          const std::string text = trimmed(line);
          if (text.rfind("subsection ", 0) == 0)
            ++nesting;
          else if (text == "end" && nesting > 0)
            --nesting;
          if (nesting == 0 && text.rfind("include ", 0) == 0)
            {
              piece += '\n';
              parse_piece();
              const std::string name = trimmed(text.substr(8));
              parse_with_includes(
                prm,
                resolve_input_path(name,
                                   file.parent_path(),
                                   "line " + std::to_string(line_number) +
                                     " of " + file.string() + ": include"),
                depth + 1,
                parsed);
            }
          else
            piece += line + '\n';
        }
      parse_piece();
    }
  } // namespace


  void
  parse_parameter_file(
    dealii::ParameterHandler                               &prm,
    const std::string                                      &file,
    const std::vector<std::pair<std::string, std::string>> &file_entries)
  {
    // each entry's value and the folder of the file that set it last
    const auto value = [&](const std::pair<std::string, std::string> &e) {
      prm.enter_subsection(e.first);
      const std::string text = prm.get(e.second);
      prm.leave_subsection();
      return text;
    };
    std::vector<std::pair<std::string, fs::path>> set_by;
    for (const auto &entry : file_entries)
      set_by.emplace_back(value(entry), fs::current_path());
    parse_with_includes(prm,
                        fs::absolute(file),
                        0,
                        [&](const fs::path &folder) {
                          for (unsigned int i = 0; i < file_entries.size(); ++i)
                            if (const std::string text = value(file_entries[i]);
                                text != set_by[i].first)
                              set_by[i] = {text, folder};
                        });
    for (unsigned int i = 0; i < file_entries.size(); ++i)
      if (const auto &[text, folder] = set_by[i]; !text.empty())
        {
          const auto &[subsection, entry] = file_entries[i];
          const fs::path resolved =
            resolve_input_path(text, folder, subsection + "/" + entry);
          prm.enter_subsection(subsection);
          prm.set(entry, resolved.string());
          prm.leave_subsection();
        }
  }
} // namespace rsfcycle
