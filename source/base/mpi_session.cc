#include <signorini/base/mpi_session.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

namespace signorini
{
  namespace
  {
    std::string session_folder;

    /** Whether mpiexec (or another launcher) started this process. */
    bool
    launched()
    {
      return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr ||
             std::getenv("PMIX_RANK") != nullptr;
    }
  } // namespace

  void
  start_isolated_singleton()
  {
    if (launched())
      return;
    // 0: the user's value, if any, stays.
    setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
    setenv("OMPI_MCA_pml", "ob1", 0);
    setenv("OMPI_MCA_btl", "self", 0);
  }

  void
  use_private_mpi_session_folder()
  {
    if (launched() || std::getenv("OMPI_MCA_orte_tmpdir_base") != nullptr)
      return;
    const char *temporary = std::getenv("TMPDIR");
    std::string folder =
      std::string(temporary != nullptr && *temporary != '\0' ? temporary :
                                                               "/tmp") +
      "/signorini-XXXXXX";
    if (mkdtemp(folder.data()) == nullptr)
      return; // Open MPI's own folder, as before
    setenv("OMPI_MCA_orte_tmpdir_base", folder.c_str(), 1);
    session_folder = folder;
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove_all(session_folder, ignored);
    });
  }
} // namespace signorini
