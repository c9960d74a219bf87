#include <deal.II/base/mpi.h>

#include <signorini/file_output.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace signorini
{
  void
  write_atomically(const std::string                         &path,
                   const std::function<void(std::ostream &)> &write)
  {
    const std::string temporary = path + ".part";
    {
      std::ofstream out(temporary, std::ios::binary);
      if (out)
        write(out);
      out.close();
      if (!out)
        {
          std::remove(temporary.c_str());
          throw std::runtime_error("cannot write '" + path + "'");
        }
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0)
      {
        std::remove(temporary.c_str());
        throw std::runtime_error("cannot write '" + path + "'");
      }
  }

  void
  write_collectively(const MPI_Comm               mpi_communicator,
                     const std::function<void()> &write)
  {
    std::string error;
    try
      {
        write();
      }
    catch (const std::exception &failure)
      {
        error = failure.what();
      }
    const unsigned int failed = error.empty() ? 0 : 1;
    if (dealii::Utilities::MPI::max(failed, mpi_communicator) > 0)
      throw std::runtime_error(
        failed ? error : "another process could not write its output");
  }
} // namespace signorini
