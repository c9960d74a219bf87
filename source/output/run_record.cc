#include <deal.II/base/data_out_base.h>

#include <signorini/output/run_record.h>

#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace signorini
{
  void
  RunRecord::add_statistics(const StatisticsRow &row)
  {
    statistics.push_back(row);
  }

  std::optional<unsigned int>
  RunRecord::last_cycle() const
  {
    if (statistics.empty())
      return {};
    return static_cast<unsigned int>(statistics.back().value("cycle"));
  }

  void
  RunRecord::add_timings(const CycleTimings &row)
  {
    timings.push_back(row);
  }

  void
  RunRecord::add_solution_file(const unsigned int cycle,
                               const std::string &name)
  {
    solution_files.emplace_back(cycle, name);
  }

  std::map<std::string, std::string>
  RunRecord::series_records() const
  {
    std::ostringstream pvd;
    dealii::DataOutBase::write_pvd_record(pvd, solution_files);
    std::string table;
    if (!statistics.empty())
      table = statistics[0].header() + '\n';
    for (const auto &row : statistics)
      table += row.line() + '\n';
    return {{"solution.pvd", pvd.str()}, {"statistics.csv", table}};
  }

  std::string
  RunRecord::timings_table() const
  {
    std::string table = "cycle,dofs,iterations,contact_solve,linear_solve,"
                        "ratio,run_time,peak_memory\n";
    char        line[256];
    for (const auto &t : timings)
      {
        const auto &row = statistics.at(t.cycle);
        std::snprintf(line,
                      sizeof(line),
                      "%u,%llu,%u,%.6f,%.6f,%.3f,%.6f,%.1f\n",
                      t.cycle,
                      static_cast<unsigned long long>(row.value("dofs")),
                      static_cast<unsigned int>(row.value("iterations")),
                      t.contact_solve,
                      t.linear_solve,
                      t.contact_solve / t.linear_solve,
                      t.run_time,
                      t.peak_memory);
        table += line;
      }
    return table;
  }
} // namespace signorini
