// fftess layout: a scene's patches written as a layout.kind = "patches" file (OBJ, CSV), read back by check to the
// same report as the scene's own layout; a bad patches file is refused with its file:line (exit 2, nothing written);
// the outputs are checked before any work and written all or nothing.
#include "run.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <functional>
#include <string>

using clitest::run;
using json = nlohmann::ordered_json;

namespace {

const std::string kTerrain = clitest::source("docs/examples/terrain.toml");
const std::string kGrid = clitest::source("docs/examples/grid.toml");

// A check report without what names the layout or the scene's bytes: scene_hash, the scene's layout kind and
// overrides, and the PatchRef fields that identify a layout (ring, tile, patch; index and level stay).
json withoutLayout(json j) {
  j.erase("scene_hash");
  j.at("scene").erase("layout");
  j.at("scene").erase("overrides");
  std::function<void(json&)> strip = [&](json& v) {
    if (v.is_object()) {
      for (const char* k : {"ring", "tile", "patch"})
        if (v.contains(k) && v[k].is_number()) v.erase(k);
      for (auto& [k, x] : v.items()) strip(x);
    } else if (v.is_array()) {
      for (json& x : v) strip(x);
    }
  };
  strip(j);
  return j;
}

} // namespace

TEST_CASE("layout: the default scene written as OBJ and CSV checks like tile rings when read back", "[cli][layout]") {
  const std::string dir = clitest::tmpDir();
  const std::string obj = dir + "/terrain_layout.obj", csv = dir + "/terrain_layout.csv";
  clitest::Result r = run({"layout", kTerrain, "--obj", obj, "--csv", csv});
  REQUIRE(r.status == 0);
  CHECK(r.out == "layout: 10240 patches (3 levels) written to '" + obj + "' and '" + csv + "'\n");
  CHECK(clitest::readFile(csv).rfind("x0,z0,x1,z1,x2,z2,x3,z3\n", 0) == 0);
  const std::string noClamp = "lod.adjacency_clamp=none"; // so that there are findings to compare
  const std::string a = dir + "/layout_rings.json";
  REQUIRE(run({"check", kTerrain, "-q", "--set", noClamp, "--json", a}).status == 1);
  const json rings = json::parse(clitest::readFile(a));
  REQUIRE(rings.at("findings").size() > 0);
  for (const std::string& file : {obj, csv}) {
    INFO(file);
    const std::string b = dir + "/layout_patches.json";
    r = run({"check", kTerrain, "-q", "--set", noClamp, "--set", "layout.kind=patches", "--set",
             "layout.file=" + file, "--json", b});
    CHECK(r.status == 1);
    const json patches = json::parse(clitest::readFile(b));
    CHECK(patches.at("scene").at("layout") == "patches");
    CHECK(withoutLayout(patches) == withoutLayout(rings));
  }
}

TEST_CASE("layout: a bad patches file is refused naming its file and line, and no report is written",
          "[cli][layout]") {
  const std::string dir = clitest::tmpDir();
  const std::string gap = clitest::source("tests/verify/data/patches/gap.obj");
  clitest::Result r = run({"check", kGrid, "--set", "layout.kind=patches", "--set", "layout.file=" + gap, "--json",
                           dir + "/gap.json"});
  CHECK(r.status == 2);
  CHECK(r.err.find(gap + ":15: a gap: nothing lies across the patch's +z edge") != std::string::npos);
  CHECK_FALSE(clitest::fileExists(dir + "/gap.json"));
  const std::string nonQuad = clitest::source("tests/verify/data/patches/non_quad.obj");
  r = run({"layout", kGrid, "--set", "layout.kind=patches", "--set", "layout.file=" + nonQuad, "--obj",
           dir + "/non_quad_out.obj"});
  CHECK(r.status == 2);
  CHECK(r.err == "fftess: error: " + nonQuad +
                     ":7: a face of 3 vertices: a patch is a quad (a face of exactly 4 vertex references) (--set "
                     "layout.file)\n");
  CHECK_FALSE(clitest::fileExists(dir + "/non_quad_out.obj"));
}

TEST_CASE("layout: outputs are checked before any work, one may be stdout, and the file reads back", "[cli][layout]") {
  const std::string dir = clitest::tmpDir();
  clitest::Result r = run({"layout", kGrid});
  CHECK(r.status == 2);
  CHECK(r.err.find("layout: nothing to write (give --obj FILE and/or --csv FILE)") != std::string::npos);
  r = run({"layout", kGrid, "--obj", kGrid});
  CHECK(r.status == 2);
  CHECK(r.err.find("--obj") != std::string::npos);
  r = run({"layout", kGrid, "--obj", dir + "/no/such/folder/x.obj"});
  CHECK(r.status == 2);
  r = run({"layout", kGrid, "--obj", "-", "--csv", "-"});
  CHECK(r.status == 2);
  // A read-back file is the scene's input: writing over it is refused.
  const std::string obj = dir + "/grid_layout.obj";
  r = run({"layout", kGrid, "--obj", "-"});
  REQUIRE(r.status == 0);
  CHECK(r.out.rfind("# fftess layout of ", 0) == 0);
  CHECK(r.out.find("\nf 1 2 3 4\n") != std::string::npos);
  clitest::writeFile(obj, r.out);
  r = run({"layout", kGrid, "--set", "layout.kind=patches", "--set", "layout.file=" + obj, "--obj", obj});
  CHECK(r.status == 2);
  CHECK(r.err.find("layout.file") != std::string::npos);
  // Written again from the read-back layout: the same faces and vertices (the comment names the kind).
  r = run({"layout", kGrid, "--set", "layout.kind=patches", "--set", "layout.file=" + obj, "--obj", "-"});
  REQUIRE(r.status == 0);
  const std::string first = clitest::readFile(obj);
  CHECK(r.out.substr(r.out.find("\nv ")) == first.substr(first.find("\nv ")));
}
