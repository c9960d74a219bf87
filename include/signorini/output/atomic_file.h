#ifndef signorini_output_atomic_file_h
#define signorini_output_atomic_file_h

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
   * writing fails. Every write is checked: on failure the temporary file is
   * removed and a std::runtime_error names the file and the system's reason
   * ("cannot write 'out/solution-03.vtu': No space left on device"), also
   * when @p write stopped with an exception because its stream failed.
   */
  void
  write_atomically(const std::string                         &path,
                   const std::function<void(std::ostream &)> &write);

  /**
   * Runs @p write on every process and throws on every process if it
   * failed on any, so that no process is left waiting for one that gave up;
   * each throws the message of the first process that failed, so that
   * process 0 reports it. Also a barrier: what one process wrote is complete
   * afterwards.
   */
  void
  write_collectively(const MPI_Comm               mpi_communicator,
                     const std::function<void()> &write);
} // namespace signorini

#endif
