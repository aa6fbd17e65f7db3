// Batch tessellation on several threads into caller-owned buffers.
#include "parallel.h"

#include <exception>
#include <thread>
#include <vector>

#include "generate.h"
#include "base/threads.h"

namespace fftess {

BatchTotals planBatch(const Patch* patches, size_t count, BatchSlot* slots, const Options& options) {
  BatchTotals t;
  for (size_t i = 0; i < count; ++i) {
    const OutputCounts c = outputCounts(patches[i], options);
    slots[i] = {t.points, t.indices, c.points, c.indices};
    t.points += c.points;
    t.indices += c.indices;
  }
  return t;
}

void forEachBatchRange(size_t count, const BatchSlot* slots, int threads,
                       const std::function<void(int thread, size_t begin, size_t end)>& work) {
  if (threads <= 0) threads = int(std::thread::hardware_concurrency());
  if (threads <= 0) threads = 1;
  if (size_t(threads) > count) threads = count > 0 ? int(count) : 1;
  // Cut points by output size (8 bytes per point, 4 per index, plus a little per patch).
  auto weightBefore = [&](size_t i) -> int64_t {
    if (i == 0) return 0;
    const BatchSlot& s = slots[i - 1];
    return 8 * (s.firstPoint + s.points) + 4 * (s.firstIndex + s.indices) + 64 * int64_t(i);
  };
  const int64_t total = weightBefore(count);
  std::vector<size_t> cut(static_cast<size_t>(threads) + 1, count);
  cut[0] = 0;
  size_t i = 0;
  for (int t = 1; t < threads; ++t) {
    const int64_t target = total * t / threads;
    while (i < count && weightBefore(i) < target) ++i;
    cut[size_t(t)] = i;
  }
  std::vector<std::exception_ptr> errors(static_cast<size_t>(threads));
  auto run = [&](int t) {
    try {
      work(t, cut[size_t(t)], cut[size_t(t) + 1]);
    } catch (...) {
      errors[size_t(t)] = std::current_exception();
    }
  };
  // Each thread has its own range: nothing to stop when a start fails (base/threads.h throws after the joins).
  runOnThreads(threads, run, [] {});
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

void tessellateBatch(const Patch* patches, size_t count, const BatchSlot* slots, DomainPoint* points,
                     int32_t* indices, int threads, const Options& options) {
  forEachBatchRange(count, slots, threads, [&](int, size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i)
      tessellateInto(patches[i], options, points + slots[i].firstPoint, indices + slots[i].firstIndex);
  });
}

} // namespace fftess
