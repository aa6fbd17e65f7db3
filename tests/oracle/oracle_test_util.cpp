#include "oracle_test_util.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace fftess {
namespace oracle {

void unavailable(const char* testName, const std::string& why) {
  if (std::getenv("CI")) {
    std::fprintf(stderr, "%s: FAILED: %s (CI is set: the GPU oracle is required here)\n", testName, why.c_str());
    std::exit(1);
  }
  std::fprintf(stderr, "%s: SKIPPED: %s (would fail with CI set)\n", testName, why.c_str());
  std::exit(kSkipExitCode);
}

std::unique_ptr<GlOracle> createOracleOrExit(const char* testName) {
  std::string error;
  auto o = GlOracle::create(error);
  if (!o) unavailable(testName, error);
  if (!o->isLlvmpipe())
    unavailable(testName, "the GL renderer is '" + o->renderer() + "', not llvmpipe (the test environment sets "
                          "GALLIUM_DRIVER=llvmpipe and Mesa's EGL vendor)");
  std::fprintf(stderr, "%s: renderer %s, %s\n", testName, o->renderer().c_str(), o->version().c_str());
  return o;
}

bool readOutFile(const std::string& path, std::vector<Expected>& out, std::string& error) {
  std::ifstream in(path);
  if (!in) {
    error = "cannot read " + path;
    return false;
  }
  out.clear();
  std::string line;
  int lineNumber = 0;
  auto fail = [&](const std::string& what) {
    error = path + ":" + std::to_string(lineNumber) + ": " + what;
    return false;
  };
  while (std::getline(in, line)) {
    ++lineNumber;
    if (line.empty()) continue;
    int n = 0, p = 0, i = 0;
    if (std::sscanf(line.c_str(), "patch %d points %d indices %d", &n, &p, &i) != 3 || n != static_cast<int>(out.size()))
      return fail("expected 'patch " + std::to_string(out.size()) + " points P indices I'");
    Expected e;
    e.points.reserve(static_cast<size_t>(p) * 2);
    for (int k = 0; k < p; ++k) {
      ++lineNumber;
      unsigned u = 0, v = 0;
      if (!std::getline(in, line) || std::sscanf(line.c_str(), "%8x %8x", &u, &v) != 2) return fail("bad point line");
      e.points.push_back(u);
      e.points.push_back(v);
    }
    while (static_cast<int>(e.indices.size()) < i) {
      ++lineNumber;
      if (!std::getline(in, line)) return fail("missing index lines");
      std::istringstream ls(line);
      for (int x; ls >> x;) e.indices.push_back(x);
    }
    if (static_cast<int>(e.indices.size()) != i) return fail("index count mismatch");
    out.push_back(std::move(e));
  }
  return true;
}

namespace {
bool isDenormal(uint32_t bits) { return (bits & 0x7f800000u) == 0 && (bits & 0x007fffffu) != 0; }
int usedFactors(const Patch& p) { return p.domain == Domain::Quad ? 6 : p.domain == Domain::Tri ? 4 : 2; }
int outerFactors(const Patch& p) { return p.domain == Domain::Quad ? 4 : p.domain == Domain::Tri ? 3 : 2; }

std::string hexPair(uint32_t u, uint32_t v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "(%08x %08x)", u, v);
  return buf;
}
} // namespace

bool hasDuplicatePoints(const Result& r) {
  std::vector<uint64_t> keys;
  keys.reserve(r.points.size() / 2);
  for (size_t i = 0; i + 1 < r.points.size(); i += 2) keys.push_back(uint64_t(r.points[i]) << 32 | r.points[i + 1]);
  std::sort(keys.begin(), keys.end());
  return std::adjacent_find(keys.begin(), keys.end()) != keys.end();
}

bool hasDenormalFactor(const Patch& p) {
  for (int i = 0; i < usedFactors(p); ++i)
    if (isDenormal(p.factorBits[i])) return true;
  return false;
}

bool hasDenormalOuterFactor(const Patch& p) {
  for (int i = 0; i < outerFactors(p); ++i)
    if (isDenormal(p.factorBits[i])) return true;
  return false;
}

Verdict compare(const Patch& patch, const Result& got, const Expected& want) {
  Verdict v;
  std::ostringstream why;
  // Points: count, bits, order.
  if (got.points != want.points) {
    v.points = false;
    const size_t n = std::min(got.points.size(), want.points.size());
    size_t k = 0;
    while (k < n && got.points[k] == want.points[k]) ++k;
    why << "points: GL " << got.pointCount() << ", expected " << want.points.size() / 2;
    if (k < n)
      why << "; first difference at point " << k / 2 << ": GL " << hexPair(got.points[k & ~size_t(1)], got.points[k | 1])
          << " expected " << hexPair(want.points[k & ~size_t(1)], want.points[k | 1]);
    why << ". ";
  }
  // Primitives as coordinates (only where GL draws primitives).
  if (hasGlPrimitives(patch)) {
    const size_t verts = got.primitives.size() / 2;
    bool same = verts == want.indices.size();
    size_t k = 0;
    for (; same && k < verts; ++k) {
      const int32_t idx = want.indices[k];
      same = idx >= 0 && static_cast<size_t>(idx) * 2 + 1 < want.points.size() &&
             want.points[2 * idx] == got.primitives[2 * k] && want.points[2 * idx + 1] == got.primitives[2 * k + 1];
    }
    if (!same) {
      v.primitives = false;
      const int per = got.verticesPerPrimitive;
      why << "primitives: GL " << verts / per << ", expected " << want.indices.size() / per;
      if (k > 0 && k <= verts) why << "; first difference in primitive " << (k - 1) / per;
      why << ". ";
    }
  }
  if (got.indices != want.indices) {
    v.indices = false;
    const size_t n = std::min(got.indices.size(), want.indices.size());
    size_t k = 0;
    while (k < n && got.indices[k] == want.indices[k]) ++k;
    why << "indices: GL " << got.indices.size() << ", expected " << want.indices.size();
    if (k < n) why << "; first difference at index " << k << ": GL " << got.indices[k] << " expected " << want.indices[k];
    why << ". ";
  }
  v.firstDifference = why.str();
  return v;
}

} // namespace oracle
} // namespace fftess
