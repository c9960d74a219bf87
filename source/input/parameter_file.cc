#include <deal.II/base/utilities.h>

#include <signorini/input/parameter_file.h>
#include <signorini/input/text_check.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <sstream>

namespace signorini
{
  namespace fs = std::filesystem;

  /**
   * Reads a file's logical lines into the text, in place of each `include`
   * line the lines of the file it names, depth first, and follows the
   * subsections that ParameterHandler will enter and leave.
   */
  class ParameterFile::Reader
  {
  public:
    Reader(ParameterFile &input)
      : input(input)
      , folder(fs::path(input.path).parent_path())
    {
    }

    /** Reads the file @p canonical, shown to the user as @p shown and named
     * @p name by ParameterHandler. */
    void
    read(const fs::path    &canonical,
         const std::string &shown,
         const std::string &name)
    {
      chain.push_back(canonical);
      shown_chain.push_back(shown);
      std::ifstream     file_in(canonical, std::ios::binary);
      const std::string bytes((std::istreambuf_iterator<char>(file_in)),
                              std::istreambuf_iterator<char>());
      if (const auto problem = text_check::first_unexpected(bytes))
        throw InputError::at(shown + ":" + std::to_string(problem->line) + ":" +
                               std::to_string(problem->column),
                             problem->what);
      // A byte-order mark at the start is the encoding's signature, not
      // text.
      std::istringstream in(
        bytes.substr(text_check::starts_with_bom(bytes) ? 3 : 0));
      std::string  physical, logical;
      unsigned int number = 0, first = 0;
      bool         continued = false;
      // As ParameterHandler::parse_input joins lines.
      while (std::getline(in, physical))
        {
          ++number;
          if (!continued)
            first = number;
          physical = dealii::Utilities::trim(physical);
          if (!physical.empty() && physical.back() == '\\')
            {
              physical.pop_back();
              logical += physical;
              continued = true;
              continue;
            }
          logical += physical;
          continued = false;
          scan(logical, name, first, first);
          logical.clear();
        }
      // ParameterHandler numbers a line by its first line, except a line
      // continued at the end of the file, by the file's last line.
      if (continued)
        scan(logical, name, first, number);
      chain.pop_back();
      shown_chain.pop_back();
    }

  private:
    /** One logical line, from line @p first of the file @p name, which
     * ParameterHandler's messages give as line @p number. */
    void
    scan(const std::string &logical,
         const std::string &name,
         const unsigned int first,
         const unsigned int number)
    {
      // As ParameterHandler::scan_line reads a line.
      std::string line = logical;
      if (line.find('#') != std::string::npos)
        line.erase(line.find('#'));
      std::replace(line.begin(), line.end(), '\t', ' ');
      line              = dealii::Utilities::trim(line);
      const auto starts = [&](const char *lower, const char *upper) {
        return line.rfind(lower, 0) == 0 || line.rfind(upper, 0) == 0;
      };
      if (starts("include ", "INCLUDE "))
        {
          line.erase(0, 7);
          line.erase(0, line.find_first_not_of(' '));
          include(line, shown_chain.back() + ":" + std::to_string(first));
          return;
        }
      if (starts("set ", "SET "))
        input.sets_entries = true;
      if (starts("subsection ", "SUBSECTION "))
        subsections.push_back(dealii::Utilities::trim(line.substr(11)));
      else if (starts("end", "END") && !subsections.empty())
        subsections.pop_back();
      input.lines.push_back({logical, name, number});
    }

    /** The `include` line at @p where naming @p name. */
    void
    include(const std::string &name, const std::string &where)
    {
      const fs::path    target = folder / name;
      const std::string what   = "include '" + name + "'";
      // The name as seen from the current folder.
      const std::string shown =
        (fs::path(shown_chain.front()).parent_path() / name)
          .lexically_normal()
          .string();
      std::error_code error;
      if (fs::is_directory(target, error))
        throw InputError::at(where,
                             what + " names a directory, not a parameter file");
      if (!fs::is_regular_file(target, error) || !std::ifstream(target))
        {
          // Where it looked: include names are relative to the top file's
          // folder, whichever file includes them.
          const std::string looked =
            fs::absolute(target, error).lexically_normal().string();
          throw InputError::at(
            where,
            what + ": cannot open the file: " +
              (fs::exists(target, error) ? "cannot read " : "there is no ") +
              looked +
              " (include names are relative to the folder of the first "
              "parameter file)");
        }

      const fs::path canonical = fs::weakly_canonical(target, error);
      for (unsigned int i = 0; i < chain.size(); ++i)
        if (chain[i] == canonical)
          {
            std::string cycle;
            for (unsigned int j = i; j < shown_chain.size(); ++j)
              cycle += shown_chain[j] + " -> ";
            throw InputError::at(where,
                                 what + " forms a cycle of includes: " + cycle +
                                   shown);
          }
      const std::string included = canonical.parent_path().string();
      auto             &folders  = input.folder_list;
      if (std::find(folders.begin() + 1, folders.end(), included) ==
          folders.end())
        folders.push_back(included);

      const auto before = subsections;
      read(canonical, shown, name);
      // ParameterHandler requires a file to end in the subsection it began
      // in; the first file that does not is an error once the lines before
      // its end are read.
      if (subsections != before && !input.unbalanced)
        input.unbalanced = Unbalanced{input.lines.size(),
                                      subsections.size(),
                                      unbalanced_error(name, before)};
      subsections = before;
    }

    /** ParameterHandler's message for the file @p name that began in the
     * subsections @p before and ended in the current ones. */
    InputError
    unbalanced_error(const std::string              &name,
                     const std::vector<std::string> &before) const
    {
      std::ostringstream paths;
      if (!before.empty())
        {
          paths << "Path before loading input:\n";
          for (unsigned int i = 0; i < before.size(); ++i)
            paths << std::setw(i * 2 + 4) << " "
                  << "subsection " << before[i] << '\n';
          paths << "Current path:\n";
          for (unsigned int i = 0; i < subsections.size(); ++i)
            paths << std::setw(i * 2 + 4) << " "
                  << "subsection " << subsections[i]
                  << (i + 1 == subsections.size() ? "" : "\n");
        }
      return InputError::at(
        input.file,
        one_line(dealii::ParameterHandler::ExcUnbalancedSubsections(
          name, paths.str())));
    }

    ParameterFile &input;
    /** The top file's folder, which include names are relative to. */
    const fs::path folder;
    /** The files being read, outermost first, by their canonical paths, and
     * as the user sees them. */
    std::vector<fs::path>    chain;
    std::vector<std::string> shown_chain;
    /** The subsections entered at the current line. */
    std::vector<std::string> subsections;
  };

  ParameterFile::ParameterFile(const std::string &file)
    : file(file)
    , path(fs::absolute(file).string())
  {
    const auto dot    = path.find_last_of('.');
    const auto ending = path.substr(dot == std::string::npos ? 0 : dot + 1);
    whole             = ending == "xml" || ending == "json";
    known             = whole || ending == "prm";
    if (!known)
      throw InputError::at(file,
                           "Unknown input file name extension. Supported "
                           "types are .prm, .xml, and .json.");
    folder_list.push_back(fs::path(path).parent_path().string());
    std::error_code error;
    Reader(*this).read(fs::weakly_canonical(path, error), file, path);
    if (!whole && !sets_entries)
      throw InputError::at(file,
                           "sets no entries (an empty scene is the default "
                           "one-cell body without load); start from a scene "
                           "of prm/ or from signorini --print-parameters");
  }

  void
  ParameterFile::parse(dealii::ParameterHandler &prm,
                       const bool                skip_undefined) const
  {
    try
      {
        if (whole)
          {
            prm.parse_input(path, "", skip_undefined);
            return;
          }
        std::string       text;
        const std::size_t n_lines =
          unbalanced ? unbalanced->n_lines : lines.size();
        for (std::size_t i = 0; i < n_lines; ++i)
          text += lines[i].text + '\n';
        // The subsections that the unbalanced file left open are closed, so
        // that the error is that file's and not the top file's.
        if (unbalanced)
          for (std::size_t i = 0; i < unbalanced->depth; ++i)
            text += "end\n";
        std::istringstream in(text);
        prm.parse_input(in, path, "", skip_undefined);
      }
    catch (const dealii::ExceptionBase &error)
      {
        throw located(one_line(error));
      }
    if (unbalanced)
      throw unbalanced->error;
  }

  const std::vector<std::string> &
  ParameterFile::folders() const
  {
    return folder_list;
  }

  std::optional<std::string>
  ParameterFile::included_setting(const std::string &entry) const
  {
    const auto trimmed = [](const std::string &text) {
      const auto first = text.find_first_not_of(" \t");
      if (first == std::string::npos)
        return std::string();
      return text.substr(first, text.find_last_not_of(" \t") - first + 1);
    };
    std::vector<std::string>   sections;
    std::optional<std::string> found;
    for (const auto &line : lines)
      {
        const std::string text = trimmed(
          line.text.substr(0, std::min(line.text.find('#'), line.text.size())));
        const auto        space = text.find_first_of(" \t");
        const std::string word  = text.substr(0, space);
        const std::string rest =
          space == std::string::npos ? "" : trimmed(text.substr(space));
        if (word == "subsection")
          sections.push_back(rest);
        else if (word == "end" && !sections.empty())
          sections.pop_back();
        else if (word == "set" && rest.find('=') != std::string::npos)
          {
            std::string name;
            for (const auto &section : sections)
              name += section + "/";
            name += trimmed(rest.substr(0, rest.find('=')));
            if (name == entry)
              found = line.file == path ?
                        std::optional<std::string>() :
                        line.file + ":" + std::to_string(line.number);
          }
      }
    return found;
  }

  namespace
  {
    /** Whether @p message starts with "Line <N> of file <": then @p n is N
     * and @p after the position after the '<' of the file. */
    bool
    starts_with_line(const std::string &message,
                     unsigned int      &n,
                     std::size_t       &after)
    {
      const std::string line = "Line <", of_file = "> of file <";
      if (message.compare(0, line.size(), line) != 0)
        return false;
      std::size_t end = line.size();
      while (end < message.size() && end < line.size() + 9 &&
             std::isdigit(static_cast<unsigned char>(message[end])))
        ++end;
      if (end == line.size() || message.compare(end, of_file.size(), of_file))
        return false;
      n     = std::stoul(message.substr(line.size(), end - line.size()));
      after = end + of_file.size();
      return true;
    }
  } // namespace

  InputError
  ParameterFile::located(const std::string &message) const
  {
    // "Line <N> of file <PATH" names a line of the text: name its file and
    // its line there instead. (No std::regex: its recursion overflows the
    // stack on a long line.)
    std::string  located_message = message;
    unsigned int n               = 0;
    std::size_t  after           = 0;
    if (starts_with_line(message, n, after) &&
        message.compare(after, path.size(), path) == 0 && n >= 1 &&
        n <= lines.size())
      located_message = "Line <" + std::to_string(lines[n - 1].number) +
                        "> of file <" + lines[n - 1].file +
                        message.substr(after + path.size());

    // "Line <N> of file <FILE>: what" is "FILE:N: what".
    if (starts_with_line(located_message, n, after))
      {
        const auto close = located_message.find('>', after);
        if (close != std::string::npos &&
            located_message.compare(close, 3, ">: ") == 0)
          {
            const std::string named =
              located_message.substr(after, close - after);
            const std::string where = named == path ? file : named;
            return InputError::at(where + ":" + std::to_string(n),
                                  located_message.substr(close + 3));
          }
      }
    return InputError::at(file, located_message);
  }
} // namespace signorini
