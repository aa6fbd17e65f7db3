// The GPU path's contract without a GPU (verify links no GL): lod.shader / lod.evaluate parsing, a scene asking for
// the GPU path without a provider, and a stand-in FactorProvider (lod/'s C++ functions) whose factors are checked
// and compared with the C++ build: equal factors give the C++ verdict and no difference; one factor moved by an ulp
// is reported as exactly one FactorDiff with both bits; a NaN factor makes a hole. docs/gpu_lod.md.
#include "verify_test_util.h"
#include "base/bits.h"
#include "verify/internal.h"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <map>
#include <cstring>

using namespace fftess::verify;
using namespace fftess::verify::test;

namespace {

// lod::distancePow2 on the grid (no size jumps), as lod_bridge.cpp would call it; then an optional perturbation.
struct StandIn : FactorProvider {
  int patch = -1;
  int factor = 0;
  bool nan = false;
  int calls = 0;
  bool evaluate(const LodPatches& patches, const fftess::lod::Camera& camera, std::vector<fftess::lod::PatchLod>& out,
                std::string&) override {
    ++calls;
    out.resize(patches.size());
    for (size_t i = 0; i < patches.size(); ++i)
      out[i] = fftess::lod::distancePow2(patches[i].patch, camera, patches.scene().lod.distancePow2);
    if (nan) {
      for (fftess::lod::PatchLod& l : out) l.factors[factor] = std::nanf(""); // every patch
    } else if (patch >= 0) {
      float& f = out[static_cast<size_t>(patch)].factors[factor];
      f = std::nextafter(f, 1e9f);
    }
    return true;
  }
};

} // namespace

TEST_CASE("gpu path: scene keys lod.shader and lod.evaluate", "[verify][gpu_lod]") {
  const std::string dir = std::string(FFTESS_EXAMPLES_DIR);
  SceneResult r = loadScene(dir + "/gpu_distance_glsl.toml");
  REQUIRE(r);
  CHECK(r.scene.lod.shader == dir + "/lod_distance.glsl"); // relative to the scene file
  CHECK(r.scene.lod.evaluate == LodEvaluate::Gpu);
  CHECK(r.scene.lod.scheme == LodScheme::DistancePow2);    // the C++ reference
  CHECK(loadScene(dir + "/gpu_distance_glsl.toml", {"lod.scheme=shader"}).scene.lod.scheme == LodScheme::Shader);
  SceneResult none = loadScene(dir + "/gpu_distance_glsl.toml", {"lod.shader=''"});
  REQUIRE(none);
  CHECK(none.scene.lod.shader.empty());
  CHECK(none.scene.lod.evaluate == LodEvaluate::Cpu);
  CHECK_THAT(loadScene(dir + "/gpu_distance_glsl.toml", {"lod.shader=missing.glsl"}).error,
             Catch::Contains("lod.shader: cannot read"));
  CHECK_THAT(loadScene(dir + "/gpu_distance_glsl.toml", {"lod.shader=lod.txt"}).error,
             Catch::Contains("expected a file name ending in .glsl"));
  CHECK_THAT(loadScene(dir + "/gpu_distance_glsl.toml", {"lod.evaluate=cpu"}).error,
             Catch::Contains("runs on the GPU only"));
  CHECK_THAT(loadScene(dir + "/grid.toml", {"lod.scheme=shader"}).error, Catch::Contains("needs lod.shader"));
  CHECK_THAT(loadScene(dir + "/geomorph.toml", {"lod.evaluate=gpu"}).error, Catch::Contains("no GPU path"));
}

TEST_CASE("gpu path: a stand-in provider's factors are checked and compared with the C++ build", "[verify][gpu_lod]") {
  const Scene cpuScene = loadExample("grid.toml", {"lod.scheme=distance_pow2"});
  const Scene gpuScene = loadExample("grid.toml", {"lod.scheme=distance_pow2", "lod.evaluate=gpu"});
  const Terrain cpu = prepared(cpuScene), gpu = prepared(gpuScene);
  const Camera cam = cpuScene.camera;

  // Without a provider the camera is not checked (the cli always attaches one).
  Report missing = checkScene(gpu, cam);
  CHECK_THAT(missing.error, Catch::Contains("needs a GPU factor provider"));

  auto standIn = std::make_shared<StandIn>();
  CheckOptions o;
  o.factors = standIn;
  const Report ref = checkScene(cpu, cam);
  Report same = checkScene(gpu, cam, o);
  REQUIRE(same.error.empty());
  CHECK(standIn->calls == 1);
  CHECK(same.stats.factorsCompared == 6 * ref.stats.patches);
  CHECK(same.stats.factorDiffs == 0);
  CHECK(same.factorDiffs.empty());
  CHECK(same.stats.matches == ref.stats.matches);
  CHECK(verdictOf(same.stats) == verdictOf(ref.stats));

  // One factor one ulp up: exactly one difference, with both values and bits.
  int target = -1;
  for (int i = 0; i < gpu.patchCount() && target < 0; ++i) {
    fftess::lod::PatchLod l = fftess::lod::distancePow2(LodPatches(gpu)[static_cast<size_t>(i)].patch,
                                                        detail::toLodCamera(cam), gpuScene.lod.distancePow2);
    if (!l.why.culled) target = i;
  }
  REQUIRE(target >= 0);
  standIn->patch = target;
  standIn->factor = 2;
  Report moved = checkScene(gpu, cam, o);
  REQUIRE(moved.factorDiffs.size() == 1);
  CHECK(moved.stats.factorDiffs == 1);
  const FactorDiff& d = moved.factorDiffs[0];
  CHECK(d.patch.index == target);
  CHECK(d.factor == 2);
  CHECK(d.gpuBits == d.cpuBits + 1);
  CHECK(d.gpu == std::nextafter(d.cpu, 1e9f));

  // A NaN factor on every patch: the tessellator discards them, holes where they are in view.
  standIn->nan = true;
  Report nan = checkScene(gpu, cam, o);
  CHECK(nan.stats.factorDiffs == ref.stats.patches);
  CHECK(nan.stats.holesDiscarded > 0);
  CHECK(nan.stats.holesDiscarded + ref.stats.culledPatches <= ref.stats.patches);
}

namespace {

// A flat grid's factors (constant 4) with one patch's outer factors denormal, and the driver's rule as a provider
// states it (FactorProvider::flushesDenormals).
struct DenormalStandIn : FactorProvider {
  int patch = -1;
  bool driverFlushes = false;
  bool evaluate(const LodPatches& patches, const fftess::lod::Camera&, std::vector<fftess::lod::PatchLod>& out,
                std::string&) override {
    out.assign(patches.size(), fftess::lod::PatchLod{});
    for (fftess::lod::PatchLod& l : out)
      for (float& f : l.factors) f = 4.0f;
    const float denormal = fftess::floatOf(0x000116C2u); // 1e-40
    for (int e = 0; e < 4; ++e) out[static_cast<size_t>(patch)].factors[e] = denormal;
    return true;
  }
  bool flushesDenormals(std::string* why) const override {
    if (why) *why = driverFlushes ? "stand-in driver: flushes" : "stand-in driver: keeps";
    return driverFlushes;
  }
};

} // namespace

TEST_CASE("gpu path: denormal factors take the driver's rule, overridable, and are reported either way", "[verify][gpu_lod]") {
  // Flat (no displacement): with the denormal kept, the patch is drawn at the minimum (1 segment per outer edge, a
  // T-junction or crack against the neighbours' 4); flushed, it is discarded: a hole where the camera sees it.
  const std::vector<std::string> flat{"lod.scheme=constant", "lod.evaluate=gpu", "displacement.kind=none",
                                      "tessellation.partitioning=integer", "camera.eye=[2.0,30.0,-20.0]",
                                      "camera.target=[2.0,0.0,2.0]"};
  const Scene scene = loadExample("grid.toml", flat);
  const Terrain terrain = prepared(scene);
  auto p = std::make_shared<DenormalStandIn>();
  for (int i = 0; i < terrain.patchCount() && p->patch < 0; ++i) {
    const LodInput in = LodPatches(terrain)[static_cast<size_t>(i)];
    if (in.patch.corners[0].x == 0.0f && in.patch.corners[0].z == 0.0f) p->patch = i;
  }
  REQUIRE(p->patch >= 0);
  CheckOptions o;
  o.factors = p;
  o.maxFindings = 100000;
  auto run = [&](const Terrain& t, bool driverFlushes, DenormalFlush cli) {
    p->driverFlushes = driverFlushes;
    o.flushDenormals = cli;
    Report r = checkScene(t, scene.camera, o);
    REQUIRE(r.error.empty());
    // Reported whether flushed or not: patch, factor, bits.
    CHECK(r.stats.denormalFactors == 4);
    REQUIRE(r.denormalFactors.size() == 4);
    for (int e = 0; e < 4; ++e) {
      CHECK(r.denormalFactors[static_cast<size_t>(e)].patch.index == p->patch);
      CHECK(r.denormalFactors[static_cast<size_t>(e)].factor == e);
      CHECK(r.denormalFactors[static_cast<size_t>(e)].bits == 0x000116C2u);
      CHECK(r.denormalFactors[static_cast<size_t>(e)].flushed == r.denormalsFlushed);
    }
    return r;
  };
  auto hasHoleAt = [&](const Report& r) {
    for (const Hole& h : r.holes)
      if (h.patch.index == p->patch && h.kind == HoleKind::Discarded && h.hullFactorBits == 0x000116C2u) return true;
    return false;
  };
  // Auto: the driver decides.
  Report flushed = run(terrain, true, DenormalFlush::Auto);
  CHECK(flushed.denormalsFlushed);
  CHECK(flushed.stats.holesDiscarded == 1);
  CHECK(hasHoleAt(flushed));
  CHECK(verdictOf(flushed.stats) != Verdict::Watertight);
  Report kept = run(terrain, false, DenormalFlush::Auto);
  CHECK_FALSE(kept.denormalsFlushed);
  CHECK(kept.stats.holes == 0);
  CHECK(kept.stats.culledPatches == 0);
  CHECK(denormalRule(scene, o).why == "stand-in driver: keeps");
  // --flush-denormals on|off overrides the driver.
  CHECK(hasHoleAt(run(terrain, false, DenormalFlush::On)));
  CHECK(run(terrain, true, DenormalFlush::Off).stats.holes == 0);
  // The whole-mesh check tessellates with the same rule: one patch fewer drawn when flushed.
  p->driverFlushes = true;
  o.flushDenormals = DenormalFlush::Auto;
  const MeshReport meshFlushed = checkSceneMesh(terrain, scene.camera, o);
  p->driverFlushes = false;
  const MeshReport meshKept = checkSceneMesh(terrain, scene.camera, o);
  CHECK(meshFlushed.patchesDrawn + 1 == meshKept.patchesDrawn);
  // The scene key overrides the driver; the command line overrides the scene key.
  std::vector<std::string> keyOn = flat;
  keyOn.push_back("lod.flush_denormals=true");
  const Scene sceneOn = loadExample("grid.toml", keyOn);
  const Terrain terrainOn = prepared(sceneOn);
  CHECK(sceneOn.lod.flushDenormals == DenormalFlush::On);
  CHECK(hasHoleAt(run(terrainOn, false, DenormalFlush::Auto)));
  CHECK(run(terrainOn, false, DenormalFlush::Off).stats.holes == 0);
  CHECK(denormalRule(sceneOn, o).why == "--flush-denormals off");
  o.flushDenormals = DenormalFlush::Auto;
  CHECK(denormalRule(sceneOn, o).why == "lod.flush_denormals = true");
}

TEST_CASE("lod.flush_denormals: \"auto\", true or false, anything else named with its position", "[verify][gpu_lod]") {
  CHECK(loadExample("grid.toml").lod.flushDenormals == DenormalFlush::Auto);
  CHECK(loadExample("grid.toml", {"lod.flush_denormals=false"}).lod.flushDenormals == DenormalFlush::Off);
  CHECK(loadExample("grid.toml", {"lod.flush_denormals=\"auto\""}).lod.flushDenormals == DenormalFlush::Auto);
  CHECK_THAT(loadScene(examplePath("grid.toml"), {"lod.flush_denormals=yes"}).error,
             Catch::Contains("--set lod.flush_denormals: unknown value \"yes\" (expected \"auto\" | true | false)"));
  CHECK_THAT(loadScene(examplePath("grid.toml"), {"lod.flush_denormals=1"}).error,
             Catch::Contains("--set lod.flush_denormals: expected \"auto\", true or false, got an integer"));
  const SceneResult r = parseScene("[layout]\nkind = \"grid\"\n[lod]\nscheme = \"constant\"\nflush_denormals = 0.5\n"
                                   "[tessellation]\npartitioning = \"integer\"\n[camera]\neye = [0.0, 10.0, -10.0]\n"
                                   "target = [0.0, 0.0, 0.0]\n",
                                   "x.toml");
  CHECK_THAT(r.error, Catch::Contains("x.toml:5:19: lod.flush_denormals: expected \"auto\", true or false, got a float"));
}

TEST_CASE("hull shader keys: uniforms, inputs, control points and domain axes read as written", "[verify][gpu_lod]") {
  const std::string scene = std::string(FFTESS_EXAMPLES_DIR) + "/gpu_distance_glsl.toml";
  SceneResult r = loadScene(scene, {"lod.entry='HS'", "lod.uniforms.gScale=1.5", "lod.uniforms.gOn=true",
                                    "lod.uniforms.gViewProj='transpose(view_projection)'",
                                    "lod.uniforms.gPair=[[1, 2], [3, 4.5]]", "lod.uniforms.gHeight='heightmap'",
                                    "lod.inputs.vPos='position'", "lod.inputs.vTex='uv'", "lod.inputs.vN=[0, 1, 0]",
                                    "lod.control_points=1",
                                    "lod.corner_order=[3]", "lod.domain_u='+z'", "lod.domain_v='-x'"});
  REQUIRE(r);
  const Lod& L = r.scene.lod;
  CHECK(L.entry == "HS");
  REQUIRE(L.uniforms.size() == 5);
  std::map<std::string, const UniformBinding*> u;
  for (const UniformBinding& b : L.uniforms) u[b.name] = &b;
  CHECK(u.at("gScale")->numbers == std::vector<double>{1.5});
  CHECK(u.at("gOn")->numbers == std::vector<double>{1.0});
  CHECK(u.at("gViewProj")->value == "view_projection");
  CHECK(u.at("gViewProj")->transpose);
  CHECK(u.at("gPair")->numbers == std::vector<double>{1, 2, 3, 4.5});
  CHECK(u.at("gHeight")->value == "heightmap");
  CHECK_FALSE(u.at("gHeight")->transpose);
  REQUIRE(L.inputs.size() == 3);
  for (const InputBinding& b : L.inputs)
    if (b.name == "vN") CHECK((b.value.empty() && b.numbers == std::vector<double>{0, 1, 0}));
  CHECK(L.controlPoints == 1);
  CHECK(L.cornerOrder[0] == 3);
  CHECK(L.domainU == DomainAxis::PlusZ);
  CHECK(L.domainV == DomainAxis::MinusX);
  const SceneResult d = loadScene(scene);
  REQUIRE(d);
  CHECK(d.scene.lod.cornerOrder == std::array<int, 4>{{0, 1, 2, 3}});
  CHECK(d.scene.lod.domainU == DomainAxis::PlusX);
  CHECK(d.scene.lod.domainV == DomainAxis::PlusZ);
}

TEST_CASE("hull shader keys: each mistake is refused naming the key", "[verify][gpu_lod]") {
  const std::string scene = std::string(FFTESS_EXAMPLES_DIR) + "/gpu_distance_glsl.toml";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"lod.uniforms.x='nope'", "unknown value \"nope\""},
      {"lod.uniforms.x='transpose(eye)'", "transpose() takes a named matrix"},
      {"lod.uniforms.x=[]", "an empty array binds nothing"},
      {"lod.uniforms.x={a = 1}", "expected a number, a boolean, an array of them or a named value"},
      {"lod.inputs.x='normal'", "unknown value \"normal\""},
      {"lod.inputs.x=[1, 2, 3, 4, 5]", "at most 4 components"},
      {"lod.control_points=3", "must be 4 (a patch's corners) or 1"},
      {"lod.corner_order=[0, 0, 1, 2]", "corner 0 twice"},
      {"lod.corner_order=[0, 1, 2]", "expected an array of 4 corner indices"},
      {"lod.corner_order=[0, 1, 2, 4]", "expected a corner index 0..3"},
      {"lod.domain_v='-x'", "must lie on different axes"},
      {"lod.domain_u='up'", "unknown value \"up\""},
      {"lod.evaluation_shader='missing.tese'", "cannot read"},
      {"lod.entry=''", "must name the hull shader function"},
  };
  for (const auto& [set, message] : cases) {
    INFO(set);
    const SceneResult r = loadScene(scene, {set});
    CHECK_FALSE(r);
    CHECK_THAT(r.error, Catch::Contains(set.substr(0, set.find('='))) && Catch::Contains(message));
  }
  const SceneResult plain = loadScene(std::string(FFTESS_EXAMPLES_DIR) + "/grid.toml", {"lod.inputs.p='position'"});
  CHECK_THAT(plain.error, Catch::Contains("lod.inputs") && Catch::Contains("needs lod.shader"));
  // --set lod.shader='' turns a hull shader scene into the built-in scheme: its hull keys stay unread.
  const SceneResult builtin = loadScene(std::string(FFTESS_EXAMPLES_DIR) + "/hull/distance_grid.toml",
                                            {"lod.shader=''", "lod.scheme=distance_pow2"});
  CHECK(builtin);
  CHECK(builtin.scene.lod.shader.empty());
  CHECK(builtin.scene.lod.uniforms.empty());
}
