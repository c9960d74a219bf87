#ifndef signorini_base_memory_h
#define signorini_base_memory_h

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
} // namespace signorini

#endif
