#include <signorini/output/output_series.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <stdexcept>

namespace signorini
{
  namespace output_series
  {
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
          name == "timings.csv")
        {
          member.owned = true;
          return member;
        }
      // Cycle numbers have at least two digits (deal.II's int_to_string).
      static const std::regex cycle_file(
        "(solution-([0-9]{2,})(\\.[0-9]{4,})?\\.vtu)|"
        "(solution-([0-9]{2,})\\.pvtu)|"
        "(contact_pressure-([0-9]{2,})\\.csv)|"
        "(checkpoint-([0-9]{2,})\\.(state|mesh|mesh\\.info|"
        "mesh_fixed\\.data|mesh_variable\\.data))");
      std::smatch match;
      if (!std::regex_match(name, match, cycle_file))
        return Member();
      member.owned = true;
      for (const unsigned int group : {2u, 5u, 7u, 9u})
        if (match[group].matched)
          member.cycle = std::stoul(match[group]);
      member.checkpoint = match[8].matched;
      return member;
    }

    std::vector<std::string>
    remove_stale_files(const std::string                 &directory,
                       const std::optional<unsigned int> &resumed_cycle)
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
          if (resumed_cycle && !member.partial)
            {
              if (!member.cycle)
                keep = true; // rewritten from the checkpoint right away
              else if (member.checkpoint)
                keep = *member.cycle == *resumed_cycle;
              else
                keep = *member.cycle <= *resumed_cycle;
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
  } // namespace output_series
} // namespace signorini
