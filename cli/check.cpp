// fftess check SCENE / fftess sweep SCENE: run verify/ on one camera or many, print a summary and one line per
// finding, write JSON / SVG reports atomically, and turn the verdict into an exit status.
#include "check.h"
#include "common.h"

#include "verify/verify.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <map>
#include <mutex>
#include <set>
#include <unistd.h>

namespace fftess::cli {
namespace {

using json = nlohmann::ordered_json;
namespace vf = fftess::verify;

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

vf::Scene load(const SceneArgs& a) {
  vf::SceneResult r = vf::loadScene(a.scene, overridesOf(a));
  if (!r) throw UsageError(r.error.empty() ? "cannot load scene '" + a.scene + "'" : r.error);
  return r.scene;
}

vf::CheckOptions checkOptions(const SceneArgs& a) {
  vf::CheckOptions o;
  if (!vf::parseKernel(a.kernel.c_str(), o.kernel))
    throw UsageError("--kernel " + quoteToken(a.kernel) + ": expected epick|epeck|float");
  o.tessellator.flushDenormals = a.flushDenormals;
  return o;
}

// ---- causes ------------------------------------------------------------------------------------------------------
bool isPow2(float f) {
  if (!(f >= 1) || f != std::floor(f) || f > 1e9f) return false;
  const auto n = static_cast<uint64_t>(f);
  return (n & (n - 1)) == 0;
}

// A short, stable name for why a finding happened, derived from the two sides' factors and sizes (the grouping key
// of sweep summaries), and a longer explanation with the numbers of this finding.
struct Cause {
  std::string key;
  std::string detail;
};

Cause causeOf(const vf::Finding& f) {
  const vf::EdgeSide& big = f.a.patch.level >= f.b.patch.level ? f.a : f.b;
  const vf::EdgeSide& small = f.a.patch.level >= f.b.patch.level ? f.b : f.a;
  const int jump = big.patch.level - small.patch.level;
  const float B = big.processedFactor, S = small.processedFactor;
  const std::string pair = formatFloat(B) + " beside " + formatFloat(S);
  const std::string part = toString(f.partitioning);
  if (jump == 0) {
    if (f.a.processedFactor != f.b.processedFactor)
      return {"same-size neighbours chose different factors",
              "same-size neighbours chose different factors (" + formatFloat(f.a.processedFactor) + " vs " +
                  formatFloat(f.b.processedFactor) + ", hull " + formatFloat(f.a.hullFactor) + " vs " +
                  formatFloat(f.b.hullFactor) + ")"};
    return {"same factor, different positions (domain shader / corners)",
            "both sides use factor " + formatFloat(B) + " but compute different positions (domain shader or corners)"};
  }
  if (jump > 1)
    return {"size jump larger than 2x", "patch sizes differ by 2^" + std::to_string(jump) + " (" + pair + ")"};
  if (B != 2 * S) {
    const float minimum = f.partitioning == Partitioning::FractionalEven ? 2.0f : 1.0f;
    return {"2x jump: the small side's factor is not half the big side's",
            "2x jump: " + pair + " (" + part + "): the small side's factor is not half the big side's" +
                (S == minimum && B < 2 * minimum ? " (half of it is below " + part + "'s minimum " + formatFloat(minimum) + ")" : "")};
  }
  if (B != std::floor(B) || S != std::floor(S))
    return {"2x jump: fractional factors do not nest",
            "2x jump: fractional factors " + pair + " (" + part + ") do not nest"};
  if (!isPow2(B))
    return {"2x jump: factor not a power of two (16.16 rounding)",
            "2x jump: " + pair + " (" + part + "): B is not a power of two, the 16.16 points do not nest (fftess explain "
            "--partitioning " + part + " " + formatFloat(B) + " " + formatFloat(S) + ")"};
  return {"2x jump: nesting factors, different positions (domain shader / corners)",
          "2x jump: " + pair + " nests in 16.16 but the positions differ (domain shader or corners)"};
}

// ---- JSON --------------------------------------------------------------------------------------------------------
json vec3(const vf::Vec3& v) { return json::array({v.x, v.y, v.z}); }

json sideJson(const vf::EdgeSide& s) {
  json j;
  j["patch"] = {{"index", s.patch.index}, {"ring", s.patch.ring}, {"tile", s.patch.tile}, {"patch", s.patch.patch},
                {"level", s.patch.level}};
  j["edge"] = edgeName(s.edge);
  j["hull_factor"] = s.hullFactor;
  j["processed_factor"] = s.processedFactor;
  j["culled"] = s.culled;
  j["param_range"] = json::array({s.paramLo, s.paramHi});
  j["point_count"] = s.pointCount;
  j["first_mismatch"] = s.firstMismatch;
  if (s.firstMismatch >= 0) {
    j["mismatch_domain"] = json::array({s.mismatchDomain.u, s.mismatchDomain.v});
    j["mismatch_world"] = vec3(s.mismatchWorld);
  } else {
    j["mismatch_domain"] = nullptr;
    j["mismatch_world"] = nullptr;
  }
  return j;
}

json findingJson(const vf::Finding& f) {
  json j;
  j["classification"] = vf::toString(f.classification);
  j["cause"] = causeOf(f).key;
  j["explanation"] = causeOf(f).detail;
  j["partitioning"] = toString(f.partitioning);
  j["a"] = sideJson(f.a);
  j["b"] = sideJson(f.b);
  j["edge_start"] = vec3(f.edgeStart);
  j["edge_end"] = vec3(f.edgeEnd);
  j["gap_world"] = f.gapWorld;
  j["gap_pixels"] = f.gapPixels;
  j["gap_vertex"] = vec3(f.gapVertex);
  j["gap_side"] = f.gapSide == 0 ? "a" : "b";
  return j;
}

json statsJson(const vf::Stats& s) {
  return {{"patches", s.patches},           {"culled_patches", s.culledPatches}, {"edges_checked", s.edgesChecked},
          {"skipped_culled", s.skippedCulled}, {"matches", s.matches},          {"t_junctions", s.tJunctions},
          {"cracks", s.cracks},             {"worst_gap_world", s.worstGapWorld}, {"worst_gap_pixels", s.worstGapPixels}};
}

json cameraJson(const vf::Camera& c) {
  return {{"eye", vec3(c.eye)},   {"target", vec3(c.target)}, {"up", vec3(c.up)},       {"fov_y", c.fovY},
          {"near", c.nearZ},      {"far", c.farZ},            {"width", c.width},       {"height", c.height}};
}

json sceneJson(const SceneArgs& a, const vf::Scene& s) {
  return {{"file", a.scene},
          {"name", s.name},
          {"overrides", overridesOf(a)},
          {"layout", vf::toString(s.layout.kind)},
          {"lod_scheme", vf::toString(s.lod.scheme)},
          {"adjacency_clamp", vf::toString(s.lod.adjacencyClamp)},
          {"partitioning", toString(s.partitioning)},
          {"stage", toString(s.stage)},
          {"domain_formula", vf::toString(s.domain.formula)},
          {"kernel", a.kernel}};
}

// ---- text --------------------------------------------------------------------------------------------------------
std::string patchText(const vf::PatchRef& p) {
  return "ring " + std::to_string(p.ring) + " tile " + std::to_string(p.tile) + " patch " + std::to_string(p.patch);
}

std::string findingLine(const vf::Finding& f) {
  char gap[96] = "";
  if (f.classification == vf::Classification::Crack)
    std::snprintf(gap, sizeof gap, " gap %.3g world (%.3g px) at (%.6g, %.6g, %.6g);", f.gapWorld, f.gapPixels,
                  static_cast<double>(f.gapVertex.x), static_cast<double>(f.gapVertex.y),
                  static_cast<double>(f.gapVertex.z));
  return std::string(f.classification == vf::Classification::Crack ? "crack      " : "t-junction ") +
         patchText(f.a.patch) + " " + edgeName(f.a.edge) + " | " + patchText(f.b.patch) + " " + edgeName(f.b.edge) +
         ":" + gap + " " + causeOf(f).detail;
}

std::string fmtWorld(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

std::string statsText(const vf::Stats& s) {
  std::string o;
  o += "  patches        " + std::to_string(s.patches) + " (" + std::to_string(s.culledPatches) + " culled)\n";
  o += "  edges checked  " + std::to_string(s.edgesChecked) + " (" + std::to_string(s.skippedCulled) +
       " skipped: a side culled)\n";
  o += "  matches        " + std::to_string(s.matches) + "\n";
  o += "  T-junctions    " + std::to_string(s.tJunctions) + "\n";
  o += "  cracks         " + std::to_string(s.cracks) + "\n";
  if (s.cracks > 0)
    o += "  worst gap      " + fmtWorld(s.worstGapWorld) + " world units, " + fmtWorld(s.worstGapPixels) + " pixels\n";
  return o;
}

// ---- SVG ---------------------------------------------------------------------------------------------------------
struct MapView {
  vf::Extent e;
  double size = 760, margin = 20, scale = 1;
  void init(const vf::Extent& ext) {
    e = ext;
    const double w = std::max(1e-9, static_cast<double>(e.maxX - e.minX)), h = std::max(1e-9, static_cast<double>(e.maxZ - e.minZ));
    scale = size / std::max(w, h);
  }
  double x(double wx) const { return margin + (wx - e.minX) * scale; }
  double y(double wz) const { return margin + (e.maxZ - wz) * scale; } // +z up on the page
};

const char* kSvgStyle =
    "<style>.p{fill:none;stroke:#bbb;stroke-width:0.3}.tl{fill:none;stroke:#777;stroke-width:0.8}.tj{stroke:#e08a00;stroke-width:2.5}"
    ".cr{stroke:#d01010;stroke-width:3}.mk{fill:none;stroke:#d01010;stroke-width:0.8}.t{font:13px sans-serif}"
    ".s{font:11px monospace}.ok{fill:#2a8a2a}.warn{fill:#e08a00}.bad{fill:#d01010}.path{fill:none;stroke:#446;"
    "stroke-width:1}.ins{fill:#fff;stroke:#222}.a{stroke:#2a5599;stroke-width:1.2}.b{stroke:#7a2a99;stroke-width:1.2}"
    ".x{stroke:#d01010;stroke-width:2}</style>\n";

// The layout from above, from verify's real patch geometry (one terrain build for all patches): every patch outlined
// thinly, and each tile (ring, tile) of a tile-ring layout outlined around its patches. Very large layouts (more
// than kSvgMaxPatches patches) are drawn as their extent only.
constexpr size_t kSvgMaxPatches = 200000;

void svgPatches(std::string& o, const vf::Scene& scene, const MapView& v) {
  char buf[256];
  o += "<g id=\"layout\">\n";
  const std::vector<vf::PatchGeometry> geo = vf::patchGeometry(scene);
  if (geo.empty() || geo.size() > kSvgMaxPatches) {
    std::snprintf(buf, sizeof buf, "<rect class=\"tl\" x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\"/>\n",
                  v.x(v.e.minX), v.y(v.e.maxZ), v.x(v.e.maxX) - v.x(v.e.minX), v.y(v.e.minZ) - v.y(v.e.maxZ));
    o += buf + std::string("</g>\n");
    return;
  }
  // Patches: one path, a closed quadrilateral per patch through its corners in order (u0v0, u1v0, u1v1, u0v1).
  o += "<path class=\"p\" d=\"";
  struct Box {
    double x0 = 1e300, z0 = 1e300, x1 = -1e300, z1 = -1e300;
  };
  std::map<std::pair<int, int>, Box> tiles;
  for (const vf::PatchGeometry& g : geo) {
    const vf::Vec3* c = g.corners;
    std::snprintf(buf, sizeof buf, "M%.2f %.2fL%.2f %.2fL%.2f %.2fL%.2f %.2fZ", v.x(c[0].x), v.y(c[0].z), v.x(c[1].x),
                  v.y(c[1].z), v.x(c[3].x), v.y(c[3].z), v.x(c[2].x), v.y(c[2].z));
    o += buf;
    Box& b = tiles[{g.ref.ring, g.ref.tile}];
    for (int k = 0; k < 4; ++k) {
      b.x0 = std::min(b.x0, static_cast<double>(c[k].x)), b.x1 = std::max(b.x1, static_cast<double>(c[k].x));
      b.z0 = std::min(b.z0, static_cast<double>(c[k].z)), b.z1 = std::max(b.z1, static_cast<double>(c[k].z));
    }
  }
  o += "\"/>\n";
  // Tiles (a grid or heightmap grid is one tile: its outline is the terrain's).
  for (const auto& kv : tiles) {
    const Box& b = kv.second;
    std::snprintf(buf, sizeof buf, "<rect class=\"tl\" x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\"/>\n",
                  v.x(b.x0), v.y(b.z1), v.x(b.x1) - v.x(b.x0), v.y(b.z0) - v.y(b.z1));
    o += buf;
  }
  o += "</g>\n";
}

// The inset: the worst finding's shared edge stretched to the inset's width, side a's points above the line and
// side b's below (from the tessellator's edge query), the points without a partner on the other side in red.
void svgInset(std::string& o, const vf::Scene& scene, const vf::Finding& f, double x, double y, double w) {
  char buf[320];
  std::snprintf(buf, sizeof buf, "<g id=\"inset\"><rect class=\"ins\" x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"150\"/>\n",
                x, y, w);
  o += buf;
  std::snprintf(buf, sizeof buf, "<text class=\"t\" x=\"%.1f\" y=\"%.1f\">worst %s, zoomed: the shared edge, side a above, side b below</text>\n",
                x + 8, y + 18, vf::toString(f.classification));
  o += buf;
  struct Tick {
    double t;
    bool partner;
  };
  auto ticks = [&](const vf::EdgeSide& s) {
    std::vector<Tick> out;
    const EdgePoints e = edgePoints(s.hullFactor, f.partitioning, scene.stage);
    const double lo = s.paramLo, hi = s.paramHi;
    for (int i = 0; i < e.count; ++i) {
      const double p = e.param[i];
      if (p < lo || p > hi || hi <= lo) continue;
      out.push_back({(p - lo) / (hi - lo), false});
    }
    return out;
  };
  std::vector<Tick> ta = ticks(f.a), tb = ticks(f.b);
  for (Tick& a : ta)
    for (Tick& b : tb)
      if (a.t == b.t) a.partner = b.partner = true;
  const double lx = x + 20, lw = w - 40, ly = y + 85;
  std::snprintf(buf, sizeof buf, "<line class=\"p\" x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\"/>\n", lx, ly, lx + lw, ly);
  o += buf;
  for (const Tick& t : ta) {
    std::snprintf(buf, sizeof buf, "<line class=\"%s\" x1=\"%.2f\" y1=\"%.1f\" x2=\"%.2f\" y2=\"%.1f\"/>\n",
                  t.partner ? "a" : "x", lx + t.t * lw, ly - 25, lx + t.t * lw, ly);
    o += buf;
  }
  for (const Tick& t : tb) {
    std::snprintf(buf, sizeof buf, "<line class=\"%s\" x1=\"%.2f\" y1=\"%.1f\" x2=\"%.2f\" y2=\"%.1f\"/>\n",
                  t.partner ? "b" : "x", lx + t.t * lw, ly, lx + t.t * lw, ly + 25);
    o += buf;
  }
  std::snprintf(buf, sizeof buf,
                "<text class=\"s\" x=\"%.1f\" y=\"%.1f\">a: %s %s factor %s  b: %s %s factor %s  gap %s world</text>\n</g>\n",
                x + 8, y + 140, patchText(f.a.patch).c_str(), edgeName(f.a.edge), formatFloat(f.a.processedFactor).c_str(),
                patchText(f.b.patch).c_str(), edgeName(f.b.edge), formatFloat(f.b.processedFactor).c_str(),
                fmtWorld(f.gapWorld).c_str());
  o += buf;
}

std::string checkSvg(const vf::Scene& scene, const vf::Report& r, const std::string& title) {
  MapView v;
  v.init(vf::terrainExtent(scene));
  const double H = v.margin * 2 + (v.e.maxZ - v.e.minZ) * v.scale, W = v.margin * 2 + (v.e.maxX - v.e.minX) * v.scale;
  const vf::Finding* worst = nullptr;
  for (const vf::Finding& f : r.findings)
    if (!worst || f.gapWorld > worst->gapWorld) worst = &f;
  const double totalH = H + 60 + (worst ? 170 : 0);
  char buf[512];
  std::string o;
  std::snprintf(buf, sizeof buf,
                "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" "
                "height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\">\n<title>%s</title>\n",
                std::max(W, 780.0), totalH, std::max(W, 780.0), totalH, xmlEscape(title).c_str());
  o += buf;
  o += kSvgStyle;
  o += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svgPatches(o, scene, v);
  o += "<g id=\"findings\">\n";
  for (const vf::Finding& f : r.findings) {
    const bool crack = f.classification == vf::Classification::Crack;
    std::snprintf(buf, sizeof buf, "<line class=\"%s\" x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n",
                  crack ? "cr" : "tj", v.x(f.edgeStart.x), v.y(f.edgeStart.z), v.x(f.edgeEnd.x), v.y(f.edgeEnd.z));
    o += buf;
    if (crack) {
      std::snprintf(buf, sizeof buf, "<circle class=\"mk\" cx=\"%.2f\" cy=\"%.2f\" r=\"2.5\"/>\n", v.x(f.gapVertex.x),
                    v.y(f.gapVertex.z));
      o += buf;
    }
  }
  o += "</g>\n";
  std::snprintf(buf, sizeof buf,
                "<text class=\"t\" x=\"20\" y=\"%.0f\">%lld edges checked: %lld match, %lld T-junctions (orange), "
                "%lld cracks (red, circled)</text>\n",
                H + 25, static_cast<long long>(r.stats.edgesChecked), static_cast<long long>(r.stats.matches),
                static_cast<long long>(r.stats.tJunctions), static_cast<long long>(r.stats.cracks));
  o += buf;
  if (worst) svgInset(o, scene, *worst, 10, H + 45, std::max(W, 780.0) - 20);
  o += "</svg>\n";
  return o;
}

// ---- shared plumbing ---------------------------------------------------------------------------------------------
void writeReport(const std::string& path, const std::string& text) {
  AtomicFile f(path);
  f.buffer() = text;
  f.commit();
}

int verdictStatus(const SceneArgs& a, const vf::Stats& s) {
  if (s.cracks > 0) return kExitFindings;
  if (a.failOnTJunctions && s.tJunctions > 0) return kExitFindings;
  return kExitClean;
}

void addSceneOptions(CLI::App* sub, SceneArgs& a) {
  sub->add_option("scene", a.scene, "Scene file (TOML, docs/verify.md)")->required();
  sub->add_option("--set", a.overrides, "Override a scene key: KEY=VALUE (repeatable), validated like the file")
      ->type_name("KEY=VALUE");
  sub->add_option("--eye", a.eye, "Camera eye X,Y,Z (shorthand for --set camera.eye=[X,Y,Z])");
  sub->add_option("--target", a.target, "Camera target X,Y,Z (shorthand for --set camera.target=[X,Y,Z])");
  sub->add_option("--kernel", a.kernel, "CGAL kernel: epick (exact predicates), epeck (exact gaps too), float (naive, wrong on purpose)")
      ->capture_default_str();
  sub->add_flag("--flush-denormals", a.flushDenormals, "Tessellator flushes denormal factors (as llvmpipe)");
  sub->add_option("--json", a.json, "Write the full report as JSON to FILE ('-': stdout, no text then)");
  sub->add_option("--svg", a.svg, "Write an SVG picture to FILE");
  sub->add_flag("-q,--quiet", a.quiet, "Print nothing but errors; the exit status tells the verdict");
  sub->add_flag("--fail-on-tjunctions", a.failOnTJunctions, "Exit 1 on T-junctions too (default: cracks only)");
}

// Ctrl-C: the first one asks the sweep to stop (reports are still written), the second one kills.
std::atomic<bool> gCancel{false};
extern "C" void onSigint(int) {
  gCancel.store(true);
  std::signal(SIGINT, SIG_DFL);
}

std::string duration(double s) {
  char b[32];
  if (!(s >= 0) || s > 1e7) return "--:--";
  const long t = std::lround(s);
  if (t >= 3600) std::snprintf(b, sizeof b, "%ld:%02ld:%02ld", t / 3600, t / 60 % 60, t % 60);
  else std::snprintf(b, sizeof b, "%ld:%02ld", t / 60, t % 60);
  return b;
}

} // namespace

// ---- check -------------------------------------------------------------------------------------------------------
CLI::App* addCheck(CLI::App& app, CheckArgs& a) {
  CLI::App* sub = app.add_subcommand("check", "Check every shared patch edge of a scene from one camera");
  sub->footer("Examples:\n"
              "  fftess check docs/examples/terrain.toml\n"
              "  fftess check docs/examples/terrain.toml --set lod.adjacency_clamp=integer --json report.json "
              "--svg report.svg\n"
              "Exit status: 0 no cracks, 1 cracks found, 2 bad usage or scene, 3 internal error.");
  addSceneOptions(sub, a);
  sub->add_option("--path-camera", a.pathCamera, "Use camera N of the scene's [[camera_path]] instead of [camera]");
  sub->add_option("--show", a.show, "Finding lines to print (default 20; all are in --json)")->capture_default_str();
  sub->add_flag("--mesh", a.mesh, "Also run the whole-mesh check (full tessellation) and compare the two verdicts");
  return sub;
}

int runCheck(const CheckArgs& a) {
  const vf::Scene scene = load(a);
  vf::Camera cam = scene.camera;
  if (a.pathCamera >= 0) {
    if (static_cast<size_t>(a.pathCamera) >= scene.cameraPath.size())
      throw UsageError("--path-camera " + std::to_string(a.pathCamera) + ": the scene's camera path has " +
                       std::to_string(scene.cameraPath.size()) + " cameras");
    cam = scene.cameraPath[static_cast<size_t>(a.pathCamera)];
  }
  vf::CheckOptions opt = checkOptions(a);
  const vf::Report r = vf::checkScene(scene, cam, opt);
  if (!r.error.empty()) throw UsageError(r.error);
  const bool jsonToStdout = a.json == "-";
  std::string text;
  if (!a.quiet && !jsonToStdout) {
    text += "fftess check " + a.scene + (scene.name.empty() ? "" : " (" + scene.name + ")") + "\n";
    for (const std::string& s : overridesOf(a)) text += "  --set " + s + "\n";
    char buf[200];
    std::snprintf(buf, sizeof buf, "  camera eye (%g, %g, %g) target (%g, %g, %g), %dx%d\n", static_cast<double>(cam.eye.x),
                  static_cast<double>(cam.eye.y), static_cast<double>(cam.eye.z), static_cast<double>(cam.target.x),
                  static_cast<double>(cam.target.y), static_cast<double>(cam.target.z), cam.width, cam.height);
    text += buf;
    text += statsText(r.stats);
    int shown = 0;
    for (const vf::Finding& f : r.findings) {
      if (f.classification == vf::Classification::Match) continue;
      if (shown++ >= a.show) break;
      text += findingLine(f) + "\n";
    }
    const int64_t nonMatch = r.stats.cracks + r.stats.tJunctions;
    if (shown > a.show || nonMatch > a.show)
      text += "  ... " + std::to_string(nonMatch - a.show) + " more findings (--show N, or --json FILE)\n";
  }
  vf::MeshReport mesh;
  if (a.mesh) {
    opt.maxFindings = static_cast<size_t>(-1);
    const vf::Report full = vf::checkScene(scene, cam, opt);
    mesh = vf::checkSceneMesh(scene, cam, opt);
    const bool agree = vf::flaggedPatchEdges(full) == mesh.flagged;
    if (!a.quiet && !jsonToStdout)
      text += "whole-mesh check: " + std::to_string(mesh.triangles) + " triangles, " +
              std::to_string(mesh.innerBorderEdges) + " inner border edges on " + std::to_string(mesh.flagged.size()) +
              " patch edges: " + (agree ? "agrees with the edge check" : "DISAGREES with the edge check") + "\n";
    if (!agree) throw std::runtime_error("whole-mesh check and edge check disagree (a verifier bug)");
  }
  const int status = verdictStatus(a, r.stats);
  if (!a.quiet && !jsonToStdout)
    text += std::string("verdict: ") + (r.stats.cracks > 0 ? "CRACKS" : r.stats.tJunctions > 0 ? "watertight now (T-junctions)" : "watertight") + "\n";
  // Reports first (atomically), then the text: a failure writing a report leaves no partial file.
  if (!a.json.empty()) {
    json j;
    j["version"] = 1;
    j["kind"] = "check";
    j["fftess_version"] = FFTESS_VERSION;
    j["scene"] = sceneJson(a, scene);
    j["camera"] = cameraJson(cam);
    j["stats"] = statsJson(r.stats);
    j["verdict"] = r.stats.cracks > 0 ? "cracks" : "clean";
    j["truncated"] = r.truncated;
    json fs = json::array();
    for (const vf::Finding& f : r.findings) fs.push_back(findingJson(f));
    j["findings"] = fs;
    if (a.mesh)
      j["mesh"] = {{"triangles", mesh.triangles}, {"vertices", mesh.vertices}, {"border_edges", mesh.borderEdges},
                   {"inner_border_edges", mesh.innerBorderEdges}, {"flagged_patch_edges", mesh.flagged.size()}};
    writeReport(a.json, j.dump(2) + "\n");
  }
  if (!a.svg.empty()) writeReport(a.svg, checkSvg(scene, r, "fftess check " + a.scene));
  writeStdout(text);
  return status;
}

// Causes over a sweep: every finding of every camera names a cause (classification + causeOf key). Per cause: the
// findings, the cameras where it appeared, and the first camera where it appeared (lowest camera index; within that
// camera the first finding in layout order, whose explanation is the example). Fed by SweepOptions::onReport, which
// sweep serialises, in whatever order the cameras finish: the result does not depend on that order.
struct CauseInfo {
  std::string detail;     // explanation of the first finding with this cause
  int64_t findings = 0;   // findings with this cause, over all cameras
  size_t cameras = 0;     // cameras with at least one finding with this cause
  size_t first = 0;       // first camera (index) where it appeared
  size_t firstFinding = 0; // index of that finding in the first camera's report
};

struct CauseTally {
  std::map<std::string, CauseInfo> causes;

  void add(size_t camera, const vf::Report& r) {
    std::set<std::string> here;
    for (size_t k = 0; k < r.findings.size(); ++k) {
      const vf::Finding& f = r.findings[k];
      if (f.classification == vf::Classification::Match) continue;
      const Cause cause = causeOf(f);
      const std::string key = std::string(vf::toString(f.classification)) + ": " + cause.key;
      auto [it, added] = causes.try_emplace(key);
      CauseInfo& c = it->second;
      ++c.findings;
      if (here.insert(key).second) ++c.cameras;
      if (added || camera < c.first || (camera == c.first && k < c.firstFinding)) {
        c.first = camera;
        c.firstFinding = k;
        c.detail = cause.detail;
      }
    }
  }

  // Cause keys in the order they first appeared (by first camera, then first finding).
  std::vector<std::string> order() const {
    std::vector<std::string> keys;
    for (const auto& kv : causes) keys.push_back(kv.first);
    std::stable_sort(keys.begin(), keys.end(), [&](const std::string& x, const std::string& y) {
      const CauseInfo &a = causes.at(x), &b = causes.at(y);
      return a.first != b.first ? a.first < b.first : a.firstFinding < b.firstFinding;
    });
    return keys;
  }
};

// ---- sweep -------------------------------------------------------------------------------------------------------
CLI::App* addSweep(CLI::App& app, SweepArgs& a) {
  CLI::App* sub = app.add_subcommand("sweep", "Check a scene from many cameras (a path, an orbit, a flyover, random)");
  sub->footer("Examples:\n"
              "  fftess sweep docs/examples/terrain.toml\n"
              "  fftess sweep docs/examples/terrain.toml --set lod.adjacency_clamp=none --random 500 --seed 3 "
              "--json sweep.json --svg sweep.svg\n"
              "Cameras: the scene's [[camera_path]] (or its [camera]) unless --orbit, --flyover or --random is given.\n"
              "Ctrl-C stops early and still prints the summary and writes the reports (exit 130 if no crack was found).\n"
              "Exit status: 0 no cracks, 1 cracks found, 2 bad usage or scene, 3 internal error.");
  addSceneOptions(sub, a);
  sub->add_option("--orbit", a.orbit, "N cameras on a circle around the terrain, looking at its centre");
  sub->add_option("--flyover", a.flyover, "N cameras on a straight flight across the terrain");
  sub->add_option("--random", a.random, "N cameras at random positions and directions (see --seed)");
  sub->add_option("--seed", a.seed, "Seed for --random")->capture_default_str();
  sub->add_option("-j,--threads", a.threads, "Worker threads (default 0: all cores)")->capture_default_str();
  sub->add_option("--label", a.label, "Name for this run in the summary (default: the scene's name)");
  return sub;
}

// Cameras when the scene has no [[camera_path]] and no generator option is given.
constexpr int kDefaultFlyover = 200;

int runSweep(const SweepArgs& a) {
  const int generators = (a.orbit > 0) + (a.flyover > 0) + (a.random > 0);
  if (generators > 1) throw UsageError("sweep: give only one of --orbit, --flyover, --random");
  if (a.orbit < 0 || a.flyover < 0 || a.random < 0) throw UsageError("sweep: camera counts must be positive");
  if (a.threads < 0) throw UsageError("--threads " + std::to_string(a.threads) + ": must be >= 0");
  const vf::Scene scene = load(a);
  vf::CheckOptions opt = checkOptions(a);
  opt.maxFindings = static_cast<size_t>(-1); // every finding reaches onReport, so the cause counts are complete
  std::vector<vf::Camera> cams;
  std::string how;
  if (a.orbit > 0) cams = vf::orbitCameras(scene, a.orbit), how = "orbit of " + std::to_string(a.orbit);
  else if (a.flyover > 0) cams = vf::flyoverCameras(scene, a.flyover), how = "flyover of " + std::to_string(a.flyover);
  else if (a.random > 0)
    cams = vf::randomCameras(scene, a.random, a.seed), how = std::to_string(a.random) + " random, seed " + std::to_string(a.seed);
  else if (!scene.cameraPath.empty()) cams = vf::pathCameras(scene), how = "the scene's camera path";
  else cams = vf::flyoverCameras(scene, kDefaultFlyover), how = "flyover of " + std::to_string(kDefaultFlyover) + ", the scene has no camera path";
  const bool jsonToStdout = a.json == "-";
  const bool talk = !a.quiet && !jsonToStdout;
  const std::string label = a.label.empty() ? (scene.name.empty() ? a.scene : scene.name) : a.label;

  // Progress on stderr: a bar on a terminal, a plain line every few seconds otherwise, nothing with --quiet.
  const bool tty = ::isatty(2) != 0;
  const auto t0 = std::chrono::steady_clock::now();
  auto last = t0;
  bool barShown = false;
  vf::SweepOptions so;
  so.threads = a.threads;
  so.cancel = &gCancel;
  if (talk) {
    so.progress = [&](size_t done, size_t total) {
      const auto now = std::chrono::steady_clock::now();
      const double el = std::chrono::duration<double>(now - t0).count();
      const double since = std::chrono::duration<double>(now - last).count();
      if (done < total && since < (tty ? 0.1 : 5.0)) return;
      last = now;
      const double rate = el > 0 ? static_cast<double>(done) / el : 0;
      const double eta = rate > 0 ? static_cast<double>(total - done) / rate : -1;
      char buf[200];
      if (tty) {
        const int width = 30, fill = static_cast<int>(width * done / std::max<size_t>(total, 1));
        std::snprintf(buf, sizeof buf, "\r  [%s%s] %zu/%zu cameras  %.1f/s  ETA %s ", std::string(static_cast<size_t>(fill), '#').c_str(),
                      std::string(static_cast<size_t>(width - fill), '.').c_str(), done, total, rate, duration(eta).c_str());
        barShown = true;
      } else {
        std::snprintf(buf, sizeof buf, "  sweep: %zu/%zu cameras (%.0f%%), %.1f/s, ETA %s\n", done, total,
                      100.0 * static_cast<double>(done) / static_cast<double>(std::max<size_t>(total, 1)), rate,
                      duration(eta).c_str());
      }
      std::fputs(buf, stderr);
      std::fflush(stderr);
    };
  }
  CauseTally tally;
  so.onReport = [&tally](size_t camera, const vf::Report& r) { tally.add(camera, r); };
  gCancel.store(false);
  auto previous = std::signal(SIGINT, onSigint);
  if (talk)
    std::fprintf(stderr, "fftess sweep %s: %s, %zu cameras (%s)\n", a.scene.c_str(), label.c_str(), cams.size(), how.c_str());
  const vf::SweepResult res = vf::sweep(scene, cams, opt, so);
  std::signal(SIGINT, previous == SIG_ERR ? SIG_DFL : previous);
  if (barShown) std::fputs("\n", stderr);
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  const std::vector<std::string> order = tally.order();
  const std::map<std::string, CauseInfo>& causes = tally.causes;
  size_t crackCameras = 0, tjCameras = 0;
  for (const vf::CameraResult& c : res.cameras) {
    if (!c.done) continue;
    if (c.stats.cracks > 0) ++crackCameras;
    else if (c.stats.tJunctions > 0) ++tjCameras;
  }
  const int status = res.cancelled && res.total.cracks == 0 ? 130 : verdictStatus(a, res.total);

  std::string text;
  if (talk) {
    char buf[256];
    text += "\n== " + label + ": lod.adjacency_clamp = " + vf::toString(scene.lod.adjacencyClamp) +
            (scene.lod.adjacencyClamp == vf::AdjacencyClamp::Pow2 ? " (the power-of-two workaround on)" : "") + " ==\n";
    for (const std::string& s : overridesOf(a)) text += "  --set " + s + "\n";
    std::snprintf(buf, sizeof buf, "  cameras        %zu of %zu%s (%s, %.1f s, %s threads)\n", res.camerasDone,
                  cams.size(), res.cancelled ? " (interrupted)" : "", how.c_str(), elapsed,
                  a.threads > 0 ? std::to_string(a.threads).c_str() : "all");
    text += buf;
    text += "  adjacency      " + std::string(vf::toString(scene.lod.adjacencyClamp)) + " clamp, " +
            toString(scene.partitioning) + " partitioning\n";
    text += statsText(res.total);
    std::snprintf(buf, sizeof buf, "  cameras with cracks %zu, with T-junctions only %zu\n", crackCameras, tjCameras);
    text += buf;
    if (!order.empty()) {
      text += "  causes (findings of each cause, cameras where it appeared, the first camera where it appeared):\n";
      for (const std::string& k : order) {
        const CauseInfo& c = causes.at(k);
        const vf::Camera& cam = cams[c.first];
        std::snprintf(buf, sizeof buf, "    %-75s %7lld findings on %5zu cameras, first #%zu eye (%.1f, %.1f, %.1f)\n",
                      k.c_str(), static_cast<long long>(c.findings), c.cameras, c.first, static_cast<double>(cam.eye.x),
                      static_cast<double>(cam.eye.y), static_cast<double>(cam.eye.z));
        text += buf;
        text += "      e.g. " + c.detail + "\n";
      }
    }
    text += std::string("verdict: ") +
            (res.total.cracks > 0 ? "CRACKS seen from " + std::to_string(crackCameras) + " of " + std::to_string(res.camerasDone) +
                                        " cameras (worst gap " + fmtWorld(res.total.worstGapWorld) + " world units, " +
                                        fmtWorld(res.total.worstGapPixels) + " px)"
             : res.cancelled ? "no cracks so far (interrupted)"
             : res.total.tJunctions > 0 ? "no cracks (T-junctions only)"
             : "WATERTIGHT from all " + std::to_string(res.camerasDone) + " cameras") +
            "\n";
  }
  if (!a.json.empty()) {
    json j;
    j["version"] = 1;
    j["kind"] = "sweep";
    j["fftess_version"] = FFTESS_VERSION;
    j["scene"] = sceneJson(a, scene);
    j["cameras_source"] = how;
    j["cameras_total"] = cams.size();
    j["cameras_done"] = res.camerasDone;
    j["cancelled"] = res.cancelled;
    j["stats"] = statsJson(res.total);
    j["verdict"] = res.total.cracks > 0 ? "cracks" : "clean";
    json cs = json::array();
    for (const std::string& k : order) {
      const CauseInfo& c = causes.at(k);
      cs.push_back({{"cause", k}, {"findings", c.findings}, {"cameras", c.cameras}, {"first_camera", c.first},
                    {"example", c.detail}});
    }
    j["causes"] = cs;
    json cl = json::array();
    for (const vf::CameraResult& c : res.cameras) {
      json jc;
      jc["index"] = c.cameraIndex;
      jc["eye"] = vec3(cams[c.cameraIndex].eye);
      jc["target"] = vec3(cams[c.cameraIndex].target);
      jc["done"] = c.done;
      jc["stats"] = statsJson(c.stats);
      jc["worst"] = c.hasFinding ? findingJson(c.worst) : json(nullptr);
      cl.push_back(jc);
    }
    j["cameras"] = cl;
    writeReport(a.json, j.dump(2) + "\n");
  }
  if (!a.svg.empty()) {
    MapView v;
    vf::Extent ext = vf::terrainExtent(scene);
    for (const vf::Camera& c : cams) { // cameras off the terrain stay on the map
      ext.minX = std::min(ext.minX, c.eye.x), ext.maxX = std::max(ext.maxX, c.eye.x);
      ext.minZ = std::min(ext.minZ, c.eye.z), ext.maxZ = std::max(ext.maxZ, c.eye.z);
    }
    v.init(ext);
    const double H = v.margin * 2 + (v.e.maxZ - v.e.minZ) * v.scale, W = v.margin * 2 + (v.e.maxX - v.e.minX) * v.scale;
    std::string o;
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" "
                  "height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\">\n<title>%s</title>\n",
                  std::max(W, 780.0), H + 60, std::max(W, 780.0), H + 60, xmlEscape("fftess sweep " + a.scene).c_str());
    o += buf;
    o += kSvgStyle;
    o += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    svgPatches(o, scene, v);
    if (a.random == 0) { // a path: join the cameras in order
      o += "<polyline class=\"path\" points=\"";
      for (const vf::Camera& c : cams) {
        std::snprintf(buf, sizeof buf, "%.2f,%.2f ", v.x(c.eye.x), v.y(c.eye.z));
        o += buf;
      }
      o += "\"/>\n";
    }
    o += "<g id=\"cameras\">\n";
    for (const vf::CameraResult& c : res.cameras) {
      const vf::Camera& cam = cams[c.cameraIndex];
      const char* cls = !c.done ? "p" : c.stats.cracks > 0 ? "bad" : c.stats.tJunctions > 0 ? "warn" : "ok";
      std::snprintf(buf, sizeof buf, "<circle class=\"%s\" cx=\"%.2f\" cy=\"%.2f\" r=\"3\"><title>camera %zu: %lld cracks</title></circle>\n",
                    cls, v.x(cam.eye.x), v.y(cam.eye.z), c.cameraIndex, static_cast<long long>(c.stats.cracks));
      o += buf;
      if (c.hasFinding && c.stats.cracks > 0) {
        std::snprintf(buf, sizeof buf, "<circle class=\"mk\" cx=\"%.2f\" cy=\"%.2f\" r=\"4\"/>\n", v.x(c.worst.gapVertex.x),
                      v.y(c.worst.gapVertex.z));
        o += buf;
      }
    }
    o += "</g>\n";
    int line = 0;
    for (const std::string& k : order) {
      const vf::Camera& cam = cams[causes.at(k).first];
      std::snprintf(buf, sizeof buf, "<text class=\"s\" x=\"%.2f\" y=\"%.2f\">%d</text>\n", v.x(cam.eye.x) + 5,
                    v.y(cam.eye.z) - 5, ++line);
      o += buf;
    }
    std::snprintf(buf, sizeof buf,
                  "<text class=\"t\" x=\"20\" y=\"%.0f\">%zu cameras from above. Dots: green clean, orange T-junctions, "
                  "red cracks.</text>\n<text class=\"t\" x=\"20\" y=\"%.0f\">Circles: worst crack of each camera. "
                  "Numbers: first camera of each cause (in summary order).</text>\n",
                  H + 20, res.camerasDone, H + 40);
    o += buf;
    o += "</svg>\n";
    writeReport(a.svg, o);
  }
  writeStdout(text);
  return status;
}

} // namespace fftess::cli
