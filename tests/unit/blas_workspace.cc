// The BLAS work space under a memory limit. With the address space
// limited (setrlimit RLIMIT_AS, as ulimit -v) and all but 64 MB of it
// taken, reserve_blas_workspace() throws OutOfMemory, saying what it could
// not reserve, rather than leave OpenBLAS to retry for ever; with the
// memory given back it reserves the work space, and a dense kernel called
// after the memory has run out again returns (without the reservation,
// OpenBLAS hangs there: the test would time out; checked by hand).

#include <deal.II/base/mpi.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <signorini/base/failures.h>
#include <signorini/base/memory.h>

#include "checks.h"
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <sys/resource.h>
#include <vector>

namespace
{
  /** The process's address space now [bytes] (VmSize). */
  double
  address_space()
  {
    std::ifstream in("/proc/self/status");
    std::string   line;
    while (std::getline(in, line))
      if (line.rfind("VmSize:", 0) == 0)
        return std::stod(line.substr(7)) * 1024.;
    return 0.;
  }

  /** Takes blocks of 16 MB until none is left. */
  std::vector<void *>
  exhaust()
  {
    std::vector<void *> blocks;
    while (void *block = std::malloc(std::size_t(16) << 20))
      blocks.push_back(block);
    return blocks;
  }

  void
  give_back(std::vector<void *> &blocks, const std::size_t n)
  {
    for (std::size_t i = 0; i < n && !blocks.empty(); ++i)
      {
        std::free(blocks.back());
        blocks.pop_back();
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using namespace signorini;

  // 1 GB beyond what the process holds now.
  const rlimit limit = {static_cast<rlim_t>(address_space() + (1 << 30)),
                        RLIM_INFINITY};
  checks::expect("address space limited", setrlimit(RLIMIT_AS, &limit) == 0);

  auto blocks = exhaust();
  checks::expect("the memory ran out", blocks.size() > 8);
  give_back(blocks, 4);
  std::string refusal;
  try
    {
      reserve_blas_workspace();
    }
  catch (const OutOfMemory &lack)
    {
      refusal = lack.what();
    }
  std::cout << "64 MB left: " << refusal << std::endl;
  checks::expect("refused with 64 MB left", !refusal.empty());

  give_back(blocks, blocks.size());
  reserve_blas_workspace();
  std::cout << "all memory back: reserved" << std::endl;

  blocks = exhaust();
  give_back(blocks, 1);
  // A product of 256 x 256 matrices: a level-3 kernel (dgemm) large
  // enough to take the work space (64 x 64 does not).
  const unsigned int               n = 256;
  dealii::LAPACKFullMatrix<double> a(n), b(n), c(n);
  for (unsigned int i = 0; i < n; ++i)
    {
      a(i, i) = 2.;
      b(i, i) = 0.25;
    }
  a.mmult(c, b);
  std::cout << "a dense kernel with 16 MB left: " << c(n - 1, n - 1)
            << std::endl;
  checks::expect("the kernel's result", c(n - 1, n - 1) == 0.5);
  give_back(blocks, blocks.size());
}
