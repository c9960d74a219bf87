#include <signorini/output/output_series.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <utility>

namespace signorini
{
  namespace output_series
  {
    namespace
    {
      /**
       * If @p text is @p prefix followed by @p minimum digits or more: the
       * number they make and the rest of @p text. Numbers of more than nine
       * digits are no cycle's.
       */
      std::optional<std::pair<unsigned int, std::string>>
      numbered(const std::string &text,
               const std::string &prefix,
               const std::size_t  minimum)
      {
        if (text.compare(0, prefix.size(), prefix) != 0)
          return {};
        std::size_t end = prefix.size();
        while (end < text.size() &&
               std::isdigit(static_cast<unsigned char>(text[end])))
          ++end;
        const std::size_t n_digits = end - prefix.size();
        if (n_digits < minimum || n_digits > 9)
          return {};
        return std::make_pair(static_cast<unsigned int>(std::stoul(
                                text.substr(prefix.size(), n_digits))),
                              text.substr(end));
      }
    } // namespace

    Member
    classify(const std::string &file_name)
    {
      Member            member;
      std::string       name = file_name;
      const std::string part = ".part";
      if (name.size() > part.size() &&
          name.compare(name.size() - part.size(), part.size(), part) == 0)
        {
          member.partial = true;
          name.erase(name.size() - part.size());
        }
      if (name == "solution.pvd" || name == "statistics.csv" ||
          name == "timings.csv" || name == "force_displacement.csv" ||
          name == "force_displacement.gnuplot")
        {
          member.owned = true;
          return member;
        }
      if (name == "history.pvd")
        {
          member.owned   = true;
          member.history = true;
          return member;
        }
      // Cycle numbers have at least two digits (deal.II's int_to_string).
      const auto cycle_file = [&](const std::string &prefix) {
        return numbered(name, prefix, 2);
      };
      bool owned = false;
      if (const auto n = numbered(name, "history-", 3))
        {
          // A load step's file: ".vtu", ".pvtu" or a piece ".RRRR.vtu".
          const std::string &rest  = n->second;
          const auto         piece = numbered(rest, ".", 4);
          owned                    = rest == ".vtu" || rest == ".pvtu" ||
                  (piece && piece->second == ".vtu");
          member.history = owned;
          member.step    = n->first;
        }
      else if (const auto n = cycle_file("solution-"))
        {
          member.cycle            = n->first;
          const std::string &rest = n->second;
          // ".vtu", ".pvtu", or a piece ".RRRR.vtu" of four digits or more.
          const auto piece = numbered(rest, ".", 4);
          owned            = rest == ".vtu" || rest == ".pvtu" ||
                  (piece && piece->second == ".vtu");
        }
      else if (const auto n = cycle_file("contact_pressure-"))
        {
          member.cycle = n->first;
          owned        = n->second == ".csv";
        }
      else if (const auto n = cycle_file("checkpoint-"))
        {
          member.cycle = n->first;
          // After a load step within the cycle: "-SSS" before the ending.
          std::string rest = n->second;
          if (const auto step = numbered(rest, "-", 3))
            {
              member.step = step->first;
              rest        = step->second;
            }
          for (const char *ending : {".state",
                                     ".mesh",
                                     ".mesh.info",
                                     ".mesh_fixed.data",
                                     ".mesh_variable.data"})
            owned = owned || rest == ending;
          member.checkpoint = owned;
        }
      if (!owned)
        return Member();
      member.owned = true;
      return member;
    }

    std::vector<std::string>
    remove_stale_files(const std::string                 &directory,
                       const std::optional<unsigned int> &resumed_cycle,
                       const std::optional<unsigned int> &history_cycle,
                       const std::optional<unsigned int> &resumed_step)
    {
      namespace fs = std::filesystem;
      std::vector<std::string> removed;
      std::error_code          error;
      if (!fs::is_directory(directory, error))
        return removed;
      for (const auto &entry : fs::directory_iterator(directory, error))
        {
          if (!entry.is_regular_file(error))
            continue;
          const std::string name   = entry.path().filename().string();
          const Member      member = classify(name);
          if (!member.owned)
            continue;
          bool keep = false;
          if (resumed_cycle && !member.partial && !resumed_step)
            {
              if (member.history)
                keep = history_cycle && *history_cycle <= *resumed_cycle;
              else if (!member.cycle)
                keep = true; // rewritten from the checkpoint right away
              else if (member.checkpoint)
                keep = *member.cycle == *resumed_cycle && !member.step;
              else
                keep = *member.cycle <= *resumed_cycle;
            }
          else if (resumed_cycle && !member.partial)
            {
              // Within cycle k, after step s: its finished steps stay.
              if (member.history)
                keep = history_cycle && *history_cycle == *resumed_cycle &&
                       (!member.step || *member.step <= *resumed_step);
              else if (!member.cycle)
                keep = true;
              else if (member.checkpoint)
                keep = *member.cycle == *resumed_cycle &&
                       member.step == resumed_step;
              else
                keep = *member.cycle < *resumed_cycle;
            }
          if (keep)
            continue;
          fs::remove(entry.path(), error);
          if (error)
            throw std::runtime_error("cannot remove the stale file '" +
                                     entry.path().string() +
                                     "' of an earlier run: " + error.message());
          removed.push_back(name);
        }
      if (error)
        throw std::runtime_error("cannot read the output directory '" +
                                 directory + "': " + error.message());
      std::sort(removed.begin(), removed.end());
      return removed;
    }

    std::vector<std::string>
    foreign_files(const std::string &directory)
    {
      namespace fs = std::filesystem;
      std::error_code error;
      if (!fs::is_directory(directory, error))
        return {};
      // A run writes its parameters first, as ParameterHandler prints them.
      std::ifstream in(directory + "/parameters.prm");
      std::string   first_line;
      if (in && std::getline(in, first_line) &&
          first_line.rfind("set Dimension", 0) == 0)
        return {};
      std::vector<std::string> found;
      for (const auto &entry : fs::directory_iterator(directory, error))
        {
          // (A folder in the way is not overwritten: the write fails.)
          const std::string name = entry.path().filename().string();
          if (entry.is_regular_file(error) &&
              (classify(name).owned || name == "parameters.prm" ||
               name == "obstacle.vtu"))
            found.push_back(name);
        }
      std::sort(found.begin(), found.end());
      return found;
    }
  } // namespace output_series
} // namespace signorini
