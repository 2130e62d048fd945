// The allocator policy for frame buffers (core/memory.h): full-size buffers come from the heap
// and stay mapped after they are freed, so the next frame reuses them without page faults.
#include <gtest/gtest.h>

#include <cstdlib>
#include <thread>
#include <vector>

#include "core/memory.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace penumbra {
namespace test_core_memory {

#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)
#define PENUMBRA_MALLOC_POLICY_APPLIES 1
#endif

// Each test runs with the policy applied, where it can act.
class CoreMemory : public ::testing::Test {
 protected:
  void SetUp() override {
#if !defined(__GLIBC__)
    GTEST_SKIP() << "the policy only acts on glibc's malloc";
#elif defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "AddressSanitizer replaces malloc: mallopt and mallinfo2 do not apply";
#else
    keepFrameBuffersMapped();
#endif
  }
};

TEST_F(CoreMemory, FrameSizedBuffersStayMappedAfterFree) {
#if defined(PENUMBRA_MALLOC_POLICY_APPLIES)
  constexpr size_t kBytes = size_t(1920) * 1080 * 4;  // one 1080p depth buffer
  const struct mallinfo2 before = mallinfo2();
  {
    std::vector<float> buffer(kBytes / sizeof(float), 1.0f);
    const struct mallinfo2 during = mallinfo2();
    // If it failed: the buffer was mmapped, and every frame would page-fault it in again
    // (core/memory.h; bench/README.md has what that costs a 1080p frame).
    EXPECT_EQ(during.hblkhd, before.hblkhd) << "an 8 MB buffer was mmapped, not taken from the heap";
    EXPECT_GE(during.arena, kBytes);
  }
  // If it failed: freeing the buffer gave the heap top back to the kernel.
  EXPECT_GE(mallinfo2().arena, kBytes) << "the freed buffer was trimmed from the heap";
#endif
}

// The passes of a frame allocate on the worker threads too, in their own arenas, which grow by
// heaps of at most 64 MiB. A heap past an arena's first was given back to the kernel when the
// frame freed it, and mapped again by the next frame: on dragon-res2 the eye pass took 45 ms
// instead of 12 in some runs, all of it page faults (CHANGELOG.md, 2026-11-28, 61b4265..eee4103).
TEST_F(CoreMemory, WorkerThreadHeapsStayMappedAfterFree) {
#if defined(PENUMBRA_MALLOC_POLICY_APPLIES)
  // Five buffers of 20 MB (each under the 32 MiB mmap threshold): more than one heap's 64 MiB.
  constexpr size_t kBytes = size_t(20) << 20;
  constexpr int kBuffers = 5;
  size_t peak = 0;
  std::thread worker([&] {
    std::vector<std::vector<char>> buffers;
    for (int i = 0; i < kBuffers; ++i) buffers.emplace_back(kBytes, char(i));
    peak = mallinfo2().arena;
  });
  worker.join();
  ASSERT_GE(peak, kBuffers * kBytes);
  // If it failed: the worker's extra heaps went back to the kernel when it freed the buffers.
  EXPECT_GE(mallinfo2().arena, kBuffers * kBytes)
      << "a worker thread's freed heaps were unmapped (peak " << peak << " bytes)";
#endif
}

}  // namespace test_core_memory
}  // namespace penumbra
