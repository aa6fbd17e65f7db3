// The camera's picture of a check (report_view.h): patch outlines, holes and on-screen findings projected through the
// check's own camera, clipped in homogeneous clip space, with a legend that fits the page.
#include "report_view.h"
#include "causes.h"
#include "common.h"
#include "svg_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

namespace fftess::cli {
namespace viewsvg { // a named namespace: the cli compiles as unity batches

constexpr double kMargin = 10;
constexpr int kLevelColours = 8;
const char* const kLevelColour[kLevelColours] = {"#1f77b4", "#2ca02c", "#9467bd", "#8c564b",
                                                 "#17becf", "#7f7f7f", "#bcbd22", "#e377c2"};

// World -> clip (projection * view of verify::viewCamera, in double) -> page.
struct Projector {
  double m[4][4] = {};
  bool zeroToOne = false; // depth in [0, w] (the D3D convention): the near plane is z >= 0, else z >= -w
  double ox = kMargin, oy = kMargin, w = 0, h = 0; // the image's rectangle on the page

  explicit Projector(const lod::Camera& c) : zeroToOne(c.depthZeroToOne) {
    for (int r = 0; r < 4; ++r)
      for (int col = 0; col < 4; ++col) {
        double sum = 0;
        for (int k = 0; k < 4; ++k) sum += double(c.projection[k][r]) * double(c.view[col][k]);
        m[r][col] = sum;
      }
  }
  glm::dvec4 clip(const glm::vec3& p) const {
    double out[4];
    for (int r = 0; r < 4; ++r) out[r] = m[r][0] * p.x + m[r][1] * p.y + m[r][2] * p.z + m[r][3];
    return {out[0], out[1], out[2], out[3]};
  }
  // Plane k of the frustum at clip point c: >= 0 inside (left, right, bottom, top, near, far).
  double plane(const glm::dvec4& c, int k) const {
    switch (k) {
    case 0: return c.w + c.x;
    case 1: return c.w - c.x;
    case 2: return c.w + c.y;
    case 3: return c.w - c.y;
    case 4: return zeroToOne ? c.z : c.w + c.z;
    default: return c.w - c.z;
    }
  }
  // The part [t0, t1] of the segment a + t (b - a) inside all six planes; false when none is.
  bool clipSegment(const glm::dvec4& a, const glm::dvec4& b, double& t0, double& t1) const {
    t0 = 0, t1 = 1;
    for (int k = 0; k < 6; ++k) {
      const double da = plane(a, k), db = plane(b, k);
      if (da < 0 && db < 0) return false;
      if (da < 0) t0 = std::max(t0, da / (da - db));
      else if (db < 0) t1 = std::min(t1, da / (da - db));
      if (t0 > t1) return false;
    }
    return true;
  }
  glm::dvec2 page(const glm::dvec4& c) const {
    return {ox + (c.x / c.w * 0.5 + 0.5) * w, oy + (0.5 - c.y / c.w * 0.5) * h};
  }
  bool inImage(const glm::dvec2& p) const { return p.x >= ox && p.x <= ox + w && p.y >= oy && p.y <= oy + h; }
};

std::string pt(char op, const glm::dvec2& p) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%c%.1f %.1f", op, p.x, p.y);
  return buf;
}

// The patch's border on the displaced surface: Veq0 (u 0 -> 1), Ueq1 (v 0 -> 1), Veq1 (u 1 -> 0), Ueq0 (v 1 -> 0),
// kViewEdgeSegments segments each.
std::vector<glm::vec3> outline(const vf::Terrain& layout, int patch) {
  std::vector<glm::vec3> pts;
  const float n = static_cast<float>(kViewEdgeSegments);
  for (int e = 0; e < 4; ++e)
    for (int k = 0; k < kViewEdgeSegments; ++k) {
      const float t = static_cast<float>(k) / n, r = 1.0f - t;
      const float u = e == 0 ? t : e == 1 ? 1.0f : e == 2 ? r : 0.0f;
      const float v = e == 0 ? 0.0f : e == 1 ? t : e == 2 ? 1.0f : r;
      pts.push_back(vf::domainPosition(layout, patch, u, v));
    }
  return pts;
}

// The closed outline's parts in view as path data ("" when none is).
std::string outlinePath(const Projector& P, const std::vector<glm::vec3>& pts) {
  std::string d;
  bool open = false; // the previous segment ended in view at its own end
  for (size_t j = 0; j < pts.size(); ++j) {
    const glm::dvec4 a = P.clip(pts[j]), b = P.clip(pts[(j + 1) % pts.size()]);
    double t0, t1;
    if (!P.clipSegment(a, b, t0, t1)) {
      open = false;
      continue;
    }
    if (!(open && t0 == 0)) d += pt('M', P.page(a + t0 * (b - a)));
    d += pt('L', P.page(a + t1 * (b - a)));
    open = t1 == 1;
  }
  return d;
}

// The closed outline clipped as a polygon (Sutherland-Hodgman against the six planes in clip space) as path data.
std::string filledPath(const Projector& P, const std::vector<glm::vec3>& pts) {
  std::vector<glm::dvec4> poly;
  for (const glm::vec3& p : pts) poly.push_back(P.clip(p));
  for (int k = 0; k < 6 && !poly.empty(); ++k) {
    std::vector<glm::dvec4> next;
    for (size_t j = 0; j < poly.size(); ++j) {
      const glm::dvec4 &a = poly[j], &b = poly[(j + 1) % poly.size()];
      const double da = P.plane(a, k), db = P.plane(b, k);
      if (da >= 0) next.push_back(a);
      if ((da >= 0) != (db >= 0)) next.push_back(a + (da / (da - db)) * (b - a));
    }
    poly.swap(next);
  }
  std::string d;
  for (size_t j = 0; j < poly.size(); ++j) d += pt(j ? 'L' : 'M', P.page(poly[j]));
  return d.empty() ? d : d + "Z";
}

// Where a mark goes: the first of the candidates in front of the eye, held inside the image.
glm::dvec2 markAt(const Projector& P, const std::vector<glm::vec3>& candidates) {
  glm::dvec2 at(P.ox + P.w / 2, P.oy + P.h / 2);
  for (const glm::vec3& c : candidates) {
    const glm::dvec4 q = P.clip(c);
    if (q.w > 0) {
      at = P.page(q);
      break;
    }
  }
  return {std::clamp(at.x, P.ox, P.ox + P.w), std::clamp(at.y, P.oy, P.oy + P.h)};
}

// A finding on screen: its crack's on-screen gap vertex, else a mismatching vertex of either side, else the shared
// edge's middle.
glm::dvec2 markAt(const Projector& P, const vf::Finding& f) {
  std::vector<glm::vec3> candidates;
  if (f.classification == vf::Classification::Crack) candidates.push_back(f.onScreenGapVertex);
  if (f.a.firstMismatch >= 0) candidates.push_back(f.a.mismatchWorld);
  if (f.b.firstMismatch >= 0) candidates.push_back(f.b.mismatchWorld);
  candidates.push_back((f.edgeStart + f.edgeEnd) * 0.5f);
  return markAt(P, candidates);
}

// A patch not drawn: where it was seen (Visible), else the middle of the sub-rectangle where the decision stopped.
glm::dvec2 markAt(const Projector& P, const vf::Terrain& layout, const vf::Hole& h) {
  if (h.visibility == vf::Visibility::Visible) return markAt(P, std::vector<glm::vec3>{h.visiblePoint});
  const float half = h.undecidedSide * 0.5f;
  return markAt(P, {vf::domainPosition(layout, h.patch.index, h.domainPoint.u + half, h.domainPoint.v + half)});
}

// A mark's label: right of it, or left of it where the page ends.
void label(std::string& body, const glm::dvec2& at, const std::string& text, double pageWidth, double bottom) {
  char buf[96];
  const double lw = svgTextWidth(text, 10, false);
  const double lx = at.x + 7 + lw <= pageWidth ? at.x + 7 : at.x - 7 - lw;
  std::snprintf(buf, sizeof buf, "<text class=\"vlb\" x=\"%.1f\" y=\"%.1f\">", std::max(0.0, lx),
                std::clamp(at.y - 6, 10.0, bottom));
  body += buf + xmlEscape(text) + "</text>\n";
}

std::string pixelsText(double px) {
  char buf[48];
  std::snprintf(buf, sizeof buf, px >= 100 ? "%.0f px" : "%.2g px", px);
  return buf;
}

struct Page {
  explicit Page(const lod::Camera& camera) : P(camera) {}
  Projector P;
  double width = 0; // the page
  std::string body;
  std::map<int, int> levels;                       // level -> patches drawn in view
  size_t inView = 0;                               // patches drawn in view, all levels
};

void drawPatches(Page& pg, const vf::Terrain& layout, const vf::Report& r) {
  pg.body += "<g id=\"patches\">\n";
  const std::vector<vf::PatchGeometry>& geo = layout.patches();
  for (size_t i = 0; i < geo.size() && i < r.drawn.size(); ++i) {
    if (!r.drawn[i]) continue;
    const std::string d = outlinePath(pg.P, outline(layout, static_cast<int>(i)));
    if (d.empty()) continue;
    const int level = geo[i].ref.level;
    ++pg.levels[level];
    if (++pg.inView > kViewMaxOutlines) continue; // counted, not outlined
    pg.body += "<path class=\"lv" + std::to_string(((level % kLevelColours) + kLevelColours) % kLevelColours) +
               "\" d=\"" + d + "\"/>\n";
  }
  pg.body += "</g>\n";
}

void drawUndrawn(Page& pg, const vf::Terrain& layout, const std::vector<vf::Hole>& holes, const char* id, const char* cls) {
  pg.body += std::string("<g id=\"") + id + "\">\n";
  for (const vf::Hole& h : holes) {
    if (h.patch.index < 0 || h.patch.index >= layout.patchCount()) continue;
    const std::string title = "<title>" + xmlEscape(holeLine(h)) + "</title>";
    const std::string d = filledPath(pg.P, outline(layout, h.patch.index));
    if (!d.empty()) pg.body += std::string("<path class=\"") + cls + "\" d=\"" + d + "\">" + title + "</path>\n";
    // Marked too: a patch seen edge on fills no area.
    const glm::dvec2 at = markAt(pg.P, layout, h);
    char buf[128];
    std::snprintf(buf, sizeof buf, "<circle class=\"%s\" cx=\"%.1f\" cy=\"%.1f\" r=\"5\">", cls, at.x, at.y);
    pg.body += buf + title + "</circle>\n";
    label(pg.body, at, h.visibility == vf::Visibility::Undecided ? "undecided" : "hole", pg.width, pg.P.oy + pg.P.h);
  }
  pg.body += "</g>\n";
}

void drawFindings(Page& pg, const vf::Report& r) {
  pg.body += "<g id=\"findings\">\n";
  char buf[128];
  for (const vf::Finding& f : r.findings) {
    if (f.classification == vf::Classification::Match || !f.onScreen) continue;
    const bool crack = f.classification == vf::Classification::Crack;
    const glm::dvec2 at = markAt(pg.P, f);
    const std::string text = crack ? pixelsText(f.onScreenGapPixels) : "T-junction";
    std::snprintf(buf, sizeof buf, "<circle class=\"%s\" cx=\"%.1f\" cy=\"%.1f\" r=\"5\"><title>", crack ? "vmk" : "vmt",
                  at.x, at.y);
    pg.body += buf + xmlEscape(findingLine(f)) + "</title></circle>\n";
    label(pg.body, at, text, pg.width, pg.P.oy + pg.P.h);
  }
  pg.body += "</g>\n";
}

// The ruler: `n` camera pixels (1000, 100, 10 or 1: the largest that is at most half the viewport's width).
double drawRuler(Page& pg, const vf::Camera& cam, double scale, double y) {
  int n = 1000;
  while (n > 1 && n * 2 > cam.width) n /= 10;
  const double len = n * scale, x = 20;
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "<g id=\"ruler\"><path class=\"vrl\" d=\"M%.1f %.1fL%.1f %.1fM%.1f %.1fL%.1f %.1fM%.1f %.1fL%.1f %.1f\"/>\n",
                x, y, x + len, y, x, y - 5, x, y + 5, x + len, y - 5, x + len, y + 5);
  pg.body += buf;
  const std::string label = std::to_string(n) + " px of the camera's " + std::to_string(cam.width) + " x " +
                            std::to_string(cam.height) + " viewport";
  const double lx = x + len + 10;
  const bool beside = lx + svgTextWidth(label, 13, false) <= pg.width - 20; // else below the ruler
  const double after = svgTextLines(pg.body, "t", label, 13, false, beside ? lx : x, beside ? y + 5 : y + 22,
                                    pg.width - 40, 17);
  pg.body += "</g>\n";
  return after;
}

double legend(Page& pg, const vf::Camera& cam, const vf::Report& r, bool countOffScreen, double scale) {
  const double textW = pg.width - 40;
  char buf[512];
  std::snprintf(buf, sizeof buf, "What the camera sees: eye (%g, %g, %g), target (%g, %g, %g), fov_y %g, %d x %d px (drawn at %.3g%%)",
                double(cam.eye.x), double(cam.eye.y), double(cam.eye.z), double(cam.target.x), double(cam.target.y),
                double(cam.target.z), double(cam.fovY), cam.width, cam.height, scale * 100);
  double y = svgTextLines(pg.body, "t", buf, 13, false, 20, pg.P.oy + pg.P.h + 24, textW, 17);
  for (const auto& [level, count] : pg.levels) {
    std::snprintf(buf, sizeof buf, "<rect class=\"lv%d\" x=\"20\" y=\"%.1f\" width=\"16\" height=\"10\" style=\"fill-opacity:0.3\"/>\n",
                  ((level % kLevelColours) + kLevelColours) % kLevelColours, y - 10);
    pg.body += buf;
    std::snprintf(buf, sizeof buf, "size level %d (patches 2^%d times the smallest): %d drawn in view", level, level, count);
    y = svgTextLines(pg.body, "t", buf, 13, false, 44, y, textW - 24, 17);
  }
  if (pg.inView > kViewMaxOutlines)
    y = svgTextLines(pg.body, "t", "the first " + std::to_string(kViewMaxOutlines) + " of the " +
                                       std::to_string(pg.inView) + " patches in view (layout order) are outlined",
                     13, false, 20, y, textW, 17);
  const int64_t off = r.stats.cracksOffScreen + r.stats.tJunctionsOffScreen;
  std::snprintf(buf, sizeof buf,
                "%lld cracks on screen (red circles, labelled with the gap on screen in pixels), %lld T-junctions on "
                "screen (orange circles); %lld holes (red, filled and circled), %lld undecided (orange, filled and circled); %lld findings off "
                "screen, not drawn (%s)",
                static_cast<long long>(r.stats.cracksOnScreen()), static_cast<long long>(r.stats.tJunctionsOnScreen()),
                static_cast<long long>(r.stats.holes), static_cast<long long>(r.stats.undecided),
                static_cast<long long>(off), countOffScreen ? "counted: --offscreen" : "not counted");
  y = svgTextLines(pg.body, "t", buf, 13, false, 20, y, textW, 17);
  for (const Cause& c : reportCauses(r, false)) { // what the picture shows: holes, undecided, findings on screen
    y = svgTextLines(pg.body, "s", "cause: " + c.key, 11, true, 20, y + 4, textW, 14);
    y = svgTextLines(pg.body, "s", "  fix: " + c.fix, 11, true, 20, y, textW, 14);
  }
  return drawRuler(pg, cam, scale, y + 10);
}

const char* const kViewStyle =
    "<style>.t{font:13px sans-serif}.s{font:11px monospace}.vlb{font:10px sans-serif;fill:#a00000}"
    ".lv0,.lv1,.lv2,.lv3,.lv4,.lv5,.lv6,.lv7{fill:none;stroke-width:0.6}"
    ".lv0{stroke:#1f77b4}.lv1{stroke:#2ca02c}.lv2{stroke:#9467bd}.lv3{stroke:#8c564b}.lv4{stroke:#17becf}"
    ".lv5{stroke:#7f7f7f}.lv6{stroke:#bcbd22}.lv7{stroke:#e377c2}"
    "rect.lv0{fill:#1f77b4}rect.lv1{fill:#2ca02c}rect.lv2{fill:#9467bd}rect.lv3{fill:#8c564b}rect.lv4{fill:#17becf}"
    "rect.lv5{fill:#7f7f7f}rect.lv6{fill:#bcbd22}rect.lv7{fill:#e377c2}"
    ".vhole{fill:#d01010;fill-opacity:0.45;stroke:#d01010;stroke-width:1}"
    ".vund{fill:#e08a00;fill-opacity:0.45;stroke:#e08a00;stroke-width:1}"
    "circle.vhole,circle.vund{fill:none;stroke-width:2}.vmk{fill:none;stroke:#d01010;stroke-width:1.5}.vmt{fill:none;stroke:#e08a00;stroke-width:1.5}"
    ".vimg{fill:#fafafa;stroke:#222;stroke-width:1}.vrl{stroke:#222;stroke-width:1.5;fill:none}</style>\n";

} // namespace viewsvg

std::string viewSvg(const vf::Terrain& layout, const vf::Camera& camera, const vf::Report& r, const std::string& title,
                    bool countOffScreen) {
  using namespace viewsvg;
  Page pg(vf::viewCamera(camera));
  const double scale = std::min(kViewWidth / camera.width, kViewWidth / camera.height);
  pg.P.w = camera.width * scale, pg.P.h = camera.height * scale;
  pg.width = std::max(pg.P.w, 800.0) + 2 * kMargin;
  char buf[256];
  std::snprintf(buf, sizeof buf, "<rect class=\"vimg\" x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\"/>\n", pg.P.ox,
                pg.P.oy, pg.P.w, pg.P.h);
  pg.body += buf;
  drawPatches(pg, layout, r);
  drawUndrawn(pg, layout, r.holes, "holes", "vhole");
  drawUndrawn(pg, layout, r.undecided, "undecided", "vund");
  drawFindings(pg, r);
  const double bottom = legend(pg, camera, r, countOffScreen, scale);
  return svgHead(pg.width, bottom + 6, title) + kViewStyle + "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n" +
         pg.body + "</svg>\n";
}

} // namespace fftess::cli
