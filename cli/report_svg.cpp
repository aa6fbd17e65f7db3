// SVG pictures of check and sweep (report_svg.h).
#include "report_svg.h"
#include "causes.h"
#include "common.h"
#include "svg_text.h"

#include <algorithm>
#include <cstdio>
#include <map>

namespace fftess::cli {
namespace {

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
    ".x{stroke:#d01010;stroke-width:2}.hole{fill:#d01010;fill-opacity:0.45;stroke:#d01010;stroke-width:1}"
    ".off{stroke:#999;stroke-width:2;stroke-dasharray:4 3}.mko{fill:none;stroke:#999;stroke-width:0.8}</style>\n";

// The layout from above, from verify's real patch geometry (one terrain build for all patches): every patch outlined
// thinly, and each tile (ring, tile) of a tile-ring layout outlined around its patches. Very large layouts (more
// than kSvgMaxPatches patches) are drawn as their extent only.
constexpr size_t kSvgMaxPatches = 200000;

void svgPatches(std::string& o, const vf::Terrain& terrain, const MapView& v) {
  char buf[256];
  o += "<g id=\"layout\">\n";
  const std::vector<vf::PatchGeometry>& geo = terrain.patches();
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
    const glm::vec3* c = g.corners;
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
// gap: the gap that counts (the on-screen one, or with --offscreen the farthest vertex's).
// Returns the inset's bottom: its height grows with its wrapped text lines.
double svgInset(std::string& o, const vf::Scene& scene, const vf::Finding& f, double gap, double x, double y, double w) {
  char buf[320];
  std::string body;
  const double textW = w - 16;
  svgTextLines(body, "t", std::string("worst ") + vf::toString(f.classification) +
                              ", zoomed: the shared edge, side a above, side b below", 13, false, x + 8, y + 18, textW, 17);
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
  body += buf;
  for (const Tick& t : ta) {
    std::snprintf(buf, sizeof buf, "<line class=\"%s\" x1=\"%.2f\" y1=\"%.1f\" x2=\"%.2f\" y2=\"%.1f\"/>\n",
                  t.partner ? "a" : "x", lx + t.t * lw, ly - 25, lx + t.t * lw, ly);
    body += buf;
  }
  for (const Tick& t : tb) {
    std::snprintf(buf, sizeof buf, "<line class=\"%s\" x1=\"%.2f\" y1=\"%.1f\" x2=\"%.2f\" y2=\"%.1f\"/>\n",
                  t.partner ? "b" : "x", lx + t.t * lw, ly, lx + t.t * lw, ly + 25);
    body += buf;
  }
  // Why and how to fix it, from the finding's records (the LOD's per side and the tessellator's), as the text report
  // says it.
  const Cause cause = findingCause(f);
  double ty = svgTextLines(body, "s", "why: " + cause.key, 11, true, x + 8, y + 124, textW, 14);
  ty = svgTextLines(body, "s", "fix: " + cause.fix, 11, true, x + 8, ty, textW, 14);
  ty = svgTextLines(body, "s", "a: " + patchText(f.a.patch) + " " + edgeName(f.a.edge) + " factor " +
                                   formatFloat(f.a.processedFactor) + "  b: " + patchText(f.b.patch) + " " +
                                   edgeName(f.b.edge) + " factor " + formatFloat(f.b.processedFactor) + "  gap " +
                                   fmtWorld(gap) + " world", 11, true, x + 8, ty, textW, 14);
  const double bottom = ty - 14 + 10;
  std::snprintf(buf, sizeof buf, "<g id=\"inset\"><rect class=\"ins\" x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\"/>\n",
                x, y, w, bottom - y);
  o += buf + body + "</g>\n";
  return bottom;
}

// A hole: the patch filled.
void svgQuad(std::string& o, const MapView& v, const glm::vec3* c, const std::string& title) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "<path class=\"hole\" d=\"M%.2f %.2fL%.2f %.2fL%.2f %.2fL%.2f %.2fZ\">", v.x(c[0].x),
                v.y(c[0].z), v.x(c[1].x), v.y(c[1].z), v.x(c[3].x), v.y(c[3].z), v.x(c[2].x), v.y(c[2].z));
  o += buf + std::string("<title>") + xmlEscape(title) + "</title></path>\n";
}
void svgHole(std::string& o, const vf::Terrain& terrain, const MapView& v, const vf::Hole& h, const std::string& title) {
  if (h.patch.index < 0 || h.patch.index >= terrain.patchCount()) return;
  svgQuad(o, v, terrain.patches()[static_cast<size_t>(h.patch.index)].corners, title);
}

} // namespace

std::string checkSvg(const vf::Terrain& terrain, const vf::Report& r, const std::string& title, bool countOffScreen) {
  MapView v;
  v.init(terrain.extent());
  const double H = v.margin * 2 + (v.e.maxZ - v.e.minZ) * v.scale, W = v.margin * 2 + (v.e.maxX - v.e.minX) * v.scale;
  const double pageW = std::max(W, 780.0);
  // The worst finding that counts: on screen by its on-screen gap, or (--offscreen) any by its gap.
  const vf::Finding* worst = nullptr;
  for (const vf::Finding& f : r.findings) {
    if (!countOffScreen && !f.onScreen) continue;
    if (!worst || (countOffScreen ? f.gapWorld > worst->gapWorld : f.onScreenGapWorld > worst->onScreenGapWorld)) worst = &f;
  }
  char buf[512];
  std::string o;
  o += kSvgStyle;
  o += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svgPatches(o, terrain, v);
  o += "<g id=\"findings\">\n";
  for (const vf::Finding& f : r.findings) {
    const bool crack = f.classification == vf::Classification::Crack;
    std::snprintf(buf, sizeof buf, "<line class=\"%s\" x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n",
                  !f.onScreen ? "off" : crack ? "cr" : "tj", v.x(f.edgeStart.x), v.y(f.edgeStart.z), v.x(f.edgeEnd.x),
                  v.y(f.edgeEnd.z));
    o += buf;
    if (crack) {
      const glm::vec3& at = f.onScreen ? f.onScreenGapVertex : f.gapVertex;
      std::snprintf(buf, sizeof buf, "<circle class=\"%s\" cx=\"%.2f\" cy=\"%.2f\" r=\"2.5\"/>\n",
                    f.onScreen ? "mk" : "mko", v.x(at.x), v.y(at.z));
      o += buf;
    }
  }
  o += "</g>\n<g id=\"holes\">\n";
  for (const vf::Hole& h : r.holes) svgHole(o, terrain, v, h, "hole: " + holeCause(h).detail);
  o += "</g>\n<g id=\"undecided\">\n"; // patches not drawn, visibility undecided: filled like holes
  for (const vf::Hole& h : r.undecided) svgHole(o, terrain, v, h, "undecided: " + holeCause(h).detail);
  o += "</g>\n";
  const int64_t off = r.stats.cracksOffScreen + r.stats.tJunctionsOffScreen;
  std::snprintf(buf, sizeof buf,
                "%lld edges checked: %lld match, %lld T-junctions (orange), %lld cracks (red, circled), %lld holes "
                "(filled) on screen; %lld off screen (grey, dashed: %s)",
                static_cast<long long>(r.stats.edgesChecked), static_cast<long long>(r.stats.matches),
                static_cast<long long>(r.stats.tJunctionsOnScreen()), static_cast<long long>(r.stats.cracksOnScreen()),
                static_cast<long long>(r.stats.holes), static_cast<long long>(off),
                countOffScreen ? "counted, --offscreen" : "not counted");
  double bottom = svgTextLines(o, "t", buf, 13, false, 20, H + 25, pageW - 40, 17) - 17 + 10;
  // Every cause the picture shows (holes, undecided patches, the findings that count), with its fix.
  for (const Cause& c : reportCauses(r, countOffScreen)) {
    bottom = svgTextLines(o, "s", "cause: " + c.key, 11, true, 20, bottom + 14, pageW - 40, 14) - 14;
    bottom = svgTextLines(o, "s", "  fix: " + c.fix, 11, true, 20, bottom + 14, pageW - 40, 14) - 14;
  }
  if (worst)
    bottom = svgInset(o, terrain.scene(), *worst,
                      countOffScreen || !worst->onScreen ? worst->gapWorld : worst->onScreenGapWorld, 10, bottom + 10,
                      pageW - 20);
  return svgHead(pageW, bottom + 10, title) + o + "</svg>\n";
}

SvgCamera svgCamera(size_t globalIndex, const vf::Camera& cam, const vf::CameraResult& c, bool countOffScreen) {
  SvgCamera d;
  d.index = globalIndex;
  d.x = cam.eye.x, d.z = cam.eye.z;
  d.cracks = countOffScreen ? c.stats.cracks : c.stats.cracksOnScreen();
  const int64_t tJunctions = countOffScreen ? c.stats.tJunctions : c.stats.tJunctionsOnScreen();
  d.verdict = d.cracks > 0 || c.stats.holes > 0 || c.stats.undecided > 0 ? 'b' : tJunctions > 0 ? 'w' : 'o';
  d.crackMark = c.hasFinding && d.cracks > 0; // CameraResult::worst is a finding that counts
  const glm::vec3& at = countOffScreen ? c.worst.gapVertex : c.worst.onScreenGapVertex;
  if (d.crackMark) d.gx = at.x, d.gz = at.z;
  return d;
}

std::string sweepSvg(const vf::Terrain& terrain, const std::vector<vf::Camera>& cams, const std::vector<SvgCamera>& dots,
                     const std::vector<SvgHole>& holes, const std::vector<size_t>& firstCameras, bool randomOrder,
                     const std::string& title, bool countOffScreen) {
  MapView v;
  vf::Extent ext = terrain.extent();
  for (const vf::Camera& c : cams) { // cameras off the terrain stay on the map
    ext.minX = std::min(ext.minX, c.eye.x), ext.maxX = std::max(ext.maxX, c.eye.x);
    ext.minZ = std::min(ext.minZ, c.eye.z), ext.maxZ = std::max(ext.maxZ, c.eye.z);
  }
  v.init(ext);
  const double H = v.margin * 2 + (v.e.maxZ - v.e.minZ) * v.scale, W = v.margin * 2 + (v.e.maxX - v.e.minX) * v.scale;
  const double pageW = std::max(W, 780.0);
  std::string o;
  char buf[512];
  o += kSvgStyle;
  o += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svgPatches(o, terrain, v);
  if (!randomOrder) { // a path: join the cameras in order
    o += "<polyline class=\"path\" points=\"";
    for (const vf::Camera& c : cams) {
      std::snprintf(buf, sizeof buf, "%.2f,%.2f ", v.x(c.eye.x), v.y(c.eye.z));
      o += buf;
    }
    o += "\"/>\n";
  }
  o += "<g id=\"holes\">\n"; // the first hole of each camera
  for (const SvgHole& h : holes) {
    if (h.hasCorners) { // a camera-dependent layout: the patch of that camera's layout
      svgQuad(o, v, h.corners, h.title);
      continue;
    }
    vf::Hole hole;
    hole.patch.index = h.patch;
    svgHole(o, terrain, v, hole, h.title);
  }
  o += "</g>\n<g id=\"cameras\">\n";
  for (const SvgCamera& c : dots) {
    const char* cls = c.verdict == 'b' ? "bad" : c.verdict == 'w' ? "warn" : "ok";
    std::snprintf(buf, sizeof buf, "<circle class=\"%s\" cx=\"%.2f\" cy=\"%.2f\" r=\"3\"><title>camera %zu: %lld cracks</title></circle>\n",
                  cls, v.x(c.x), v.y(c.z), c.index, static_cast<long long>(c.cracks));
    o += buf;
    if (c.crackMark) {
      std::snprintf(buf, sizeof buf, "<circle class=\"mk\" cx=\"%.2f\" cy=\"%.2f\" r=\"4\"/>\n", v.x(c.gx), v.y(c.gz));
      o += buf;
    }
  }
  o += "</g>\n";
  int line = 0;
  for (size_t first : firstCameras) {
    const vf::Camera& cam = cams[first];
    const std::string number = std::to_string(++line);
    // Right of the dot, or left of it where the page ends; never above the page.
    double nx = v.x(cam.eye.x) + 5;
    if (nx + svgTextWidth(number, 11, true) > pageW) nx = v.x(cam.eye.x) - 5 - svgTextWidth(number, 11, true);
    std::snprintf(buf, sizeof buf, "<text class=\"s\" x=\"%.2f\" y=\"%.2f\">%s</text>\n", std::max(0.0, nx),
                  std::max(12.0, v.y(cam.eye.z) - 5), number.c_str());
    o += buf;
  }
  std::snprintf(buf, sizeof buf,
                "%zu cameras from above. Dots: green clean, orange T-junctions, red cracks, holes or undecided patches "
                "(%s).", dots.size(), countOffScreen ? "off screen too, --offscreen" : "on screen");
  double y = svgTextLines(o, "t", buf, 13, false, 20, H + 20, pageW - 40, 17);
  y = svgTextLines(o, "t", "Circles: worst crack of each camera; filled patches: each camera's first hole. Numbers: "
                           "first camera of each cause (in summary order).", 13, false, 20, y, pageW - 40, 17);
  return svgHead(pageW, y - 17 + 10, title) + o + "</svg>\n";
}

} // namespace fftess::cli
