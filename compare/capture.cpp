#include "compare/capture.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <sstream>

#include "tessellator/batch.h"
#include "tessellator/fixed.h"

namespace fftess {
namespace {

std::string trim(const std::string& s) {
  size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

bool skippable(const std::string& line) {
  const std::string t = trim(line);
  return t.empty() || t[0] == '#';
}

// A non-negative decimal integer that fits in 62 bits.
bool parseCount(const std::string& s, int64_t& out) {
  if (s.empty() || s.size() > 18) return false;
  int64_t v = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return false;
    v = v * 10 + (c - '0');
  }
  out = v;
  return true;
}

bool parseHex8(const std::string& s, uint32_t& out) {
  if (s.size() != 8) return false;
  uint32_t v = 0;
  for (char c : s) {
    int d = (c >= '0' && c <= '9')   ? c - '0'
            : (c >= 'a' && c <= 'f') ? c - 'a' + 10
            : (c >= 'A' && c <= 'F') ? c - 'A' + 10
                                     : -1;
    if (d < 0) return false;
    v = (v << 4) | uint32_t(d);
  }
  out = v;
  return true;
}

std::vector<std::string> splitWords(const std::string& line) {
  std::vector<std::string> t;
  std::istringstream in(line);
  for (std::string s; in >> s;) t.push_back(s);
  return t;
}

} // namespace

CaptureReader::CaptureReader(std::istream& in, std::string source, CaptureFormat format)
    : in_(in), source_(std::move(source)), format_(format) {}

void CaptureReader::fail(int line, const std::string& why) const {
  throw CaptureError(source_ + ":" + std::to_string(line) + ": " + why);
}

bool CaptureReader::readLine(std::string& line) {
  if (havePushedBack_) {
    havePushedBack_ = false;
    line = pushedBack_;
    return true;
  }
  if (!std::getline(in_, line)) return false;
  ++lineNo_;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return true;
}

bool CaptureReader::next(CapturedPatch& out) {
  if (format_ == CaptureFormat::Auto) {
    std::string line;
    while (readLine(line)) {
      if (skippable(line)) continue;
      format_ = trim(line).compare(0, 6, "patch ") == 0 ? CaptureFormat::Hex : CaptureFormat::Csv;
      pushedBack_ = line;
      havePushedBack_ = true;
      break;
    }
    if (format_ == CaptureFormat::Auto) return false; // empty capture
  }
  return format_ == CaptureFormat::Hex ? nextHex(out) : nextCsv(out);
}

bool CaptureReader::nextHex(CapturedPatch& out) {
  std::string line;
  do {
    if (!readLine(line)) return false;
  } while (skippable(line));
  const int headerLine = lineNo_;
  const auto w = splitWords(line);
  int64_t n = 0, points = 0, indices = 0;
  if (w.size() != 6 || w[0] != "patch" || w[2] != "points" || w[4] != "indices" || !parseCount(w[1], n) ||
      !parseCount(w[3], points) || !parseCount(w[5], indices))
    fail(headerLine, "expected a block header 'patch N points P indices I'");
  if (n <= lastPatch_)
    fail(headerLine, "patch " + std::to_string(n) + " comes after patch " + std::to_string(lastPatch_) +
                         " (patches must increase)");
  if (points > 65 * 65 || indices > 64 * 64 * 6 * 2) fail(headerLine, "more points or indices than any patch has");
  lastPatch_ = n;
  std::vector<CapturedVertex> pts(static_cast<size_t>(points));
  for (auto& p : pts) {
    if (!readLine(line)) fail(lineNo_, "file ends inside patch " + std::to_string(n) + "'s points");
    const auto t = splitWords(line);
    if (t.size() != 2 || !parseHex8(t[0], p.u) || !parseHex8(t[1], p.v))
      fail(lineNo_, "expected a point 'UUUUUUUU VVVVVVVV' (8 hex digits each)");
  }
  out.patch = n;
  out.line = headerLine;
  out.vertices.clear();
  out.indices.clear();
  out.verticesPerPrimitive = indices ? 0 : (points ? 1 : 0);
  if (!indices) out.vertices = pts;
  int64_t read = 0;
  while (read < indices) {
    if (!readLine(line)) fail(lineNo_, "file ends inside patch " + std::to_string(n) + "'s indices");
    const auto t = splitWords(line);
    if (t.empty() || t.size() > 3) fail(lineNo_, "expected 1, 2 or 3 indices on a line");
    if (out.verticesPerPrimitive == 0) out.verticesPerPrimitive = int(t.size());
    if (int(t.size()) != out.verticesPerPrimitive)
      fail(lineNo_, "expected " + std::to_string(out.verticesPerPrimitive) + " indices on the line, as on the first");
    for (const auto& s : t) {
      int64_t i = 0;
      if (!parseCount(s, i) || i >= points)
        fail(lineNo_, "index '" + s + "' is not a point of the patch (0.." + std::to_string(points - 1) + ")");
      out.vertices.push_back(pts[static_cast<size_t>(i)]);
      out.indices.push_back(int32_t(i));
    }
    read += int64_t(t.size());
  }
  if (read != indices) fail(lineNo_, "more indices than the header's " + std::to_string(indices));
  return true;
}

bool CaptureReader::readCsvRow(Row& row) {
  std::string line;
  while (readLine(line)) {
    if (skippable(line)) continue;
    std::vector<std::string> f;
    std::string cell;
    std::istringstream in(line);
    while (std::getline(in, cell, ',')) f.push_back(trim(cell));
    if (!line.empty() && line.back() == ',') f.push_back("");
    int64_t patch = 0, prim = 0, vert = 0;
    const bool firstNumeric = !f.empty() && parseCount(f[0], patch);
    if (!firstNumeric && !sawRow_) {
      sawRow_ = true; // a header line: only before the first row
      continue;
    }
    if (f.size() < 5 || f.size() > 6)
      fail(lineNo_, "expected 5 or 6 fields 'patch,primitive,vertex,u,v[,w]', found " + std::to_string(f.size()));
    if (!firstNumeric) fail(lineNo_, "field 1 (patch) '" + f[0] + "' is not a non-negative integer");
    if (!parseCount(f[1], prim)) fail(lineNo_, "field 2 (primitive) '" + f[1] + "' is not a non-negative integer");
    if (!parseCount(f[2], vert) || vert > 2) fail(lineNo_, "field 3 (vertex) '" + f[2] + "' is not 0, 1 or 2");
    float uv[3] = {0, 0, 0};
    for (size_t i = 3; i < f.size(); ++i) {
      std::string why;
      if (!parseFactor(f[i], uv[i - 3], &why))
        fail(lineNo_, "field " + std::to_string(i + 1) + " (" + "uvw"[i - 3] + ") '" + f[i] +
                          "': " + (why.empty() ? "not a float" : why));
    }
    sawRow_ = true;
    row = Row{patch, prim, int(vert), CapturedVertex{fx::bitsOf(uv[0]), fx::bitsOf(uv[1])}, lineNo_};
    return true;
  }
  return false;
}

bool CaptureReader::nextCsv(CapturedPatch& out) {
  rows_.clear();
  Row r{};
  if (havePending_) {
    r = pending_;
    havePending_ = false;
  } else if (!readCsvRow(r)) {
    return false;
  }
  if (r.patch <= lastPatch_)
    fail(r.line, "patch " + std::to_string(r.patch) + " after patch " + std::to_string(lastPatch_) +
                     " (rows of a patch must be contiguous, patches in increasing order)");
  lastPatch_ = r.patch;
  rows_.push_back(r);
  while (readCsvRow(r)) {
    if (r.patch != lastPatch_) {
      pending_ = r;
      havePending_ = true;
      break;
    }
    if (rows_.size() > size_t(64 * 64 * 2 * 3 * 2)) fail(r.line, "more rows than any patch has");
    rows_.push_back(r);
  }
  out.line = rows_.front().line;
  std::stable_sort(rows_.begin(), rows_.end(), [](const Row& a, const Row& b) {
    return a.primitive != b.primitive ? a.primitive < b.primitive : a.vertex < b.vertex;
  });
  int arity = 0;
  for (const Row& x : rows_) arity = std::max(arity, x.vertex + 1);
  out.patch = lastPatch_;
  out.verticesPerPrimitive = arity;
  out.vertices.clear();
  out.indices.clear();
  // Each primitive needs vertices 0..arity-1 exactly once.
  for (size_t i = 0; i < rows_.size(); i += size_t(arity)) {
    for (int k = 0; k < arity; ++k) {
      const size_t j = i + size_t(k);
      if (j >= rows_.size() || rows_[j].primitive != rows_[i].primitive || rows_[j].vertex != k ||
          (i > 0 && rows_[i].primitive == rows_[i - 1].primitive)) {
        const Row& bad = j < rows_.size() ? rows_[j] : rows_.back();
        fail(bad.line, "patch " + std::to_string(lastPatch_) + " primitive " + std::to_string(rows_[i].primitive) +
                           ": expected vertices 0.." + std::to_string(arity - 1) + " once each");
      }
      out.vertices.push_back(rows_[j].value);
    }
  }
  return true;
}

} // namespace fftess
