#pragma once
// Parallel-for over independent work items (tiles, primitive chunks) on TBB. Work items never
// share output pixels, so results do not depend on the thread count.
#include <cstddef>
#include <functional>

namespace penumbra {

// Limits the worker threads for the lifetime of the object (0 = all cores).
class ThreadLimit {
 public:
  explicit ThreadLimit(int threads);
  ~ThreadLimit();
  ThreadLimit(const ThreadLimit&) = delete;
  ThreadLimit& operator=(const ThreadLimit&) = delete;

 private:
  void* control_ = nullptr;
};

// Calls fn(i) for i in [0, count), in parallel, each index exactly once.
void parallelFor(size_t count, const std::function<void(size_t)>& fn);

// Runs a() and b() at once and returns when both are done: two passes that do not depend on each
// other share the threads, and each one's serial steps (a merge, a counting sort) leave the
// other's parallel work room. Nested parallelFor calls inside either are fine.
void parallelInvoke(const std::function<void()>& a, const std::function<void()>& b);

// Number of threads parallelFor may use now.
int workerCount();

}  // namespace penumbra
