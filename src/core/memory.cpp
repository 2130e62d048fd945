#include "core/memory.h"

// Any libc header defines __GLIBC__; without one the test below is always false and the policy
// silently does nothing (it did, until the page faults showed up in a profile).
#include <cstdlib>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace penumbra {

void keepFrameBuffersMapped() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  // A worker thread's arena grows in heaps of at most 64 MiB, and a freed heap past its first
  // goes back to the kernel unless the pad would still need it: 64 MiB keeps every one.
  mallopt(M_TOP_PAD, 64 << 20);
#endif
}

}  // namespace penumbra
