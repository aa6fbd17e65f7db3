// fftess batch tessellation on several threads into caller-owned buffers (issue 11). Part of the public contract
// of the tessellator module, next to tessellator.h (standard library only).
//
// Two steps: planBatch() gives every patch its slot in two packed output arrays (points and indices of all patches,
// patch after patch, in input order); the caller allocates the arrays once for the totals; tessellateBatch() fills
// them on N threads. The result is the same bytes for any thread count, and each patch's part is exactly what
// Tessellator::tessellate gives for it (indices count from the patch's own first point, as there). Nothing is
// allocated per patch. Stream a long batch by planning and tessellating it in chunks that reuse the same arrays.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>

#include "tessellator.h"

namespace fftess {

// Where one patch's output lies in the packed arrays, and its size.
struct BatchSlot {
  int64_t firstPoint = 0; // offset of the patch's first point in the points array
  int64_t firstIndex = 0; // offset of the patch's first index in the indices array
  int32_t points = 0;     // number of points (outputCounts(patch).points)
  int32_t indices = 0;    // number of indices
};

struct BatchTotals {
  int64_t points = 0;  // size the points array needs
  int64_t indices = 0; // size the indices array needs
};

// Lays out count patches one after the other (closed-form counts, no tessellation): fills slots[0..count) and
// returns the array sizes. patches, slots: count elements each (count may be 0). options as for tessellate().
BatchTotals planBatch(const Patch* patches, size_t count, BatchSlot* slots, const Options& options = {});

// Tessellates patches[0..count) into points / indices at the places slots give (from planBatch with the same
// patches and options), on `threads` threads (<= 0: one per hardware thread; the calling thread is one of them).
// points, indices: at least the totals planBatch returned. Patches are split into contiguous ranges of about equal
// output size; the bytes written do not depend on the thread count. A thread the system will not start:
// std::runtime_error ("could not start thread K of N: ...") after the ranges started have finished (base/threads.h).
void tessellateBatch(const Patch* patches, size_t count, const BatchSlot* slots, DomainPoint* points,
                     int32_t* indices, int threads, const Options& options = {});

// The splitting tessellateBatch uses, for work that follows it (formatting, hashing): runs work(thread, begin, end)
// on `threads` contiguous ranges of [0, count) of about equal output size by slots (ranges may be empty), the first
// on the calling thread, and returns when all are done. threads <= 0: one per hardware thread. An exception thrown
// by work is rethrown here (the first one, by range order) after all ranges finished; a thread the system will not
// start, std::runtime_error as for tessellateBatch.
void forEachBatchRange(size_t count, const BatchSlot* slots, int threads,
                       const std::function<void(int thread, size_t begin, size_t end)>& work);

} // namespace fftess
