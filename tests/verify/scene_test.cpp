// Scene files: the bundled examples load; every malformed scene is rejected with the key and the file position.
#include "verify_test_util.h"

#include <cmath>

using namespace fftess::verify;
using namespace fftess::verify::test;

namespace {

const char* kBase = R"(name = "t"
[layout]
kind = "tile_rings"
rings = 2
tiles_per_ring_edge = 4
patches_per_tile_edge = 2
base_patch_size = 1.0
[displacement]
kind = "none"
[lod]
scheme = "screen_sphere"
adjacency_clamp = "pow2"
[tessellation]
partitioning = "fractional_even"
[camera]
eye = [0.0, 10.0, -20.0]
target = [0.0, 0.0, 0.0]
)";

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const size_t at = s.find(from);
  REQUIRE(at != std::string::npos);
  return s.replace(at, from.size(), to);
}

void requireError(const SceneResult& r, const std::vector<std::string>& parts) {
  INFO(r.error);
  REQUIRE_FALSE(r.ok);
  for (const std::string& p : parts) CHECK(r.error.find(p) != std::string::npos);
}

} // namespace

TEST_CASE("bundled example scenes load", "[verify][scene]") {
  for (const char* name : {"terrain.toml", "grid.toml", "rings_small.toml", "broken_lod.toml", "luna.toml", "geomorph.toml",
                           "bonaventura_mip.toml", "luna_r16.toml"}) {
    INFO(name);
    Scene s = loadExample(name);
    CHECK(prepared(s).patchCount() > 0);
    CHECK(s.source.find(name) != std::string::npos);
  }
}

TEST_CASE("default scene is the NVIDIA sample setup", "[verify][scene]") {
  Scene s = loadExample("terrain.toml");
  CHECK(s.layout.kind == LayoutKind::TileRings);
  CHECK(s.layout.patchesPerTileEdge == 8);
  CHECK(s.lod.scheme == LodScheme::ScreenSphere);
  CHECK(s.lod.screenSphere.sphere.tessellatedTriWidth == 3.0f);
  CHECK(s.camera.width == 1920);
  CHECK(s.camera.height == 1200);
  CHECK(s.partitioning == fftess::Partitioning::FractionalEven);
  CHECK(s.lod.screenSphere.clamp == AdjacencyClamp::Pow2);
  CHECK(s.displacement.kind == DisplacementKind::Fbm);
  REQUIRE(s.displacement.texels);
  CHECK(s.displacement.texels->size() == size_t(513) * 513);
  // rings 3 of 8x8 tiles of 8x8 patches: 64 tiles + 2 x 48 tiles.
  CHECK(prepared(s).patchCount() == (64 + 48 + 48) * 64);
}

TEST_CASE("tile ring layout: sizes and extent", "[verify][scene]") {
  SceneResult r = parseScene(kBase, "t.toml");
  REQUIRE(r.ok);
  // ring 0: 4x4 tiles of 2x2 patches; ring 1: 12 tiles of 2x2 patches of size 2.
  CHECK(prepared(r.scene).patchCount() == 16 * 4 + 12 * 4);
  Extent e = prepared(r.scene).extent();
  CHECK(e.minX == -8.0f);
  CHECK(e.maxX == 8.0f);
  CHECK(prepared(r.scene).patches()[0].ref.ring == 0);
  CHECK(prepared(r.scene).patches()[16 * 4].ref.ring == 1);
  CHECK(prepared(r.scene).patches()[16 * 4].ref.level == 1);
}

TEST_CASE("malformed scenes name the key and the file position", "[verify][scene]") {
  SECTION("syntax error") { requireError(parseScene("[layout\nkind = 1", "bad.toml"), {"bad.toml:1:"}); }
  SECTION("missing table") {
    requireError(parseScene(replaced(kBase, "[lod]\nscheme = \"screen_sphere\"\nadjacency_clamp = \"pow2\"\n", ""),
                            "t.toml"),
                 {"t.toml:", "lod: missing table"});
  }
  SECTION("missing key") {
    requireError(parseScene(replaced(kBase, "partitioning = \"fractional_even\"\n", ""), "t.toml"),
                 {"tessellation.partitioning: missing key"});
  }
  SECTION("wrong type") {
    requireError(parseScene(replaced(kBase, "rings = 2", "rings = \"two\""), "t.toml"),
                 {"t.toml:4:9: layout.rings: expected an integer, got a string"});
  }
  SECTION("negative size") {
    requireError(parseScene(replaced(kBase, "base_patch_size = 1.0", "base_patch_size = -1.0"), "t.toml"),
                 {"t.toml:7:", "layout.base_patch_size: must be > 0"});
  }
  SECTION("odd tile count") {
    requireError(parseScene(replaced(kBase, "tiles_per_ring_edge = 4", "tiles_per_ring_edge = 6"), "t.toml"),
                 {"t.toml:5:", "layout.tiles_per_ring_edge"});
  }
  SECTION("NaN in a camera") {
    requireError(parseScene(replaced(kBase, "eye = [0.0, 10.0, -20.0]", "eye = [0.0, nan, -20.0]"), "t.toml"),
                 {"t.toml:16:", "camera.eye", "finite"});
  }
  SECTION("camera looking at itself") {
    requireError(parseScene(replaced(kBase, "target = [0.0, 0.0, 0.0]", "target = [0.0, 10.0, -20.0]"), "t.toml"),
                 {"t.toml:17:", "camera.target"});
  }
  SECTION("unknown key") {
    requireError(parseScene(replaced(kBase, "rings = 2", "rings = 2\nringz = 3"), "t.toml"),
                 {"t.toml:5:", "layout.ringz: unknown key"});
  }
  SECTION("unknown table") {
    requireError(parseScene(std::string(kBase) + "[lighting]\nsun = 1\n", "t.toml"), {"t.toml:", "lighting: unknown key"});
  }
  SECTION("unknown enum value") {
    requireError(parseScene(replaced(kBase, "adjacency_clamp = \"pow2\"", "adjacency_clamp = \"pow3\""), "t.toml"),
                 {"t.toml:12:", "lod.adjacency_clamp: unknown value \"pow3\""});
  }
  SECTION("heightmap of the wrong size") {
    std::string text = replaced(kBase, "kind = \"none\"",
                                "kind = \"raw\"\nfile = \"luna_heightmap.raw\"\nwidth = 100\nheight = 129\nbits = 8");
    requireError(parseScene(text, "t.toml", {}, FFTESS_EXAMPLES_DIR),
                 {"t.toml:10:", "displacement.file", "16641 bytes, expected 12900"});
  }
  SECTION("missing heightmap file") {
    std::string text = replaced(kBase, "kind = \"none\"",
                                "kind = \"raw\"\nfile = \"nope.raw\"\nwidth = 4\nheight = 4");
    requireError(parseScene(text, "t.toml", {}, FFTESS_EXAMPLES_DIR), {"displacement.file", "cannot open"});
  }
  SECTION("raw keys on a procedural displacement") {
    requireError(parseScene(replaced(kBase, "kind = \"none\"", "kind = \"fbm\"\nwidth = 4"), "t.toml"),
                 {"t.toml:10:", "displacement.width: only allowed with kind = \"raw\""});
  }
}

TEST_CASE("overrides are validated like the file", "[verify][scene]") {
  SceneResult ok = parseScene(kBase, "t.toml", {"lod.adjacency_clamp=integer", "camera.eye=[1, 2, 3]",
                                                 "layout.rings=3", "displacement.kind=fbm"});
  INFO(ok.error);
  REQUIRE(ok.ok);
  CHECK(ok.scene.lod.screenSphere.clamp == AdjacencyClamp::Integer);
  CHECK(ok.scene.camera.eye.z == 3.0f);
  CHECK(ok.scene.layout.rings == 3);
  CHECK(ok.scene.displacement.kind == DisplacementKind::Fbm);

  requireError(parseScene(kBase, "t.toml", {"lod.adjacency_clamp=sometimes"}),
               {"--set lod.adjacency_clamp: unknown value \"sometimes\""});
  requireError(parseScene(kBase, "t.toml", {"lod.bogus=1"}), {"--set lod.bogus: unknown key"});
  requireError(parseScene(kBase, "t.toml", {"camera.eye=[0, nan, 0]"}), {"--set camera.eye", "finite"});
  requireError(parseScene(kBase, "t.toml", {"layout.rings=-2"}), {"--set layout.rings: must be in [1, 16]"});
  requireError(parseScene(kBase, "t.toml", {"no-equals-sign"}), {"--set no-equals-sign: expected KEY=VALUE"});
  requireError(parseScene(kBase, "t.toml", {"layout=3"}), {"--set layout", "table"});
}

TEST_CASE("loadScene reports a missing file", "[verify][scene]") {
  SceneResult r = loadScene("/nonexistent/scene.toml");
  REQUIRE_FALSE(r.ok);
  CHECK(r.error.find("/nonexistent/scene.toml") != std::string::npos);
}

TEST_CASE("prepared terrain: every patch's ref and corners, as the domain shader uses them", "[verify][scene]") {
  // kBase: hand-counted 16 * 4 ring-0 patches of size 1 and 12 * 4 ring-1 patches of size 2 over [-8, 8]^2.
  for (const char* corners : {"reconstructed", "shared"}) {
    INFO(corners);
    SceneResult r = parseScene(kBase, "t.toml", {std::string("layout.corners=") + corners});
    REQUIRE(r.ok);
    const Terrain terrain = prepared(r.scene);
    const std::vector<PatchGeometry>& geo = terrain.patches();
    REQUIRE(static_cast<int>(geo.size()) == terrain.patchCount());
    REQUIRE(geo.size() == 16 * 4 + 12 * 4);
    double area = 0;
    for (size_t i = 0; i < geo.size(); ++i) {
      INFO("patch " << i);
      const PatchGeometry& g = geo[i];
      CHECK(g.ref.index == static_cast<int>(i));
      CHECK(g.ref.ring == (i < 16 * 4 ? 0 : 1));
      CHECK(g.ref.level == g.ref.ring);
      // Flat terrain: the domain shader at the corner (u, v) = (0, 0) is corner 0 exactly; all corners have y = 0.
      const glm::vec3 p = domainPosition(terrain, static_cast<int>(i), 0.0f, 0.0f);
      CHECK(p.x == g.corners[0].x);
      CHECK(p.z == g.corners[0].z);
      // corners[u + 2v]: an axis-aligned square of side 2^level.
      const float side = static_cast<float>(1 << g.ref.level);
      CHECK(g.corners[1].x - g.corners[0].x == side);
      CHECK(g.corners[1].z == g.corners[0].z);
      CHECK(g.corners[2].z - g.corners[0].z == side);
      CHECK(g.corners[2].x == g.corners[0].x);
      CHECK(g.corners[3].x == g.corners[1].x);
      CHECK(g.corners[3].z == g.corners[2].z);
      for (const glm::vec3& c : g.corners) {
        CHECK(c.y == 0.0f);
        CHECK(std::fabs(c.x) <= 8.0f);
        CHECK(std::fabs(c.z) <= 8.0f);
      }
      area += static_cast<double>(side) * side;
    }
    CHECK(area == 16.0 * 16.0); // the rings tile the extent without gaps or overlaps (with the square check above)
  }
  SceneResult bad = parseScene(kBase, "t.toml");
  REQUIRE(bad.ok);
  bad.scene.displacement.kind = DisplacementKind::Fbm; // built by hand without its texture: no terrain
  bad.scene.displacement.texels.reset();
  const TerrainResult none = prepareTerrain(bad.scene);
  CHECK_FALSE(none.ok);
  CHECK(none.error.find("displacement") != std::string::npos);
  CHECK(none.terrain.empty());
}

TEST_CASE("a neighbour-rule key that cannot apply is refused, naming the key and its position", "[verify][scene]") {
  // kBase: tile rings, 2 rings, lod.adjacency_clamp on line 12. Fine as it is; refused where no size jump exists.
  REQUIRE(parseScene(kBase, "t.toml").ok);
  requireError(parseScene(replaced(kBase, "rings = 2", "rings = 1"), "t.toml"),
               {"t.toml:12:", "lod.adjacency_clamp: cannot apply", "no size jumps", "tile_rings\" with layout.rings = 1"});
  requireError(parseScene(replaced(kBase, "kind = \"tile_rings\"", "kind = \"grid\""), "t.toml"),
               {"t.toml:12:", "lod.adjacency_clamp: cannot apply", "layout.kind = \"grid\""});
  const std::string noClamp = replaced(kBase, "adjacency_clamp = \"pow2\"\n", "");
  requireError(parseScene(replaced(noClamp, "scheme = \"screen_sphere\"", "scheme = \"screen_sphere\"\nreconstruction = \"resampled\""),
                          "t.toml", {"layout.rings=1"}),
               {"t.toml:12:", "lod.reconstruction: cannot apply"});
  requireError(parseScene(replaced(kBase, "scheme = \"screen_sphere\"", "scheme = \"patch_center\""), "t.toml"),
               {"t.toml:12:", "lod.adjacency_clamp: cannot apply", "patch_center"});
  // Overrides name --set KEY.
  requireError(parseScene(noClamp, "t.toml", {"layout.kind=grid", "lod.reconstruction=far_corner"}),
               {"--set lod.reconstruction: cannot apply", "grid"});
  // Defaults never error: the same scenes without the keys load.
  CHECK(parseScene(noClamp, "t.toml", {"layout.rings=1"}).ok);
  CHECK(parseScene(noClamp, "t.toml", {"layout.kind=grid"}).ok);
  CHECK(parseScene(noClamp, "t.toml", {"lod.scheme=patch_center"}).ok);
  // resampled is a value; the scene default is resampled, lod.h's nvidiaTile default stays edge_vector.
  const SceneResult r = parseScene(noClamp, "t.toml");
  REQUIRE(r.ok);
  CHECK(r.scene.lod.screenSphere.reconstruction == fftess::lod::Reconstruction::Resampled);
  CHECK(fftess::lod::NvidiaTileParams{}.reconstruction == fftess::lod::Reconstruction::EdgeVector);
}

TEST_CASE("an unknown key or value names the nearest known one, in the file and in --set", "[verify][scene]") {
  using Catch::EndsWith;
  const std::string clmp = replaced(kBase, "adjacency_clamp = \"pow2\"", "adjacency_clmp = \"pow2\"");
  CHECK_THAT(parseScene(clmp, "t.toml").error,
             EndsWith("t.toml:12:18: lod.adjacency_clmp: unknown key (did you mean \"lod.adjacency_clamp\"?)"));
  CHECK(parseScene(kBase, "t.toml", {"lod.adjacency_clmp=pow2"}).error ==
        "--set lod.adjacency_clmp: unknown key (did you mean \"lod.adjacency_clamp\"?)");
  CHECK_THAT(parseScene(replaced(kBase, "[lod]", "[lodd]"), "t.toml").error,
             EndsWith(": lodd: unknown key (did you mean \"lod\"?)"));
  CHECK(parseScene(kBase, "t.toml", {"lod.scheme=screen_sphre"}).error ==
        "--set lod.scheme: unknown value \"screen_sphre\" (expected \"constant\" | \"screen_sphere\" | "
        "\"distance_pow2\" | \"bonaventura\" | \"clip_diameter\" | \"patch_center\" | \"geomorph\" | \"shader\"; "
        "did you mean \"screen_sphere\"?)");
  CHECK_THAT(parseScene(kBase, "t.toml", {"tessellation.partitioning=fractional_evn"}).error,
             EndsWith("; did you mean \"fractional_even\"?)"));
  CHECK_THAT(parseScene(kBase, "t.toml", {"tessellation.stage=hlsl-avgg"}).error,
             EndsWith("; did you mean \"hlsl-avg\"?)"));
  CHECK_THAT(parseScene(kBase, "t.toml", {"lod.flush_denormals=\"aut\""}).error,
             EndsWith("(expected \"auto\" | true | false; did you mean \"auto\"?)"));
  // Nothing near: no guess.
  CHECK(parseScene(kBase, "t.toml", {"lod.bogus=1"}).error == "--set lod.bogus: unknown key");
  CHECK(parseScene(kBase, "t.toml", {"lod.adjacency_clamp=sometimes"}).error ==
        "--set lod.adjacency_clamp: unknown value \"sometimes\" (expected \"none\" | \"integer\" | \"pow2\")");
}
