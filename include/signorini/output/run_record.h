#ifndef signorini_output_run_record_h
#define signorini_output_run_record_h

#include <signorini/base/statistics_row.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace signorini
{
  /** The costs of one cycle, one row of timings.csv. */
  struct CycleTimings
  {
    unsigned int cycle = 0;
    /** Wall time of the contact solve [s]. */
    double contact_solve = 0.;
    /** Wall time of one linear elasticity solve on the same mesh [s]. */
    double linear_solve = 0.;
    /** Wall time since the start, without output and linear_solve [s]. */
    double run_time = 0.;
    /** Peak resident memory, summed over the processes [MB]. */
    double peak_memory = 0.;

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &cycle &contact_solve &linear_solve &run_time &peak_memory;
    }
  };

  /**
   * What a run has recorded so far: a statistics row per cycle (per load
   * step of a load history) and a timings row per cycle, the solution files
   * of the series, and with a load history the force-displacement rows and
   * the final cycle's file per step. It writes the series' records
   * (solution.pvd, statistics.csv, timings.csv; force_displacement.csv and
   * history.pvd) and saves and loads itself for checkpoints.
   */
  class RunRecord
  {
  public:
    void
    add_statistics(const StatisticsRow &row);

    /** A row of force_displacement.csv. */
    void
    add_force_displacement(const StatisticsRow &row);

    void
    add_timings(const CycleTimings &row);

    /** Cycle @p cycle's solution file @p name (relative to the output
     * directory). */
    void
    add_solution_file(const unsigned int cycle, const std::string &name);

    /** Load step file @p name of the final cycle at pseudo-time @p time
     * (relative to the output directory). */
    void
    add_history_file(const double time, const std::string &name);

    /** The records that list the cycles so far, by file name:
     * solution.pvd and statistics.csv, and force_displacement.csv and
     * history.pvd once they have rows. */
    std::map<std::string, std::string>
    series_records() const;

    /** The text of timings.csv. */
    std::string
    timings_table() const;

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &statistics &timings &solution_files &force_displacement
        &history_files;
    }

  private:
    std::vector<StatisticsRow>                  statistics;
    std::vector<CycleTimings>                   timings;
    std::vector<std::pair<double, std::string>> solution_files;
    std::vector<StatisticsRow>                  force_displacement;
    std::vector<std::pair<double, std::string>> history_files;
  };
} // namespace signorini

#endif
