// layout.kind = "patches" (verify/scene_patches.cpp, verify/layout_patches.cpp, verify/layout_export.cpp): a scene's
// layout written as an OBJ or CSV and read back gives the same report as the scene itself (tile rings, a grid), for
// the scene camera and random ones, with and without the adjacency clamp; adjacency is derived exactly from the
// coordinates (a hand-checked big square beside two small ones); each bad file is refused naming its file, line and
// cause (fixtures in tests/verify/data/patches/, one per refusal).
#include "verify_test_util.h"

#include "verify/internal.h"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

using namespace fftess;
using namespace fftess::verify;
using namespace fftess::verify::test;

namespace {

std::string fixture(const std::string& name) {
  return std::string(FFTESS_EXAMPLES_DIR) + "/../../tests/verify/data/patches/" + name;
}

std::string tmpFile(const std::string& name) {
  ::mkdir(FFTESS_TEST_TMP_DIR, 0755);
  return std::string(FFTESS_TEST_TMP_DIR) + "/" + name;
}

void writeFile(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::string hexOf(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%a", v);
  return buf;
}

std::string vecOf(const glm::vec3& v) { return hexOf(v.x) + "," + hexOf(v.y) + "," + hexOf(v.z); }

// A patch as the report names it, without what only identifies a layout (PatchRef::ring, tile, patch).
std::string refOf(const PatchRef& r) { return "#" + std::to_string(r.index) + "/L" + std::to_string(r.level); }

std::string sideOf(const EdgeSide& s) {
  std::ostringstream os;
  os << refOf(s.patch) << " e" << s.edge << " f" << s.hullFactorBits << " p" << hexOf(s.processedFactor)
     << " c" << s.culled << " n" << hexOf(s.lod.neighbourSize) << " m" << hexOf(s.lod.why.metric) << " u"
     << hexOf(s.lod.why.unclamped) << " x" << s.lod.why.fixes << " [" << hexOf(s.paramLo) << "," << hexOf(s.paramHi)
     << "] " << s.pointCount << " " << s.firstMismatch << " " << vecOf(s.mismatchWorld);
  return os.str();
}

std::string holeOf(const Hole& h) {
  std::ostringstream os;
  os << int(h.kind) << " " << refOf(h.patch) << " " << int(h.visibility) << " " << vecOf(h.visiblePoint) << " e"
     << h.edge << " f" << h.hullFactorBits << " " << hexOf(h.lodBoxMinY) << " " << hexOf(h.lodBoxMaxY);
  return os.str();
}

// Everything a report says (every count, every finding, hole and undecided patch with its factors' bits), but the
// layout-identifying PatchRef fields: two reports of the same terrain under two layout kinds describe alike.
std::string describe(const Report& r) {
  const Stats& s = r.stats;
  std::ostringstream os;
  os << "error " << r.error << "\npatches " << s.patches << " culled " << s.culledPatches << " edges "
     << s.edgesChecked << " skipped " << s.skippedCulled << " holes " << s.holes << "/" << s.holesDiscarded << "/"
     << s.holesCulledVisible << " undecided " << s.culledUndecided << "/" << s.undecided << " visibility "
     << s.visibilityTests << " matches " << s.matches << " tj " << s.tJunctions << "/" << s.tJunctionsOffScreen
     << " cracks " << s.cracks << "/" << s.cracksOffScreen << " worst " << hexOf(s.worstGapWorld) << " "
     << hexOf(s.worstGapPixels) << " " << hexOf(s.worstGapWorldOnScreen) << " " << hexOf(s.worstGapPixelsOnScreen)
     << " denormals " << s.denormalFactors << " truncated " << r.truncated << "\n";
  os << "work " << r.work.domainEvaluations << " " << r.work.heightSamples << " " << r.work.lodEvaluations << " "
     << r.work.edgeQueries << " " << r.work.cgalCalls << " " << r.work.sharedEdgePoints << "\n";
  for (const Finding& f : r.findings)
    os << toString(f.classification) << " a " << sideOf(f.a) << " | b " << sideOf(f.b) << " | " << vecOf(f.edgeStart)
       << " " << vecOf(f.edgeEnd) << " gap " << hexOf(f.gapWorld) << " " << hexOf(f.gapPixels) << " "
       << vecOf(f.gapVertex) << " " << f.gapSide << " on " << f.onScreen << " " << hexOf(f.onScreenGapWorld) << " "
       << hexOf(f.onScreenGapPixels) << "\n";
  for (const Hole& h : r.holes) os << "hole " << holeOf(h) << "\n";
  for (const Hole& h : r.undecided) os << "undecided " << holeOf(h) << "\n";
  return os.str();
}

// The scene's layout exported (OBJ or CSV) and read back as layout.kind = "patches" with the same other keys.
Terrain readBack(const std::string& example, const std::vector<std::string>& overrides, const Terrain& original,
                 const std::string& name) {
  const bool obj = name.size() > 4 && name.compare(name.size() - 4, 4, ".obj") == 0;
  const std::string file = tmpFile(name);
  writeFile(file, obj ? layoutObj(original) : layoutCsv(original));
  std::vector<std::string> o = overrides;
  o.push_back("layout.kind=\"patches\"");
  o.push_back("layout.file=\"" + file + "\"");
  return prepared(loadExample(example, o));
}

// The same cameras checked on the scene and on its read-back layout: equal reports; returns the findings seen.
size_t sameReports(const Terrain& a, const Terrain& b, const std::vector<Camera>& cameras) {
  size_t findings = 0;
  for (size_t i = 0; i < cameras.size(); ++i) {
    INFO("camera " << i);
    const Report ra = checkScene(a, cameras[i]);
    const Report rb = checkScene(b, cameras[i]);
    REQUIRE(ra.error.empty());
    CHECK(describe(ra) == describe(rb));
    findings += ra.findings.size() + ra.holes.size();
  }
  return findings;
}

void roundTrip(const std::string& example, const std::vector<std::string>& overrides, const std::string& name,
               bool expectFindings) {
  const Terrain original = prepared(loadExample(example, overrides));
  for (const char* ext : {".obj", ".csv"}) {
    INFO(example << " as " << ext);
    const Terrain back = readBack(example, overrides, original, name + ext);
    REQUIRE(back.patchCount() == original.patchCount());
    for (int i = 0; i < original.patchCount(); ++i)
      for (int c = 0; c < 4; ++c) {
        REQUIRE(bitsOf(back.patches()[size_t(i)].corners[c].x) == bitsOf(original.patches()[size_t(i)].corners[c].x));
        REQUIRE(bitsOf(back.patches()[size_t(i)].corners[c].z) == bitsOf(original.patches()[size_t(i)].corners[c].z));
        REQUIRE(bitsOf(back.patches()[size_t(i)].heights[c]) == bitsOf(original.patches()[size_t(i)].heights[c]));
      }
    CHECK(back.patches()[0].ref.level == original.patches()[0].ref.level);
    CHECK(back.patches().back().ref.level == original.patches().back().ref.level);
    std::vector<Camera> cameras{original.scene().camera};
    for (const Camera& c : randomCameras(original, 5, 20261202)) cameras.push_back(c);
    const size_t findings = sameReports(original, back, cameras);
    if (expectFindings) CHECK(findings > 0); // the comparison saw findings, not only clean reports
  }
}

// The error of loading and preparing a scene whose layout is the fixture (loadScene's or prepareTerrain's).
std::string refusal(const std::string& name) {
  const SceneResult r =
      loadScene(examplePath("grid.toml"), {"layout.kind=\"patches\"", "layout.file=\"" + fixture(name) + "\""});
  if (!r) return r.error;
  const TerrainResult t = prepareTerrain(r.scene);
  return t ? std::string() : t.error;
}

} // namespace

TEST_CASE("patches layout: the default scene read back from its OBJ and CSV gives the tile rings' reports",
          "[verify][patches]") {
  roundTrip("terrain.toml", {}, "terrain_pow2", false);
}

TEST_CASE("patches layout: without the clamp the read-back default scene finds the tile rings' very cracks",
          "[verify][patches]") {
  roundTrip("terrain.toml", {"lod.adjacency_clamp=\"none\""}, "terrain_none", true);
}

TEST_CASE("patches layout: a grid scene read back gives the grid's reports, with findings under patch_center LOD",
          "[verify][patches]") {
  roundTrip("grid.toml", {}, "grid", false);
  roundTrip("grid.toml", {"lod.scheme=\"patch_center\""}, "grid_patch_center", true);
}

TEST_CASE("patches layout: a big square beside two small ones gets exact sizes, levels and neighbour lists",
          "[verify][patches]") {
  const std::string file = tmpFile("big_and_two_small.csv");
  // Patch 0: [0, 2] x [0, 2]; patch 1: [2, 3] x [0, 1]; patch 2: [2, 3] x [1, 2] (corners in any order). Also read:
  // a byte order mark, CRLF, a quoted column name, y columns (ignored), spaces, a comment and a blank line.
  writeFile(file, "\xEF\xBB\xBF\"x0\",y0,z0,x1,z1,x2,z2,x3,z3\r\n# big first\r\n0,9,0,2,0,0,2,2,2\r\n\r\n"
                  "3, 9, 1, 2,0,3,0,2,1\n2,9,1,3,1,2,2,3,2\n");
  const Terrain t = prepared(loadExample("grid.toml", {"layout.kind=\"patches\"", "layout.file=\"" + file + "\""}));
  const detail::TerrainData& d = t.data();
  REQUIRE(d.patches.size() == 3);
  CHECK(d.unit == 1.0);
  CHECK(d.unitsX == 3);
  CHECK(d.unitsZ == 2);
  CHECK(d.adjacency);
  CHECK(d.extent.minX == 0.0f);
  CHECK(d.extent.maxX == 3.0f);
  CHECK(d.extent.maxZ == 2.0f);
  const int64_t sizes[3] = {2, 1, 1}, ux[3] = {0, 2, 2}, uz[3] = {0, 0, 1};
  const int levels[3] = {1, 0, 0};
  // Neighbour lists per edge (Ueq0 Veq0 Ueq1 Veq1), in order along the edge.
  const std::vector<int32_t> lists[3][4] = {{{}, {}, {1, 2}, {}}, {{0}, {}, {}, {2}}, {{0}, {1}, {}, {}}};
  for (size_t i = 0; i < 3; ++i) {
    const detail::TerrainPatch& p = d.patches[i];
    INFO("patch " << i);
    CHECK(p.size == sizes[i]);
    CHECK(p.ux == ux[i]);
    CHECK(p.uz == uz[i]);
    CHECK(p.ref.level == levels[i]);
    for (int e = 0; e < 4; ++e)
      CHECK(std::vector<int32_t>(d.neighboursBegin(p, e), d.neighboursEnd(p, e)) == lists[i][e]);
  }
  // Corners in fftess's order: patch 1 was given as (3,1) (2,0) (3,0) (2,1).
  CHECK(d.patches[1].corners[0] == glm::vec3(2, 0, 0));
  CHECK(d.patches[1].corners[1] == glm::vec3(3, 0, 0));
  CHECK(d.patches[1].corners[2] == glm::vec3(2, 0, 1));
  CHECK(d.patches[1].corners[3] == glm::vec3(3, 0, 1));
  // The LOD's neighbour inputs: the big side sees 0.5 across +x, the small ones 2 across -x, the second one odd.
  CHECK(d.patches[0].tile.size[Ueq1] == 0.5f);
  CHECK(d.patches[1].tile.size[Ueq0] == 2.0f);
  CHECK(d.patches[2].tile.size[Ueq0] == 2.0f);
  CHECK_FALSE(d.patches[1].tile.oddV);
  CHECK(d.patches[2].tile.oddV);
  CHECK(d.patches[1].tile.farCorner[Ueq0] == d.patches[0].lod.corners[3]); // (2, 2): the big edge's other end
  CHECK(d.patches[2].tile.farCorner[Ueq0] == d.patches[0].lod.corners[1]); // (2, 0)
}

TEST_CASE("patches layout: the lattice step is the coordinates' common power of two, sizes any integer",
          "[verify][patches]") {
  const std::string file = tmpFile("thirds.obj");
  // Two squares of side 0.75 at x = 10.25 and 11: differences 0, 0.75, 1.5 from the lowest x: step 0.25.
  writeFile(file, "v 10.25 0 -1\nv 11 0 -1\nv 11.75 0 -1\nv 10.25 0 -0.25\nv 11 0 -0.25\nv 11.75 0 -0.25\n"
                  "f 1 4 5 2\nf 2/1 3/1 6/1 5/1\n");
  const Terrain t = prepared(loadExample("grid.toml", {"layout.kind=\"patches\"", "layout.file=\"" + file + "\""}));
  const detail::TerrainData& d = t.data();
  CHECK(d.unit == 0.25);
  CHECK(d.patches[0].size == 3);
  CHECK(d.patches[1].ux == 3);
  CHECK(d.unitsX == 6);
  CHECK(d.unitsZ == 3);
  CHECK_FALSE(d.adjacency);
  CHECK(std::vector<int32_t>(d.neighboursBegin(d.patches[0], Ueq1), d.neighboursEnd(d.patches[0], Ueq1)) ==
        std::vector<int32_t>{1});
}

TEST_CASE("patches layout: each bad file is refused naming the file, the line and the cause", "[verify][patches]") {
  struct Case {
    const char* file;
    const char* where; // "FILE:LINE" as the message names it
    const char* cause;
  };
  const Case cases[] = {
      {"non_quad.obj", "non_quad.obj:7:", "a face of 3 vertices: a patch is a quad"},
      {"bad_index.obj", "bad_index.obj:6:", "vertex reference '9' is out of range (4 vertices defined before this line)"},
      {"nan.obj", "nan.obj:3:", "vertex x: 'nan' is not finite"},
      {"not_square.obj", "not_square.obj:6:", "not a square: its x side is 2, its z side 1"},
      {"bow_tie.obj", "bow_tie.obj:6:", "the face's vertices do not go round the square"},
      {"overlap.obj", "overlap.obj:10 and line 11:", "patches overlap (x 0 .. 2, z 0 .. 2; x 1 .. 3, z 1 .. 3): they overlap"},
      {"inside.obj", "inside.obj:15 and line 16:", "the second lies inside the first"},
      {"gap.obj", "gap.obj:15:", "a gap: nothing lies across the patch's +z edge (x 1 .. 2, z 0 .. 1) at z 1, x 1 .. 2"},
      {"non_nesting.obj", "non_nesting.obj:30 and line 32:", "share part of an edge without one edge containing the other"},
      {"lattice_too_fine.obj", "lattice_too_fine.obj:6:", "the lattice is too fine"},
      {"empty.obj", "empty.obj:1:", "no patches: the file holds no face"},
      {"line_element.obj", "line_element.obj:3:", "OBJ statement 'l' is not read"},
      {"missing_column.csv", "missing_column.csv:2:", "header: missing column 'z2'"},
      {"bad_number.csv", "bad_number.csv:3:", "column x1 (field 3): 'two' is not a number"},
      {"header_only.csv", "header_only.csv:1:", "no patches: a header without rows"},
      {"short_row.csv", "short_row.csv:3:", "a row of 7 fields (the header has 8)"},
  };
  for (const Case& c : cases) {
    INFO(c.file);
    const std::string error = refusal(c.file);
    INFO(error);
    CHECK(error.find(fixture(c.where)) == 0); // the data file's position first
    CHECK(error.find(c.cause) != std::string::npos);
  }
  // A loader refusal names where layout.file was given, after the data file's position.
  CHECK(refusal("non_quad.obj").find("(--set layout.file)") != std::string::npos);
}

TEST_CASE("patches layout: the file's bytes are part of the scene's content hash", "[verify][patches]") {
  const std::string file = tmpFile("hash.csv");
  const std::vector<std::string> o{"layout.kind=\"patches\"", "layout.file=\"" + file + "\""};
  writeFile(file, "x0,z0,x1,z1,x2,z2,x3,z3\n0,0,1,0,0,1,1,1\n");
  const uint64_t a = loadExample("grid.toml", o).contentHash;
  writeFile(file, "x0,z0,x1,z1,x2,z2,x3,z3\n0,0,1,0,0,1,1,1\n\n");
  CHECK(loadExample("grid.toml", o).contentHash != a);
}

TEST_CASE("patches layout: the example scene's own layout is watertight with the pow2 clamp and cracks without",
          "[verify][patches]") {
  // docs/examples/patches.toml: patches.obj, a 2:1 balanced refinement of 136 squares of 1 to 16 world units.
  const Terrain t = prepared(loadExample("patches.toml"));
  REQUIRE(t.patchCount() == 136);
  CHECK(t.data().adjacency);
  const Report clamped = checkScene(t, t.scene().camera);
  CHECK(verdictOf(clamped.stats) == Verdict::Watertight);
  CHECK(clamped.stats.edgesChecked == 284);
  const Terrain none = prepared(loadExample("patches.toml", {"lod.adjacency_clamp=none"}));
  const Report cracked = checkScene(none, none.scene().camera);
  CHECK(verdictOf(cracked.stats) == Verdict::Cracks);
  CHECK(cracked.stats.cracks == 70);
  for (const Finding& f : cracked.findings) // every crack at a size jump: side a the larger patch
    CHECK(f.a.patch.level == f.b.patch.level + 1);
}
