#include <deal.II/base/data_out_base.h>

#include <signorini/output/run_record.h>

#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string>

namespace signorini
{
  void
  RunRecord::add_statistics(const StatisticsRow &row)
  {
    statistics.push_back(row);
  }

  void
  RunRecord::add_force_displacement(const StatisticsRow &row)
  {
    force_displacement.push_back(row);
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

  void
  RunRecord::add_history_file(const double time, const std::string &name)
  {
    history_files.emplace_back(time, name);
  }

  namespace
  {
    /** The rows as a table with the first one's header. */
    std::string
    csv_table(const std::vector<StatisticsRow> &rows)
    {
      std::string table;
      if (!rows.empty())
        table = rows[0].header() + '\n';
      for (const auto &row : rows)
        table += row.line() + '\n';
      return table;
    }
  } // namespace

  std::map<std::string, std::string>
  RunRecord::series_records() const
  {
    std::ostringstream pvd;
    dealii::DataOutBase::write_pvd_record(pvd, solution_files);
    std::map<std::string, std::string> records = {{"solution.pvd", pvd.str()},
                                                  {"statistics.csv",
                                                   csv_table(statistics)}};
    if (!force_displacement.empty())
      records["force_displacement.csv"] = csv_table(force_displacement);
    if (!history_files.empty())
      {
        std::ostringstream history;
        dealii::DataOutBase::write_pvd_record(history, history_files);
        records["history.pvd"] = history.str();
      }
    return records;
  }

  std::string
  RunRecord::timings_table() const
  {
    std::string table = "cycle,dofs,iterations,contact_solve,linear_solve,"
                        "ratio,run_time,peak_memory\n";
    char        line[256];
    for (const auto &t : timings)
      {
        // The cycle's last row (its last load step's).
        const StatisticsRow *found = nullptr;
        for (const auto &row : statistics)
          if (row.value("cycle") == t.cycle)
            found = &row;
        if (!found)
          throw std::out_of_range("timings: no statistics row of cycle " +
                                  std::to_string(t.cycle));
        const auto &row = *found;
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
