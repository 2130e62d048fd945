#pragma once

namespace penumbra {

// Every frame allocates and frees full-size buffers (depth, primitive ids, stencil, visibility,
// colour, set-up triangles: ~30 MB at 1920x1080). By default glibc serves blocks over 128 KiB
// with mmap and gives freed heap tops back to the kernel, so each frame page-faults all of it
// in again (bench/README.md has the cost). After this call blocks up to 32 MiB
// (the most mallopt accepts) come from the heap, which is never trimmed, and a worker
// thread's arena keeps the extra heaps it grew (a frame's parallel passes allocate there):
// freed buffers are reused as they are. A process-wide policy, so programs (the CLI, the
// benchmarks) opt in; the library never calls it itself. Does nothing outside glibc.
void keepFrameBuffersMapped();

}  // namespace penumbra
