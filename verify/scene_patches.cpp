// layout.kind = "patches": layout.file read into Layout::patchList (declared in verify/scene_reader.h): an OBJ of
// quads (one face per patch) or a CSV of corners (one row per patch), each patch an axis-aligned square whose four
// corners are kept as the file's floats. Every refusal names the data file and its line first (Reader::failInFile).
// docs/verify.md, "Patches".
#include "verify/internal.h"
#include "verify/scene_reader.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <string_view>
#include <vector>

namespace fftess::verify::detail {

namespace {

constexpr size_t kMaxPatches = 4000000; // as the other layouts: at most 4 million patches

// The file being read: refusals at one of its lines.
struct Source {
  Reader& r;
  const toml::table& t;
  const std::string& file;
  [[noreturn]] void fail(int line, const std::string& msg) const {
    r.failInFile(file + ":" + std::to_string(line), "layout.file", t.get("file"), msg);
  }
};

std::string quoted(std::string_view s) {
  std::string out = "'";
  for (char c : s.substr(0, 80)) out += c;
  return out + (s.size() > 80 ? "...'" : "'");
}

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

// One number of the file as a float: the decimal (or C99 hex-float) token read whole, rounded to nearest (what
// strtof gives, locale-independent). "" or why it is refused.
std::string parseFloat(std::string_view s, float& out) {
  std::string_view digits = s;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  const char* end = digits.data() + digits.size();
  const auto [ptr, ec] = std::from_chars(digits.data(), end, out);
  if (digits.empty() || ptr != end || (ec != std::errc() && ec != std::errc::result_out_of_range))
    return quoted(s) + " is not a number";
  if (ec == std::errc::result_out_of_range) return quoted(s) + " is out of float range";
  if (!std::isfinite(out)) return quoted(s) + " is not finite";
  return "";
}

// Calls f(line, text) for each line (1-based; "\n" or "\r\n"; a UTF-8 byte order mark at the start skipped).
// Returns the number of lines.
template <class F>
int forEachLine(const std::string& text, F&& f) {
  size_t at = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  int line = 0;
  while (at < text.size()) {
    size_t end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    std::string_view s(text.data() + at, end - at);
    if (!s.empty() && s.back() == '\r') s.remove_suffix(1);
    f(++line, s);
    at = end + 1;
  }
  return std::max(line, 1);
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split(std::string_view s, char sep) {
  std::vector<std::string_view> out;
  for (size_t at = 0;;) {
    const size_t end = sep == ' ' ? s.find_first_of(" \t", at) : s.find(sep, at);
    std::string_view part = s.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at);
    if (sep != ' ' || !part.empty()) out.push_back(sep == ' ' ? part : trim(part));
    if (end == std::string_view::npos) return out;
    at = end + 1;
  }
}

// The four points as the corners of an axis-aligned square, in fftess's order (corners[u + 2v]); slot[k]: the
// corner point k became. "" or why not (the sides compared exactly: their lengths as exact differences of floats).
std::string squareCorners(const glm::vec2 (&p)[4], LayoutPatch& out, int (&slot)[4]) {
  float x0 = p[0].x, x1 = p[0].x, z0 = p[0].y, z1 = p[0].y;
  for (const glm::vec2& q : p) {
    x0 = std::min(x0, q.x);
    x1 = std::max(x1, q.x);
    z0 = std::min(z0, q.y);
    z1 = std::max(z1, q.y);
  }
  if (!(x0 < x1) || !(z0 < z1))
    return "not a square: the corners span x " + num(x0) + " .. " + num(x1) + ", z " + num(z0) + " .. " + num(z1) +
           " (no area)";
  unsigned seen = 0;
  for (int k = 0; k < 4; ++k) {
    const int u = p[k].x == x0 ? 0 : p[k].x == x1 ? 1 : -1, v = p[k].y == z0 ? 0 : p[k].y == z1 ? 1 : -1;
    const std::string at = "corner " + std::to_string(k + 1) + " (x " + num(p[k].x) + ", z " + num(p[k].y) + ")";
    if (u < 0 || v < 0) return "not an axis-aligned square: " + at + " is not at x " + num(x0) + " or " + num(x1) +
                               " and z " + num(z0) + " or " + num(z1);
    if (seen & (1u << (u + 2 * v))) return "not a square: " + at + " is given twice";
    seen |= 1u << (u + 2 * v);
    slot[k] = u + 2 * v;
    out.corners[u + 2 * v] = p[k];
  }
  double w, h;
  if (!exactDifference(x1, x0, w) || !exactDifference(z1, z0, h))
    return "the sides' lengths are not exact in double (coordinates of too different magnitudes: x " + num(x0) +
           " .. " + num(x1) + ", z " + num(z0) + " .. " + num(z1) + ")";
  if (w != h) return "not a square: its x side is " + num(w) + ", its z side " + num(h);
  return "";
}

void addPatch(const Source& src, int line, const glm::vec2 (&p)[4], std::vector<LayoutPatch>& out, int (&slot)[4]) {
  if (out.size() >= kMaxPatches) src.fail(line, "more than 4 million patches");
  LayoutPatch lp;
  lp.line = line;
  const std::string why = squareCorners(p, lp, slot);
  if (!why.empty()) src.fail(line, why);
  out.push_back(lp);
}

// One vertex reference of a face ("a", "a/b", "a/b/c", "a//c"; negative: relative to the end): the vertex's index.
size_t vertexIndex(const Source& src, int line, std::string_view ref, size_t vertices) {
  const std::string_view v = ref.substr(0, ref.find('/'));
  long long i = 0;
  const auto [ptr, ec] = std::from_chars(v.data(), v.data() + v.size(), i);
  if (v.empty() || ec != std::errc() || ptr != v.data() + v.size())
    src.fail(line, "vertex reference " + quoted(ref) + " is not an index");
  const long long n = static_cast<long long>(vertices);
  const long long at = i > 0 ? i - 1 : n + i;
  if (i == 0 || at < 0 || at >= n)
    src.fail(line, "vertex reference " + quoted(ref) + " is out of range (" + std::to_string(n) +
                       " vertices defined before this line)");
  return static_cast<size_t>(at);
}

void objFace(const Source& src, int line, const std::vector<std::string_view>& tok,
             const std::vector<glm::vec2>& verts, std::vector<LayoutPatch>& out) {
  if (tok.size() != 5)
    src.fail(line, "a face of " + std::to_string(tok.size() - 1) +
                       " vertices: a patch is a quad (a face of exactly 4 vertex references)");
  glm::vec2 p[4];
  for (int k = 0; k < 4; ++k) p[k] = verts[vertexIndex(src, line, tok[static_cast<size_t>(k) + 1], verts.size())];
  int slot[4];
  addPatch(src, line, p, out, slot);
  for (int k = 0; k < 4; ++k)
    if ((slot[k] ^ slot[(k + 1) % 4]) == 3)
      src.fail(line, "the face's vertices do not go round the square (vertices " + std::to_string(k + 1) + " and " +
                         std::to_string((k + 1) % 4 + 1) + " are opposite corners: a self-intersecting quad)");
}

// OBJ: v (x y z: x and z kept, y ignored), f (4 vertex references: one patch), the statements that carry no geometry
// ignored, any other refused (a line, a point or a free-form surface is no patch).
void readObj(const Source& src, const std::string& text, std::vector<LayoutPatch>& out) {
  static const char* const kIgnored[] = {"vt",     "vn",  "vp",        "o",         "g",         "s",
                                         "mg",     "usemtl", "mtllib", "usemap",    "maplib",    "bevel",
                                         "c_interp", "d_interp", "lod", "shadow_obj", "trace_obj"};
  std::vector<glm::vec2> verts;
  const int lines = forEachLine(text, [&](int line, std::string_view s) {
    const std::vector<std::string_view> tok = split(s.substr(0, s.find('#')), ' ');
    if (tok.empty()) return;
    if (tok[0] == "v") {
      if (tok.size() < 4 || tok.size() > 8)
        src.fail(line, "a vertex needs x y z (then at most w, or r g b, or r g b a): got " +
                           std::to_string(tok.size() - 1) + " numbers");
      float c[7];
      static const char* const kNames[] = {"x", "y", "z", "w or r", "g", "b", "a"};
      for (size_t k = 1; k < tok.size(); ++k) {
        const std::string why = parseFloat(tok[k], c[k - 1]);
        if (!why.empty()) src.fail(line, std::string("vertex ") + kNames[k - 1] + ": " + why);
      }
      verts.emplace_back(c[0], c[2]);
    } else if (tok[0] == "f") {
      objFace(src, line, tok, verts, out);
    } else if (std::none_of(std::begin(kIgnored), std::end(kIgnored), [&](const char* k) { return tok[0] == k; })) {
      src.fail(line, "OBJ statement " + quoted(tok[0]) +
                         " is not read: patches are quad faces (f) of vertices (v); vt, vn, o, g, s, usemtl, "
                         "mtllib and the other statements without geometry are ignored");
    }
  });
  if (out.empty()) src.fail(lines, "no patches: the file holds no face (f)");
}

// CSV: a header naming the columns x0,z0,x1,z1,x2,z2,x3,z3 (the four corners in any order; y0..y3 optional and
// ignored), then one row per patch. Blank lines and lines starting with '#' are skipped.
void readCsv(const Source& src, const std::string& text, std::vector<LayoutPatch>& out) {
  static const char* const kColumns[] = {"x0", "z0", "x1", "z1", "x2", "z2", "x3", "z3", "y0", "y1", "y2", "y3"};
  int column[12];     // field index of each column, -1 absent
  size_t fields = 0;  // fields per row (the header's)
  bool header = false;
  const int lines = forEachLine(text, [&](int line, std::string_view s) {
    if (trim(s).empty() || trim(s).front() == '#') return;
    const std::vector<std::string_view> f = split(s, ',');
    if (!header) {
      header = true;
      fields = f.size();
      std::fill(std::begin(column), std::end(column), -1);
      for (size_t i = 0; i < f.size(); ++i) {
        std::string_view name = f[i];
        if (name.size() >= 2 && name.front() == '"' && name.back() == '"') name = name.substr(1, name.size() - 2);
        const auto* it = std::find_if(std::begin(kColumns), std::end(kColumns), [&](const char* c) { return name == c; });
        if (it == std::end(kColumns))
          src.fail(line, "header field " + std::to_string(i + 1) + ": unknown column " + quoted(name) +
                             " (the columns are x0,z0,x1,z1,x2,z2,x3,z3, optionally y0..y3)");
        if (column[it - kColumns] >= 0) src.fail(line, "header: column " + quoted(name) + " is given twice");
        column[it - kColumns] = static_cast<int>(i);
      }
      for (int c = 0; c < 8; ++c)
        if (column[c] < 0)
          src.fail(line, std::string("header: missing column '") + kColumns[c] +
                             "' (the header needs x0,z0,x1,z1,x2,z2,x3,z3)");
      return;
    }
    if (f.size() != fields)
      src.fail(line, "a row of " + std::to_string(f.size()) + " fields (the header has " + std::to_string(fields) + ")");
    float v[12] = {};
    for (int c = 0; c < 12; ++c) {
      if (column[c] < 0) continue;
      const std::string why = parseFloat(f[static_cast<size_t>(column[c])], v[c]);
      if (!why.empty())
        src.fail(line, std::string("column ") + kColumns[c] + " (field " + std::to_string(column[c] + 1) + "): " + why);
    }
    const glm::vec2 p[4] = {{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}};
    int slot[4];
    addPatch(src, line, p, out, slot);
  });
  if (out.empty())
    src.fail(lines, header ? "no patches: a header without rows" : "no patches: the file is empty (a header, then one row per patch)");
}

} // namespace

void readPatchesFile(Reader& r, const toml::table& t, Layout& L) {
  const Source src{r, t, L.file};
  std::string ext = L.file.size() >= 4 ? L.file.substr(L.file.size() - 4) : "";
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".obj" && ext != ".csv")
    r.fail("layout.file", t.get("file"), "\"" + L.file + "\": expected an .obj or a .csv file (docs/verify.md, Patches)");
  std::string text;
  const int rc = readBounded(L.file, kMaxSceneBytes, text);
  if (rc <= 0)
    r.fail("layout.file", t.get("file"),
           "\"" + L.file + "\": " + (rc < 0 ? "larger than " + std::to_string(kMaxSceneBytes) + " bytes (16 MiB, the limit)"
                                            : std::string("cannot read it")));
  auto list = std::make_shared<std::vector<LayoutPatch>>();
  if (ext == ".obj") readObj(src, text, *list);
  else readCsv(src, text, *list);
  L.patchList = std::move(list);
}

} // namespace fftess::verify::detail
