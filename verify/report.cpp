// The verdict of a check or a sweep (verify/report.h) and how stats add up.
#include "verify/report.h"

#include <algorithm>

namespace fftess::verify {

void accumulate(Stats& s, const Stats& c) {
  s.patches += c.patches;
  s.culledPatches += c.culledPatches;
  s.edgesChecked += c.edgesChecked;
  s.skippedCulled += c.skippedCulled;
  s.matches += c.matches;
  s.tJunctions += c.tJunctions;
  s.cracks += c.cracks;
  s.holes += c.holes;
  s.holesDiscarded += c.holesDiscarded;
  s.holesCulledVisible += c.holesCulledVisible;
  s.culledUndecided += c.culledUndecided;
  s.undecided += c.undecided;
  s.factorsCompared += c.factorsCompared;
  s.factorDiffs += c.factorDiffs;
  s.factorDiffsTessellation += c.factorDiffsTessellation;
  s.denormalFactors += c.denormalFactors;
  s.visibilityTests += c.visibilityTests;
  s.patchesOffScreen += c.patchesOffScreen;
  s.edgesOffScreen += c.edgesOffScreen;
  s.gpuFloatPairs += c.gpuFloatPairs;
  s.gpuFloatFindings += c.gpuFloatFindings;
  s.gpuModelFactors += c.gpuModelFactors;
  s.gpuModelOutside += c.gpuModelOutside;
  s.worstGapWorld = std::max(s.worstGapWorld, c.worstGapWorld);
  s.worstGapPixels = std::max(s.worstGapPixels, c.worstGapPixels);
  s.cracksOffScreen += c.cracksOffScreen;
  s.tJunctionsOffScreen += c.tJunctionsOffScreen;
  s.worstGapWorldOnScreen = std::max(s.worstGapWorldOnScreen, c.worstGapWorldOnScreen);
  s.worstGapPixelsOnScreen = std::max(s.worstGapPixelsOnScreen, c.worstGapPixelsOnScreen);
}

Verdict verdictOf(const Stats& s, bool countOffScreen) {
  if ((countOffScreen ? s.cracks : s.cracksOnScreen()) > 0) return Verdict::Cracks;
  if (s.holes > 0) return Verdict::Holes;
  if (s.undecided > 0) return Verdict::Undecided;
  if (s.gpuFloatFindings > 0) return Verdict::GpuFloat; // counted only with CheckOptions::gpuFloat
  if (s.edgesChecked == 0) return Verdict::NothingChecked;
  if ((countOffScreen ? s.tJunctions : s.tJunctionsOnScreen()) > 0) return Verdict::TJunctionsOnly;
  return Verdict::Watertight;
}

Verdict verdictOf(const SweepResult& r, bool countOffScreen) {
  const Verdict v = verdictOf(r.total, countOffScreen);
  if (v == Verdict::Cracks || v == Verdict::Holes || v == Verdict::Undecided || v == Verdict::GpuFloat) return v;
  if (r.camerasInvalid > 0) return Verdict::Unchecked;
  return v;
}

const char* toString(Verdict v) {
  switch (v) {
  case Verdict::Watertight: return "watertight";
  case Verdict::TJunctionsOnly: return "t_junctions";
  case Verdict::Cracks: return "cracks";
  case Verdict::Holes: return "holes";
  case Verdict::NothingChecked: return "nothing_checked";
  case Verdict::Unchecked: return "unchecked";
  case Verdict::Undecided: return "undecided";
  case Verdict::GpuFloat: return "gpu_float";
  }
  return "?";
}

} // namespace fftess::verify
