#include <deal.II/base/utilities.h>

#include <signorini/input/include_check.h>
#include <signorini/input/input_error.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <vector>

namespace signorini
{
  namespace
  {
    namespace fs = std::filesystem;

    /** An `include` line: where it is and the file it names. */
    struct Include
    {
      unsigned int line;
      std::string  name;
    };

    /** The `include` lines of @p in, read the way ParameterHandler reads
     * lines (see ParameterHandler::parse_input and scan_line). */
    std::vector<Include>
    find_includes(std::istream &in)
    {
      std::vector<Include> includes;
      std::string          line, logical;
      unsigned int         number = 0, logical_number = 0;
      bool                 continued = false;
      const auto           scan      = [&](std::string text) {
        if (text.find('#') != std::string::npos)
          text.erase(text.find('#'));
        for (char &c : text)
          if (c == '\t')
            c = ' ';
        text = dealii::Utilities::trim(text);
        if (text.rfind("include ", 0) != 0 && text.rfind("INCLUDE ", 0) != 0)
          return;
        text.erase(0, 7);
        while (!text.empty() && text[0] == ' ')
          text.erase(0, 1);
        // An include without a name is left to ParameterHandler's message.
        if (!text.empty())
          includes.push_back({logical_number, text});
      };
      while (std::getline(in, line))
        {
          ++number;
          if (!continued)
            logical_number = number;
          line = dealii::Utilities::trim(line);
          if (!line.empty() && line.back() == '\\')
            {
              line.pop_back();
              logical += line;
              continued = true;
              continue;
            }
          logical += line;
          continued = false;
          scan(logical);
          logical.clear();
        }
      if (continued)
        scan(logical);
      return includes;
    }

    /** Depth-first search of the include graph; @p chain holds the files
     * being read, outermost first, by their canonical paths, and @p shown
     * the same files as the user sees them. */
    void
    visit(const fs::path           &folder,
          const std::string        &shown_file,
          std::vector<fs::path>    &chain,
          std::vector<std::string> &shown,
          std::vector<std::string> &folders)
    {
      std::ifstream in(chain.back());
      for (const auto &include : find_includes(in))
        {
          const std::string where =
            shown_file + ":" + std::to_string(include.line);
          const fs::path    target = folder / include.name;
          const std::string what   = "include '" + include.name + "'";
          // The name as seen from the current folder.
          const std::string target_shown =
            (fs::path(shown.front()).parent_path() / include.name)
              .lexically_normal()
              .string();
          std::error_code error;
          if (fs::is_directory(target, error))
            throw InputError::at(where,
                                 what +
                                   " names a directory, not a parameter file");
          if (!fs::is_regular_file(target, error) || !std::ifstream(target))
            throw InputError::at(where, what + ": cannot open the file");

          const fs::path canonical = fs::weakly_canonical(target, error);
          for (unsigned int i = 0; i < chain.size(); ++i)
            if (chain[i] == canonical)
              {
                std::string cycle;
                for (unsigned int j = i; j < shown.size(); ++j)
                  cycle += shown[j] + " -> ";
                throw InputError::at(where,
                                     what + " forms a cycle of includes: " +
                                       cycle + target_shown);
              }
          const std::string included = canonical.parent_path().string();
          if (std::find(folders.begin(), folders.end(), included) ==
              folders.end())
            folders.push_back(included);
          chain.push_back(canonical);
          shown.push_back(target_shown);
          visit(folder, target_shown, chain, shown, folders);
          chain.pop_back();
          shown.pop_back();
        }
    }
  } // namespace

  std::vector<std::string>
  check_includes(const std::string &file)
  {
    std::error_code          error;
    const fs::path           path = fs::absolute(file);
    std::vector<fs::path>    chain{fs::weakly_canonical(path, error)};
    std::vector<std::string> shown{file};
    std::vector<std::string> folders;
    visit(path.parent_path(), file, chain, shown, folders);
    return folders;
  }
} // namespace signorini
