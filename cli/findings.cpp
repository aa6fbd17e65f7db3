// Findings in words and the scene options shared by check and sweep (findings.h).
#include "findings.h"
#include "common.h"
#include "gpu_lod.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fftess::cli {

const char* const kEdgeNames[4] = {"Ueq0", "Veq0", "Ueq1", "Veq1"};
const char* edgeName(int e) { return e >= 0 && e < 4 ? kEdgeNames[e] : "?"; }

// ---- scene loading -----------------------------------------------------------------------------------------------
std::vector<std::string> overridesOf(const SceneArgs& a) {
  std::vector<std::string> o;
  auto vec = [](const std::string& opt, const std::string& v) {
    std::string t = v;
    std::replace(t.begin(), t.end(), ';', ',');
    if (t.empty() || t.front() != '[') t = "[" + t + "]";
    (void)opt;
    return t;
  };
  if (!a.eye.empty()) o.push_back("camera.eye=" + vec("--eye", a.eye));
  if (!a.target.empty()) o.push_back("camera.target=" + vec("--target", a.target));
  o.insert(o.end(), a.overrides.begin(), a.overrides.end());
  for (const std::string& s : a.overrides)
    if (s.find('=') == std::string::npos || s.front() == '=')
      throw UsageError("--set " + quoteToken(s) + ": expected KEY=VALUE (e.g. --set lod.adjacency_clamp=none)");
  return o;
}

// The loader names --eye / --target as the overrides they become ("--set camera.eye: ..."): name the option given.
static std::string shorthandNamed(const SceneArgs& a, std::string error) {
  const std::pair<const char*, const std::string*> opts[] = {{"eye", &a.eye}, {"target", &a.target}};
  for (const auto& [key, value] : opts) {
    const std::string prefix = std::string("--set camera.") + key + ": ";
    bool viaSet = false;
    for (const std::string& o : a.overrides) viaSet = viaSet || o.rfind(std::string("camera.") + key + "=", 0) == 0;
    if (!value->empty() && !viaSet && error.rfind(prefix, 0) == 0)
      error = "--" + std::string(key) + " " + *value + ": " + error.substr(prefix.size());
  }
  return error;
}

std::string loaderMessage(const std::string& scene, const std::string& error) {
  if (error.compare(0, scene.size(), scene) == 0) return printable(scene, std::string::npos) + printable(error.substr(scene.size()));
  return printable(error);
}

vf::Terrain load(const SceneArgs& a) {
  vf::SceneResult r = vf::loadScene(a.scene, overridesOf(a));
  if (!r)
    throw UsageError(r.error.empty() ? "cannot load scene " + quotePath(a.scene)
                                     : loaderMessage(a.scene, shorthandNamed(a, r.error)));
  refuseSameFiles(reportArgs(a), sceneInputs(a, &r.scene)); // the files the scene reads are inputs too
  vf::TerrainResult t = vf::prepareTerrain(r.scene);
  if (!t) throw UsageError(loaderMessage(a.scene, a.scene + ": " + t.error));
  return t.terrain;
}

vf::CheckOptions checkOptions(const SceneArgs& a) {
  vf::CheckOptions o;
  if (!vf::parseKernel(a.kernel.c_str(), o.kernel))
    throw UsageError("--kernel " + quoteToken(a.kernel) + ": expected epick|epeck|float");
  const std::string& fd = a.flushDenormals;
  if (fd == "on" || fd == "true") o.flushDenormals = vf::DenormalFlush::On;
  else if (fd == "off" || fd == "false") o.flushDenormals = vf::DenormalFlush::Off;
  else if (fd == "auto") o.flushDenormals = vf::DenormalFlush::Auto;
  else throw UsageError("--flush-denormals=" + quoteToken(fd) + ": expected on|off|auto");
  o.countOffScreen = a.offscreen;
  return o;
}

vf::CheckOptions checkOptions(const SceneArgs& a, const vf::Terrain& terrain) {
  vf::CheckOptions o = checkOptions(a);
  attachGpuLod(terrain, a, o);
  return o;
}

// ---- causes ------------------------------------------------------------------------------------------------------
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
      return {std::string("same-size neighbours chose different factors (lod ") + vf::toString(f.a.lod.scheme) + ")",
              "same-size neighbours chose different factors (" + formatFloat(f.a.processedFactor) + " vs " +
                  formatFloat(f.b.processedFactor) + sides + ")"};
    return {"same factor, different positions (domain shader / corners)",
            "both sides use factor " + formatFloat(B) + " but compute different positions (domain shader or corners)"};
  }
  if (jump > 1)
    return {"size jump larger than 2x", "patch sizes differ by 2^" + std::to_string(jump) + " (" + pair + record + ")"};
  const std::string rule = " (" + jumpRule(small) + ")";
  if (B != 2 * S) {
    const float minimum = f.partitioning == Partitioning::FractionalEven ? 2.0f : 1.0f;
    return {"2x jump: the small side's factor is not half the big side's" + rule,
            "2x jump: " + pair + " (" + part + "): the small side's factor is not half the big side's" +
                (S == minimum && B < 2 * minimum ? " (half of it is below " + part + "'s minimum " + formatFloat(minimum) + ")" : "") +
                record};
  }
  if (B != std::floor(B) || S != std::floor(S))
    return {"2x jump: fractional factors do not nest" + rule,
            "2x jump: fractional factors " + pair + " (" + part + ") do not nest" + record};
  if (!isPow2(B))
    return {"2x jump: factor not a power of two (16.16 rounding)" + rule,
            "2x jump: " + pair + " (" + part + "): B is not a power of two, the 16.16 points do not nest (fftess explain "
            "--partitioning " + part + " " + formatFloat(B) + " " + formatFloat(S) + ")" + record};
  return {"2x jump: nesting factors, different positions (domain shader / corners)",
          "2x jump: " + pair + " nests in 16.16 but the positions differ (domain shader or corners)" + record};
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

std::string findingLine(const vf::Finding& f) {
  std::string gap;
  if (f.classification == vf::Classification::Crack) {
    const bool same = f.onScreenGapWorld == f.gapWorld && f.onScreenGapVertex == f.gapVertex;
    if (!f.onScreen || same) gap = gapText("gap", f.gapWorld, f.gapPixels, f.gapVertex);
    else
      gap = gapText("gap on screen", f.onScreenGapWorld, f.onScreenGapPixels, f.onScreenGapVertex) +
            gapText("farthest vertex of all", f.gapWorld, f.gapPixels, f.gapVertex);
  }
  const bool crack = f.classification == vf::Classification::Crack;
  return std::string(crack ? "crack      " : "t_junction ") + (f.onScreen ? "" : "(off screen) ") +
         patchText(f.a.patch) + " " + edgeName(f.a.edge) + " | " + patchText(f.b.patch) + " " + edgeName(f.b.edge) +
         ":" + gap + " " + findingCause(f).detail;
}

// A patch not drawn whose visibility stayed undecided (Report::undecided): which way it was not drawn, and where
// the decision stopped.
static Cause undecidedCause(const vf::Hole& h) {
  const std::string scheme = vf::toString(h.lod.scheme);
  std::string how;
  if (h.kind == vf::HoleKind::CulledWhileVisible)
    how = "culled by lod " + scheme;
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
  const std::string key = h.kind == vf::HoleKind::CulledWhileVisible ? "undecided: culled (lod " + scheme + ")"
                                                                     : "undecided: discarded (lod " + scheme + ")";
  return {key, how + buf};
}

Cause holeCause(const vf::Hole& h) {
  if (h.visibility == vf::Visibility::Undecided) return undecidedCause(h);
  char buf[480];
  const std::string scheme = vf::toString(h.lod.scheme);
  if (h.kind == vf::HoleKind::CulledWhileVisible) {
    const bool bound = h.visiblePoint.y < h.lodBoxMinY || h.visiblePoint.y > h.lodBoxMaxY;
    std::snprintf(buf, sizeof buf,
                  "culled by lod %s's frustum test, but the surface is in view at (%.6g, %.6g, %.6g); lod's box y "
                  "[%.6g, %.6g]%s",
                  scheme.c_str(), double(h.visiblePoint.x), double(h.visiblePoint.y), double(h.visiblePoint.z),
                  double(h.lodBoxMinY), double(h.lodBoxMaxY),
                  bound ? ": the surface leaves it (height bounds too small)" : ": the surface is inside it (a wrong plane)");
    return {std::string("culled while visible (lod ") + scheme + (bound ? ", height bounds too small)" : ", frustum test)"), buf};
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
    if (h.lod.scheme != vf::LodScheme::Constant) {
      std::snprintf(buf, sizeof buf, "; lod %s: metric %s, unclamped %s", scheme.c_str(),
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
                                " (lod " + scheme + ")";
  return {key, "discarded by the tessellator: " + why + seen};
}

std::string holeLine(const vf::Hole& h) {
  return (h.visibility == vf::Visibility::Undecided ? "undecided  " : "hole       ") + patchText(h.patch) + ": " +
         holeCause(h).detail;
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
// ---- shared plumbing ---------------------------------------------------------------------------------------------
std::vector<FileArg> reportArgs(const SceneArgs& a) { return {{"--json", a.json}, {"--svg", a.svg}}; }

std::vector<FileArg> sceneInputs(const SceneArgs& a, const vf::Scene* scene) {
  std::vector<FileArg> in{{"SCENE", a.scene}};
  if (!scene) return in;
  in.push_back({"(the scene's lod.shader)", scene->lod.shader});
  const std::string& raw = scene->displacement.file; // relative to the scene file's folder
  if (!raw.empty()) {
    const size_t slash = a.scene.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "." : a.scene.substr(0, slash + 1);
    in.push_back({"(the scene's displacement.file)", raw.front() == '/' ? raw : dir + "/" + raw});
  }
  return in;
}

ReportFiles::ReportFiles(const SceneArgs& a) {
  refuseSameFiles(reportArgs(a), sceneInputs(a, nullptr));
  if (!a.json.empty()) json_ = std::make_unique<AtomicFile>(a.json);
  if (!a.svg.empty()) svg_ = std::make_unique<AtomicFile>(a.svg);
}

void ReportFiles::commit() {
  AtomicFile* files[2];
  size_t n = 0;
  if (json_) files[n++] = json_.get();
  if (svg_) files[n++] = svg_.get();
  commitAll(files, n);
}

int verdictStatus(const SceneArgs& a, vf::Verdict v) {
  switch (v) {
  case vf::Verdict::Watertight: return kExitClean;
  case vf::Verdict::TJunctionsOnly: return a.failOnTJunctions ? kExitFindings : kExitClean;
  default: return kExitFindings;
  }
}

void addSceneOptions(CLI::App* sub, SceneArgs& a) {
  sub->add_option("scene", a.scene, "Scene file (TOML, docs/verify.md)")->required();
  sub->add_option("--set", a.overrides, "Override a scene key: KEY=VALUE (repeatable), validated like the file")
      ->type_name("KEY=VALUE");
  sub->add_option("--eye", a.eye, "Camera eye X,Y,Z (shorthand for --set camera.eye=[X,Y,Z])");
  sub->add_option("--target", a.target, "Camera target X,Y,Z (shorthand for --set camera.target=[X,Y,Z])");
  sub->add_option("--kernel", a.kernel, "CGAL kernel: epick (exact predicates), epeck (exact gaps too), float (naive, wrong on purpose)")
      ->capture_default_str();
  sub->add_flag("--flush-denormals{on}", a.flushDenormals,
                "Denormal hull factors: =on flushed to zero (as llvmpipe; bare flag), =off kept (the D3D11 reference, "
                "NVIDIA), =auto (default) the scene's lod.flush_denormals, else the GPU driver's rule");
  sub->add_option("--json", a.json, "Write the full report as JSON to FILE ('-': stdout, no text then)");
  sub->add_option("--svg", a.svg, "Write an SVG picture to FILE");
  sub->add_flag("-q,--quiet", a.quiet, "Print nothing but errors; the exit status tells the verdict");
  sub->add_flag("--fail-on-tjunctions", a.failOnTJunctions, "Exit 1 on T-junctions too (default: cracks only)");
  sub->add_flag("--offscreen", a.offscreen,
                "Count cracks and T-junctions outside the view frustum too (whole-mesh comparisons, strict CI); "
                "default: only what the camera sees counts");
  sub->add_flag("--gpu-hardware", a.gpuHardware,
                "lod.shader / lod.evaluate = \"gpu\": use a GPU's EGL device (default: Mesa's llvmpipe first)");
}

} // namespace fftess::cli
