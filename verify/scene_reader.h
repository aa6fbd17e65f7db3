// Internal header of fftess_verify's scene parser (scene.cpp, scene_sections.cpp): the TOML reader that names the
// key and the file position (or the override) in every error, and the tables of the scene format's enumerated
// values. Not installed, not part of the contract; toml++ is included only here and in those two files.
#pragma once

#include "verify/did_you_mean.h"
#include "verify/scene.h"

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <toml++/toml.h>

namespace fftess::verify::detail {

struct Enum {
  const char* name;
  int value;
};

inline const Enum kLayoutKinds[] = {{"grid", int(LayoutKind::Grid)},
                             {"tile_rings", int(LayoutKind::TileRings)},
                             {"heightmap_grid", int(LayoutKind::HeightmapGrid)},
                             {"quadtree", int(LayoutKind::Quadtree)},
                             {"patches", int(LayoutKind::Patches)}};
inline const Enum kQuadtreeSplits[] = {{"distance", int(QuadtreeSplit::Distance)},
                                       {"screen_error", int(QuadtreeSplit::ScreenError)}};
inline const Enum kQuadtreeBalances[] = {{"2to1", int(QuadtreeBalance::TwoToOne)}, {"none", int(QuadtreeBalance::None)}};
inline const Enum kCameraConventions[] = {{"gl", int(CameraConvention::Gl)}, {"d3d", int(CameraConvention::D3d)}};
inline const Enum kCornerModes[] = {{"reconstructed", int(CornerMode::Reconstructed)}, {"shared", int(CornerMode::Shared)}};
inline const Enum kDisplacementKinds[] = {{"none", int(DisplacementKind::None)},
                                   {"raw", int(DisplacementKind::Raw)},
                                   {"fbm", int(DisplacementKind::Fbm)},
                                   {"ridge", int(DisplacementKind::Ridge)}};
inline const Enum kSchemes[] = {{"constant", int(LodScheme::Constant)},
                         {"screen_sphere", int(LodScheme::ScreenSphere)},
                         {"distance_pow2", int(LodScheme::DistancePow2)},
                         {"bonaventura", int(LodScheme::Bonaventura)},
                         {"clip_diameter", int(LodScheme::ClipDiameter)},
                         {"patch_center", int(LodScheme::PatchCenter)},
                         {"geomorph", int(LodScheme::Geomorph)},
                         {"shader", int(LodScheme::Shader)}};
inline const Enum kEvaluates[] = {{"cpu", int(LodEvaluate::Cpu)}, {"gpu", int(LodEvaluate::Gpu)}};
inline const Enum kMipModes[] = {{"none", int(MipMode::None)},
                          {"per_patch", int(MipMode::PerPatch)},
                          {"per_vertex", int(MipMode::PerVertex)}};
inline const Enum kTexelFormats[] = {{"float", int(TexelFormat::Float)}, {"r16_float", int(TexelFormat::R16Float)}};
inline const Enum kHeightBounds[] = {{"global", int(HeightBounds::Global)}, {"per_patch", int(HeightBounds::PerPatch)}};
inline const Enum kInsideRules[] = {{"average", int(lod::InsideRule::Average)},
                             {"min", int(lod::InsideRule::Min)},
                             {"max", int(lod::InsideRule::Max)}};
inline const Enum kInsideFrom[] = {{"own_edges", 0}, {"fixed_edges", 1}};
inline const Enum kSphereCentres[] = {{"half_sum", int(lod::SphereCentre::HalfSum)},
                                      {"around_quad_scaled", int(lod::SphereCentre::AroundQuadScaled)}};
inline const Enum kClamps[] = {{"none", int(AdjacencyClamp::None)},
                        {"integer", int(AdjacencyClamp::Integer)},
                        {"pow2", int(AdjacencyClamp::Pow2)}};
inline const Enum kReconstructions[] = {{"edge_vector", int(lod::Reconstruction::EdgeVector)},
                                 {"far_corner", int(lod::Reconstruction::FarCorner)},
                                 {"resampled", int(lod::Reconstruction::Resampled)}};
inline const Enum kPartitionings[] = {{"integer", int(Partitioning::Integer)},
                               {"pow2", int(Partitioning::Pow2)},
                               {"fractional_odd", int(Partitioning::FractionalOdd)},
                               {"fractional_even", int(Partitioning::FractionalEven)}};
inline const Enum kFormulas[] = {{"nvidia", int(LerpFormula::Nvidia)},     {"lerp", int(LerpFormula::Lerp)},
                          {"lerp_fma", int(LerpFormula::LerpFma)}, {"blend", int(LerpFormula::Blend)},
                          {"blend_fma", int(LerpFormula::BlendFma)}};
inline const Enum kOrders[] = {{"u_first", int(LerpOrder::UFirst)}, {"v_first", int(LerpOrder::VFirst)}};
inline const Enum kHeightUvs[] = {{"world", int(HeightUv::World)}, {"interpolated", int(HeightUv::Interpolated)}};

template <size_t N>
const char* nameOf(const Enum (&table)[N], int v) {
  for (const Enum& e : table)
    if (e.value == v) return e.name;
  return "?";
}

struct Failed {};

inline constexpr int64_t kMaxTexels = int64_t(8193) * 8193; // a raw heightmap's texels at most

// Reads one table, remembering which keys were read so that the rest can be reported as unknown.
class Reader {
public:
  Reader(const std::string& file, const std::map<std::string, std::string>& overridden) : file_(file), overridden_(overridden) {}

  std::string error;

  [[noreturn]] void fail(const std::string& key, const toml::node* at, const std::string& msg) {
    error = position(key, at) + ": " + msg;
    throw Failed{};
  }

  // A file the key names is bad (layout.file): "WHERE: msg (POSITION)", the data file's own position (FILE:LINE)
  // first, then where the key was given as fail() names it.
  [[noreturn]] void failInFile(const std::string& where, const std::string& key, const toml::node* at,
                               const std::string& msg) {
    error = where + ": " + msg + " (" + position(key, at) + ")";
    throw Failed{};
  }

  // Where a key was given: "FILE:LINE:COL: key", "--set key", or "--set KEY=VALUE: key" (an override that made or
  // holds it).
  std::string position(const std::string& key, const toml::node* at) const {
    std::ostringstream os;
    const std::string* by = nullptr; // an override that made or holds this key: "--set a.b.c=5" for a key "a"
    for (const auto& [k, given] : overridden_) {
      const bool below = key.size() > k.size() && key.compare(0, k.size(), k) == 0 && key[k.size()] == '.';
      const bool above = k.size() > key.size() && k.compare(0, key.size(), key) == 0 && k[key.size()] == '.';
      if (below || above) by = &given;
    }
    if (overridden_.count(key)) {
      os << "--set " << key;
    } else if (by) {
      os << "--set " << *by << ": " << key;
    } else {
      os << file_;
      if (at && at->source().begin) os << ":" << at->source().begin.line << ":" << at->source().begin.column;
      os << ": " << key;
    }
    return os.str();
  }

  // "; did you mean "PREFIXNAME"?" for the candidate nearest to word (verify/did_you_mean.h), "" when none is near.
  static std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates,
                                const std::string& prefix = "") {
    const std::string near = nearestName(word, candidates);
    return near.empty() ? "" : "; did you mean \"" + prefix + near + "\"?";
  }

  // Checks that every key of tbl is in `known`; an unknown one names the nearest known key (with its prefix, as
  // --set takes it): `lod.adjacency_clmp: unknown key (did you mean "lod.adjacency_clamp"?)`.
  void unknownKeys(const toml::table& tbl, const std::string& prefix, std::initializer_list<const char*> known) {
    for (auto&& [k, v] : tbl) {
      bool ok = false;
      for (const char* n : known) ok = ok || k.str() == n;
      if (ok) continue;
      const std::string near = didYouMean(std::string(k.str()), {known.begin(), known.end()}, prefix);
      fail(prefix + std::string(k.str()), &v, "unknown key" + (near.empty() ? "" : " (" + near.substr(2) + ")"));
    }
  }

  const toml::table* table(const toml::table& parent, const std::string& prefix, const char* key, bool required) {
    const toml::node* n = parent.get(key);
    if (!n) {
      if (required) fail(prefix + key, &parent, "missing table");
      return nullptr;
    }
    if (!n->is_table()) fail(prefix + key, n, "expected a table");
    return n->as_table();
  }

  bool number(const toml::table& t, const std::string& prefix, const char* key, float& out, bool required = false) {
    const toml::node* n = t.get(key);
    if (!n) {
      if (required) fail(prefix + key, &t, "missing key");
      return false;
    }
    double d;
    if (n->is_floating_point()) d = n->as_floating_point()->get();
    else if (n->is_integer()) d = static_cast<double>(n->as_integer()->get());
    else fail(prefix + key, n, std::string("expected a number, got ") + typeName(*n));
    if (!std::isfinite(d)) fail(prefix + key, n, "must be finite (got " + std::to_string(d) + ")");
    if (std::fabs(d) > 3.0e38) fail(prefix + key, n, "out of float range");
    out = static_cast<float>(d);
    return true;
  }

  bool integer(const toml::table& t, const std::string& prefix, const char* key, int64_t& out, bool required = false) {
    const toml::node* n = t.get(key);
    if (!n) {
      if (required) fail(prefix + key, &t, "missing key");
      return false;
    }
    if (!n->is_integer()) fail(prefix + key, n, std::string("expected an integer, got ") + typeName(*n));
    out = n->as_integer()->get();
    return true;
  }

  bool integer(const toml::table& t, const std::string& prefix, const char* key, int& out, int64_t lo, int64_t hi) {
    int64_t v;
    if (!integer(t, prefix, key, v)) return false;
    if (v < lo || v > hi)
      fail(prefix + key, t.get(key), "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "] (got " +
                                         std::to_string(v) + ")");
    out = static_cast<int>(v);
    return true;
  }

  bool boolean(const toml::table& t, const std::string& prefix, const char* key, bool& out) {
    const toml::node* n = t.get(key);
    if (!n) return false;
    if (!n->is_boolean()) fail(prefix + key, n, std::string("expected true or false, got ") + typeName(*n));
    out = n->as_boolean()->get();
    return true;
  }

  bool string(const toml::table& t, const std::string& prefix, const char* key, std::string& out,
              bool required = false) {
    const toml::node* n = t.get(key);
    if (!n) {
      if (required) fail(prefix + key, &t, "missing key");
      return false;
    }
    if (!n->is_string()) fail(prefix + key, n, std::string("expected a string, got ") + typeName(*n));
    out = n->as_string()->get();
    return true;
  }

  template <class E, size_t N>
  bool enumeration(const toml::table& t, const std::string& prefix, const char* key, const Enum (&table)[N], E& out,
                   bool required = false) {
    std::string s;
    if (!string(t, prefix, key, s, required)) return false;
    for (const Enum& e : table)
      if (s == e.name) {
        out = static_cast<E>(e.value);
        return true;
      }
    std::string choices;
    std::vector<std::string> names;
    for (const Enum& e : table) choices += std::string(choices.empty() ? "" : " | ") + "\"" + e.name + "\"";
    for (const Enum& e : table) names.push_back(e.name);
    fail(prefix + key, t.get(key), "unknown value \"" + s + "\" (expected " + choices + didYouMean(s, names) + ")");
  }

  bool vector(const toml::table& t, const std::string& prefix, const char* key, float* out, size_t count,
              bool required = false) {
    const toml::node* n = t.get(key);
    if (!n) {
      if (required) fail(prefix + key, &t, "missing key");
      return false;
    }
    const toml::array* a = n->as_array();
    if (!a || a->size() != count)
      fail(prefix + key, n, "expected an array of " + std::to_string(count) + " numbers");
    for (size_t i = 0; i < count; ++i) {
      const toml::node& e = *a->get(i);
      double d;
      if (e.is_floating_point()) d = e.as_floating_point()->get();
      else if (e.is_integer()) d = static_cast<double>(e.as_integer()->get());
      else fail(prefix + key, &e, "element " + std::to_string(i) + ": expected a number");
      if (!std::isfinite(d)) fail(prefix + key, &e, "element " + std::to_string(i) + ": must be finite");
      out[i] = static_cast<float>(d);
    }
    return true;
  }

  static const char* typeName(const toml::node& n) {
    switch (n.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a float";
    case toml::node_type::boolean: return "a boolean";
    default: return "a date/time";
    }
  }

private:
  std::string file_;
  const std::map<std::string, std::string>& overridden_; // KEY -> the override as given (KEY=VALUE)
};

// The sections of a scene file, read in this order by readScene (scene.cpp); each throws Failed (r.error set) at the
// first bad key. root: the whole document, overrides applied. baseDir: the folder relative file names resolve against.
// scene_layout.cpp
// Patches of different sizes can meet: tile_rings with rings >= 2, a quadtree with max_depth >= 1, a patches file
// whose squares differ in size.
bool layoutHasSizeJumps(const Layout& L);
void readLayout(Reader& r, const toml::table& root, Scene& s, const std::string& baseDir);
// scene_patches.cpp: layout.file (L.file, resolved and readable) read into L.patchList: an OBJ of quads or a CSV of
// corners; a bad file fails at "layout.file" with the file's own line (file:line: what is wrong).
void readPatchesFile(Reader& r, const toml::table& t, Layout& L);
void readDisplacement(Reader& r, const toml::table& root, Scene& s, const std::string& baseDir);
void readLod(Reader& r, const toml::table& root, Scene& s, const std::string& baseDir);
// scene_hull.cpp: a hull shader as written (lod.entry, lod.evaluation_shader, [lod.uniforms], [lod.inputs],
// lod.control_points, lod.corner_order, lod.domain_u, lod.domain_v), after lod.shader; refused without lod.shader.
void readHullKeys(Reader& r, const toml::table& t, Lod& L, const std::string& baseDir);
void readTessellation(Reader& r, const toml::table& root, Scene& s);
// What needs a particular scheme, partitioning or layout (geomorph, displacement.mip with lod.shader / a scheme).
void checkSchemeEffects(Reader& r, const toml::table& root, const Scene& s);
void readDomain(Reader& r, const toml::table& root, Scene& s);
// [camera] and [[camera_path]] (each path entry starts from [camera]); every camera validated (validateCamera).
void readCameras(Reader& r, const toml::table& root, Scene& s);

} // namespace fftess::verify::detail
