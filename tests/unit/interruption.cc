// Writes that fail and signals. write_atomically into a missing folder,
// beyond a file-size limit (setrlimit, SIGXFSZ ignored as the program does)
// and with a writer that throws: each names the file and the system's
// reason, and no .part file is left. interruption: a SIGTERM raised after
// install() is recorded, not fatal; check() turns it into Interrupted on
// every process, with status 143 and its line for each case. Each of these
// is checked, not only printed.

#include <deal.II/base/mpi.h>

#include <signorini/base/interruption.h>
#include <signorini/output/file_output.h>

#include "checks.h"
#include <csignal>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <sys/resource.h>

using namespace signorini;
namespace fs = std::filesystem;

namespace
{
  /** Writes @p path by write_atomically and prints what happened;
   * checks that no .part file is left, that a write that succeeded wrote
   * all 10000 bytes, and that a failure says @p expected. */
  void
  attempt(const std::string                         &what,
          const std::string                         &path,
          const std::function<void(std::ostream &)> &write,
          const std::string                         &expected = "")
  {
    std::cout << what << ": ";
    std::string message;
    try
      {
        write_atomically(path, write);
        std::cout << "written, " << fs::file_size(path) << " bytes";
      }
    catch (const std::exception &error)
      {
        message = error.what();
        std::cout << message;
      }
    const bool part = fs::exists(path + ".part");
    std::cout << "; .part left: " << (part ? "yes" : "no") << '\n';
    checks::expect("no .part file left", !part);
    if (expected.empty())
      checks::expect("written whole",
                     message.empty() && fs::exists(path) &&
                       fs::file_size(path) == 10000);
    else
      checks::expect("failed, saying \"" + expected + "\"",
                     message.find(expected) != std::string::npos &&
                       !fs::exists(path));
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  interruption::install();

  fs::remove_all("written");
  fs::create_directory("written");
  const std::string block(10000, 'x');
  attempt("10 kB", "written/a.txt", [&](std::ostream &out) { out << block; });
  attempt(
    "into a missing folder",
    "missing/a.txt",
    [&](std::ostream &out) { out << block; },
    "cannot write 'missing/a.txt': No such file or directory");
  attempt(
    "a writer that throws",
    "written/b.txt",
    [&](std::ostream &out) {
      out << block;
      throw std::runtime_error("the writer's own failure");
    },
    "the writer's own failure");
  struct rlimit limit;
  getrlimit(RLIMIT_FSIZE, &limit);
  const rlim_t soft = limit.rlim_cur;
  limit.rlim_cur    = 4096;
  setrlimit(RLIMIT_FSIZE, &limit);
  attempt(
    "10 kB beyond a limit of 4 kB",
    "written/c.txt",
    [&](std::ostream &out) { out << block; },
    "cannot write 'written/c.txt': File too large");
  attempt(
    "10 kB in bytes beyond a limit of 4 kB",
    "written/d.txt",
    [&](std::ostream &out) {
      for (const char c : block)
        out << c;
    },
    "cannot write 'written/d.txt': File too large");
  limit.rlim_cur = soft;
  setrlimit(RLIMIT_FSIZE, &limit);
  fs::remove_all("written");

  std::cout << "signal before install: " << interruption::received() << '\n';
  checks::expect("none recorded before a signal",
                 interruption::received() == 0);
  std::raise(SIGTERM);
  std::cout << "SIGTERM raised: recorded " << interruption::received()
            << " (SIGTERM is " << SIGTERM << ")\n";
  checks::expect("SIGTERM recorded, the program still running",
                 interruption::received() == SIGTERM);
  try
    {
      interruption::check(MPI_COMM_WORLD);
      std::cout << "check: FAIL, no Interrupted\n";
      checks::failed();
    }
  catch (Interrupted &stop)
    {
      std::cout << "check: Interrupted, status " << stop.status() << '\n';
      checks::expect("status 128 + SIGTERM", stop.status() == 128 + SIGTERM);
      std::cout << "  none finished: " << stop.message("scene.prm") << '\n';
      stop.finished_cycle = 3;
      stop.resumable      = true;
      std::cout << "  cycle 3 with its checkpoint: "
                << stop.message("scene.prm") << '\n';
      checks::expect("the message says how to resume",
                     stop.message("scene.prm").find("--resume scene.prm") !=
                       std::string::npos);
      stop.resumable = false;
      std::cout << "  cycle 3 without: " << stop.message("scene.prm") << '\n';
      checks::expect("without a checkpoint it does not",
                     stop.message("scene.prm").find("--resume") ==
                       std::string::npos);
    }
}
