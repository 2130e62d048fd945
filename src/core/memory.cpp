#include "core/memory.h"

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
