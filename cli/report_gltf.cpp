// The 3D picture of one checked camera (report_gltf.h): a tinygltf Model built from verify's view mesh and the
// report, serialised by tinygltf as binary glTF (or glTF JSON with an embedded buffer).
#include "report_gltf.h"
#include "causes.h"
#include "common.h"
#include "report_json.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <map>
#include <sstream>
#include <stdexcept>

namespace fftess::cli {

namespace {

// Colours (linear RGB): the patch sizes from a palette of blues, greens and browns that no finding colour uses;
// cracks red, T-junctions yellow, holes magenta, undecided patches grey (docs/cli.md, "3D view").
constexpr double kLevelColours[8][3] = {{0.26, 0.52, 0.80}, {0.36, 0.68, 0.36}, {0.20, 0.65, 0.65},
                                        {0.50, 0.42, 0.75}, {0.55, 0.45, 0.30}, {0.20, 0.30, 0.60},
                                        {0.55, 0.60, 0.25}, {0.35, 0.80, 0.85}};
constexpr double kCrack[3] = {1.0, 0.0, 0.0};
constexpr double kTJunction[3] = {1.0, 0.9, 0.0};
constexpr double kHole[3] = {1.0, 0.0, 1.0};
constexpr double kUndecided[3] = {0.5, 0.5, 0.5};

// nlohmann JSON (the report's own records, report_json.h) as a glTF extras value.
tinygltf::Value toValue(const json& j) {
  if (j.is_object()) {
    tinygltf::Value::Object o;
    for (auto it = j.begin(); it != j.end(); ++it) o[it.key()] = toValue(it.value());
    return tinygltf::Value(std::move(o));
  }
  if (j.is_array()) {
    tinygltf::Value::Array a;
    for (const json& e : j) a.push_back(toValue(e));
    return tinygltf::Value(std::move(a));
  }
  if (j.is_boolean()) return tinygltf::Value(j.get<bool>());
  if (j.is_number_integer() && j.get<int64_t>() >= INT32_MIN && j.get<int64_t>() <= INT32_MAX)
    return tinygltf::Value(static_cast<int>(j.get<int64_t>()));
  if (j.is_number()) return tinygltf::Value(j.get<double>());
  if (j.is_string()) return tinygltf::Value(j.get<std::string>());
  return tinygltf::Value();
}

// The model being built: one buffer, a buffer view per accessor.
class Builder {
public:
  Builder() { m_.buffers.emplace_back(); }
  tinygltf::Model& model() { return m_; }

  int positions(const std::vector<glm::vec3>& pts) {
    // The bounds glTF asks for, over the finite points (a non-finite position is written as it is).
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : pts)
      if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) lo = glm::min(lo, p), hi = glm::max(hi, p);
    if (lo.x > hi.x) lo = hi = glm::vec3(0.0f);
    tinygltf::Accessor a;
    a.bufferView = view(pts.data(), pts.size() * sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER);
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.type = TINYGLTF_TYPE_VEC3;
    a.count = pts.size();
    a.minValues = {lo.x, lo.y, lo.z};
    a.maxValues = {hi.x, hi.y, hi.z};
    m_.accessors.push_back(a);
    return static_cast<int>(m_.accessors.size()) - 1;
  }
  int indices(const std::vector<uint32_t>& idx) {
    tinygltf::Accessor a;
    a.bufferView = view(idx.data(), idx.size() * sizeof(uint32_t), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    a.type = TINYGLTF_TYPE_SCALAR;
    a.count = idx.size();
    m_.accessors.push_back(a);
    return static_cast<int>(m_.accessors.size()) - 1;
  }
  // Opaque, unlit-looking (no metal, full roughness); emissive for findings so they show in any light.
  int material(const std::string& name, const double* rgb, bool emissive) {
    tinygltf::Material mat;
    mat.name = name;
    mat.pbrMetallicRoughness.baseColorFactor = {rgb[0], rgb[1], rgb[2], 1.0};
    mat.pbrMetallicRoughness.metallicFactor = 0.0;
    mat.pbrMetallicRoughness.roughnessFactor = 1.0;
    if (emissive) mat.emissiveFactor = {rgb[0], rgb[1], rgb[2]};
    mat.doubleSided = true;
    m_.materials.push_back(mat);
    return static_cast<int>(m_.materials.size()) - 1;
  }
  // A mesh of one primitive and the node that shows it; returns the node. pts must not be empty; idx empty: drawn in
  // order.
  int meshNode(const std::string& name, const std::vector<glm::vec3>& pts, const std::vector<uint32_t>& idx, int mode,
               int material, const json& extras) {
    tinygltf::Primitive prim;
    prim.attributes["POSITION"] = positions(pts);
    if (!idx.empty()) prim.indices = indices(idx);
    prim.mode = mode;
    prim.material = material;
    tinygltf::Mesh mesh;
    mesh.name = name;
    mesh.primitives.push_back(prim);
    m_.meshes.push_back(mesh);
    tinygltf::Node node;
    node.name = name;
    node.mesh = static_cast<int>(m_.meshes.size()) - 1;
    if (!extras.is_null()) node.extras = toValue(extras);
    return addNode(node);
  }
  // A node that only groups others.
  int group(const std::string& name, const std::vector<int>& children) {
    tinygltf::Node node;
    node.name = name;
    node.children = children;
    return addNode(node);
  }
  int addNode(const tinygltf::Node& node) {
    m_.nodes.push_back(node);
    return static_cast<int>(m_.nodes.size()) - 1;
  }

private:
  int view(const void* data, size_t bytes, int target) {
    std::vector<unsigned char>& bin = m_.buffers[0].data;
    bin.resize((bin.size() + 3) & ~size_t(3)); // every view 4-byte aligned
    tinygltf::BufferView v;
    v.buffer = 0;
    v.byteOffset = bin.size();
    v.byteLength = bytes;
    v.target = target;
    bin.resize(bin.size() + bytes);
    std::memcpy(bin.data() + v.byteOffset, data, bytes);
    m_.bufferViews.push_back(v);
    return static_cast<int>(m_.bufferViews.size()) - 1;
  }
  tinygltf::Model m_;
};

// One mesh per patch size (PatchRef::level), its patches' points and triangles in layout order; its node's extras
// list the patches (indices into the report's layout) and each one's six hull factors (Ueq0 Veq0 Ueq1 Veq1 insideU
// insideV, as the tessellator got them).
int terrainNodes(Builder& b, const vf::ViewMesh& vm) {
  std::map<int, std::vector<const vf::ViewPatch*>> levels;
  for (const vf::ViewPatch& p : vm.patches) levels[p.ref.level].push_back(&p);
  std::vector<int> nodes;
  for (const auto& [level, patches] : levels) {
    std::vector<glm::vec3> pts;
    std::vector<uint32_t> idx;
    json list = json::array(), factors = json::array();
    for (const vf::ViewPatch* p : patches) {
      const uint32_t base = static_cast<uint32_t>(pts.size());
      pts.insert(pts.end(), vm.points.begin() + p->firstPoint, vm.points.begin() + p->firstPoint + p->pointCount);
      for (uint32_t k = p->firstIndex; k < p->firstIndex + p->indexCount; ++k)
        idx.push_back(vm.indices[k] - p->firstPoint + base);
      list.push_back(p->ref.index);
      factors.push_back(std::vector<float>(p->factors, p->factors + 6));
    }
    const double size = patches.front()->size;
    const std::string name = "level " + std::to_string(level) + ": patches of side " + formatNumber(size) + " (" +
                             std::to_string(patches.size()) + " patches)";
    const int mat = b.material("level " + std::to_string(level) + " (side " + formatNumber(size) + ")",
                               kLevelColours[static_cast<size_t>(level) % 8], false);
    const json extras = {{"level", level}, {"side", size}, {"points", pts.size()}, {"triangles", idx.size() / 3},
                         {"patches", list}, {"factors", factors}};
    nodes.push_back(b.meshNode(name, pts, idx, TINYGLTF_MODE_TRIANGLES, mat, extras));
  }
  return b.group("terrain: " + std::to_string(vm.patches.size()) + " patches drawn, by size", nodes);
}

std::string sideText(const vf::EdgeSide& s) {
  return "patch " + std::to_string(s.patch.index) + " " + edgeName(s.edge);
}

// The vertices of one polyline that are not (bit for bit) vertices of the other.
void unmatched(const std::vector<glm::vec3>& from, const std::vector<glm::vec3>& other, std::vector<glm::vec3>& out) {
  for (const glm::vec3& p : from)
    if (std::none_of(other.begin(), other.end(), [&](const glm::vec3& q) { return p == q; })) out.push_back(p);
}

// A crack: both sides' edge polylines over the shared part as one LINES primitive. A T-junction: the vertices of
// either side that are not the other's, as one POINTS primitive.
int findingNode(Builder& b, const vf::ViewMesh& vm, const vf::Finding& f, int number, int crackMat, int tjMat) {
  const bool crack = f.classification == vf::Classification::Crack;
  const auto side = [&](const vf::EdgeSide& s) {
    return vf::edgePolyline(vm, s.patch.index, s.edge, s.paramLo, s.paramHi, crack);
  };
  const std::vector<glm::vec3> a = side(f.a), bb = side(f.b);
  std::vector<glm::vec3> pts;
  std::vector<uint32_t> idx;
  if (crack) {
    for (const std::vector<glm::vec3>* line : {&a, &bb}) {
      const uint32_t base = static_cast<uint32_t>(pts.size());
      pts.insert(pts.end(), line->begin(), line->end());
      for (uint32_t k = 1; k < line->size(); ++k) idx.insert(idx.end(), {base + k - 1, base + k});
    }
  } else {
    unmatched(a, bb, pts);
    unmatched(bb, a, pts);
  }
  if (pts.empty() || (crack && idx.empty())) return -1; // a side not drawn (not for a classified pair)
  std::string name = std::string(crack ? "crack " : "t-junction ") + std::to_string(number) + ": " + sideText(f.a) +
                     " / " + sideText(f.b);
  if (crack) name += ", gap " + fmtWorld(f.gapWorld) + " (" + fmtWorld(f.gapPixels) + " px)";
  if (!f.onScreen) name += ", off screen";
  return b.meshNode(name, pts, idx, crack ? TINYGLTF_MODE_LINE : TINYGLTF_MODE_POINTS, crack ? crackMat : tjMat,
                    findingJson(f));
}

// Cracks and T-junctions, each in its group node (none when there are none).
void findingGroups(Builder& b, const vf::ViewMesh& vm, const vf::Report& r, std::vector<int>& roots) {
  int crackMat = -1, tjMat = -1; // made when first used (glTF validators flag unused materials)
  for (const vf::Finding& f : r.findings) {
    if (f.classification == vf::Classification::Crack && crackMat < 0) crackMat = b.material("crack", kCrack, true);
    if (f.classification == vf::Classification::TJunction && tjMat < 0)
      tjMat = b.material("t-junction", kTJunction, true);
  }
  std::vector<int> cracks, tjs;
  for (const vf::Finding& f : r.findings) {
    if (f.classification == vf::Classification::Match) continue;
    std::vector<int>& list = f.classification == vf::Classification::Crack ? cracks : tjs;
    const int node = findingNode(b, vm, f, static_cast<int>(list.size()) + 1, crackMat, tjMat);
    if (node >= 0) list.push_back(node);
  }
  if (!cracks.empty()) roots.push_back(b.group("cracks (" + std::to_string(cracks.size()) + ")", cracks));
  if (!tjs.empty()) roots.push_back(b.group("t-junctions (" + std::to_string(tjs.size()) + ")", tjs));
}

// Holes and undecided patches: each patch's surface (vm.fills, in the order holes then undecided), in its group.
void fillGroups(Builder& b, const vf::ViewMesh& vm, const vf::Report& r, std::vector<int>& roots) {
  size_t next = 0;
  const auto group = [&](const std::vector<vf::Hole>& holes, const std::string& what, const std::string& plural,
                         const double* rgb) {
    if (holes.empty()) return;
    const int mat = b.material(what, rgb, true);
    std::vector<int> nodes;
    for (const vf::Hole& h : holes) {
      const vf::ViewPatch& p = vm.fills[next++];
      const auto first = vm.points.begin() + p.firstPoint;
      const std::vector<glm::vec3> pts(first, first + p.pointCount);
      std::vector<uint32_t> idx;
      for (uint32_t k = p.firstIndex; k < p.firstIndex + p.indexCount; ++k) idx.push_back(vm.indices[k] - p.firstPoint);
      const bool culled = h.kind == vf::HoleKind::CulledWhileVisible;
      const std::string how = h.visibility == vf::Visibility::Undecided ? (culled ? "culled" : "discarded")
                                                                         : vf::toString(h.kind);
      const std::string name = what + " " + std::to_string(nodes.size() + 1) + ": patch " +
                               std::to_string(h.patch.index) + " (" + how + ")";
      nodes.push_back(b.meshNode(name, pts, idx, TINYGLTF_MODE_TRIANGLES, mat, holeJson(h)));
    }
    roots.push_back(b.group(plural + " (" + std::to_string(nodes.size()) + ")", nodes));
  };
  group(r.holes, "hole", "holes", kHole);
  group(r.undecided, "undecided", "undecided patches", kUndecided);
}

// The camera: a glTF perspective camera on a node at the eye, its rotation taking the camera's local axes (+X right,
// +Y up, looking down -Z) to the view's basis: f = normalize(target - eye), r = normalize(cross(f, up)), u = cross(r,
// f), in double; the rotation's columns are r, u, -f (what glm::lookAt inverts).
int cameraNode(Builder& b, const vf::Camera& c) {
  const glm::dvec3 eye(c.eye), f = glm::normalize(glm::dvec3(c.target) - eye);
  const glm::dvec3 r = glm::normalize(glm::cross(f, glm::dvec3(c.up))), u = glm::cross(r, f);
  const glm::dquat q = glm::normalize(glm::quat_cast(glm::dmat3(r, u, -f)));
  tinygltf::Camera cam;
  cam.type = "perspective";
  cam.name = "fftess camera";
  cam.perspective.yfov = static_cast<double>(c.fovY) * 3.14159265358979323846 / 180.0;
  cam.perspective.aspectRatio = static_cast<double>(c.width) / static_cast<double>(c.height);
  cam.perspective.znear = c.nearZ;
  cam.perspective.zfar = c.farZ;
  tinygltf::Model& m = b.model();
  m.cameras.push_back(cam);
  tinygltf::Node node;
  node.name = "camera: eye (" + formatNumber(c.eye.x) + ", " + formatNumber(c.eye.y) + ", " + formatNumber(c.eye.z) +
              ") target (" + formatNumber(c.target.x) + ", " + formatNumber(c.target.y) + ", " +
              formatNumber(c.target.z) + ")";
  node.camera = static_cast<int>(m.cameras.size()) - 1;
  node.translation = {eye.x, eye.y, eye.z};
  node.rotation = {q.x, q.y, q.z, q.w};
  node.extras = toValue(cameraJson(c));
  return b.addNode(node);
}

std::string serialise(tinygltf::Model& m, bool text) {
  if (m.buffers[0].data.size() > 0xFFFFFFF0u) // GLB chunk lengths are 32-bit
    throw std::runtime_error("--gltf: the mesh takes " + std::to_string(m.buffers[0].data.size()) +
                             " bytes, more than a glTF binary chunk holds (4 GiB)");
  if (m.buffers[0].data.empty()) m.buffers.clear(); // nothing drawn, nothing found: no buffer
  std::ostringstream os;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&m, os, text, !text) || !os)
    throw std::runtime_error("--gltf: tinygltf could not serialise the model");
  return os.str();
}

} // namespace

std::string checkGltf(const vf::Terrain& terrain, const vf::Camera& camera, const vf::CheckOptions& options,
                      const vf::Report& report, const GltfTitle& title, bool text) {
  std::vector<int> fill; // holes first, then undecided patches (fillGroups reads vm.fills in that order)
  for (const vf::Hole& h : report.holes) fill.push_back(h.patch.index);
  for (const vf::Hole& h : report.undecided) fill.push_back(h.patch.index);
  const vf::ViewMesh vm = vf::viewMesh(terrain, camera, options, fill);
  if (!vm.error.empty()) throw std::runtime_error("--gltf: " + vm.error);
  Builder b;
  std::vector<int> roots{terrainNodes(b, vm)};
  findingGroups(b, vm, report, roots);
  fillGroups(b, vm, report, roots);
  roots.push_back(cameraNode(b, camera));
  tinygltf::Model& m = b.model();
  const vf::Scene& scene = terrain.scene();
  m.asset.version = "2.0";
  m.asset.generator = std::string("fftess ") + FFTESS_VERSION + " (tinygltf)";
  m.asset.extras = toValue(json{{"command", title.command},
                                {"scene", scene.name},
                                {"source", scene.source},
                                {"verdict", title.verdict},
                                {"camera", title.camera},
                                {"stats", statsJson(report.stats)}});
  tinygltf::Scene s;
  s.name = (scene.name.empty() ? scene.source : scene.name) + ": " + title.verdict + " (" + title.camera + ")";
  s.nodes = roots;
  m.scenes.push_back(s);
  m.defaultScene = 0;
  return serialise(m, text);
}

bool gltfTextPath(const std::string& path) {
  if (path.size() < 5) return false;
  std::string ext = path.substr(path.size() - 5);
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return ext == ".gltf";
}

} // namespace fftess::cli
