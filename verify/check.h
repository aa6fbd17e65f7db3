// fftess verify, stage 7: the check of one camera (checkScene). Its options, its report and the statistics a
// verdict is made from. One check runs the stages in data-flow order (docs/architecture.md, "verify: the stages of
// a check"): the camera's validation, the LOD's factors (lod_bridge.h), which patches are drawn and the holes among
// the others (visibility.h), then every shared edge's points, tessellated and positioned, classified exactly
// (edges.h). Findings are reports, not exceptions: nothing here turns a report into an exit status.
#pragma once

#include "tessellator/tessellator.h"
#include "verify/edges.h"
#include "verify/lod_bridge.h"
#include "verify/scene.h"
#include "verify/terrain.h"
#include "verify/visibility.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace fftess::verify {

// The CGAL kernel the edge check classifies with (CheckOptions::kernel; the cli's --kernel).
enum class Kernel : uint8_t {
  Epick,      // CGAL Exact_predicates_inexact_constructions_kernel: exact classification, gap in double (default)
  Epeck,      // CGAL Exact_predicates_exact_constructions_kernel: exact classification and exact gap
  FloatNaive, // CGAL Simple_cartesian<float>: predicates evaluated in float. Wrong on purpose (for comparison)
};

// One deliberate perturbation of a check, for the fault-injection tests only: defined in verify/testing.h, which
// product code never includes.
struct Fault;

// Whether a check also asks what conformant GPU compilers may change (CheckOptions::gpuFloat).
enum class GpuFloat : uint8_t { Off, Conformant };

// A shared edge pair that matches with lod/'s C++ build but whose match depends on a choice a conformant GPU compiler
// may make (Report::gpuFloat): the two sides compute the edge's factor through different operation sequences, and the
// factor sets they may produce tessellate the edge differently. Which operation differs, on which side, and the fix.
struct GpuFloatFinding {
  PatchRef a, b;               // the two sides (a: the bigger or lower-index patch), as Finding's
  int edgeA = 0, edgeB = 0;    // FactorIndex of the edge on each side
  float factorA = 0, factorB = 0;         // the C++ build's factors (they match)
  float loA = 0, hiA = 0, loB = 0, hiB = 0; // what a conformant compiler may produce on each side
  std::string operationA, operationB;     // the first operation where the two sides' sequences differ (BoundContext::describe)
  std::string fix;             // e.g. "declare the edge's factor computation precise, or compute it once from the
                               // edge's two ends in a fixed order"
  // Why the match depends on the compiler, in words: the two sides' operations differ and their factor sets
  // tessellate the edge differently (operationA / operationB set), or a side may be culled, discarded (its factor set
  // holds NaN or <= 0), or the evaluation had too many undecided comparisons (operationA / operationB empty).
  std::string why;
};

// The options of one check (checkScene) and of every camera of a sweep. Each field's default is its initialiser;
// the defaults are what the cli runs without options.
struct CheckOptions {
  Kernel kernel = Kernel::Epick;  // classification is exact with Epick and Epeck; they agree on every verdict
  size_t maxFindings = 1000;      // findings (and holes) kept in Report::findings / Report::holes (stats count all)
  bool keepMatches = false;       // also keep matching pairs as findings
  Options tessellator{};          // handed to fftess::edgePoints / Tessellator (flushDenormals)
  // Holes: whether a patch that is not drawn is visible is decided by splitting its (u, v) domain (see Hole):
  // sub-rectangles down to a side of 2^-visibilityDepth of the patch, at most visibilityBudget boxes per patch;
  // what is still open then is Visibility::Undecided (Report::undecided, never a clean verdict).
  int visibilityDepth = 10;       // 0..20 (10: 1/1024 of the patch side)
  int64_t visibilityBudget = 16384; // sub-rectangle boxes per patch (>= 1)
  // The fault-injection hook (verify/testing.h; tests only): null (the default) changes nothing and costs nothing.
  std::shared_ptr<const Fault> fault;
  // The GPU path: where the scene asks for it (lod.evaluate = "gpu" or lod.shader), the factors come from here.
  // Null there: every camera gets Report::error (verify links no GL; the cli builds it, gpu_lod/gpu_lod.h).
  std::shared_ptr<FactorProvider> factors;
  // Denormal hull factors (--flush-denormals on|off|auto): On/Off override the scene's lod.flush_denormals and the
  // driver's rule (denormalRule). tessellator.flushDenormals is the rule of lod/'s C++ path under Auto.
  DenormalFlush flushDenormals = DenormalFlush::Auto;
  // Findings the camera cannot see (Finding::onScreen false) count like the others: sweep's CameraResult::worst is
  // chosen among all findings. The Report and its Stats are the same either way (Stats keeps both numbers); pass
  // the same choice to verdictOf. The cli's --offscreen (whole-mesh comparisons, strict CI).
  bool countOffScreen = false;
  // Also keep which patches are drawn (Report::drawn): pictures of what the camera sees (the cli's check --view).
  bool keepDrawn = false;
  // Visible first (docs/verify.md, "Sweep shortcuts"): patches whose displaced box is proven off screen
  // (FrustumTest::boxOffScreen, in double) get no LOD evaluation and no hole check, and shared edge pairs whose two
  // sides' boxes together are proven off screen are not classified (Stats::patchesOffScreen, edgesOffScreen): what
  // is skipped could only give off-screen findings, so the on-screen findings and the verdict are those of the full
  // check. Ignored (the full check runs, Report::visibleFirst false) with countOffScreen, keepDrawn or gpuFloat
  // Conformant (its findings are of matching pairs wherever they lie, on screen or not). The cli's
  // sweep turns it on (--no-visible-first: off); check runs the full check (it lists off-screen findings apart).
  bool visibleFirst = false;
  // GPU float freedom (--gpu-float conformant; docs/verify.md, "GPU float freedom"): each side of each shared edge pair
  // that matches is evaluated again with lod/lod_bound.h under FloatModel::Conformant (every contraction choice, the
  // spec's error bounds of the transcendental operations); a pair whose two sides compute their factors through
  // different operation sequences and whose match then depends on those choices is a GpuFloatFinding. Needs a
  // built-in scheme on the CPU path (Report::error otherwise). Off: nothing is done.
  GpuFloat gpuFloat = GpuFloat::Off;
};

// Why the scene cannot run CheckOptions::gpuFloat = Conformant (a user shader, lod.evaluate = "gpu", geomorph: the
// GPU float model covers lod/'s built-in schemes on the CPU path), or "" when it can. checkScene reports it as
// Report::error for every camera; the cli refuses the command with it.
std::string gpuFloatRefusal(const Scene& scene);

// The denormal rule one check runs with, and where it came from: the first that is not Auto of
// CheckOptions::flushDenormals ("--flush-denormals"), lod.flush_denormals ("lod.flush_denormals"); else the driver's
// (FactorProvider::flushesDenormals, on the GPU path with a provider) or CheckOptions::tessellator.flushDenormals.
struct DenormalRule {
  bool flush = false;
  std::string why; // e.g. "--flush-denormals on", "the driver: llvmpipe (...) flushes denormal factors"
};
// scene: the terrain's (Terrain::scene()); options: the check's (its factors provider is asked for the driver's rule).
DenormalRule denormalRule(const Scene& scene, const CheckOptions& options);

// What one check counted (Report::stats), or a sweep in total (accumulate, report.h). Every count starts at 0.
struct Stats {
  int64_t patches = 0;         // patches in the layout
  int64_t culledPatches = 0;   // culled by the LOD (frustum) or by the tessellator (factor not > 0)
  int64_t edgesChecked = 0;    // shared edge pairs classified (a 2x jump counts as two pairs)
  int64_t skippedCulled = 0;   // shared edge pairs not classified because a side is culled (or a hole)
  int64_t holes = 0;           // Hole findings (both kinds)
  int64_t holesDiscarded = 0;  // HoleKind::Discarded
  int64_t holesCulledVisible = 0; // HoleKind::CulledWhileVisible
  int64_t culledUndecided = 0; // lod-culled patches neither proven invisible nor visible (see Hole)
  int64_t visibilityTests = 0; // culled or discarded patches whose box touched the frustum (domain split)
  int64_t matches = 0;
  int64_t tJunctions = 0;
  int64_t cracks = 0;
  double worstGapWorld = 0;
  double worstGapPixels = 0;
  // Patches not drawn whose visibility stayed undecided (Report::undecided; culled ones also in culledUndecided):
  // the verdict is Undecided unless there are cracks or holes.
  int64_t undecided = 0;
  // The GPU path with a C++ reference (lod.evaluate = "gpu", or lod.shader with a built-in lod.scheme): factors
  // compared, those whose bits differ, and those of them that change the tessellation (FactorDiff).
  int64_t factorsCompared = 0;
  int64_t factorDiffs = 0;
  int64_t factorDiffsTessellation = 0;
  int64_t denormalFactors = 0; // hull factors the source returned as denormals (DenormalFactor), flushed or not
  // On screen (docs/verify.md, "On screen"). cracks, tJunctions, worstGapWorld and worstGapPixels above count every
  // finding (whole-mesh comparisons); of them, these are proven off screen (Finding::onScreen false): the factors
  // that made them belong to this camera, so no other camera sees them either. verdictOf counts only the on-screen
  // ones unless asked for all. Holes are on screen by construction (Hole::onScreen).
  int64_t cracksOffScreen = 0;
  int64_t tJunctionsOffScreen = 0;
  double worstGapWorldOnScreen = 0;  // the maxima of Finding::onScreenGapWorld / onScreenGapPixels
  double worstGapPixelsOnScreen = 0;
  // Visible first (CheckOptions::visibleFirst): patches proven off screen (not evaluated: neither in culledPatches
  // nor hole-checked) and shared edge pairs not classified because both sides are proven off screen (neither in
  // edgesChecked nor in skippedCulled). 0 in a full check.
  int64_t patchesOffScreen = 0;
  int64_t edgesOffScreen = 0;
  // GPU float freedom (CheckOptions::gpuFloat): matching pairs evaluated under the conformant model, and those whose
  // match depends on a compiler's choice (GpuFloatFinding).
  int64_t gpuFloatPairs = 0;
  int64_t gpuFloatFindings = 0;
  // The GPU path (lod.evaluate = "gpu") under CheckOptions::gpuFloat: the GPU's factors checked against the
  // conformant model of the scene's built-in scheme (the union of lod/lod_bound.h's runs for the patch and camera),
  // and those outside it (a driver beyond the GLSL spec's bounds, or a model that is too narrow: never expected).
  int64_t gpuModelFactors = 0;
  int64_t gpuModelOutside = 0;
  int64_t cracksOnScreen() const { return cracks - cracksOffScreen; }
  int64_t tJunctionsOnScreen() const { return tJunctions - tJunctionsOffScreen; }
};

// The result of one check (checkScene): findings, holes and the rest, each list in layout order.
struct Report {
  std::string error;             // non-empty: the camera is invalid and nothing was checked
  std::vector<Finding> findings; // non-matching pairs (and matches with keepMatches), in layout order
  std::vector<Hole> holes;       // holes, in layout order (at most maxFindings; Stats::holes counts all)
  std::vector<Hole> undecided;   // patches not drawn, visibility undecided (Hole::visibility Undecided), in layout
                                 // order (at most maxFindings; Stats::undecided counts all)
  std::vector<FactorDiff> factorDiffs; // GPU vs C++ build, in layout order (at most maxFindings; Stats counts all)
  std::vector<DenormalFactor> denormalFactors; // in layout order (at most maxFindings; Stats counts all)
  std::vector<GpuFloatFinding> gpuFloat; // CheckOptions::gpuFloat: in layout order (at most maxFindings; Stats counts all)
  bool denormalsFlushed = false; // the rule this camera ran with (denormalRule)
  bool truncated = false;        // more findings than maxFindings
  Stats stats;
  WorkStats work;                // this camera's work (camera-dependent only; see Terrain::stats())
  bool visibleFirst = false;     // the check ran visible first (CheckOptions::visibleFirst; Stats::patchesOffScreen)
  // With CheckOptions::keepDrawn: per patch of layoutFor(terrain, camera) 1 when it is drawn (lod/ did not cull it
  // and the tessellator does not discard it), else 0; empty otherwise (or when Report::error is set).
  std::vector<uint8_t> drawn;
};

// Checks every shared edge of the terrain from one camera.
// terrain: from prepareTerrain. camera: finite values; a camera behind, inside or on a patch is fine (the LOD
// decides what is culled); an invalid camera gives Report::error.
Report checkScene(const Terrain& terrain, const Camera& camera, const CheckOptions& options = {});

// The kernel's name as --kernel spells it: "epick", "epeck", "float". parseKernel: false for any other word.
const char* toString(Kernel k);
bool parseKernel(const char* s, Kernel& out);

} // namespace fftess::verify
