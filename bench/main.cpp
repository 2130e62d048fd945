// penumbra_bench: Google Benchmark over the library (bench/README.md). The context block of the
// JSON output names what the numbers depend on besides the machine: the SIMD target Highway
// dispatched to, and the worker threads.
#include <benchmark/benchmark.h>

#include <string>

#include "core/memory.h"
#include "core/parallel.h"
#include "raster/tile_kernels.h"
#include "scene_file_bench.h"

int main(int argc, char** argv) {
  penumbra::keepFrameBuffersMapped();
  benchmark::AddCustomContext("penumbra_simd_target", penumbra::simdTargetName());
  benchmark::AddCustomContext("penumbra_threads", std::to_string(penumbra::workerCount()));
  // Before Initialize, which refuses the --scene and --technique arguments it does not know.
  penumbra::registerSceneFileBenchmarks(argc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
