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
   * Sets glibc's malloc to keep no fast bins (M_MXFAST = 0): small blocks
   * are still served by its per-thread cache, and freeing a large block no
   * longer makes malloc_consolidate() sweep the fast bins, which took 3 to
   * 8 % of a run's samples (the per-cell vectors of solution transfer,
   * checkpoints and FEValues). Measured in alternating runs (wall, medians
   * of three): sphere indentation at 1.49 M dofs on two processes,
   * matrix-free, 19.9 s -> 18.9 s; 2D Hertz at 442k dofs on one process
   * 11.4 s -> 10.2 s; peak memory the same. Call first thing in main(); nothing
   * elsewhere.
   */
  void
  tune_allocator();

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

  /**
   * Has the BLAS take its work space now, while there is memory, instead
   * of at the first dense kernel of a direct solve. OpenBLAS (Debian's
   * libblas.so.3) reserves 128 MB on its first level-3 call and keeps it;
   * where it cannot, it retries for ever, deaf to SIGTERM: under a limit
   * of 600 to 800 MB (ulimit -v) the 2D Hertz scene hung in its first
   * factorisation. Throws OutOfMemory, saying so, where 160 MB cannot be
   * allocated first. Call once, before the problem is set up.
   */
  void
  reserve_blas_workspace();
} // namespace signorini

#endif
