// A terrain's patches written as a layout.kind = "patches" file (verify/terrain.h: layoutObj, layoutCsv), so that any
// scene's layout (tile rings, a camera's quadtree) can be read back, edited or handed to another tool.
// docs/verify.md, "Patches".
#include "verify/terrain.h"

#include "base/bits.h"

#include <charconv>
#include <unordered_map>

namespace fftess::verify {

namespace {

// The shortest decimal that reads back (from_chars, strtof) to the same float: std::to_chars' guarantee.
void appendFloat(std::string& out, float f) {
  char buf[48];
  const auto r = std::to_chars(buf, buf + sizeof buf, f);
  out.append(buf, r.ptr);
}

} // namespace

std::string layoutObj(const Terrain& layout, const std::vector<std::string>& comments) {
  std::string out;
  for (const std::string& c : comments) out += "# " + c + "\n";
  std::unordered_map<uint64_t, int64_t> index; // (x bits, z bits) -> 1-based vertex number
  std::string faces;
  for (const PatchGeometry& p : layout.patches()) {
    faces += 'f';
    for (int c : {0, 2, 3, 1}) { // counter-clockwise seen from +y: (x0 z0) (x0 z1) (x1 z1) (x1 z0)
      const glm::vec3& q = p.corners[c];
      const uint64_t key = uint64_t(bitsOf(q.x)) << 32 | bitsOf(q.z);
      auto [it, added] = index.emplace(key, static_cast<int64_t>(index.size()) + 1);
      if (added) {
        out += "v ";
        appendFloat(out, q.x);
        out += ' ';
        appendFloat(out, p.heights[c]);
        out += ' ';
        appendFloat(out, q.z);
        out += '\n';
      }
      faces += ' ' + std::to_string(it->second);
    }
    faces += '\n';
  }
  return out + faces;
}

std::string layoutCsv(const Terrain& layout) {
  std::string out = "x0,z0,x1,z1,x2,z2,x3,z3\n";
  for (const PatchGeometry& p : layout.patches()) {
    for (int c = 0; c < 4; ++c) {
      appendFloat(out, p.corners[c].x);
      out += ',';
      appendFloat(out, p.corners[c].z);
      out += c < 3 ? ',' : '\n';
    }
  }
  return out;
}

} // namespace fftess::verify
