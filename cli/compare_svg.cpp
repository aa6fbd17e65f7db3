// The --svg picture of compare and driver-check (compare_svg.h).
#include "compare_svg.h"

#include "svg_text.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <iterator>

namespace fftess::cli {
namespace {

constexpr double kPanelW = 300, kDomain = 240, kPad = 30, kHeading = 52, kPanelH = kHeading + kDomain + 2 * kPad;
constexpr int kColumns = 3;
constexpr double kWidth = kColumns * kPanelW;

const char* kStyle =
    "<style>.t{font:14px sans-serif}.s{font:11px sans-serif}.d{fill:#fafafa;stroke:#333;stroke-width:1}"
    ".r{fill:none;stroke:#888;stroke-width:0.7}.c{fill:none;stroke:#1f5fbf;stroke-width:0.7;stroke-dasharray:3 2}"
    ".or{fill:#d62728;fill-opacity:0.35;stroke:#d62728;stroke-width:1.4}"
    ".oc{fill:none;stroke:#2ca02c;stroke-width:2;stroke-dasharray:5 2}"
    ".rp{fill:#888}.cp{fill:#1f5fbf}.mp{fill:none;stroke:#d62728;stroke-width:1.5}.xp{stroke:#2ca02c;stroke-width:1.8}"
    "</style>\n";

// Domain (u, v) to the page: v up, u to the right; values outside the domain clamped to half a domain around it.
struct Frame {
  double x0, y0;
  double x(float u) const { return x0 + std::clamp(double(u), -0.5, 1.5) * kDomain; }
  double y(float v) const { return y0 + (1.0 - std::clamp(double(v), -0.5, 1.5)) * kDomain; }
};

bool finite(CapturedVertex v) { return std::isfinite(floatOf(v.u)) && std::isfinite(floatOf(v.v)); }

// One path of the primitives whose flag is 'want' (flags empty: all), each closed (a segment: one line).
void primitivesPath(std::string& o, const char* cls, const std::vector<CapturedVertex>& v, int arity,
                    const std::vector<char>& flags, const Frame& f) {
  std::string d;
  char buf[64];
  for (size_t i = 0, p = 0; i + size_t(arity) <= v.size(); i += size_t(arity), ++p) {
    if (!flags.empty() && !flags[p]) continue;
    if (!std::all_of(v.begin() + long(i), v.begin() + long(i) + arity, finite)) continue;
    for (int k = 0; k < arity; ++k) {
      std::snprintf(buf, sizeof buf, "%c%.2f %.2f", k ? 'L' : 'M', f.x(floatOf(v[i + size_t(k)].u)),
                    f.y(floatOf(v[i + size_t(k)].v)));
      d += buf;
    }
    if (arity == 3) d += "Z";
  }
  if (!d.empty()) o += std::string("<path class=\"") + cls + "\" d=\"" + d + "\"/>\n";
}

void pointMarks(std::string& o, const char* cls, const std::vector<CapturedVertex>& pts, const Frame& f, bool cross) {
  char buf[160];
  for (CapturedVertex p : pts) {
    if (!finite(p)) continue;
    const double x = f.x(floatOf(p.u)), y = f.y(floatOf(p.v));
    if (cross)
      std::snprintf(buf, sizeof buf, "<path class=\"%s\" d=\"M%.2f %.2fL%.2f %.2fM%.2f %.2fL%.2f %.2f\"/>\n", cls,
                    x - 4, y - 4, x + 4, y + 4, x - 4, y + 4, x + 4, y - 4);
    else
      std::snprintf(buf, sizeof buf, "<circle class=\"%s\" cx=\"%.2f\" cy=\"%.2f\" r=\"%s\"/>\n", cls, x, y,
                    cls[0] == 'm' ? "4" : "1.2");
    o += buf;
  }
}

void domainOutline(std::string& o, Domain d, const Frame& f) {
  char buf[200];
  if (d == Domain::Tri)
    std::snprintf(buf, sizeof buf, "<path class=\"d\" d=\"M%.2f %.2fL%.2f %.2fL%.2f %.2fZ\"/>\n", f.x(0), f.y(0),
                  f.x(1), f.y(0), f.x(0), f.y(1));
  else
    std::snprintf(buf, sizeof buf, "<rect class=\"d\" x=\"%.2f\" y=\"%.2f\" width=\"%.0f\" height=\"%.0f\"/>\n",
                  f.x(0), f.y(1), kDomain, kDomain);
  o += buf;
  std::snprintf(buf, sizeof buf,
                "<text class=\"s\" x=\"%.2f\" y=\"%.2f\">(0,0)</text><text class=\"s\" x=\"%.2f\" y=\"%.2f\" "
                "text-anchor=\"end\">u=1</text><text class=\"s\" x=\"%.2f\" y=\"%.2f\">v=1</text>\n",
                f.x(0) - 14, f.y(0) + 14, f.x(1), f.y(0) + 14, f.x(0) - 24, f.y(1) - 4);
  o += buf;
}

void panel(std::string& o, const ComparePanel& p, double px, double py) {
  const std::string where = p.line > 0 ? " (line " + std::to_string(p.line) + ")" : "";
  double y = svgTextLines(o, "t", "patch " + std::to_string(p.index) + where + ": " + toString(p.kind), 14,
                          false, px + 8, py + 18, kPanelW - 16, 16);
  std::string counts = p.arity == 1 ? "" : std::to_string(p.onlyInReferenceCount) + " only in the reference, " +
                                               std::to_string(p.onlyInCaptureCount) + " only in the capture";
  if (!p.missingPoints.empty() || !p.extraPoints.empty())
    counts += std::string(counts.empty() ? "" : "; ") + "points: " + std::to_string(p.missingPoints.size()) +
              " missing, " + std::to_string(p.extraPoints.size()) + " extra";
  svgTextLines(o, "s", counts, 11, false, px + 8, y, kPanelW - 16, 13);
  const Frame f{px + kPad, py + kHeading + kPad};
  domainOutline(o, p.domain, f);
  if (p.arity == 1) {
    pointMarks(o, "rp", p.reference, f, false);
    pointMarks(o, "cp", p.capture, f, false);
  } else {
    primitivesPath(o, "r", p.reference, p.arity, {}, f);
    primitivesPath(o, "c", p.capture, p.arity, {}, f);
    primitivesPath(o, "or", p.reference, p.arity, p.onlyInReference, f);
    primitivesPath(o, "oc", p.capture, p.arity, p.onlyInCapture, f);
  }
  pointMarks(o, "mp", p.missingPoints, f, false);
  pointMarks(o, "xp", p.extraPoints, f, true);
}

double legend(std::string& o, double y) {
  struct Item {
    const char* cls;
    const char* text;
  };
  static const Item kItems[] = {
      {"r", "the reference's primitives"},  {"c", "the capture's primitives (dashed)"},
      {"or", "only in the reference"},      {"oc", "only in the capture (outlined)"},
      {"mp", "point only in the reference"}, {"xp", "point only in the capture"},
  };
  char buf[320];
  for (size_t i = 0; i < std::size(kItems); ++i) {
    const double x = 12 + double(i % 3) * kPanelW, yy = y + double(i / 3) * 22;
    const std::string cls = kItems[i].cls;
    if (cls == "mp")
      std::snprintf(buf, sizeof buf, "<circle class=\"mp\" cx=\"%.0f\" cy=\"%.0f\" r=\"4\"/>", x + 12, yy - 4);
    else if (cls == "xp")
      std::snprintf(buf, sizeof buf, "<path class=\"xp\" d=\"M%.0f %.0fL%.0f %.0fM%.0f %.0fL%.0f %.0f\"/>", x + 8,
                    yy - 8, x + 16, yy, x + 8, yy, x + 16, yy - 8);
    else
      std::snprintf(buf, sizeof buf, "<path class=\"%s\" d=\"M%.0f %.0fL%.0f %.0fL%.0f %.0fZ\"/>", cls.c_str(), x,
                    yy, x + 24, yy, x + 12, yy - 12);
    o += buf;
    std::snprintf(buf, sizeof buf, "<text class=\"s\" x=\"%.0f\" y=\"%.0f\">", x + 32, yy);
    o += buf + xmlEscape(kItems[i].text) + "</text>\n";
  }
  return y + 3 * 22;
}

// Distinct points of a, as keys, minus those of b.
std::vector<CapturedVertex> pointsOnlyIn(const std::vector<CapturedVertex>& a, const std::vector<CapturedVertex>& b) {
  auto distinct = [](std::vector<CapturedVertex> v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
  };
  const auto da = distinct(a), db = distinct(b);
  std::vector<CapturedVertex> out;
  std::set_difference(da.begin(), da.end(), db.begin(), db.end(), std::back_inserter(out));
  return out;
}

} // namespace

std::string compareSvg(const std::vector<ComparePanel>& panels, const std::string& title, const std::string& summary) {
  const size_t rows = (std::max<size_t>(panels.size(), 1) + kColumns - 1) / kColumns;
  const double head = 56, height = head + double(rows) * kPanelH + 90;
  std::string o = svgHead(kWidth, height, title);
  o += kStyle;
  double y = svgTextLines(o, "t", title, 14, false, 12, 22, kWidth - 24, 17);
  svgTextLines(o, "s", summary, 11, false, 12, y, kWidth - 24, 13);
  if (panels.empty())
    svgTextLines(o, "t", "no differing patch: nothing to draw", 14, false, 12, head + 30, kWidth - 24, 17);
  for (size_t i = 0; i < panels.size(); ++i)
    panel(o, panels[i], double(i % kColumns) * kPanelW, head + double(i / kColumns) * kPanelH);
  legend(o, head + double(rows) * kPanelH + 24);
  o += "</svg>\n";
  return o;
}

CompareSvg::CompareSvg(const std::string& path, const CompareOptions& options) : options_(options) {
  if (path.empty()) return;
  try {
    file_ = std::make_unique<AtomicFile>(path);
  } catch (const UsageError& e) {
    throw UsageError(std::string("--svg: ") + e.what());
  }
  options_.maxPrimitiveDetails = INT_MAX;
  options_.maxPointDetails = 0;
  options_.recognise = false;
}

CompareSvg::~CompareSvg() = default;

void CompareSvg::add(int64_t index, int line, const Patch& patch, const CapturedPatch* got, const PatchComparison& c) {
  if (!file_ || c.kind == DifferenceKind::Same || panels_.size() >= kMaxPanels) return;
  Tessellator tess;
  const PatchComparison all = comparePatch(patch, got, options_, tess);
  ComparePanel p;
  p.index = index;
  p.line = line;
  p.kind = c.kind;
  p.domain = patch.domain;
  p.arity = all.verticesPerPrimitive;
  p.reference = referenceCapture(patch, index, options_.emulator, p.arity == 1).vertices;
  if (got) p.capture = got->vertices;
  p.onlyInReference.assign(p.reference.size() / size_t(p.arity), 0);
  p.onlyInCapture.assign(p.capture.size() / size_t(p.arity), 0);
  for (const auto& d : all.onlyInReference) p.onlyInReference[size_t(d.primitive)] = 1;
  for (const auto& d : all.onlyInCapture) p.onlyInCapture[size_t(d.primitive)] = 1;
  p.onlyInReferenceCount = all.onlyInReferenceCount;
  p.onlyInCaptureCount = all.onlyInCaptureCount;
  p.missingPoints = pointsOnlyIn(p.reference, p.capture);
  p.extraPoints = pointsOnlyIn(p.capture, p.reference);
  panels_.push_back(std::move(p));
}

void CompareSvg::commit(const std::string& title, const CompareSummary& s) {
  if (!file_) return;
  const std::string summary = std::to_string(s.patches) + " patches, " + std::to_string(s.same) + " same, " +
                              std::to_string(s.differing) + " differ; the first " + std::to_string(panels_.size()) +
                              " differing drawn in the (u, v) domain, v up";
  file_->buffer() = compareSvg(panels_, title, summary);
  file_->commit();
}

} // namespace fftess::cli
