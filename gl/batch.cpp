// Batch text format for the GL oracle (the same format as `fftess tessellate --format hex` and shared/golden),
// parsed here independently of the fftess CLI so the oracle shares no code with what it checks.
#include "gl_capture.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace fftess {
namespace oracle {

const char* toString(Domain d) {
  switch (d) {
  case Domain::Quad: return "quad";
  case Domain::Tri: return "tri";
  case Domain::Isoline: return "isoline";
  }
  return "?";
}

const char* toString(Partitioning p) {
  switch (p) {
  case Partitioning::Integer: return "integer";
  case Partitioning::Pow2: return "pow2";
  case Partitioning::FractionalOdd: return "fractional_odd";
  case Partitioning::FractionalEven: return "fractional_even";
  }
  return "?";
}

const char* toString(Topology t) {
  switch (t) {
  case Topology::Point: return "point";
  case Topology::Line: return "line";
  case Topology::TriangleCw: return "triangle_cw";
  case Topology::TriangleCcw: return "triangle_ccw";
  }
  return "?";
}

std::string batchLine(const Patch& p) {
  std::string s = std::string(toString(p.domain)) + " " + toString(p.partitioning) + " " + toString(p.topology) + " hw";
  char buf[16];
  for (uint32_t b : p.factorBits) {
    std::snprintf(buf, sizeof buf, " 0x%08x", b);
    s += buf;
  }
  return s;
}

int indicesPerPrimitive(const Patch& p) {
  switch (p.topology) {
  case Topology::Point: return 1;
  case Topology::Line: return 2;
  case Topology::TriangleCw:
  case Topology::TriangleCcw: return p.domain == Domain::Isoline ? 2 : 3;
  }
  return 1;
}

bool hasGlPrimitives(const Patch& p) {
  if (p.domain == Domain::Isoline) return p.topology == Topology::Line;
  return p.topology == Topology::TriangleCw || p.topology == Topology::TriangleCcw;
}

namespace {

bool parseFactor(const std::string& tok, uint32_t& bits) {
  if (tok.size() >= 2 && tok[0] == '0' && (tok[1] == 'x' || tok[1] == 'X')) {
    if (tok.size() != 10) return false;
    uint32_t v = 0;
    for (size_t i = 2; i < 10; ++i) {
      const char c = tok[i];
      int d = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
      if (d < 0) return false;
      v = v << 4 | static_cast<uint32_t>(d);
    }
    bits = v;
    return true;
  }
  if (tok.empty()) return false;
  char* end = nullptr;
  errno = 0;
  const float f = std::strtof(tok.c_str(), &end);
  if (end != tok.c_str() + tok.size()) return false;
  std::memcpy(&bits, &f, sizeof bits);
  return true;
}

} // namespace

bool parseBatch(const std::string& text, std::vector<BatchLine>& out, std::string& error) {
  out.clear();
  std::istringstream in(text);
  std::string line;
  int lineNumber = 0;
  while (std::getline(in, line)) {
    ++lineNumber;
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream ls(line);
    std::vector<std::string> tok;
    for (std::string t; ls >> t;) tok.push_back(t);
    if (tok.empty()) continue;
    auto fail = [&](const std::string& what) {
      error = "line " + std::to_string(lineNumber) + ": " + what;
      return false;
    };
    if (tok.size() != 10)
      return fail("expected 10 fields 'DOMAIN PARTITIONING TOPOLOGY STAGE f0 .. f5', got " + std::to_string(tok.size()));
    BatchLine b;
    b.lineNumber = lineNumber;
    Patch& p = b.patch;
    if (tok[0] == "quad") p.domain = Domain::Quad;
    else if (tok[0] == "tri") p.domain = Domain::Tri;
    else if (tok[0] == "isoline") p.domain = Domain::Isoline;
    else return fail("bad domain '" + tok[0] + "' (quad|tri|isoline)");
    if (tok[1] == "integer") p.partitioning = Partitioning::Integer;
    else if (tok[1] == "pow2") p.partitioning = Partitioning::Pow2;
    else if (tok[1] == "fractional_odd") p.partitioning = Partitioning::FractionalOdd;
    else if (tok[1] == "fractional_even") p.partitioning = Partitioning::FractionalEven;
    else return fail("bad partitioning '" + tok[1] + "' (integer|pow2|fractional_odd|fractional_even)");
    if (tok[2] == "point") p.topology = Topology::Point;
    else if (tok[2] == "line") p.topology = Topology::Line;
    else if (tok[2] == "triangle_cw") p.topology = Topology::TriangleCw;
    else if (tok[2] == "triangle_ccw") p.topology = Topology::TriangleCcw;
    else return fail("bad topology '" + tok[2] + "' (point|line|triangle_cw|triangle_ccw)");
    if (p.domain == Domain::Isoline && (p.topology == Topology::TriangleCw || p.topology == Topology::TriangleCcw))
      return fail("topology '" + tok[2] + "' is not an isoline output (point|line)");
    if (tok[3] != "hw") {
      const bool known = tok[3].rfind("hlsl-", 0) == 0;
      return fail("stage '" + tok[3] + "' " +
                  (known ? "is not supported by the GPU oracle: a fixed-function tessellator has only the hw stage"
                         : "is unknown (the GPU oracle accepts only hw)"));
    }
    for (int i = 0; i < 6; ++i) {
      if (!parseFactor(tok[4 + i], p.factorBits[i]))
        return fail("bad factor f" + std::to_string(i) + " '" + tok[4 + i] +
                    "' (a decimal float or 0x followed by exactly 8 hex digits)");
    }
    out.push_back(b);
  }
  return true;
}

void writePatchBlock(std::string& out, int patchNumber, const Patch& patch, const Result& r) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "patch %d points %d indices %zu\n", patchNumber, r.pointCount(), r.indices.size());
  out += buf;
  for (size_t i = 0; i < r.points.size(); i += 2) {
    std::snprintf(buf, sizeof buf, "%08x %08x\n", r.points[i], r.points[i + 1]);
    out += buf;
  }
  const size_t per = static_cast<size_t>(indicesPerPrimitive(patch));
  for (size_t i = 0; i < r.indices.size(); i += per) {
    for (size_t k = 0; k < per && i + k < r.indices.size(); ++k) {
      std::snprintf(buf, sizeof buf, k ? " %d" : "%d", r.indices[i + k]);
      out += buf;
    }
    out += '\n';
  }
}

} // namespace oracle
} // namespace fftess
