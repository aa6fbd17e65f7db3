// check --view (the camera's picture), legends that fit their pictures (check --svg, check --view, sweep --svg) and
// the fix line of every cause (text, JSON, pictures). docs/cli.md, "check --view" and "Fixes".
#include "run.h"

#include "verify/verify.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <regex>
#include <set>
#include <cstring>
#include <string>
#include <vector>

using clitest::run;
using nlohmann::json;
namespace vf = fftess::verify;

namespace {

const std::string kScene = clitest::source("docs/examples/terrain.toml");
const std::vector<std::string> kNoClamp = {"--set", "lod.adjacency_clamp=none"};

// ---- a small look at SVG elements -------------------------------------------------------------------------------
struct Element {
  std::string name;
  std::map<std::string, std::string> attr;
  std::string text; // <text>: its content, entities decoded
};

std::string unescape(std::string s) {
  const std::pair<const char*, const char*> entities[] = {{"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&apos;", "'"}, {"&amp;", "&"}};
  for (const auto& [from, to] : entities)
    for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + 1)) s.replace(at, std::strlen(from), to);
  return s;
}

// Every start tag of `name` in document order, with its attributes (and a <text>'s content).
std::vector<Element> elements(const std::string& svg, const std::string& name) {
  std::vector<Element> out;
  const std::string open = "<" + name + " ";
  for (size_t at = svg.find(open); at != std::string::npos; at = svg.find(open, at + 1)) {
    const size_t end = svg.find('>', at);
    Element e;
    e.name = name;
    // name="value" pairs (no regex: a path's data runs to megabytes)
    for (size_t eq = svg.find("=\"", at); eq < end; eq = svg.find("=\"", eq + 1)) {
      size_t k = eq;
      while (k > at && svg[k - 1] != ' ') --k;
      const size_t close = svg.find('"', eq + 2);
      e.attr[svg.substr(k, eq - k)] = svg.substr(eq + 2, close - eq - 2);
      eq = close;
    }
    if (name == "text") e.text = unescape(svg.substr(end + 1, svg.find("</text>", end) - end - 1));
    out.push_back(e);
  }
  return out;
}

// The part of the document inside <g id="ID">...</g> (no nested groups in these pictures).
std::string group(const std::string& svg, const std::string& id) {
  const size_t at = svg.find("<g id=\"" + id + "\">");
  if (at == std::string::npos) return "";
  return svg.substr(at, svg.find("</g>", at) - at);
}

// The font of each text class from the picture's <style>: ".t{font:13px sans-serif}".
struct Font {
  double px = 0;
  bool mono = false;
};
std::map<std::string, Font> fonts(const std::string& svg) {
  std::map<std::string, Font> out;
  static const std::regex re("\\.([a-z]+)\\{font:([0-9.]+)px ([a-z-]+)");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), re); it != std::sregex_iterator(); ++it)
    out[(*it)[1]] = {std::stod((*it)[2]), (*it)[3] == "monospace"};
  return out;
}

// An upper bound of a text's width (docs/cli.md, "Pictures"): monospace 0.62 em per glyph; sans-serif by glyph class
// (DejaVu Sans advance widths are below these): narrow 0.42, wide 1.0, other capitals 0.8, the rest 0.66 em.
double textWidth(const std::string& s, const Font& f) {
  double em = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if ((c & 0xC0) == 0x80) continue; // UTF-8 continuation
    if (f.mono) em += 0.62;
    else if (c >= 0x80 || std::string("mwMW@%=+<>~#&").find(static_cast<char>(c)) != std::string::npos) em += 1.0;
    else if (std::string(" .,:;'|!()[]/ijlftr-").find(static_cast<char>(c)) != std::string::npos) em += 0.42;
    else if (c >= 'A' && c <= 'Z') em += 0.8;
    else em += 0.66;
  }
  return em * f.px;
}

struct Box {
  double w = 0, h = 0;
};
Box viewBox(const std::string& svg) {
  const Element root = elements(svg, "svg").at(0);
  double x, y, w, h;
  REQUIRE(std::sscanf(root.attr.at("viewBox").c_str(), "%lf %lf %lf %lf", &x, &y, &w, &h) == 4);
  CHECK(x == 0);
  CHECK(y == 0);
  return {w, h};
}

// Every text element's estimated extent (baseline y, the font's size above it) inside the viewBox; every number of a
// path's data, circle (with its radius) and rect inside it.
void everythingInside(const std::string& svg) {
  std::string why;
  REQUIRE(clitest::wellFormedXml(svg, why));
  const Box box = viewBox(svg);
  const std::map<std::string, Font> font = fonts(svg);
  for (const Element& t : elements(svg, "text")) {
    INFO(t.text);
    REQUIRE(font.count(t.attr.at("class")));
    const Font& f = font.at(t.attr.at("class"));
    const double x = std::stod(t.attr.at("x")), y = std::stod(t.attr.at("y"));
    CHECK(x >= 0);
    CHECK(x + textWidth(t.text, f) <= box.w);
    CHECK(y - f.px >= 0);
    CHECK(y <= box.h);
  }
  for (const Element& c : elements(svg, "circle")) {
    const double x = std::stod(c.attr.at("cx")), y = std::stod(c.attr.at("cy")), r = std::stod(c.attr.at("r"));
    CHECK(x - r >= -r); // the mark's centre inside the page (its stroke may touch the image's border)
    CHECK(x <= box.w);
    CHECK(y >= 0);
    CHECK(y <= box.h);
  }
  for (const Element& p : elements(svg, "path")) { // M/L x y pairs and Z
    const char* c = p.attr.at("d").c_str();
    bool isX = true, inside = true;
    while (*c) {
      if (*c == 'M' || *c == 'L' || *c == 'Z' || *c == ' ') {
        ++c;
        continue;
      }
      char* end = nullptr;
      const double v = std::strtod(c, &end);
      REQUIRE(end != c);
      c = end;
      inside = inside && v >= 0 && v <= (isX ? box.w : box.h);
      isX = !isX;
    }
    CHECK(inside);
  }
}

// ---- the independent count of patch outlines in view -------------------------------------------------------------
// Whether part of the segment a..b (clip space) lies inside the six planes of the GL clip volume (|x|, |y|, |z| <= w).
bool segmentInView(const glm::dvec4& a, const glm::dvec4& b) {
  double lo = 0, hi = 1;
  const glm::dvec4 d = b - a;
  for (int axis = 0; axis < 3; ++axis)
    for (const double sign : {1.0, -1.0}) {
      // w + sign * c >= 0 along the segment: f(t) = fa + t (fb - fa)
      const double fa = a.w + sign * a[axis], fd = d.w + sign * d[axis];
      if (fd == 0) {
        if (fa < 0) return false;
        continue;
      }
      const double t = -fa / fd;
      if (fd > 0) lo = std::max(lo, t);
      else hi = std::min(hi, t);
    }
  return lo <= hi;
}

// Per size level, the drawn patches of the check whose outline (4 segments per edge on the displaced surface, as
// docs/cli.md says) has a part in view.
std::map<int, int> outlinesInView(const std::vector<std::string>& overrides) {
  const vf::SceneResult s = vf::loadScene(kScene, overrides);
  REQUIRE(s.ok);
  const vf::TerrainResult t = vf::prepareTerrain(s.scene);
  REQUIRE(t.ok);
  vf::CheckOptions o;
  o.keepDrawn = true;
  const vf::Report r = vf::checkScene(t.terrain, s.scene.camera, o);
  const vf::Terrain layout = vf::layoutFor(t.terrain, s.scene.camera);
  REQUIRE(r.drawn.size() == layout.patches().size());
  CHECK(std::count(r.drawn.begin(), r.drawn.end(), 1) == r.stats.patches - r.stats.culledPatches);
  const auto cam = vf::viewCamera(s.scene.camera);
  const glm::dmat4 clip = glm::dmat4(cam.projection) * glm::dmat4(cam.view);
  std::map<int, int> levels;
  for (int i = 0; i < layout.patchCount(); ++i) {
    if (!r.drawn[static_cast<size_t>(i)]) continue;
    std::vector<glm::dvec4> ring;
    const float uv[16][2] = {{0, 0},     {.25, 0}, {.5, 0},   {.75, 0}, {1, 0},  {1, .25}, {1, .5},  {1, .75},
                             {1, 1},     {.75, 1}, {.5, 1},   {.25, 1}, {0, 1},  {0, .75}, {0, .5},  {0, .25}};
    for (const auto& p : uv) ring.push_back(clip * glm::dvec4(glm::dvec3(vf::domainPosition(layout, i, p[0], p[1])), 1.0));
    bool in = false;
    for (size_t k = 0; k < ring.size() && !in; ++k) in = segmentInView(ring[k], ring[(k + 1) % ring.size()]);
    if (in) ++levels[layout.patches()[static_cast<size_t>(i)].ref.level];
  }
  return levels;
}

std::string pixelsLabel(double px) {
  char buf[48];
  std::snprintf(buf, sizeof buf, px >= 100 ? "%.0f px" : "%.2g px", px);
  return buf;
}

std::vector<std::string> withArgs(std::vector<std::string> a, const std::vector<std::string>& more) {
  a.insert(a.end(), more.begin(), more.end());
  return a;
}

} // namespace

TEST_CASE("check --view marks every on-screen finding with its pixel gap and outlines every drawn patch in view",
          "[cli][view]") {
  const std::string js = clitest::tmpDir() + "/view.json", svgPath = clitest::tmpDir() + "/view.svg";
  const auto r = run(withArgs({"check", kScene, "--json", js, "--view", svgPath}, kNoClamp));
  INFO(r.err);
  REQUIRE(r.status == 1);
  const json j = json::parse(clitest::readFile(js));
  const std::string svg = clitest::readFile(svgPath);
  everythingInside(svg);

  // One mark per on-screen finding, each crack labelled with its on-screen gap in pixels.
  std::multiset<std::string> want, got;
  int onScreen = 0, offScreen = 0;
  for (const json& f : j.at("findings")) {
    if (f.at("classification") == "match") continue;
    if (!f.at("on_screen").get<bool>()) {
      ++offScreen;
      continue;
    }
    ++onScreen;
    want.insert(f.at("classification") == "crack" ? pixelsLabel(f.at("on_screen_gap_pixels").get<double>()) : "T-junction");
  }
  REQUIRE(onScreen > 0);
  REQUIRE(offScreen > 0); // off-screen findings counted in the legend, not drawn
  const std::string marks = group(svg, "findings");
  CHECK(elements(marks, "circle").size() == static_cast<size_t>(onScreen));
  for (const Element& t : elements(marks, "text")) got.insert(t.text);
  CHECK(got == want);

  // One outline per drawn patch in view, per size level as counted here from verify's public API.
  const std::map<int, int> levels = outlinesInView({"lod.adjacency_clamp=none"});
  int total = 0;
  for (const auto& [level, n] : levels) total += n;
  REQUIRE(total > 0);
  REQUIRE(levels.size() >= 2); // the picture shows a size jump
  CHECK(elements(group(svg, "patches"), "path").size() == static_cast<size_t>(total));
  std::string legend;
  for (const Element& t : elements(svg, "text")) legend += t.text + "\n";
  for (const auto& [level, n] : levels) {
    const std::string line = "size level " + std::to_string(level) + " (patches 2^" + std::to_string(level) +
                             " times the smallest): " + std::to_string(n) + " drawn in view";
    INFO(line);
    CHECK(legend.find(line) != std::string::npos);
  }
  CHECK(legend.find(std::to_string(offScreen) + " findings off screen, not drawn") != std::string::npos);
  CHECK(legend.find("px of the camera's 1920 x 1200 viewport") != std::string::npos); // the ruler
  // Each on-screen cause with its fix.
  for (const json& f : j.at("findings")) {
    if (!f.at("on_screen").get<bool>()) continue;
    CHECK(legend.find("cause: " + f.at("classification").get<std::string>() + ": " + f.at("cause").get<std::string>()) != std::string::npos);
  }
  CHECK(legend.find("fix: ") != std::string::npos);
}

TEST_CASE("check --view circles every hole where it is seen, and says how to fix it", "[cli][view]") {
  // The eye in the plane of a flat grid: the edges whose midpoints lie in the eye's plane get NaN factors (w = 0).
  const std::string js = clitest::tmpDir() + "/view-holes.json", svgPath = clitest::tmpDir() + "/view-holes.svg";
  const auto r = run({"check", clitest::source("docs/examples/grid.toml"), "--set", "displacement.kind=none", "--set",
                      "lod.scheme=screen_sphere", "--set", "tessellation.partitioning=fractional_even", "--set",
                      "lod.frustum_cull=false", "--eye", "0,0,2", "--target", "0,0,100", "--json", js, "--view", svgPath});
  REQUIRE(r.status == 1);
  const json j = json::parse(clitest::readFile(js));
  const std::string svg = clitest::readFile(svgPath);
  everythingInside(svg);
  const std::string holes = group(svg, "holes");
  REQUIRE(!j.at("holes").empty());
  CHECK(elements(holes, "circle").size() == j.at("holes").size());
  for (const Element& t : elements(holes, "text")) CHECK(t.text == "hole");
  CHECK(elements(holes, "text").size() == j.at("holes").size());
  CHECK(svg.find("fix: guard w &lt;= 0 in the edge's projection") != std::string::npos);
}

TEST_CASE("check --view of an unusable path exits 2 naming --view, and writes no report", "[cli][view]") {
  const std::string d = clitest::tmpDir() + "/view-bad";
  clitest::writeFile(d + ".plain", "x");
  const std::string js = clitest::tmpDir() + "/view-bad.json";
  const auto r = run({"check", kScene, "--json", js, "--view", d + ".plain/x.svg"});
  CHECK(r.status == 2);
  CHECK(r.err.find("--view") != std::string::npos);
  CHECK_FALSE(clitest::fileExists(js));
  const auto same = run({"check", kScene, "--json", js, "--view", js});
  CHECK(same.status == 2);
  CHECK(same.err.find("--view") != std::string::npos);
}

TEST_CASE("every text of check --svg, check --view, sweep --svg and bench --svg lies inside its picture",
          "[cli][view][svg][slow]") {
  const std::string d = clitest::tmpDir();
  const auto b = run({"bench", "--scene", clitest::source("docs/examples/rings_small.toml"), "--cameras", "1",
                      "--mesh-cameras", "1", "--repeats", "1", "-q", "--svg", d + "/fit-bench.svg"});
  CHECK(b.status == 0);
  const auto c = run(withArgs({"check", kScene, "-q", "--svg", d + "/fit-check.svg", "--view", d + "/fit-view.svg"}, kNoClamp));
  CHECK(c.status == 1);
  const auto s = run(withArgs({"sweep", kScene, "-q", "--random", "6", "--seed", "3", "--svg", d + "/fit-sweep.svg"}, kNoClamp));
  CHECK(s.status == 1);
  for (const char* name : {"/fit-check.svg", "/fit-view.svg", "/fit-sweep.svg", "/fit-bench.svg"}) {
    INFO(name);
    const std::string svg = clitest::readFile(d + name);
    if (std::string(name) == "/fit-check.svg" || std::string(name) == "/fit-view.svg")
      CHECK(svg.find("fix: ") != std::string::npos);
    everythingInside(svg);
  }
}

TEST_CASE("every cause says how to fix it, in check's text and JSON and in sweep's", "[cli][fix]") {
  const std::string js = clitest::tmpDir() + "/fix.json";
  auto r = run(withArgs({"check", kScene, "--json", js}, kNoClamp));
  REQUIRE(r.status == 1);
  json j = json::parse(clitest::readFile(js));
  REQUIRE(!j.at("findings").empty());
  std::set<std::string> causes;
  for (const json& f : j.at("findings")) {
    CHECK(!f.at("fix").get<std::string>().empty());
    causes.insert(f.at("cause").get<std::string>());
  }
  // Text: each cause's header, then its fix line.
  for (const std::string& cause : causes) {
    const size_t at = r.out.find(": " + cause + ": ");
    INFO(cause);
    REQUIRE(at != std::string::npos);
    CHECK(r.out.compare(r.out.find('\n', at) + 1, 9, "    fix: ") == 0);
  }
  // --show N: N edges under each header; the cause is explained once ("e.g."), the edges only say where.
  const auto shown = run(withArgs({"check", kScene, "--show", "3"}, kNoClamp));
  std::vector<std::string> lines;
  for (size_t at = 0; (at = shown.out.find("\n      ring ", at)) != std::string::npos; ++at)
    lines.push_back(shown.out.substr(at + 1, shown.out.find('\n', at + 1) - at - 1));
  size_t headers = 0;
  for (size_t at = 0; (at = shown.out.find("\n    fix: ", at)) != std::string::npos; ++at) ++headers;
  REQUIRE(lines.size() >= 3);
  REQUIRE(lines.size() <= 3 * headers);
  CHECK(shown.out.find("\n    e.g. 2x jump") != std::string::npos);
  CHECK(lines[0].find("2x jump") == std::string::npos);
  CHECK(shown.out.find(" more findings (--show N, or --json FILE)") != std::string::npos);
  // The 16.16 cause (the integer clamp's 12 beside 6) names the scene key that removes it.
  r = run({"check", kScene, "--set", "lod.adjacency_clamp=integer", "--json", js});
  REQUIRE(r.status == 1);
  j = json::parse(clitest::readFile(js));
  for (const json& f : j.at("findings")) {
    INFO(f.at("cause"));
    if (f.at("cause").get<std::string>().rfind("2x jump: factor not a power of two", 0) == 0)
      CHECK(f.at("fix").get<std::string>().rfind("round the larger side's factor to a power of two (lod.adjacency_clamp = \"pow2\")", 0) == 0);
  }
  CHECK(r.out.find("\n    fix: round the larger side's factor to a power of two (lod.adjacency_clamp = \"pow2\")") != std::string::npos);

  // Holes: the projection's w = 0 at an edge's midpoint.
  const std::string grid = clitest::source("docs/examples/grid.toml");
  r = run({"check", grid, "--set", "displacement.kind=none", "--set", "lod.scheme=screen_sphere", "--set",
           "tessellation.partitioning=fractional_even", "--set", "lod.frustum_cull=false", "--eye", "0,0,2", "--target",
           "0,0,100", "--json", js});
  REQUIRE(r.status == 1);
  j = json::parse(clitest::readFile(js));
  REQUIRE(!j.at("holes").empty());
  for (const json& h : j.at("holes")) CHECK(h.at("fix").get<std::string>().rfind("guard w <= 0 in the edge's projection", 0) == 0);
  CHECK(r.out.find("    fix: guard w <= 0 in the edge's projection") != std::string::npos);

  // The pow2 clamp with edge_vector reconstruction (the moved corner keeps its height): the small side's factor is not
  // half the big side's, fixed by rebuilding the corner bit-exactly.
  r = run({"sweep", kScene, "--set", "lod.reconstruction=edge_vector", "--random", "40", "--seed", "2", "-q", "--json", js});
  REQUIRE(r.status == 1);
  j = json::parse(clitest::readFile(js));
  bool rebuilt = false;
  for (const json& c : j.at("causes"))
    if (c.at("cause").get<std::string>().find("not half the big side's (lod pow2 clamp, rebuilt edge_vector)") != std::string::npos) {
      rebuilt = true;
      CHECK(c.at("fix").get<std::string>().rfind("rebuild the neighbour's corner bit-exactly (lod.reconstruction = \"far_corner\" or \"resampled\")", 0) == 0);
    }
  CHECK(rebuilt);

  // Sweep: each cause of the table with its fix, in the text and the JSON.
  r = run(withArgs({"sweep", kScene, "--random", "6", "--seed", "3", "--json", js}, kNoClamp));
  REQUIRE(r.status == 1);
  j = json::parse(clitest::readFile(js));
  REQUIRE(!j.at("causes").empty());
  for (const json& c : j.at("causes")) {
    const std::string fix = c.at("fix");
    CHECK(!fix.empty());
    CHECK(r.out.find("      fix: " + fix + "\n") != std::string::npos);
  }
}
