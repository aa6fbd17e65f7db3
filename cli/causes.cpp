// Findings in words (causes.h): edge and patch names, the cause of a finding or hole from its records, finding lines,
// the stats block and the verdict words of check, sweep and merge.
#include "causes.h"
#include "common.h"

#include <cmath>
#include <cstdio>

namespace fftess::cli {

const char* const kEdgeNames[4] = {"Ueq0", "Veq0", "Ueq1", "Veq1"};
const char* edgeName(int e) { return e >= 0 && e < 4 ? kEdgeNames[e] : "?"; }

// ---- causes ------------------------------------------------------------------------------------------------------

// What produced an edge's factors, in causes' words: "lod SCHEME" for a built-in scheme, "the shader FILE" when the
// factors came from lod.shader (findings blame the code that produced them, not the scheme named for comparison).
static std::string gShaderName = "the shader";
void setShaderBlame(const vf::Scene& scene) {
  const std::string& f = scene.lod.shader;
  gShaderName = f.empty() ? "the shader" : "the shader " + f.substr(f.find_last_of('/') == std::string::npos ? 0 : f.find_last_of('/') + 1);
}
static std::string producer(const vf::EdgeLod& l) {
  return l.scheme == vf::LodScheme::Shader ? gShaderName : "lod " + std::string(vf::toString(l.scheme));
}
// From the finding's own records: the LOD's (EdgeSide::lod: scheme, fix bits, neighbour rule) and the tessellator's
// (processed factors, partitioning). Nothing is inferred from factor pairs about what the LOD did.
static bool isPow2(float f) {
  if (!(f >= 1) || f != std::floor(f) || f > 1e9f) return false;
  const auto n = static_cast<uint64_t>(f);
  return (n & (n - 1)) == 0;
}

// The rule the LOD applied at a 2x jump, from the small side's record: "<clamp> clamp, rebuilt <reconstruction>",
// or the scheme's name when no adjacency code ran.
static std::string jumpRule(const vf::EdgeSide& small) {
  const vf::EdgeLod& l = small.lod;
  if (l.scheme == vf::LodScheme::Shader) return producer(l) + ": its own neighbour rule";
  if (l.neighbourSize != 2.0f) return std::string("lod ") + vf::toString(l.scheme) + ": no neighbour rule";
  return std::string("lod ") + vf::toString(l.clamp) + " clamp, rebuilt " + vf::toString(l.reconstruction);
}

// One side's fix bits in lod's words ("integer-clamp, larger-neighbour"), "-" when lod/ changed nothing.
static std::string fixWords(const vf::EdgeSide& s) {
  std::string out;
  for (uint32_t bit = 1; bit <= lod::FixLiteralSource; bit <<= 1)
    if (s.lod.why.fixes & bit) out += (out.empty() ? "" : ", ") + std::string(lod::fixName(static_cast<lod::Fix>(bit)));
  return out.empty() ? "-" : out;
}

// A jump beyond 2x (an unbalanced quadtree, a patches layout): lod/'s neighbour rule handles 2x jumps only, so
// neither side adapted its factor to the other (EdgeLod::neighbourSize carries the ratio).
static Cause largeJumpCause(int jump, const std::string& record) {
  const std::string ratio = std::to_string(int64_t(1) << jump) + "x";
  return {"size jump " + ratio + ": lod/'s neighbour rule handles 2x jumps only",
          "neighbour " + ratio + ": lod/'s neighbour rule handles 2x jumps only, no side adapted its factor (" +
              record + ")",
          "balance the quadtree 2:1 (layout.balance = \"2to1\") or keep neighbouring patches within 2x of each other",
          "jump_beyond_2x"};
}

// ---- fixes: one line a user can act on, per cause (derived from the same records as the cause) -------------------
static const char* const kPow2Fix =
    "round the larger side's factor to a power of two (lod.adjacency_clamp = \"pow2\"): only powers of two nest in "
    "the tessellator's 16.16 points (fftess explain --why-pow2)";
static const char* const kPositionsFix =
    "make both sides position a shared point from the same inputs: each corner computed once (layout.corners = "
    "\"shared\") and a lerp exact at its ends (domain.formula = \"blend\")";

// Same-size neighbours with different factors: the factor of a shared edge must be a function of that edge alone.
static std::string sameSizeFix(const vf::EdgeLod& l) {
  if (l.scheme == vf::LodScheme::Shader)
    return "compute an edge's factor from that edge's two corners only, in the same order of float operations on both "
           "sides (" + producer(l) + ")";
  if (l.scheme == vf::LodScheme::PatchCenter)
    return "compute an edge's factor from the edge, not from each patch's centre (lod.scheme = \"screen_sphere\")";
  return "give both patches the same corners for a shared edge, bit for bit (layout.corners = \"shared\")";
}

// A 2x jump where the small side's factor is not half the big side's, from the small side's record (the rule that ran).
static std::string halfFix(const vf::EdgeSide& small, bool belowMinimum) {
  const vf::EdgeLod& l = small.lod;
  if (l.scheme == vf::LodScheme::Shader)
    return "give the small side exactly half the big side's factor at a 2x jump, both powers of two (" + producer(l) +
           ": as lod.adjacency_clamp = \"pow2\" does)";
  if (l.neighbourSize != 2.0f || l.clamp == lod::AdjacencyClamp::None)
    return "turn the neighbour rule on (lod.adjacency_clamp = \"pow2\"): the small side takes half the big side's "
           "factor, both powers of two";
  if (belowMinimum)
    return "keep the big side's factor at least twice the partitioning's minimum at a jump (lod.adjacency_clamp = "
           "\"pow2\" raises it to 4 or more)";
  // A clamp ran and still the small side did not get half: its rebuilt big edge is not the big side's own.
  if (l.reconstruction == lod::Reconstruction::FarCorner)
    return "give both sides the same corner positions, bit for bit (layout.corners = \"shared\"), so the small side's "
           "far corner is the big side's own";
  return "rebuild the neighbour's corner bit-exactly (lod.reconstruction = \"far_corner\"" +
         std::string(l.reconstruction == lod::Reconstruction::EdgeVector ? " or \"resampled\"" : "") +
         "), so the small side computes the big side's factor from the big side's own corners";
}

Cause findingCause(const vf::Finding& f) {
  const vf::EdgeSide& big = f.a.patch.level >= f.b.patch.level ? f.a : f.b;
  const vf::EdgeSide& small = f.a.patch.level >= f.b.patch.level ? f.b : f.a;
  const int jump = big.patch.level - small.patch.level;
  const float B = big.processedFactor, S = small.processedFactor;
  const std::string pair = formatFloat(B) + " beside " + formatFloat(S);
  const std::string part = toString(f.partitioning);
  const std::string record = "; lod fixes: big " + fixWords(big) + "; small " + fixWords(small);
  if (jump == 0) {
    const std::string sides = ", hull " + formatFloat(f.a.hullFactor) + " vs " + formatFloat(f.b.hullFactor) +
                              "; lod fixes: a " + fixWords(f.a) + "; b " + fixWords(f.b);
    if (f.a.processedFactor != f.b.processedFactor)
      return {"same-size neighbours chose different factors (" + producer(f.a.lod) + ")",
              "same-size neighbours chose different factors (" + formatFloat(f.a.processedFactor) + " vs " +
                  formatFloat(f.b.processedFactor) + sides + ")",
              sameSizeFix(f.a.lod), "same_size_different_factors"};
    return {"same factor, different positions (domain shader / corners)",
            "both sides use factor " + formatFloat(B) + " but compute different positions (domain shader or corners)",
            kPositionsFix, "same_size_different_positions"};
  }
  if (jump > 1) return largeJumpCause(jump, pair + record);
  const std::string rule = " (" + jumpRule(small) + ")";
  if (B != 2 * S) {
    const float minimum = f.partitioning == Partitioning::FractionalEven ? 2.0f : 1.0f;
    const bool belowMinimum = S == minimum && B < 2 * minimum;
    return {"2x jump: the small side's factor is not half the big side's" + rule,
            "2x jump: " + pair + " (" + part + "): the small side's factor is not half the big side's" +
                (belowMinimum ? " (half of it is below " + part + "'s minimum " + formatFloat(minimum) + ")" : "") +
                record,
            halfFix(small, belowMinimum), "jump_not_half"};
  }
  if (B != std::floor(B) || S != std::floor(S))
    return {"2x jump: fractional factors do not nest" + rule,
            "2x jump: fractional factors " + pair + " (" + part + ") do not nest" + record,
            small.lod.scheme == vf::LodScheme::Shader
                ? "round the factors at a jump to powers of two (" + producer(small.lod) +
                      ": as lod.adjacency_clamp = \"pow2\" does); fractional factors never nest"
                : std::string("round the factors at a jump to powers of two (lod.adjacency_clamp = \"pow2\"); "
                              "fractional factors never nest"),
            "jump_fractional_factors"};
  if (!isPow2(B))
    return {"2x jump: factor not a power of two (16.16 rounding)" + rule,
            "2x jump: " + pair + " (" + part + "): B is not a power of two, the 16.16 points do not nest (fftess explain "
            "--partitioning " + part + " " + formatFloat(B) + " " + formatFloat(S) + ")" + record,
            small.lod.scheme == vf::LodScheme::Shader ? std::string(kPow2Fix) + " (" + producer(small.lod) + ")" : kPow2Fix,
            "jump_not_pow2"};
  return {"2x jump: nesting factors, different positions (domain shader / corners)",
          "2x jump: " + pair + " nests in 16.16 but the positions differ (domain shader or corners)" + record,
          kPositionsFix, "jump_different_positions"};
}

// ---- text --------------------------------------------------------------------------------------------------------
std::string patchText(const vf::PatchRef& p) {
  return "ring " + std::to_string(p.ring) + " tile " + std::to_string(p.tile) + " patch " + std::to_string(p.patch);
}

static std::string gapText(const char* what, double world, double pixels, const glm::vec3& at) {
  char gap[160];
  std::snprintf(gap, sizeof gap, " %s %.3g world (%.3g px) at (%.6g, %.6g, %.6g);", what, world, pixels,
                static_cast<double>(at.x), static_cast<double>(at.y), static_cast<double>(at.z));
  return gap;
}

// A crack's gap (" gap ...;", or the on-screen gap and then the farthest vertex's), "" for other findings.
static std::string findingGap(const vf::Finding& f) {
  if (f.classification != vf::Classification::Crack) return "";
  const bool same = f.onScreenGapWorld == f.gapWorld && f.onScreenGapVertex == f.gapVertex;
  if (!f.onScreen || same) return gapText("gap", f.gapWorld, f.gapPixels, f.gapVertex);
  return gapText("gap on screen", f.onScreenGapWorld, f.onScreenGapPixels, f.onScreenGapVertex) +
         gapText("farthest vertex of all", f.gapWorld, f.gapPixels, f.gapVertex);
}

std::string findingWhere(const vf::Finding& f) {
  std::string gap = findingGap(f);
  if (!gap.empty()) gap.pop_back(), gap = ":" + gap; // ": gap ..." without the ';'
  return patchText(f.a.patch) + " " + edgeName(f.a.edge) + " | " + patchText(f.b.patch) + " " + edgeName(f.b.edge) + gap;
}

std::string findingLine(const vf::Finding& f, bool withCause) {
  std::string gap = findingGap(f);
  const bool crack = f.classification == vf::Classification::Crack;
  if (!withCause && !gap.empty()) gap.pop_back(); // the ';' before the cause
  return std::string(crack ? "crack      " : "t_junction ") + (f.onScreen ? "" : "(off screen) ") +
         patchText(f.a.patch) + " " + edgeName(f.a.edge) + " | " + patchText(f.b.patch) + " " + edgeName(f.b.edge) +
         ":" + gap + (withCause ? " " + findingCause(f).detail : std::string());
}

// A patch not drawn whose visibility stayed undecided (Report::undecided): which way it was not drawn, and where
// the decision stopped.
static Cause undecidedCause(const vf::Hole& h) {
  const std::string by = producer(h.lod);
  std::string how;
  if (h.kind == vf::HoleKind::CulledWhileVisible)
    how = "culled by " + by;
  else if (h.edge < 0)
    how = "not drawn (patch dropped)";
  else
    how = "discarded by the tessellator: " + std::string(edgeName(h.edge)) + " factor " + formatFloat(h.hullFactor);
  char buf[320];
  if (h.budgetExhausted)
    std::snprintf(buf, sizeof buf,
                  "; visibility undecided: the work bound was reached (sub-rectangle of side %g at u %g, v %g still "
                  "straddles a frustum plane)",
                  double(h.undecidedSide), double(h.domainPoint.u), double(h.domainPoint.v));
  else
    std::snprintf(buf, sizeof buf,
                  "; visibility undecided: a sub-rectangle of side %g at u %g, v %g (the finest) still touches the "
                  "view frustum, and no point evaluated in it is in view (a view smaller than it, or a surface that "
                  "grazes the view)",
                  double(h.undecidedSide), double(h.domainPoint.u), double(h.domainPoint.v));
  const bool culled = h.kind == vf::HoleKind::CulledWhileVisible;
  const std::string key = culled ? "undecided: culled (" + by + ")" : "undecided: discarded (" + by + ")";
  return {key, how + buf,
          culled ? "cull only what is proven outside the view: a culling box that holds the displaced surface "
                   "(lod.height_bounds) tested against the camera's own frustum planes"
                 : "draw every patch that may be in view: outer factors >= 1 (lod.min_factor), never NaN, <= 0 or "
                   "denormal",
          culled ? "undecided_culled" : "undecided_discarded"};
}

// The fix of a hole the tessellator made (a factor that is NaN, <= 0 or denormal), from its record: the projection's
// w at the edge's midpoint, the factor's class and who wrote it.
static std::string discardFix(const vf::Hole& h, const std::string& by) {
  const float f = h.hullFactor;
  const bool shader = h.lod.scheme == vf::LodScheme::Shader;
  const std::string in = shader ? " (" + by + ")" : "";
  if (h.edge < 0) return "draw every patch whose surface is in view (the patch was dropped without a factor)";
  if (!shader && h.lod.scheme != vf::LodScheme::Constant && !(h.midpointW > 0))
    return "guard w <= 0 in the edge's projection (the edge's midpoint is " +
           std::string(h.midpointW == 0 ? "in the eye's plane" : "behind the eye") +
           "): clamp the projected size before dividing by w";
  if (std::fpclassify(f) == FP_SUBNORMAL)
    return "the tessellator flushes a denormal factor to zero and discards the patch: clamp factors to >= 1 before "
           "output" + (shader ? in : std::string(" (lod.min_factor = 1)"));
  if (std::isnan(f)) return "guard the divisions that make the factor NaN and clamp factors to [1, 64] with a NaN-safe max" + in;
  return "clamp outer factors to >= 1 unless the patch is meant to be culled: a factor <= 0 discards it" +
         (shader ? in : std::string(" (lod.min_factor = 1)"));
}

Cause holeCause(const vf::Hole& h) {
  if (h.visibility == vf::Visibility::Undecided) return undecidedCause(h);
  char buf[480];
  const std::string by = producer(h.lod);
  const bool shader = h.lod.scheme == vf::LodScheme::Shader;
  if (h.kind == vf::HoleKind::CulledWhileVisible) {
    const bool bound = h.visiblePoint.y < h.lodBoxMinY || h.visiblePoint.y > h.lodBoxMaxY;
    if (shader) { // the shader's own test: fftess knows its verdict, not its box
      std::snprintf(buf, sizeof buf, "culled by %s (it said culled), but the surface is in view at (%.6g, %.6g, %.6g)",
                    by.c_str(), double(h.visiblePoint.x), double(h.visiblePoint.y), double(h.visiblePoint.z));
      return {"culled while visible (" + by + ")", buf,
              "cull only boxes that hold the displaced surface and lie outside the camera's frustum planes (" + by + ")",
              "culled_while_visible_shader"};
    }
    std::snprintf(buf, sizeof buf,
                  "culled by %s's frustum test, but the surface is in view at (%.6g, %.6g, %.6g); lod's box y "
                  "[%.6g, %.6g]%s",
                  by.c_str(), double(h.visiblePoint.x), double(h.visiblePoint.y), double(h.visiblePoint.z),
                  double(h.lodBoxMinY), double(h.lodBoxMaxY),
                  bound ? ": the surface leaves it (height bounds too small)" : ": the surface is inside it (a wrong plane)");
    return {"culled while visible (" + by + (bound ? ", height bounds too small)" : ", frustum test)"), buf,
            bound ? "widen the culling box's height range to the heights the domain shader reaches there "
                    "(lod.height_bounds = \"per_patch\" bounds each patch by the texels it samples)"
                  : "build the culling planes from the view-projection the camera renders with (camera.convention; "
                    "lod.frustum_cull = false turns culling off)",
            bound ? "culled_while_visible_height_bounds" : "culled_while_visible_frustum_test"};
  }
  std::string why;
  const float f = h.hullFactor;
  const std::string what = std::isnan(f) ? "NaN" : f < 0 ? "negative" : f == 0 ? "zero"
                           : std::fpclassify(f) == FP_SUBNORMAL ? "denormal, flushed to zero" : "not > 0";
  if (h.edge < 0) {
    why = "not drawn (patch dropped)";
  } else {
    std::snprintf(buf, sizeof buf, "%s factor %s (0x%08X, %s)", edgeName(h.edge), formatFloat(f).c_str(),
                  static_cast<unsigned>(h.hullFactorBits), what.c_str());
    why = buf;
    if (shader) {
      why += "; written by " + by;
    } else if (h.lod.scheme != vf::LodScheme::Constant) {
      std::snprintf(buf, sizeof buf, "; %s: metric %s, unclamped %s", by.c_str(),
                    formatFloat(h.lod.why.metric).c_str(), formatFloat(h.lod.why.unclamped).c_str());
      why += buf;
      if (h.midpointW == 0)
        why += "; w = 0 in the projection: the edge's midpoint lies in the eye's plane (x/0)";
      else if (!(h.midpointW > 0))
        why += "; the edge's midpoint is behind the eye (w " + formatFloat(h.midpointW) + ")";
    }
  }
  const std::string seen = h.visibility == vf::Visibility::Visible
                               ? "; in view at (" + formatFloat(h.visiblePoint.x) + ", " + formatFloat(h.visiblePoint.y) +
                                     ", " + formatFloat(h.visiblePoint.z) + ")"
                               : "; near the view frustum (not proven invisible)";
  const std::string key = h.edge < 0 ? "discarded: patch not drawn"
                          : std::string("discarded: ") +
                                (std::fpclassify(f) == FP_SUBNORMAL ? std::string("denormal factor, flushed to zero") : what + " factor") +
                                (h.lod.scheme != vf::LodScheme::Constant && h.midpointW == 0 ? " (w = 0 at the edge midpoint)" : "") +
                                " (" + by + ")";
  const char* id = h.edge < 0 ? "discarded_patch_dropped"
                   : std::isnan(f) ? "discarded_nan" : f < 0 ? "discarded_negative" : f == 0 ? "discarded_zero"
                   : std::fpclassify(f) == FP_SUBNORMAL ? "discarded_denormal" : "discarded_not_positive";
  return {key, "discarded by the tessellator: " + why + seen, discardFix(h, by), id};
}

std::string holeLine(const vf::Hole& h) {
  return (h.visibility == vf::Visibility::Undecided ? "undecided  " : "hole       ") + patchText(h.patch) + ": " +
         holeCause(h).detail;
}

Cause gpuFloatCause(const vf::GpuFloatFinding& g) {
  Cause c;
  const bool ops = !g.operationA.empty();
  c.key = std::string("may crack on some GPUs: ") +
          (ops ? "the two sides compute the factor through different operations" : g.why);
  c.detail = "factors " + formatFloat(g.factorA) + " | " + formatFloat(g.factorB) +
             " (lod/'s C++ build: a match); a conformant GPU compiler may give " + formatFloat(g.loA) + ".." +
             formatFloat(g.hiA) + " | " + formatFloat(g.loB) + ".." + formatFloat(g.hiB);
  if (ops)
    c.detail += ", which tessellate the edge differently; the first operation that differs: side a " + g.operationA +
                ", side b " + g.operationB;
  else
    c.detail += ": " + g.why;
  c.fix = g.fix;
  // The reason's words are g.why (the frustum test may cull a side, a factor may be NaN or <= 0, too many evaluation
  // paths); only "different operations" names an operation.
  c.id = ops ? "gpu_float_operations" : "gpu_float_other";
  return c;
}

std::string gpuFloatWhere(const vf::GpuFloatFinding& g) {
  return patchText(g.a) + " " + edgeName(g.edgeA) + " | " + patchText(g.b) + " " + edgeName(g.edgeB);
}

std::string gpuFloatLine(const vf::GpuFloatFinding& g, bool withCause) {
  return "gpu float  " + patchText(g.a) + " " + edgeName(g.edgeA) + " | " + patchText(g.b) + " " + edgeName(g.edgeB) +
         (withCause ? ": " + gpuFloatCause(g).detail : std::string());
}

std::vector<Cause> reportCauses(const vf::Report& r, bool offScreenToo) {
  std::vector<Cause> out;
  auto add = [&](Cause c, const std::string& prefix) {
    c.key = prefix + c.key;
    for (const Cause& o : out)
      if (o.key == c.key) return;
    out.push_back(std::move(c));
  };
  for (const vf::Hole& h : r.holes) add(holeCause(h), "hole: ");
  for (const vf::Hole& h : r.undecided) add(holeCause(h), ""); // "undecided: ..."
  for (const vf::Finding& f : r.findings)
    if (f.classification != vf::Classification::Match && (f.onScreen || offScreenToo))
      add(findingCause(f), std::string(vf::toString(f.classification)) + ": ");
  for (const vf::GpuFloatFinding& g : r.gpuFloat) add(gpuFloatCause(g), "");
  return out;
}

std::string fmtWorld(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

double countedGapWorld(const vf::Stats& s, bool countOffScreen) {
  return countOffScreen ? s.worstGapWorld : s.worstGapWorldOnScreen;
}
double countedGapPixels(const vf::Stats& s, bool countOffScreen) {
  return countOffScreen ? s.worstGapPixels : s.worstGapPixelsOnScreen;
}

std::string offScreenWords(const vf::Stats& s, bool countOffScreen, bool explain) {
  if (s.cracksOffScreen == 0 && s.tJunctionsOffScreen == 0) return "";
  std::string what;
  if (s.cracksOffScreen > 0) what = std::to_string(s.cracksOffScreen) + (s.cracksOffScreen == 1 ? " crack" : " cracks");
  if (s.tJunctionsOffScreen > 0)
    what += (what.empty() ? "" : " and ") + std::to_string(s.tJunctionsOffScreen) +
            (s.tJunctionsOffScreen == 1 ? " T-junction" : " T-junctions");
  if (countOffScreen) return what + " off screen, counted: --offscreen";
  if (!explain) return what + " off screen, not counted";
  return what + " off screen, not counted: the factors that made them belong to their camera, so no other camera sees "
                "them either (--offscreen counts them)";
}

// "N", "N - M on screen (+ M off screen, not counted)" or (countOffScreen) "N (M of them off screen, counted: ...)".
static std::string countText(int64_t all, int64_t off, bool countOffScreen) {
  if (off == 0) return std::to_string(all);
  if (countOffScreen) return std::to_string(all) + " (" + std::to_string(off) + " of them off screen, counted: --offscreen)";
  return std::to_string(all - off) + " on screen (+ " + std::to_string(off) + " off screen, not counted)";
}

std::string statsText(const vf::Stats& s, bool countOffScreen) {
  std::string o;
  o += "  patches        " + std::to_string(s.patches) + " (" + std::to_string(s.culledPatches) + " culled)\n";
  o += "  edges checked  " + std::to_string(s.edgesChecked) + " (" + std::to_string(s.skippedCulled) +
       " skipped: a side culled)\n";
  o += "  matches        " + std::to_string(s.matches) + "\n";
  o += "  T-junctions    " + countText(s.tJunctions, s.tJunctionsOffScreen, countOffScreen) + "\n";
  o += "  cracks         " + countText(s.cracks, s.cracksOffScreen, countOffScreen) + "\n";
  o += "  holes          " + std::to_string(s.holes) + " (" + std::to_string(s.holesDiscarded) +
       " discarded by the tessellator, " + std::to_string(s.holesCulledVisible) + " culled while visible)\n";
  if (s.undecided > 0)
    o += "  undecided      " + std::to_string(s.undecided) + " (" + std::to_string(s.culledUndecided) + " culled, " +
         std::to_string(s.undecided - s.culledUndecided) +
         " discarded): patches not drawn, neither proven visible nor invisible (not clean)\n";
  if (s.gpuFloatPairs > 0 || s.gpuFloatFindings > 0)
    o += "  gpu float      " + std::to_string(s.gpuFloatPairs) +
         " matching pairs evaluated under a conformant GPU compiler's choices (--gpu-float conformant), " +
         std::to_string(s.gpuFloatFindings) + " may crack on some GPUs\n";
  if (s.gpuModelFactors > 0)
    o += "  gpu model      " + std::to_string(s.gpuModelFactors) +
         " GPU factors checked against the conformant model of the scheme, " + std::to_string(s.gpuModelOutside) +
         " outside it\n";
  const int64_t counted = countOffScreen ? s.cracks : s.cracksOnScreen();
  const bool differ = fmtWorld(s.worstGapWorld) != fmtWorld(s.worstGapWorldOnScreen) ||
                      fmtWorld(s.worstGapPixels) != fmtWorld(s.worstGapPixelsOnScreen); // as printed
  if (counted > 0)
    o += "  worst gap      " + fmtWorld(countedGapWorld(s, countOffScreen)) + " world units, " +
         fmtWorld(countedGapPixels(s, countOffScreen)) + " pixels" +
         (countOffScreen ? " (all cracks, --offscreen)" : " (on screen)") + "\n";
  if (countOffScreen && s.cracksOnScreen() > 0 && differ)
    o += "  on screen      worst gap " + fmtWorld(s.worstGapWorldOnScreen) + " world units, " +
         fmtWorld(s.worstGapPixelsOnScreen) + " pixels\n";
  if (!countOffScreen && s.cracks > 0 && differ)
    o += "  all cracks     worst gap " + fmtWorld(s.worstGapWorld) + " world units, " + fmtWorld(s.worstGapPixels) +
         " pixels, on screen or not (--offscreen counts them)\n";
  if (!countOffScreen && (s.cracksOffScreen > 0 || s.tJunctionsOffScreen > 0))
    o += "  off screen     " + offScreenWords(s, countOffScreen, true) + "\n";
  return o;
}

// ---- verdicts ----------------------------------------------------------------------------------------------------
// The verdict line without the off-screen findings.
static std::string verdictHeadline(vf::Verdict verdict, const vf::SweepResult& res, size_t crackCameras,
                                   size_t holeCameras, size_t cameras, bool countOffScreen) {
  const std::string holesText = "HOLES seen from " + std::to_string(holeCameras) + " of " +
                                std::to_string(res.camerasDone) + " cameras (" + std::to_string(res.total.holes) +
                                " patches not drawn while in view)";
  const std::string undecidedText = res.total.undecided > 0 ? "; " + std::to_string(res.total.undecided) +
                                                                   " patches undecided on " +
                                                                   std::to_string(res.camerasUndecided) + " cameras"
                                                             : "";
  switch (verdict) {
  case vf::Verdict::Cracks:
    return "CRACKS seen from " + std::to_string(crackCameras) + " of " + std::to_string(res.camerasDone) +
           " cameras (worst gap" + (countOffScreen ? " " : " on screen ") + fmtWorld(countedGapWorld(res.total, countOffScreen)) +
           " world units, " + fmtWorld(countedGapPixels(res.total, countOffScreen)) + " px)" +
           (res.total.holes > 0 ? "; " + holesText : "") + undecidedText;
  case vf::Verdict::Holes: return holesText + undecidedText;
  case vf::Verdict::NothingChecked:
    return "NOTHING CHECKED: no camera classified a shared edge (" + std::to_string(res.camerasDone) +
           " cameras checked, " + std::to_string(res.camerasInvalid) + " invalid); not a clean verdict";
  case vf::Verdict::Unchecked:
    return "NOT CLEAN: " + std::to_string(res.camerasInvalid) + " of " + std::to_string(cameras) +
           " cameras could not be checked (the other " + std::to_string(res.camerasDone) + " found no crack or hole)";
  case vf::Verdict::Undecided:
    return "NOT WATERTIGHT: UNDECIDED from " + std::to_string(res.camerasUndecided) + " of " +
           std::to_string(res.camerasDone) + " cameras (" + std::to_string(res.total.undecided) +
           " patches not drawn, neither proven visible nor invisible)";
  case vf::Verdict::GpuFloat:
    return "MAY CRACK ON SOME GPUS: " + std::to_string(res.total.gpuFloatFindings) + " matching shared edges on " +
           std::to_string(res.camerasGpuFloat) + " of " + std::to_string(res.camerasDone) +
           " cameras depend on a conformant GPU compiler's choices (--gpu-float conformant); no crack with lod/'s "
           "C++ build";
  case vf::Verdict::TJunctionsOnly: return res.cancelled ? "no cracks so far (interrupted)" : "no cracks (T-junctions only)";
  case vf::Verdict::Watertight:
    return res.cancelled ? "no cracks so far (interrupted)" : "WATERTIGHT from all " + std::to_string(res.camerasDone) + " cameras";
  }
  return "?";
}

// The verdict line's words (sweep and merge).
std::string verdictWords(vf::Verdict verdict, const vf::SweepResult& res, size_t crackCameras, size_t holeCameras,
                         size_t cameras, bool countOffScreen) {
  const std::string off = offScreenWords(res.total, countOffScreen);
  return verdictHeadline(verdict, res, crackCameras, holeCameras, cameras, countOffScreen) +
         (off.empty() ? "" : " (" + off + ")");
}

} // namespace fftess::cli
