#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <signorini/base/failures.h>
#include <signorini/base/memory.h>

#include <cstdlib> // defines __GLIBC__ where glibc is the C library
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <sys/resource.h>

#if defined(__GLIBC__)
#  include <malloc.h>
#endif

extern "C" void
dtrsm_(const char   *side,
       const char   *uplo,
       const char   *transa,
       const char   *diag,
       const int    *m,
       const int    *n,
       const double *alpha,
       const double *a,
       const int    *lda,
       double       *b,
       const int    *ldb);

namespace signorini
{
  void
  tune_allocator()
  {
#if defined(__GLIBC__)
    mallopt(M_MXFAST, 0);
#endif
  }

  void
  release_free_memory()
  {
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
  }

  namespace
  {
    /** The value [bytes] of the line "NAME: VALUE kB" of /proc/meminfo,
     * infinite if there is none. */
    double
    meminfo_value(const std::string &name)
    {
      std::ifstream in("/proc/meminfo");
      std::string   line;
      while (std::getline(in, line))
        if (line.compare(0, name.size() + 1, name + ":") == 0)
          {
            std::istringstream value(line.substr(name.size() + 1));
            double             kilobytes = 0;
            if (value >> kilobytes)
              return kilobytes * 1024.;
          }
      return std::numeric_limits<double>::infinity();
    }
  } // namespace

  void
  reserve_blas_workspace()
  {
    static bool reserved = false;
    if (reserved)
      return;
    // The work space and a margin, given back before the BLAS takes it.
    if (void *room = std::malloc(std::size_t(160) << 20))
      std::free(room);
    else
      throw OutOfMemory("the dense kernels (BLAS) could not reserve their "
                        "work space of 128 MB");
    // A 1 x 1 triangular solve is a level-3 call: it takes the work space.
    const int    one   = 1;
    const double alpha = 1., a = 1.;
    double       b = 1.;
    dtrsm_("L", "L", "N", "N", &one, &one, &alpha, &a, &one, &b, &one);
    reserved = true;
  }

  double
  available_memory(const MPI_Comm comm)
  {
    // The processes of comm on this node share its memory.
    MPI_Comm node;
    MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
    const unsigned int on_node = dealii::Utilities::MPI::n_mpi_processes(node);
    MPI_Comm_free(&node);
    double mine = meminfo_value("MemAvailable") / on_node;

    rlimit limit;
    if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
      {
        dealii::Utilities::System::MemoryStats memory;
        dealii::Utilities::System::get_memory_stats(memory);
        mine =
          std::min(mine,
                   static_cast<double>(limit.rlim_cur) - memory.VmSize * 1024.);
      }
    return dealii::Utilities::MPI::min(mine, comm) *
           dealii::Utilities::MPI::n_mpi_processes(comm);
  }
} // namespace signorini
