#ifndef signorini_base_interruption_h
#define signorini_base_interruption_h

#include <mpi.h>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace signorini
{
  /**
   * SIGINT and SIGTERM turned into a request to stop. The handlers only
   * record the signal; the run looks at it at collective points (before
   * each cycle, before each Newton step), where every process agrees to stop
   * together, so that no file is cut short and the series, the statistics
   * and the checkpoint end at the same cycle.
   */
  namespace interruption
  {
    /**
     * Installs the handlers of SIGINT and SIGTERM, each for its first
     * delivery (a second one of the same signal stops the program at once,
     * as without the handler), and ignores SIGXFSZ, so that a write beyond
     * the file-size limit (`ulimit -f`) fails with EFBIG and is reported
     * like a full disk instead of killing the process.
     */
    void
    install();

    /** The signal received by this process (SIGINT or SIGTERM), 0 if none.
     * Not collective. */
    int
    received();

    /** Collective: throws Interrupted on every process of
     * @p mpi_communicator if any of them has received a signal. */
    void
    check(const MPI_Comm mpi_communicator);
  } // namespace interruption

  /**
   * A run stopped by a signal at a collective point. The run fills in the
   * last cycle whose files are complete and whether a checkpoint of it
   * exists.
   */
  class Interrupted : public std::runtime_error
  {
  public:
    explicit Interrupted(const int signal);

    /** The exit status: 128 + the signal's number, as a shell reports a
     * process killed by it (130 for SIGINT, 143 for SIGTERM). */
    int
    status() const;

    /** The line reported for the parameter file @p file: "interrupted by
     * SIGTERM after cycle 3; resume with --resume FILE" (or "after load
     * step 2 of cycle 4"). */
    std::string
    message(const std::string &file) const;

    /** The signal's number. */
    int signal;
    /** The last cycle whose files are complete, if any. */
    std::optional<unsigned int> finished_cycle;
    /** The last load step (step, cycle) whose files are complete within a
     * later cycle, if any. */
    std::optional<std::pair<unsigned int, unsigned int>> finished_step;
    /** Whether the last finished cycle or step has a checkpoint to resume
     * from. */
    bool resumable = false;
  };
} // namespace signorini

#endif
