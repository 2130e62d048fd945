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
#endif
}

}  // namespace penumbra
