// Writes that fail and signals. write_atomically into a missing folder,
// beyond a file-size limit (setrlimit, SIGXFSZ ignored as the program does)
// and with a writer that throws: each names the file and the system's
// reason, and no .part file is left. interruption: a SIGTERM raised after
// install() is recorded, not fatal; check() turns it into Interrupted on
// every process, with status 143 and its line for each case.

#include <deal.II/base/mpi.h>

#include <signorini/base/interruption.h>
#include <signorini/output/file_output.h>

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
  void
  attempt(const std::string                         &what,
          const std::string                         &path,
          const std::function<void(std::ostream &)> &write)
  {
    std::cout << what << ": ";
    try
      {
        write_atomically(path, write);
        std::cout << "written, " << fs::file_size(path) << " bytes";
      }
    catch (const std::exception &error)
      {
        std::cout << error.what();
      }
    std::cout << "; .part left: " << (fs::exists(path + ".part") ? "yes" : "no")
              << '\n';
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
  attempt("into a missing folder", "missing/a.txt", [&](std::ostream &out) {
    out << block;
  });
  attempt("a writer that throws", "written/b.txt", [&](std::ostream &out) {
    out << block;
    throw std::runtime_error("the writer's own failure");
  });
  struct rlimit limit;
  getrlimit(RLIMIT_FSIZE, &limit);
  const rlim_t soft = limit.rlim_cur;
  limit.rlim_cur    = 4096;
  setrlimit(RLIMIT_FSIZE, &limit);
  attempt("10 kB beyond a limit of 4 kB",
          "written/c.txt",
          [&](std::ostream &out) { out << block; });
  attempt("10 kB in bytes beyond a limit of 4 kB",
          "written/d.txt",
          [&](std::ostream &out) {
            for (const char c : block)
              out << c;
          });
  limit.rlim_cur = soft;
  setrlimit(RLIMIT_FSIZE, &limit);
  fs::remove_all("written");

  std::cout << "signal before install: " << interruption::received() << '\n';
  std::raise(SIGTERM);
  std::cout << "SIGTERM raised: recorded " << interruption::received()
            << " (SIGTERM is " << SIGTERM << ")\n";
  try
    {
      interruption::check(MPI_COMM_WORLD);
      std::cout << "check: FAIL, no Interrupted\n";
    }
  catch (Interrupted &stop)
    {
      std::cout << "check: Interrupted, status " << stop.status() << '\n';
      std::cout << "  none finished: " << stop.message("scene.prm") << '\n';
      stop.finished_cycle = 3;
      stop.resumable      = true;
      std::cout << "  cycle 3 with its checkpoint: "
                << stop.message("scene.prm") << '\n';
      stop.resumable = false;
      std::cout << "  cycle 3 without: " << stop.message("scene.prm") << '\n';
    }
}
