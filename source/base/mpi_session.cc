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
  } // namespace

  void
  use_private_mpi_session_folder()
  {
    if (std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr ||
        std::getenv("PMIX_RANK") != nullptr ||
        std::getenv("OMPI_MCA_orte_tmpdir_base") != nullptr)
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
