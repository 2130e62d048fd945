#pragma once
// What a frame did, for files and for people: the per-frame stats JSON (every counter and the
// time of every pass) and a one-line summary.
#include <string>

#include <penumbra/render/frame.h>
#include <penumbra/shadows/technique.h>

namespace penumbra {

struct MachineInfo {
  std::string cpu_model;  // /proc/cpuinfo "model name", else "unknown"
  int cores = 0;          // hardware threads
};
MachineInfo machineInfo();

// JSON text: scene, image size, technique (name, description, what it claims, and each of its
// options under the option's name with '_' for '-'), threads, SIMD, machine, the eye
// pass's stats, per light its stats and mean visibility, and the totals. Stats objects hold
// every counter (the shared ones of core/stats.h and the technique's own) under its own name and
// "time_ms": [{"pass", "ms"}...] in the order the passes ran, plus "total_ms".
std::string frameStatsJson(const Scene& scene, const FrameOptions& options,
                           const FrameResult& result);
void writeStatsJson(const std::string& path, const Scene& scene, const FrameOptions& options,
                    const FrameResult& result);

// One line for the terminal: size, triangles, technique, milliseconds per pass, counters.
std::string frameSummaryLine(const Scene& scene, const FrameOptions& options,
                             const FrameResult& result);

}  // namespace penumbra
