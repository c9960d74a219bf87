// output_series: what classify() makes of file names of the series and of
// names that only look like them, and what remove_stale_files() removes from
// a directory holding a run's files and others, for a fresh run and a run
// resumed after cycle 1. Each result is checked against the documented rule
// (output_series.h), written out here: the names of the series are owned,
// the others not; a fresh run removes every series file and nothing else;
// a run resumed after cycle k keeps the files of cycles 0..k, the
// checkpoint of cycle k and the files of no cycle, and removes the rest of
// the series (later cycles, other checkpoints, temporaries). The files of a
// load history's steps are the final cycle's: kept by a run resumed after
// it, removed by one resumed before it; force_displacement.* are the run's
// tables.

#include <signorini/output/output_series.h>

#include "checks.h"
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <unistd.h>
#include <vector>

using namespace signorini;
namespace fs = std::filesystem;

namespace
{
  void
  print(const std::string &name)
  {
    const auto member = output_series::classify(name);
    std::cout << "  " << name << ": " << (member.owned ? "owned" : "not owned");
    if (member.cycle)
      std::cout << ", cycle " << *member.cycle;
    if (member.checkpoint)
      std::cout << ", checkpoint";
    if (member.checkpoint && member.step)
      std::cout << ", step " << *member.step;
    if (member.partial)
      std::cout << ", partial";
    if (member.history)
      std::cout << ", history";
    std::cout << '\n';
  }

  // The series of a run with cycles 0..2 and checkpoints after 0, 1 and 2, an
  // interrupted write, and files and folders of someone else.
  const std::vector<std::string> series = {
    "solution-00.vtu",
    "solution-01.vtu",
    "solution-02.vtu",
    "solution-02.pvtu",
    "solution-02.0000.vtu",
    "solution-02.0001.vtu",
    "contact_pressure-00.csv",
    "contact_pressure-01.csv",
    "contact_pressure-02.csv",
    "checkpoint-00.state",
    "checkpoint-00.mesh",
    "checkpoint-01.state",
    "checkpoint-01.mesh",
    "checkpoint-01.mesh.info",
    "checkpoint-02.state",
    "checkpoint-02.mesh_fixed.data",
    "checkpoint-02.mesh_variable.data",
    "solution.pvd",
    "statistics.csv",
    "timings.csv",
    "solution-01.vtu.part",
    "statistics.csv.part",
  };
  const std::vector<std::string> others = {
    "obstacle.vtu",
    "parameters.prm",
    "notes.txt",
    "solution-3.vtu",
    "solution-01.csv",
    "checkpoint-01.txt",
    "my_statistics.csv",
    "solution.pvd.bak",
  };

  void
  populate(const fs::path &directory)
  {
    fs::create_directories(directory);
    for (const auto &names : {series, others})
      for (const auto &name : names)
        std::ofstream(directory / name) << name << '\n';
    // A folder with a series name is not a series file.
    fs::create_directory(directory / "solution-05.vtu");
  }

  void
  list(const fs::path &directory)
  {
    std::vector<std::string> names;
    for (const auto &entry : fs::directory_iterator(directory))
      names.push_back(entry.path().filename().string() +
                      (entry.is_directory() ? "/" : ""));
    std::sort(names.begin(), names.end());
    std::cout << "  left (" << names.size() << "):";
    for (const auto &name : names)
      std::cout << ' ' << name;
    std::cout << '\n';
  }

  /** The series files that the rule says a run resumed after
   * @p resumed_cycle (none: a fresh run) removes, sorted. */
  std::vector<std::string>
  stale(const std::optional<unsigned int> &resumed_cycle)
  {
    std::vector<std::string> names;
    for (const auto &name : series)
      {
        const auto member = output_series::classify(name);
        if (!resumed_cycle || member.partial ||
            (member.cycle && *member.cycle > *resumed_cycle) ||
            (member.checkpoint && member.cycle != resumed_cycle))
          names.push_back(name);
      }
    std::sort(names.begin(), names.end());
    return names;
  }

  std::vector<std::string>
  remove_and_list(const fs::path                    &directory,
                  const std::optional<unsigned int> &resumed_cycle,
                  const std::optional<unsigned int> &history_cycle = {})
  {
    const auto removed = output_series::remove_stale_files(directory.string(),
                                                           resumed_cycle,
                                                           history_cycle);
    std::cout << "  removed (" << removed.size() << "):";
    for (const auto &name : removed)
      std::cout << ' ' << name;
    std::cout << '\n';
    if (fs::exists(directory))
      list(directory);
    else
      std::cout << "  (no directory)\n";
    auto sorted = removed;
    std::sort(sorted.begin(), sorted.end());
    return sorted;
  }

  /** How many of @p names are a load history's step files. */
  long
  count_history(const std::vector<std::string> &names)
  {
    return std::count_if(names.begin(),
                         names.end(),
                         [](const std::string &name) {
                           return name.rfind("history", 0) == 0;
                         });
  }
} // namespace

int
main()
{
  unsigned int n_wrong = 0;
  std::cout << "classify, series files:\n";
  for (const auto &name : series)
    {
      print(name);
      n_wrong += !output_series::classify(name).owned;
    }
  for (const auto &name : {"solution-123.vtu",
                           "solution-10.12345.vtu",
                           "checkpoint-00.mesh_fixed.data.part",
                           "timings.csv.part"})
    {
      print(name);
      n_wrong += !output_series::classify(name).owned;
    }
  // The cycle of a series file is the number in its name.
  for (const auto &name : series)
    {
      const auto member = output_series::classify(name);
      const auto dash   = name.find('-');
      if (dash != std::string::npos &&
          member.cycle !=
            static_cast<unsigned int>(std::stoul(name.substr(dash + 1, 2))))
        ++n_wrong;
      n_wrong += member.checkpoint != (name.rfind("checkpoint", 0) == 0);
      n_wrong += member.partial !=
                 (name.size() > 5 && name.substr(name.size() - 5) == ".part");
    }
  std::cout << "classify, other files:\n";
  for (const auto &name : others)
    {
      print(name);
      n_wrong += output_series::classify(name).owned;
    }
  for (const auto &name : {"",
                           ".part",
                           "solution-01.000.vtu",
                           "solution-01.pvtu.part.part",
                           "solution-aa.vtu",
                           "Solution-01.vtu",
                           "contact_pressure-01.csv~",
                           "checkpoint-01",
                           "checkpoint-01.mesh.info.bak",
                           "statistics.csv.part.txt",
                           "sub/solution-01.vtu",
                           "solution-01.vtu.vtu",
                           "checkpoint-01.state.mesh",
                           "solution-99999999999999999999999.vtu"})
    {
      print(name);
      n_wrong += output_series::classify(name).owned;
    }
  checks::expect("series files owned, with their cycle, checkpoint and "
                 "partial as named; other files not owned",
                 n_wrong == 0);

  const fs::path directory =
    fs::temp_directory_path() /
    ("signorini-unit-output-series-" + std::to_string(::getpid()));
  fs::remove_all(directory);

  // What is left: the files of others, and the series files kept.
  const auto left_as_ruled = [&](const std::optional<unsigned int> &cycle) {
    std::vector<std::string> names = others;
    names.push_back("solution-05.vtu/");
    const auto removed = stale(cycle);
    for (const auto &name : series)
      if (!std::binary_search(removed.begin(), removed.end(), name))
        names.push_back(name);
    std::sort(names.begin(), names.end());
    std::vector<std::string> left;
    for (const auto &entry : fs::directory_iterator(directory))
      left.push_back(entry.path().filename().string() +
                     (entry.is_directory() ? "/" : ""));
    std::sort(left.begin(), left.end());
    return left == names;
  };

  std::cout << "remove_stale_files, a missing directory:\n";
  checks::expect("nothing removed, no directory made",
                 remove_and_list(directory.string() + "-missing", {}).empty() &&
                   !fs::exists(directory.string() + "-missing"));

  std::cout << "remove_stale_files, fresh run:\n";
  populate(directory);
  checks::expect("every series file removed",
                 remove_and_list(directory, {}) == stale({}));
  checks::expect("the others left", left_as_ruled({}));

  std::cout << "remove_stale_files, run resumed after cycle 1:\n";
  fs::remove_all(directory);
  populate(directory);
  checks::expect("later cycles, other checkpoints, temporaries removed",
                 remove_and_list(directory, 1u) == stale(1u));
  checks::expect("the rest left", left_as_ruled(1u));

  std::cout << "remove_stale_files, again (nothing left to remove):\n";
  checks::expect("nothing removed", remove_and_list(directory, 1u).empty());

  // A load history: the final cycle's step files (history) are that
  // cycle's, force_displacement.* are the run's tables.
  const std::vector<std::string> history = {"history-001.vtu",
                                            "history-002.pvtu",
                                            "history-002.0000.vtu",
                                            "history-002.0001.vtu",
                                            "history-1000.vtu",
                                            "history.pvd",
                                            "history-003.vtu.part"};
  const std::vector<std::string> tables  = {"force_displacement.csv",
                                            "force_displacement.gnuplot"};
  std::cout << "classify, load history files:\n";
  unsigned int n_history_wrong = 0;
  for (const auto &name : history)
    {
      print(name);
      const auto member = output_series::classify(name);
      n_history_wrong += !member.owned || !member.history || member.cycle;
    }
  for (const auto &name : tables)
    {
      print(name);
      const auto member = output_series::classify(name);
      n_history_wrong += !member.owned || member.history || member.cycle;
    }
  for (const auto &name : {"history-01.vtu",
                           "history-001.csv",
                           "history.pvd.bak",
                           "force_displacement.png"})
    {
      print(name);
      n_history_wrong += output_series::classify(name).owned;
    }
  checks::expect("history files owned as the final cycle's, the tables as "
                 "the run's; other names not owned",
                 n_history_wrong == 0);

  // A run of cycles 0..2 whose steps were written on cycle 2.
  const auto populate_history = [&]() {
    fs::remove_all(directory);
    fs::create_directories(directory);
    for (const auto &names : {history,
                              tables,
                              std::vector<std::string>{"solution-00.vtu",
                                                       "solution-01.vtu",
                                                       "solution-02.vtu",
                                                       "statistics.csv"}})
      for (const auto &name : names)
        std::ofstream(directory / name) << name << '\n';
  };
  const auto removed_history = [&](const std::optional<unsigned int> &cycle) {
    return count_history(remove_and_list(directory, cycle, 2u));
  };
  std::cout << "remove_stale_files, history of cycle 2, resumed after "
               "cycle 1:\n";
  populate_history();
  checks::expect("every history file removed, the tables kept",
                 removed_history(1u) == 7 &&
                   fs::exists(directory / "force_displacement.csv") &&
                   fs::exists(directory / "force_displacement.gnuplot"));
  std::cout << "remove_stale_files, history of cycle 2, resumed after "
               "cycle 2:\n";
  populate_history();
  checks::expect("only the temporary removed",
                 removed_history(2u) == 1 &&
                   fs::exists(directory / "history.pvd"));
  std::cout << "remove_stale_files, history of cycle 2, fresh run:\n";
  populate_history();
  checks::expect("every series file removed",
                 removed_history({}) == 7 &&
                   !fs::exists(directory / "force_displacement.csv"));

  // Checkpoints after load steps within a cycle: checkpoint-CC-SSS.*.
  std::cout << "classify, checkpoints of load steps:\n";
  unsigned int n_step_wrong = 0;
  for (const auto &name : {"checkpoint-02-001.state",
                           "checkpoint-02-001.mesh",
                           "checkpoint-02-003.mesh_variable.data",
                           "checkpoint-10-1000.mesh.info.part"})
    {
      print(name);
      const auto member = output_series::classify(name);
      n_step_wrong +=
        !member.owned || !member.checkpoint || !member.cycle || !member.step;
    }
  for (const auto &name :
       {"checkpoint-02-01.state", "checkpoint-02-.state", "checkpoint-02-001"})
    {
      print(name);
      n_step_wrong += output_series::classify(name).owned;
    }
  checks::expect("step checkpoints owned with their cycle and step; other "
                 "names not owned",
                 n_step_wrong == 0);

  // A run of cycles 0..2 stopped after step 2 of cycle 2 (its final one),
  // with a stale checkpoint of step 1 and one of cycle 1 beside it.
  std::cout << "remove_stale_files, resumed after step 2 of cycle 2:\n";
  populate_history();
  for (const auto &name : {"checkpoint-01.state",
                           "checkpoint-02-001.state",
                           "checkpoint-02-002.state",
                           "checkpoint-02-002.mesh"})
    std::ofstream(directory / name) << name << '\n';
  {
    const auto removed =
      output_series::remove_stale_files(directory.string(), 2u, 2u, 2u);
    std::cout << "  removed (" << removed.size() << "):";
    for (const auto &name : removed)
      std::cout << ' ' << name;
    std::cout << '\n';
    std::vector<std::string> left;
    for (const auto &entry : fs::directory_iterator(directory))
      left.push_back(entry.path().filename().string());
    std::sort(left.begin(), left.end());
    std::cout << "  left (" << left.size() << "):";
    for (const auto &name : left)
      std::cout << ' ' << name;
    std::cout << '\n';
    checks::expect("the cycle's solution file, later steps' files, other "
                   "checkpoints and the temporary removed",
                   removed ==
                     std::vector<std::string>{"checkpoint-01.state",
                                              "checkpoint-02-001.state",
                                              "history-003.vtu.part",
                                              "history-1000.vtu",
                                              "solution-02.vtu"});
  }

  fs::remove_all(directory);
  std::cout << "temporary directory removed: "
            << (fs::exists(directory) ? "no" : "yes") << '\n';
}
