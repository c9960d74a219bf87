#include <signorini/base/memory.h>

#include <cstdlib> // defines __GLIBC__ where glibc is the C library

#if defined(__GLIBC__)
#  include <malloc.h>
#endif

namespace signorini
{
  void
  release_free_memory()
  {
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
  }
} // namespace signorini
