#ifndef signorini_file_output_h
#define signorini_file_output_h

#include <functional>
#include <mpi.h>
#include <ostream>
#include <string>

namespace signorini
{
  /**
   * Writes @p path whole or not at all: @p write fills a temporary file
   * beside it, which is renamed to @p path once complete. A reader never
   * sees a half-written file, and an earlier version stays intact if
   * writing fails. Throws std::runtime_error naming the file on failure.
   */
  void
  write_atomically(const std::string                         &path,
                   const std::function<void(std::ostream &)> &write);

  /**
   * Runs @p write on every process and throws on every process if it
   * failed on any, so that no process is left waiting for one that gave up.
   * Also a barrier: what one process wrote is complete afterwards.
   */
  void
  write_collectively(const MPI_Comm               mpi_communicator,
                     const std::function<void()> &write);
} // namespace signorini

#endif
