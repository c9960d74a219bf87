#ifndef signorini_base_memory_h
#define signorini_base_memory_h

#include <deal.II/base/mpi.h>

namespace signorini
{
  /**
   * Returns the heap memory that is free to the operating system (glibc's
   * malloc_trim). Large structures freed at the end of a phase (the sparsity
   * pattern's construction, a cycle's matrix and AMG, the output patches
   * built by worker threads in their own heaps) otherwise stay resident,
   * and what the next phase allocates elsewhere adds to the peak
   * (README, "what each lever bought").
   */
  void
  release_free_memory();

  /**
   * The memory [bytes] that the processes of @p comm can allocate together
   * if each takes an equal share: the number of processes times the least
   * that one of them can allocate, which is its node's available memory
   * (MemAvailable of /proc/meminfo) divided among the node's processes of
   * @p comm, or less if its address space is limited (ulimit -v).
   * Collective; infinite if nothing limits it.
   */
  double
  available_memory(const MPI_Comm comm);
} // namespace signorini

#endif
