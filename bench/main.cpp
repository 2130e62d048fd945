// penumbra_bench: Google Benchmark over the library (bench/README.md). The context block of the
// JSON output names what the numbers depend on besides the machine: the SIMD target Highway
// dispatched to, and the worker threads.
#include <benchmark/benchmark.h>

#include <string>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "core/parallel.h"
#include "raster/tile_kernels.h"

namespace {

// Every frame allocates and frees full-size buffers (depth, primitive ids, stencil, visibility,
// colour, set-up triangles: ~30 MB at 1920x1080). By default glibc serves blocks over 128 KiB
// with mmap and gives freed heap tops back to the kernel, so each frame page-faulted all of it
// in again (14 % of a 1920x1080 frame, bench/README.md). Blocks up to 32 MiB (the most mallopt
// accepts) now come from the heap, which is never trimmed: freed buffers are reused as they are.
void keepFrameBuffersMapped() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}
}  // namespace

int main(int argc, char** argv) {
  keepFrameBuffersMapped();
  benchmark::AddCustomContext("penumbra_simd_target", penumbra::simdTargetName());
  benchmark::AddCustomContext("penumbra_threads", std::to_string(penumbra::workerCount()));
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
