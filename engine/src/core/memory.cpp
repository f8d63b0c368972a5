#include "tessera/core/memory.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace tessera {

void tune_allocator() {
#if defined(__GLIBC__)
  // A fixed threshold also stops glibc from moving the trim threshold with it: set that too, so
  // that a cycle's short-lived arrays do not grow and shrink the heap every cycle.
  mallopt(M_MMAP_THRESHOLD, 128 * 1024);
  mallopt(M_TRIM_THRESHOLD, 32 * 1024 * 1024);
#endif
}

}  // namespace tessera
