// Seed effects selectable in a scene and checked: geomorphing (lod.scheme = "geomorph"), Bonaventura's mip-level
// coherence (displacement.mip), Luna's R16_FLOAT heights (displacement.format) and per-patch height bounds
// (lod.height_bounds), the inside-factor rule (lod.inside); and none of them costs anything unless a scene asks.
#include "base/bits.h"
#include "verify/internal.h"
#include "verify_test_util.h"

#include <cmath>
#include <cstdio>
#include <cstring>

using namespace fftess;
using namespace fftess::verify;
using namespace fftess::verify::test;

namespace {

std::string hex(uint32_t v, int digits) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%0*x", digits, v);
  return buf;
}

std::vector<Camera> someCameras(const Terrain& t) {
  std::vector<Camera> cams = pathCameras(t);
  for (const Camera& c : orbitCameras(t, 6)) cams.push_back(c);
  for (const Camera& c : randomCameras(t, 6, 42)) cams.push_back(c);
  return cams;
}

Stats total(const Terrain& t, const std::vector<Camera>& cams) {
  SweepOptions so;
  so.threads = 2;
  return sweep(t, cams, {}, so).total;
}

} // namespace

TEST_CASE("effects: float -> half -> float special values, printed in hex", "[verify][effects][half]") {
  struct Row {
    uint32_t in;
    uint16_t half;
  };
  const Row rows[] = {
      {0x00000000u, 0x0000}, // +0
      {0x80000000u, 0x8000}, // -0
      {0x3f800000u, 0x3c00}, // 1
      {0xbf800000u, 0xbc00}, // -1
      {0x477fe000u, 0x7bff}, // 65504, the largest half
      {0x477fefffu, 0x7bff}, // just below 65520: rounds down to 65504
      {0x477ff000u, 0x7c00}, // 65520: the tie between 65504 and 2^16 goes to even = infinity
      {0x7f800000u, 0x7c00}, // +inf
      {0xff800000u, 0xfc00}, // -inf
      {0x7fc00000u, 0x7e00}, // quiet NaN
      {0x38800000u, 0x0400}, // 2^-14, the smallest normal half
      {0x387fc000u, 0x03ff}, // 1023 * 2^-24, the largest subnormal half
      {0x33800000u, 0x0001}, // 2^-24, the smallest subnormal half
      {0x33000000u, 0x0000}, // 2^-25: tie between 0 and 2^-24 -> even (0)
      {0x33000001u, 0x0001}, // just above 2^-25: rounds up
      {0x33c00000u, 0x0002}, // 3 * 2^-25: tie between 1 and 2 (units of 2^-24) -> even (2)
      {0x3f801000u, 0x3c00}, // 1 + 2^-11: tie between 1 and 1 + 2^-10 -> even (1)
      {0x3f803000u, 0x3c02}, // 1 + 3 * 2^-11: tie -> even (1 + 2^-9)
      {0x3f801001u, 0x3c01}, // just above the tie: up
      {0x3dcccccdu, 0x2e66}, // 0.1f
      {0x3f7ff000u, 0x3c00}, // 1 - 2^-12: tie between 1 - 2^-11 and 1 -> even (1, the carry into the exponent)
  };
  for (const Row& r : rows) {
    const uint16_t h = detail::floatToHalf(floatOf(r.in));
    INFO("float " << hex(r.in, 8) << " -> half " << hex(h, 4) << ", expected " << hex(r.half, 4));
    CHECK(h == r.half);
  }
  // half -> float is exact and inverse: every half that is not NaN comes back to its own bits.
  int roundTrips = 0;
  for (uint32_t h = 0; h < 0x10000u; ++h) {
    const bool nan = (h & 0x7c00u) == 0x7c00u && (h & 0x3ffu) != 0;
    if (nan) continue;
    const float f = detail::halfToFloat(static_cast<uint16_t>(h));
    INFO("half " << hex(h, 4) << " -> float " << hex(bitsOf(f), 8));
    REQUIRE(detail::floatToHalf(f) == h);
    ++roundTrips;
  }
  CHECK(roundTrips == 65536 - 2 * 1023);
  CHECK(bitsOf(detail::halfToFloat(0x7bff)) == 0x477fe000u);
  CHECK(bitsOf(detail::halfToFloat(0x0001)) == 0x33800000u);
  CHECK(bitsOf(detail::halfToFloat(0x03ff)) == 0x387fc000u);
}

TEST_CASE("effects: displacement.format = r16_float quantises every texel to half at load", "[verify][effects][luna]") {
  const Scene r16 = loadExample("luna_r16.toml");
  const Scene f32 = loadExample("luna_r16.toml", {"displacement.format=float"});
  REQUIRE(r16.displacement.format == TexelFormat::R16Float);
  REQUIRE(r16.displacement.texels->size() == f32.displacement.texels->size());
  int changed = 0;
  for (size_t i = 0; i < r16.displacement.texels->size(); ++i) {
    const float a = (*f32.displacement.texels)[i], b = (*r16.displacement.texels)[i];
    REQUIRE(bitsOf(b) == bitsOf(detail::halfToFloat(detail::floatToHalf(a))));
    changed += a != b;
  }
  CHECK(changed > 0);
  CHECK(r16.displacement.mips == nullptr); // no mip chain unless displacement.mip asks
  // The bundled Luna heightmap (8-bit UNORM) too.
  const Scene luna = loadExample("luna.toml", {"displacement.format=r16_float"});
  for (float t : *luna.displacement.texels) REQUIRE(bitsOf(t) == bitsOf(detail::halfToFloat(detail::floatToHalf(t))));
}

TEST_CASE("effects: lod.height_bounds = per_patch holds every height of the patch and culls more than global",
          "[verify][effects][luna]") {
  const Scene perPatch = loadExample("luna_r16.toml");
  const Scene global = loadExample("luna_r16.toml", {"lod.height_bounds=global"});
  const Terrain tp = prepared(perPatch), tg = prepared(global);
  const detail::TerrainData& d = tp.data();
  for (int i = 0; i < tp.patchCount(); ++i) {
    const lod::Patch& b = d.patches[static_cast<size_t>(i)].lod;
    const lod::Patch& g = tg.data().patches[static_cast<size_t>(i)].lod;
    REQUIRE(b.useHeightBounds);
    CHECK(b.minHeight >= g.minHeight);
    CHECK(b.maxHeight <= g.maxHeight);
    for (int k = 0; k <= 16; ++k)
      for (int j = 0; j <= 16; ++j) {
        const glm::vec3 p = domainPosition(tp, i, static_cast<float>(j) / 16.0f, static_cast<float>(k) / 16.0f);
        INFO("patch " << i << " (" << j << ", " << k << ") y " << p.y << " bounds " << b.minHeight << " .. "
                      << b.maxHeight);
        REQUIRE(p.y >= b.minHeight);
        REQUIRE(p.y <= b.maxHeight);
      }
  }
  // Tighter boxes: never fewer culled patches, and more in total over the cameras.
  const std::vector<Camera> cams = someCameras(tp);
  int64_t culledPer = 0, culledGlobal = 0;
  for (const Camera& c : cams) {
    const Report a = checkScene(tp, c), b = checkScene(tg, c);
    CHECK(a.stats.culledPatches >= b.stats.culledPatches);
    culledPer += a.stats.culledPatches;
    culledGlobal += b.stats.culledPatches;
  }
  CHECK(culledPer > culledGlobal);
}

TEST_CASE("effects: geomorph: the shared border tween is watertight, the literal article weight cracks",
          "[verify][effects][geomorph]") {
  const Scene s = loadExample("geomorph.toml");
  REQUIRE(s.lod.scheme == LodScheme::Geomorph);
  const Terrain t = prepared(s);
  const std::vector<Camera> cams = someCameras(t);
  const Stats shared = total(t, cams);
  CHECK(shared.edgesChecked > 0);
  CHECK(shared.cracks == 0);
  CHECK(shared.tJunctions == 0);

  const Scene lit = loadExample("geomorph.toml", {"lod.literal_article_weight=true"});
  const Terrain tl = prepared(lit);
  const Stats literal = total(tl, cams);
  CHECK(literal.cracks > 0);
  // The whole-mesh check sees the same patch edges.
  CheckOptions all;
  all.maxFindings = 1u << 20;
  const Report r = checkScene(tl, lit.camera, all);
  REQUIRE(r.stats.cracks > 0);
  CHECK(flaggedPatchEdges(r) == checkSceneMesh(tl, lit.camera).flagged);
}

TEST_CASE("effects: geomorph: the domain shader's border heights are lod::geomorphEdgeHeights'", "[verify][effects][geomorph]") {
  const Scene s = loadExample("geomorph.toml");
  const Terrain t = prepared(s);
  const detail::TerrainData& d = t.data();
  WorkStats work;
  std::vector<lod::PatchLod> factors;
  detail::computeFactors(d, s.camera, factors, work);
  const detail::DomainCamera cam = detail::domainCamera(d, factors);
  REQUIRE(cam.patches.size() == d.patches.size());
  int morphed = 0, compared = 0;
  for (size_t i = 0; i < d.patches.size(); ++i) {
    const detail::TerrainPatch& p = d.patches[i];
    const int nb = p.nb[Ueq1][0];
    if (nb < 0) continue;
    float fine[65];
    for (int k = 0; k <= 64; ++k)
      fine[k] = domainPosition(t, static_cast<int>(i), 1.0f, static_cast<float>(k) / 64.0f).y; // true heights
    const float level = factors[i].why.factor[4].metric, nl = factors[static_cast<size_t>(nb)].why.factor[4].metric;
    const lod::GeomorphEdge want = lod::geomorphEdgeHeights(level, nl, fine, s.lod.geomorph);
    REQUIRE(static_cast<float>(want.segments) == factors[i].factors[Ueq1]);
    for (int k = 0; k <= want.segments; ++k) {
      const float v = static_cast<float>(k) / static_cast<float>(want.segments);
      const float y = detail::evalDomain(d, p, 1.0f, v, cam.at(i), work).y;
      INFO("patch " << i << " k " << k << "/" << want.segments);
      REQUIRE(bitsOf(y) == bitsOf(want.heights[k]));
      morphed += y != fine[k * (64 / want.segments)];
      ++compared;
    }
  }
  CHECK(compared > 100);
  CHECK(morphed > 0); // some vertices really are between their tween-0 and true heights
}

TEST_CASE("effects: geomorph sweeps, and the scene refuses what it cannot draw", "[verify][effects][geomorph]") {
  const Scene s = loadExample("geomorph.toml");
  const Terrain t = prepared(s);
  const SweepResult r = sweep(t, randomCameras(t, 16, 7));
  CHECK(r.camerasDone == 16);
  CHECK(r.total.cracks == 0);
  CHECK(r.total.edgesChecked > 0);

  const SceneResult bad = loadScene(examplePath("geomorph.toml"), {"tessellation.partitioning=fractional_odd"});
  REQUIRE_FALSE(bad.ok);
  CHECK(bad.error.find("tessellation.partitioning") != std::string::npos);
  CHECK(bad.error.find("integer") != std::string::npos);
  const SceneResult rings = loadScene(examplePath("rings_small.toml"),
                                      {"lod.scheme=geomorph", "tessellation.partitioning=integer"});
  REQUIRE_FALSE(rings.ok);
  CHECK(rings.error.find("one size") != std::string::npos);
  const SceneResult level = loadScene(examplePath("geomorph.toml"), {"lod.finest_level=6"});
  REQUIRE_FALSE(level.ok);
  CHECK(level.error.find("lod.finest_level") != std::string::npos);
}

TEST_CASE("effects: Bonaventura mip levels: per_patch cracks, per_vertex is watertight", "[verify][effects][mip]") {
  const Scene v = loadExample("bonaventura_mip.toml");
  REQUIRE(v.displacement.mip == MipMode::PerVertex);
  const Terrain tv = prepared(v);
  const std::vector<Camera> cams = someCameras(tv);
  const Stats perVertex = total(tv, cams);
  CHECK(perVertex.edgesChecked > 0);
  CHECK(perVertex.cracks == 0);
  CHECK(perVertex.tJunctions == 0);

  const Scene p = loadExample("bonaventura_mip.toml", {"displacement.mip=per_patch"});
  const Terrain tp = prepared(p);
  const Stats perPatch = total(tp, cams);
  CHECK(perPatch.cracks > 0);
  CheckOptions all;
  all.maxFindings = 1u << 20;
  const Report r = checkScene(tp, p.camera, all);
  REQUIRE(r.stats.cracks > 0);
  CHECK(flaggedPatchEdges(r) == checkSceneMesh(tp, p.camera).flagged);

  // Without the mip chain the same LOD is watertight too: the cracks are the mip levels'.
  const Scene none = loadExample("bonaventura_mip.toml", {"displacement.mip=none"});
  CHECK(total(prepared(none), cams).cracks == 0);
}

TEST_CASE("effects: the mip chain is a box filter built at load, only when asked", "[verify][effects][mip]") {
  const Scene s = loadExample("bonaventura_mip.toml");
  REQUIRE(s.displacement.mips);
  const std::vector<MipLevel>& m = *s.displacement.mips;
  const int sizes[] = {128, 64, 32, 16, 8, 4, 2, 1};
  REQUIRE(m.size() == 8);
  for (size_t i = 0; i < m.size(); ++i) {
    CHECK(m[i].width == sizes[i]);
    CHECK(m[i].height == sizes[i]);
  }
  const std::vector<float>& t0 = *s.displacement.texels;
  const int w = s.displacement.texWidth; // 257: the last column and row are not read (floor rule)
  for (int j = 0; j < 128; j += 37)
    for (int i = 0; i < 128; i += 29) {
      auto at = [&](int x, int z) { return t0[static_cast<size_t>(z) * w + x]; };
      const float want =
          ((at(2 * i, 2 * j) + at(2 * i + 1, 2 * j)) + (at(2 * i, 2 * j + 1) + at(2 * i + 1, 2 * j + 1))) * 0.25f;
      CHECK(bitsOf(m[0].texels[static_cast<size_t>(j) * 128 + i]) == bitsOf(want));
    }
  // Trilinear between levels: at an integer level it is that level's bilinear sample.
  CHECK(detail::sampleTrilinear(s.displacement, 0.3f, 0.6f, 2.0f) ==
        detail::sampleBilinearLevel(s.displacement, 2, 0.3f, 0.6f));
  CHECK(detail::sampleTrilinear(s.displacement, 0.3f, 0.6f, -1.0f) == detail::sampleBilinear(s.displacement, 0.3f, 0.6f));
  CHECK(detail::sampleTrilinear(s.displacement, 0.3f, 0.6f, 99.0f) == m.back().texels[0]);

  const SceneResult wrongScheme = loadScene(examplePath("grid.toml"), {"displacement.mip=per_vertex"});
  REQUIRE_FALSE(wrongScheme.ok);
  CHECK(wrongScheme.error.find("displacement.mip") != std::string::npos);
  CHECK(wrongScheme.error.find("bonaventura") != std::string::npos);
}

TEST_CASE("effects: scene defaults: Bonaventura's rank 0.4 (the thesis'), lod.inside sets the inside rule",
          "[verify][effects]") {
  const Scene s = loadExample("grid.toml", {"lod.scheme=bonaventura"});
  CHECK(s.lod.bonaventura.rank == 0.4f);
  CHECK(lod::BonaventuraParams{}.rank == 0.5f); // lod's own default is unchanged
  for (const char* rule : {"min", "max", "average"}) {
    const Scene c = loadExample("grid.toml", {"lod.scheme=screen_sphere", std::string("lod.inside=") + rule});
    const Terrain t = prepared(c);
    WorkStats work;
    std::vector<lod::PatchLod> f;
    detail::computeFactors(t.data(), c.camera, f, work);
    for (const lod::PatchLod& p : f) {
      if (p.why.culled) continue;
      const float a = p.factors[Veq0], b = p.factors[Veq1]; // insideU from the edges along u
      const float want = rule[1] == 'i' ? std::fmin(a, b) : rule[1] == 'a' && rule[2] == 'x' ? std::fmax(a, b) : p.factors[4];
      INFO(rule);
      REQUIRE(p.factors[4] == want);
    }
  }
}

TEST_CASE("effects: scenes that do not opt in do no extra work", "[verify][effects][prepared]") {
  for (const char* name : {"rings_small.toml", "grid.toml", "luna.toml", "terrain.toml"}) {
    INFO(name);
    const Scene plain = loadExample(name);
    const Scene spelled = loadExample(name, {"displacement.format=float", "displacement.mip=none",
                                             "lod.height_bounds=global"});
    CHECK(plain.displacement.mips == nullptr);
    const Terrain a = prepared(plain), b = prepared(spelled);
    // Four corner heights per patch, plus (lod.reconstruction = "resampled", the default) one per corner the
    // smaller side of a size jump rebuilds.
    int64_t rebuilt = 0;
    if (plain.lod.screenSphere.reconstruction == lod::Reconstruction::Resampled && plain.lod.displacedCorners)
      for (const detail::TerrainPatch& p : a.data().patches)
        for (float size : p.tile.size) rebuilt += size == 2.0f;
    CHECK(a.stats().heightSamples == 4 * static_cast<int64_t>(a.patchCount()) + rebuilt);
    const Report ra = checkScene(a, plain.camera), rb = checkScene(b, spelled.camera);
    REQUIRE(ra.error.empty());
    // No per-camera domain state, one height sample per domain evaluation, one lod/ call per patch.
    WorkStats w;
    std::vector<lod::PatchLod> f;
    detail::computeFactors(a.data(), plain.camera, f, w);
    CHECK(detail::domainCamera(a.data(), f).patches.empty());
    CHECK(ra.work.heightSamples == ra.work.domainEvaluations);
    CHECK(ra.work.lodEvaluations == a.patchCount());
    // Spelling the defaults out changes nothing, work or verdicts.
    CHECK(rb.work.heightSamples == ra.work.heightSamples);
    CHECK(rb.work.domainEvaluations == ra.work.domainEvaluations);
    CHECK(rb.work.lodEvaluations == ra.work.lodEvaluations);
    CHECK(rb.work.edgeQueries == ra.work.edgeQueries);
    CHECK(rb.work.cgalCalls == ra.work.cgalCalls);
    CHECK(rb.stats.cracks == ra.stats.cracks);
    CHECK(rb.stats.culledPatches == ra.stats.culledPatches);
  }
  // The scenes that opt in: a mip scene samples once per evaluation (one trilinear fetch), a geomorph scene adds the
  // two neighbour heights of each inserted vertex, and both keep one lod/ call per patch.
  const Scene mip = loadExample("bonaventura_mip.toml");
  const Terrain tm = prepared(mip);
  const Report rm = checkScene(tm, mip.camera);
  CHECK(rm.work.heightSamples == rm.work.domainEvaluations);
  CHECK(rm.work.lodEvaluations == tm.patchCount());
  const Scene geo = loadExample("geomorph.toml");
  const Terrain tg = prepared(geo);
  const Report rg = checkScene(tg, geo.camera);
  CHECK(rg.work.heightSamples > rg.work.domainEvaluations);
  CHECK(rg.work.lodEvaluations == tg.patchCount());
}

TEST_CASE("effects: lod.inside_from = fixed_edges averages the edges after the neighbour rule (the sample's order)",
          "[verify][effects]") {
  const Scene own = loadExample("rings_small.toml");
  const Scene fixed = loadExample("rings_small.toml", {"lod.inside_from=fixed_edges"});
  CHECK(!own.lod.screenSphere.insideFromFixedEdges);
  REQUIRE(fixed.lod.screenSphere.insideFromFixedEdges);
  const Terrain a = prepared(own), b = prepared(fixed);
  std::vector<lod::PatchLod> fa, fb;
  WorkStats w;
  detail::computeFactors(a.data(), own.camera, fa, w);
  detail::computeFactors(b.data(), fixed.camera, fb, w);
  int differ = 0, jumps = 0;
  for (size_t i = 0; i < fa.size(); ++i) {
    INFO("patch " << i);
    for (int e = 0; e < 4; ++e) CHECK(fa[i].factors[e] == fb[i].factors[e]); // edges never change
    if (fb[i].why.culled) continue;
    // fixed_edges: exactly the average of the (fixed) edge factors, in the sample's order.
    CHECK(fb[i].factors[4] == (fb[i].factors[1] + fb[i].factors[3]) * 0.5f);
    CHECK(fb[i].factors[5] == (fb[i].factors[0] + fb[i].factors[2]) * 0.5f);
    bool jump = false;
    for (float s : a.data().patches[i].tile.size) jump = jump || s != 1.0f;
    jumps += jump;
    differ += fa[i].factors[4] != fb[i].factors[4] || fa[i].factors[5] != fb[i].factors[5];
  }
  CHECK(jumps > 0);
  CHECK(differ > 0); // patches at a size jump get other inside factors
  // Edge verdicts are the same.
  CHECK(checkScene(a, own.camera).stats.matches == checkScene(b, fixed.camera).stats.matches);
}
