// fftess verify, stage 9: the verdict. One place that turns a check's Stats (check.h) or a sweep's total (sweep.h)
// into a Verdict; the cli turns the verdict into words and an exit status. Also how stats add up (accumulate).
#pragma once

#include "verify/check.h"
#include "verify/sweep.h"

#include <cstdint>

namespace fftess::verify {

// The verdict of a report or a sweep, in one place (the cli turns it into words and an exit status).
enum class Verdict : uint8_t {
  Watertight,      // at least one shared edge classified, every one a match, no hole, no undecided patch, every
                   // camera checked (by default: every finding off screen; see verdictOf)
  TJunctionsOnly,  // as Watertight but some T-junctions (no gap now; a gap once displacement differs)
  Cracks,          // at least one crack (holes may come with them)
  Holes,           // at least one hole, no crack
  NothingChecked,  // no shared edge was classified (and no crack or hole): not clean
  Unchecked,       // some cameras could not be checked (and no crack or hole): not clean
  Undecided,       // some patch not drawn could be neither proven visible nor invisible (and no crack or hole): not
                   // clean. Precedence: Cracks, Holes, Undecided, GpuFloat, NothingChecked, Unchecked, TJunctionsOnly,
                   // Watertight
  GpuFloat,        // CheckOptions::gpuFloat only: some matching shared edge may crack on a conformant GPU
                   // (Stats::gpuFloatFindings > 0; Report::gpuFloat) and no crack, hole or undecided patch: not clean
};
// countOffScreen false (default): cracks and T-junctions proven off screen (Stats::cracksOffScreen,
// tJunctionsOffScreen) do not count; true: every finding counts (CheckOptions::countOffScreen, the cli's --offscreen).
Verdict verdictOf(const Stats& s, bool countOffScreen = false);
Verdict verdictOf(const SweepResult& r, bool countOffScreen = false);

// Adds one camera's (or one shard's) stats to a total: every count summed, the worst gaps the maxima. What sweep
// does per camera; merging shards does it per shard.
void accumulate(Stats& total, const Stats& s);
const char* toString(Verdict v); // "watertight", "t_junctions", "cracks", "holes", "nothing_checked", "unchecked",
                                 // "undecided", "gpu_float"

} // namespace fftess::verify
