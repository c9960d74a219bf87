// output_series: what classify() makes of file names of the series and of
// names that only look like them, and what remove_stale_files() removes from
// a directory holding a run's files and others, for a fresh run and a run
// resumed after cycle 1.

#include <signorini/output/output_series.h>

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
    if (member.partial)
      std::cout << ", partial";
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

  void
  remove_and_list(const fs::path                    &directory,
                  const std::optional<unsigned int> &resumed_cycle)
  {
    const auto removed =
      output_series::remove_stale_files(directory.string(), resumed_cycle);
    std::cout << "  removed (" << removed.size() << "):";
    for (const auto &name : removed)
      std::cout << ' ' << name;
    std::cout << '\n';
    if (fs::exists(directory))
      list(directory);
    else
      std::cout << "  (no directory)\n";
  }
} // namespace

int
main()
{
  std::cout << "classify, series files:\n";
  for (const auto &name : series)
    print(name);
  for (const auto &name : {"solution-123.vtu",
                           "solution-10.12345.vtu",
                           "checkpoint-00.mesh_fixed.data.part",
                           "timings.csv.part"})
    print(name);
  std::cout << "classify, other files:\n";
  for (const auto &name : others)
    print(name);
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
    print(name);

  const fs::path directory =
    fs::temp_directory_path() /
    ("signorini-unit-output-series-" + std::to_string(::getpid()));
  fs::remove_all(directory);

  std::cout << "remove_stale_files, a missing directory:\n";
  remove_and_list(directory.string() + "-missing", {});

  std::cout << "remove_stale_files, fresh run:\n";
  populate(directory);
  remove_and_list(directory, {});

  std::cout << "remove_stale_files, run resumed after cycle 1:\n";
  fs::remove_all(directory);
  populate(directory);
  remove_and_list(directory, 1u);

  std::cout << "remove_stale_files, again (nothing left to remove):\n";
  remove_and_list(directory, 1u);

  fs::remove_all(directory);
  std::cout << "temporary directory removed: "
            << (fs::exists(directory) ? "no" : "yes") << '\n';
}
