#ifndef signorini_output_output_series_h
#define signorini_output_output_series_h

#include <optional>
#include <string>
#include <vector>

namespace signorini
{
  /**
   * The files a run owns in its output directory: the series
   * solution-CC.vtu, solution-CC.pvtu and their pieces solution-CC.RRRR.vtu,
   * contact_pressure-CC.csv and checkpoint-CC.* for cycles CC (and
   * checkpoint-CC-SSS.* after load step SSS of cycle CC), and
   * solution.pvd, statistics.csv and timings.csv; of a load history
   * force_displacement.csv and force_displacement.gnuplot, and the final
   * cycle's history-SSS.vtu, history-SSS.pvtu, their pieces
   * history-SSS.RRRR.vtu for load steps SSS, and history.pvd; each also as
   * the temporary NAME.part of an interrupted write. (obstacle.vtu and
   * parameters.prm are rewritten at the start of every run.) Nothing else in
   * the directory is the run's.
   */
  namespace output_series
  {
    /** What a file name means to the series. */
    struct Member
    {
      /** The file belongs to the series. */
      bool owned = false;
      /** Its cycle, for the files of one cycle. */
      std::optional<unsigned int> cycle;
      /** A checkpoint file. */
      bool checkpoint = false;
      /** The load step of a checkpoint written within its cycle
       * (checkpoint-CC-SSS.*) or of a step file (history-SSS.*). */
      std::optional<unsigned int> step;
      /** A temporary file of an interrupted write. */
      bool partial = false;
      /** A file of the final cycle's load steps (history-SSS.*,
       * history.pvd). */
      bool history = false;
    };

    /** Classifies @p name, a file name without its folder. */
    Member
    classify(const std::string &name);

    /**
     * Removes from @p directory the series files that a previous run left
     * and that this run does not continue from. A fresh run (@p resumed_cycle
     * empty) removes every series file, so that a run that stops early leaves
     * no cycles of an earlier one. A run resumed after cycle k keeps the files
     * of cycles 0..k and the checkpoint of cycle k, and removes those of
     * later cycles, other checkpoints and temporaries. The files of the
     * load steps are those of cycle @p history_cycle (the final one; none:
     * of no cycle kept). A run resumed after load step s (@p resumed_step)
     * within cycle k keeps the files of cycles 0..k-1, the checkpoint of
     * step s of cycle k and, if k is the final cycle, its step files
     * 1..s. Files outside the series are never touched; a missing directory
     * is fine. Returns the names removed; throws std::runtime_error if one
     * cannot be removed.
     */
    std::vector<std::string>
    remove_stale_files(const std::string                 &directory,
                       const std::optional<unsigned int> &resumed_cycle,
                       const std::optional<unsigned int> &history_cycle = {},
                       const std::optional<unsigned int> &resumed_step  = {});

    /**
     * The regular files of @p directory that a run would remove or overwrite
     * (its series, parameters.prm, obstacle.vtu) if no signorini run wrote
     * them: if the directory holds no parameters.prm of a run (whose first line
     * sets the Dimension). Empty for a missing directory, one of a run, or
     * one with none of those files.
     */
    std::vector<std::string>
    foreign_files(const std::string &directory);
  } // namespace output_series
} // namespace signorini

#endif
