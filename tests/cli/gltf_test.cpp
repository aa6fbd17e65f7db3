// check --gltf / sweep --gltf: the file is read back with tinygltf (Debian's libtinygltf) and its contents are
// compared with what the test computes itself through the public APIs: the tessellator's output for each patch's
// hull factors (fftess::Tessellator, fftess::outputCounts, fftess::edgePoints), the domain shader's positions
// (verify::domainPosition on verify::layoutFor), and the check's JSON report of the same command.
#include "run.h"

#include "base/bits.h"
#include "tessellator/tessellator.h"
#include "verify/verify.h"

#include <catch2/catch.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <vector>

using clitest::run;
using nlohmann::json;
namespace vf = fftess::verify;

namespace {

const std::string kRings = clitest::source("docs/examples/rings_small.toml");

tinygltf::Model loadGlb(const std::string& path) {
  tinygltf::Model m;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  const bool ok = loader.LoadBinaryFromFile(&m, &err, &warn, path);
  INFO(err << warn);
  REQUIRE(ok);
  CHECK(err.empty());
  CHECK(warn.empty());
  return m;
}

// The accessor's bytes (tightly packed, as fftess writes them).
template <class T>
std::vector<T> accessorData(const tinygltf::Model& m, int accessor, int componentType, int type) {
  const tinygltf::Accessor& a = m.accessors.at(static_cast<size_t>(accessor));
  REQUIRE(a.componentType == componentType);
  REQUIRE(a.type == type);
  const tinygltf::BufferView& v = m.bufferViews.at(static_cast<size_t>(a.bufferView));
  REQUIRE(v.byteLength == a.count * sizeof(T));
  std::vector<T> out(a.count);
  std::memcpy(out.data(), m.buffers.at(static_cast<size_t>(v.buffer)).data.data() + v.byteOffset + a.byteOffset,
              v.byteLength);
  return out;
}

std::vector<glm::vec3> positionsOf(const tinygltf::Model& m, const tinygltf::Primitive& p) {
  return accessorData<glm::vec3>(m, p.attributes.at("POSITION"), TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3);
}

std::vector<uint32_t> indicesOf(const tinygltf::Model& m, const tinygltf::Primitive& p) {
  return accessorData<uint32_t>(m, p.indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR);
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// The children of the scene's root node whose name starts with prefix (none: empty).
std::vector<const tinygltf::Node*> groupChildren(const tinygltf::Model& m, const std::string& prefix) {
  std::vector<const tinygltf::Node*> out;
  for (int root : m.scenes.at(0).nodes) {
    const tinygltf::Node& g = m.nodes.at(static_cast<size_t>(root));
    if (!startsWith(g.name, prefix)) continue;
    for (int c : g.children) out.push_back(&m.nodes.at(static_cast<size_t>(c)));
  }
  return out;
}

const tinygltf::Primitive& onlyPrimitive(const tinygltf::Model& m, const tinygltf::Node& n) {
  REQUIRE(n.mesh >= 0);
  const tinygltf::Mesh& mesh = m.meshes.at(static_cast<size_t>(n.mesh));
  REQUIRE(mesh.primitives.size() == 1);
  return mesh.primitives[0];
}

const tinygltf::Material& materialOf(const tinygltf::Model& m, const tinygltf::Primitive& p) {
  return m.materials.at(static_cast<size_t>(p.material));
}

// The scene with overrides, prepared, and the layout the camera sees (report patch indices index it).
struct Scene {
  vf::Terrain terrain, view;
};
Scene loadScene(const std::string& path, const std::vector<std::string>& overrides) {
  const vf::SceneResult s = vf::loadScene(path, overrides);
  REQUIRE(s.ok);
  const vf::TerrainResult t = vf::prepareTerrain(s.scene);
  REQUIRE(t.ok);
  return {t.terrain, vf::layoutFor(t.terrain, s.scene.camera)};
}

int edgeIndex(const std::string& name) {
  const char* names[] = {"Ueq0", "Veq0", "Ueq1", "Veq1"};
  for (int e = 0; e < 4; ++e)
    if (name == names[e]) return e;
  FAIL("edge name " << name);
  return -1;
}

// One finding side's edge points in world space (fftess::edgePoints of its hull factor, the domain shader's
// positions), those with an edge parameter in [lo, hi].
std::vector<glm::vec3> sidePoints(const Scene& sc, const json& side) {
  const vf::Scene& scene = sc.view.scene();
  const std::string bits = side.at("factor_bits");
  const float factor = fftess::floatOf(static_cast<uint32_t>(std::stoul(bits, nullptr, 16)));
  const fftess::EdgePoints ep = fftess::edgePoints(factor, scene.partitioning, scene.stage);
  const int e = edgeIndex(side.at("edge"));
  const float lo = side.at("param_range")[0], hi = side.at("param_range")[1];
  std::vector<glm::vec3> out;
  for (int k = 0; k < ep.count; ++k) {
    const float t = ep.param[k];
    if (t < lo || t > hi) continue;
    const float u = e == fftess::Ueq0 ? 0.0f : e == fftess::Ueq1 ? 1.0f : t;
    const float v = e == fftess::Veq0 ? 0.0f : e == fftess::Veq1 ? 1.0f : t;
    out.push_back(vf::domainPosition(sc.view, side.at("patch").at("index"), u, v));
  }
  return out;
}

bool contains(const std::vector<glm::vec3>& v, const glm::vec3& p) {
  return std::find(v.begin(), v.end(), p) != v.end();
}

json readJson(const std::string& path) { return json::parse(clitest::readFile(path)); }

// `fftess check SCENE --set OVERRIDE... --gltf NAME.glb --json NAME.json -q` (exit status `status`), its JSON report,
// the file read back, and the test's own prepared scene.
struct Checked {
  json report;
  tinygltf::Model model;
  Scene scene;
};
Checked checkWithGltf(const std::string& scenePath, const std::vector<std::string>& overrides, int status,
                      const std::string& name) {
  const std::string glb = clitest::tmpDir() + "/" + name + ".glb", js = clitest::tmpDir() + "/" + name + ".json";
  std::vector<std::string> args{"check", scenePath, "--gltf", glb, "--json", js, "-q"};
  for (const std::string& o : overrides) args.insert(args.end(), {"--set", o});
  const auto r = run(args);
  INFO(r.err);
  REQUIRE(r.status == status);
  return {readJson(js), loadGlb(glb), loadScene(scenePath, overrides)};
}

// The report's findings of one classification ("crack", "t_junction") paired with the file's nodes of that kind (the
// children of the group node "cracks (N)" / "t-junctions (N)", in report order): one node per finding, and no group
// of the other kind.
std::vector<std::pair<const json*, const tinygltf::Node*>> findingNodes(const json& report, const tinygltf::Model& m,
                                                                         const std::string& classification) {
  const bool crack = classification == "crack";
  const std::vector<const tinygltf::Node*> nodes = groupChildren(m, crack ? "cracks (" : "t-junctions (");
  const size_t count = report.at("stats").at(crack ? "cracks" : "t_junctions").get<size_t>();
  REQUIRE(count > 0);
  REQUIRE(report.at("truncated") == false);
  REQUIRE(nodes.size() == count);
  CHECK(groupChildren(m, crack ? "t-junctions (" : "cracks (").empty());
  std::vector<std::pair<const json*, const tinygltf::Node*>> out;
  for (const json& f : report.at("findings"))
    if (f.at("classification") == classification) out.emplace_back(&f, nodes.at(out.size()));
  return out;
}

} // namespace

TEST_CASE("check --gltf: each patch-size mesh is the emulator's tessellation of its patches at the domain shader's "
          "positions",
          "[cli][gltf]") {
  const Checked c = checkWithGltf(kRings, {"lod.adjacency_clamp=none"}, 1, "rings");
  const json& report = c.report;
  const tinygltf::Model& m = c.model;
  const Scene& sc = c.scene;
  const vf::Scene& scene = sc.view.scene();
  const std::vector<const tinygltf::Node*> levels = groupChildren(m, "terrain:");
  REQUIRE(levels.size() == 3); // rings_small: patch sides 2, 4, 8
  std::set<int> drawn;
  std::map<std::pair<int, int>, float> factorOf; // (patch, factor index) -> the factor the file says
  fftess::Tessellator tess;
  for (const tinygltf::Node* n : levels) {
    const tinygltf::Primitive& prim = onlyPrimitive(m, *n);
    CHECK(prim.mode == TINYGLTF_MODE_TRIANGLES);
    const std::vector<glm::vec3> pts = positionsOf(m, prim);
    const std::vector<uint32_t> idx = indicesOf(m, prim);
    const tinygltf::Value& patches = n->extras.Get("patches");
    const tinygltf::Value& factors = n->extras.Get("factors");
    REQUIRE(patches.ArrayLen() == factors.ArrayLen());
    const int level = n->extras.Get("level").GetNumberAsInt();
    CHECK(startsWith(n->name, "level " + std::to_string(level) + ": patches of side "));
    size_t base = 0, ibase = 0, expectPoints = 0, expectIndices = 0;
    for (size_t k = 0; k < patches.ArrayLen(); ++k) {
      const int i = patches.Get(static_cast<int>(k)).GetNumberAsInt();
      CHECK(sc.view.patches().at(static_cast<size_t>(i)).ref.level == level);
      CHECK(drawn.insert(i).second);
      fftess::Patch p;
      p.domain = fftess::Domain::Quad;
      p.partitioning = scene.partitioning;
      p.primitive = fftess::OutputPrimitive::TriangleCw;
      p.stage = scene.stage;
      for (int f = 0; f < 6; ++f) {
        p.factors[f] = static_cast<float>(factors.Get(static_cast<int>(k)).Get(f).GetNumberAsDouble());
        factorOf[{i, f}] = p.factors[f];
      }
      const fftess::OutputCounts counts = fftess::outputCounts(p); // closed form
      expectPoints += static_cast<size_t>(counts.points), expectIndices += static_cast<size_t>(counts.indices);
      const int count = tess.tessellate(p);
      REQUIRE(count == counts.points);
      REQUIRE(base + static_cast<size_t>(count) <= pts.size());
      for (int q = 0; q < count; ++q) {
        const fftess::DomainPoint& d = tess.points()[static_cast<size_t>(q)];
        const glm::vec3 w = vf::domainPosition(sc.view, i, d.u, d.v);
        if (!(pts[base + static_cast<size_t>(q)] == w)) FAIL_CHECK("patch " << i << " point " << q);
      }
      for (size_t q = 0; q < tess.indices().size(); ++q)
        if (idx.at(ibase + q) != base + static_cast<uint32_t>(tess.indices()[q]))
          FAIL_CHECK("patch " << i << " index " << q);
      base += static_cast<size_t>(count), ibase += tess.indices().size();
    }
    CHECK(pts.size() == expectPoints); // the vertices are the patches' tessellation points, nothing merged or added
    CHECK(idx.size() == expectIndices);
  }
  // The patches drawn are those the check did not cull, and the factors are the check's (every finding's sides).
  const json& stats = report.at("stats");
  const int64_t notCulled = stats.at("patches").get<int64_t>() - stats.at("culled_patches").get<int64_t>();
  CHECK(static_cast<int64_t>(drawn.size()) == notCulled);
  REQUIRE(!report.at("findings").empty());
  for (const json& f : report.at("findings"))
    for (const char* s : {"a", "b"}) {
      const json& side = f.at(s);
      const float mine = factorOf.at({side.at("patch").at("index").get<int>(), edgeIndex(side.at("edge"))});
      CHECK(fftess::bitsOf(mine) == std::stoul(side.at("factor_bits").get<std::string>(), nullptr, 16));
    }
}

TEST_CASE("check --gltf: one red line primitive per crack joins both sides' edge points of the shared part",
          "[cli][gltf]") {
  const Checked c = checkWithGltf(kRings, {"lod.adjacency_clamp=none"}, 1, "cracks");
  const tinygltf::Model& m = c.model;
  const Scene& sc = c.scene;
  size_t k = 0;
  for (const auto& [fp, np] : findingNodes(c.report, m, "crack")) {
    const json& f = *fp;
    const tinygltf::Node& n = *np;
    ++k;
    INFO(n.name);
    const int patchA = f.at("a").at("patch").at("index");
    CHECK(startsWith(n.name, "crack " + std::to_string(k) + ": patch " + std::to_string(patchA)));
    CHECK(n.extras.Get("gap_world").GetNumberAsDouble() == f.at("gap_world").get<double>());
    const tinygltf::Primitive& prim = onlyPrimitive(m, n);
    CHECK(prim.mode == TINYGLTF_MODE_LINE);
    const tinygltf::Material& mat = materialOf(m, prim);
    CHECK(mat.name == "crack");
    CHECK(mat.pbrMetallicRoughness.baseColorFactor == std::vector<double>{1, 0, 0, 1});
    const std::vector<glm::vec3> pts = positionsOf(m, prim);
    const std::vector<uint32_t> idx = indicesOf(m, prim);
    CHECK(idx.size() == 2 * (pts.size() - 2)); // two polylines
    // Every edge point of either side in the shared part is on the lines (side b's: its whole shared part; side a's
    // line may reach one point beyond the part at each end, to span it).
    const std::vector<glm::vec3> a = sidePoints(sc, f.at("a")), b = sidePoints(sc, f.at("b"));
    REQUIRE(!b.empty());
    for (const glm::vec3& p : a) CHECK(contains(pts, p));
    for (const glm::vec3& p : b) CHECK(contains(pts, p));
    CHECK(pts.size() <= a.size() + b.size() + 2);
  }
}

TEST_CASE("check --gltf: each T-junction is the yellow points one side has and the other lacks", "[cli][gltf]") {
  const Checked c = checkWithGltf(clitest::source("docs/examples/t_junction.toml"), {}, 0, "tj");
  const tinygltf::Model& m = c.model;
  const Scene& sc = c.scene;
  for (const auto& [fp, np] : findingNodes(c.report, m, "t_junction")) {
    const json& f = *fp;
    const tinygltf::Node& n = *np;
    INFO(n.name);
    const tinygltf::Primitive& prim = onlyPrimitive(m, n);
    CHECK(prim.mode == TINYGLTF_MODE_POINTS);
    CHECK(materialOf(m, prim).pbrMetallicRoughness.baseColorFactor == std::vector<double>{1, 0.9, 0, 1});
    const std::vector<glm::vec3> a = sidePoints(sc, f.at("a")), b = sidePoints(sc, f.at("b"));
    std::vector<glm::vec3> expect;
    for (const glm::vec3& p : a)
      if (!contains(b, p)) expect.push_back(p);
    for (const glm::vec3& p : b)
      if (!contains(a, p)) expect.push_back(p);
    REQUIRE(!expect.empty());
    const std::vector<glm::vec3> pts = positionsOf(m, prim);
    CHECK(pts.size() == expect.size());
    for (const glm::vec3& p : expect) CHECK(contains(pts, p));
  }
}

TEST_CASE("check --gltf: the camera node sits at the eye and looks down its -Z at the target with the camera's "
          "field of view, aspect ratio and clip planes",
          "[cli][gltf]") {
  const std::string glb = clitest::tmpDir() + "/camera.glb";
  const auto r = run({"check", kRings, "--eye", "30,40,-50", "--target", "5,0,3", "--set", "camera.fov_y=45", "--set",
                      "camera.width=800", "--set", "camera.height=600", "--set", "camera.near=0.5", "--set",
                      "camera.far=900", "--gltf", glb, "-q"});
  REQUIRE(r.status == 0);
  const tinygltf::Model m = loadGlb(glb);
  const tinygltf::Node* cam = nullptr;
  for (int root : m.scenes.at(0).nodes)
    if (m.nodes.at(static_cast<size_t>(root)).camera >= 0) cam = &m.nodes[static_cast<size_t>(root)];
  REQUIRE(cam);
  CHECK(startsWith(cam->name, "camera: eye (30, 40, -50) target (5, 0, 3)"));
  REQUIRE(cam->translation.size() == 3);
  CHECK(glm::dvec3(cam->translation[0], cam->translation[1], cam->translation[2]) == glm::dvec3(30, 40, -50));
  REQUIRE(cam->rotation.size() == 4);
  const glm::dquat q(cam->rotation[3], cam->rotation[0], cam->rotation[1], cam->rotation[2]); // glTF: x, y, z, w
  CHECK(std::abs(glm::length(q) - 1.0) < 1e-12);
  const glm::dvec3 forward = q * glm::dvec3(0, 0, -1), up = q * glm::dvec3(0, 1, 0), right = q * glm::dvec3(1, 0, 0);
  const glm::dvec3 want = glm::normalize(glm::dvec3(5, 0, 3) - glm::dvec3(30, 40, -50));
  CHECK(glm::length(forward - want) < 1e-12);
  CHECK(std::abs(right.y) < 1e-12); // no roll: the image's x axis stays level (scene up = +y)
  CHECK(up.y > 0);
  const tinygltf::Camera& c = m.cameras.at(static_cast<size_t>(cam->camera));
  CHECK(c.type == "perspective");
  CHECK(c.perspective.yfov == Approx(45.0 * 3.14159265358979323846 / 180.0).epsilon(1e-15));
  CHECK(c.perspective.aspectRatio == 800.0 / 600.0);
  CHECK(c.perspective.znear == 0.5);
  CHECK(c.perspective.zfar == 900.0);
  CHECK(m.scenes.at(0).name == "rings-small: watertight (the scene's camera)");
  CHECK(m.asset.extras.Get("verdict").Get<std::string>() == "watertight");
}

TEST_CASE("check --gltf: holes are filled in magenta, one surface per hole", "[cli][gltf]") {
  const std::string grid = clitest::source("docs/examples/grid.toml");
  const Checked c = checkWithGltf(grid,
                                  {"displacement.kind=none", "lod.scheme=screen_sphere",
                                   "tessellation.partitioning=fractional_even", "lod.frustum_cull=false",
                                   "camera.eye=[0,0,2]", "camera.target=[0,0,100]"},
                                  1, "holes");
  const json& report = c.report;
  const tinygltf::Model& m = c.model;
  const std::vector<const tinygltf::Node*> holes = groupChildren(m, "holes (");
  REQUIRE(holes.size() == report.at("holes").size());
  REQUIRE(!holes.empty());
  for (size_t k = 0; k < holes.size(); ++k) {
    const int patch = report.at("holes")[k].at("patch").at("index");
    CHECK(holes[k]->name == "hole " + std::to_string(k + 1) + ": patch " + std::to_string(patch) + " (discarded)");
    const tinygltf::Primitive& prim = onlyPrimitive(m, *holes[k]);
    CHECK(prim.mode == TINYGLTF_MODE_TRIANGLES);
    CHECK(materialOf(m, prim).pbrMetallicRoughness.baseColorFactor == std::vector<double>{1, 0, 1, 1});
    const std::vector<glm::vec3> pts = positionsOf(m, prim);
    REQUIRE(pts.size() == 81); // the 8 x 8 grid over the patch's domain, at the domain shader's positions
    for (int b = 0; b <= 8; ++b)
      for (int a = 0; a <= 8; ++a)
        CHECK(pts[static_cast<size_t>(b * 9 + a)] == vf::domainPosition(c.scene.view, patch, static_cast<float>(a) / 8.0f,
                                                                           static_cast<float>(b) / 8.0f));
    CHECK(indicesOf(m, prim).size() == 8 * 8 * 6);
  }
}

TEST_CASE("check --gltf: a name ending in .gltf gives glTF JSON with the same content", "[cli][gltf]") {
  const std::string dir = clitest::tmpDir();
  REQUIRE(run({"check", kRings, "--set", "lod.adjacency_clamp=none", "--gltf", dir + "/text.gltf", "-q"}).status == 1);
  REQUIRE(run({"check", kRings, "--set", "lod.adjacency_clamp=none", "--gltf", dir + "/bin.glb", "-q"}).status == 1);
  const std::string text = clitest::readFile(dir + "/text.gltf");
  CHECK(startsWith(text, "{"));
  CHECK(text.find("data:application/octet-stream;base64,") != std::string::npos);
  tinygltf::Model t;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  REQUIRE(loader.LoadASCIIFromFile(&t, &err, &warn, dir + "/text.gltf"));
  const tinygltf::Model b = loadGlb(dir + "/bin.glb");
  CHECK(t.nodes.size() == b.nodes.size());
  CHECK(t.accessors.size() == b.accessors.size());
  CHECK(t.buffers.at(0).data == b.buffers.at(0).data);
}

TEST_CASE("check --gltf: a path that cannot be written is refused before the work, exit 2 naming --gltf",
          "[cli][gltf]") {
  const std::string dir = clitest::tmpDir();
  const auto missing = run({"check", kRings, "--gltf", dir + "/no/such/dir/view.glb"});
  CHECK(missing.status == 2);
  CHECK(missing.err.find("--gltf") != std::string::npos);
  CHECK(missing.out.empty());
  const auto toStdout = run({"check", kRings, "--gltf", "-"});
  CHECK(toStdout.status == 2);
  CHECK(toStdout.err.find("--gltf -") != std::string::npos);
  const auto same = run({"check", kRings, "--gltf", dir + "/same.out", "--json", dir + "/same.out"});
  CHECK(same.status == 2);
  CHECK(same.err.find("--gltf") != std::string::npos);
  // All or nothing: a report that cannot be written leaves no .glb (nor a temporary file) behind.
  const auto svgDir = run({"check", kRings, "--gltf", dir + "/alone.glb", "--svg", dir});
  CHECK(svgDir.status == 2);
  CHECK(!clitest::fileExists(dir + "/alone.glb"));
  for (const std::string& f : clitest::listDir(dir)) CHECK(f.find(".tmp.") == std::string::npos);
}

TEST_CASE("sweep --gltf: the file shows the sweep's worst camera, checked again", "[cli][gltf]") {
  const std::string glb = clitest::tmpDir() + "/sweep.glb", js = clitest::tmpDir() + "/sweep.json";
  const auto r = run({"sweep", kRings, "--set", "lod.adjacency_clamp=none", "--random", "6", "--seed", "4", "--gltf",
                      glb, "--json", js, "-q"});
  REQUIRE(r.status == 1);
  const json report = readJson(js);
  // The worst camera: the largest on-screen crack gap (the lowest index among equals).
  size_t worst = 0;
  double gap = -1;
  for (const json& c : report.at("cameras")) {
    if (c.at("stats").at("cracks").get<int64_t>() - c.at("stats").at("cracks_off_screen").get<int64_t>() <= 0) continue;
    const double g = c.at("worst").at("on_screen_gap_world");
    if (g > gap) gap = g, worst = c.at("index");
  }
  REQUIRE(gap > 0);
  const tinygltf::Model m = loadGlb(glb);
  const std::string which = m.asset.extras.Get("camera").Get<std::string>();
  CHECK(startsWith(which, "camera " + std::to_string(worst) + " of the sweep"));
  const json& cam = report.at("cameras").at(worst);
  REQUIRE(cam.at("index") == worst);
  const tinygltf::Node* node = nullptr;
  for (const tinygltf::Node& n : m.nodes)
    if (n.camera >= 0) node = &n;
  REQUIRE(node);
  for (int k = 0; k < 3; ++k) CHECK(node->translation.at(static_cast<size_t>(k)) == cam.at("eye")[k].get<double>());
  CHECK(m.asset.extras.Get("verdict").Get<std::string>() == "cracks");
  CHECK(!groupChildren(m, "cracks (").empty());
  // The summary names it too.
  const auto talk = run({"sweep", kRings, "--set", "lod.adjacency_clamp=none", "--random", "6", "--seed", "4", "--gltf",
                         glb});
  CHECK(talk.status == 1);
  const std::string line = "  3D view        camera " + std::to_string(worst) + " (the worst: crack gap ";
  CHECK(talk.out.find(line) != std::string::npos);
}
