// Scene files: TOML (toml++) -> Scene, with every error naming the key and the file position, unknown keys
// rejected, and `KEY=VALUE` overrides validated exactly like the file.
#include "verify/internal.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <sys/stat.h>

#include <toml++/toml.h>

namespace fftess::verify {

namespace {

struct Enum {
  const char* name;
  int value;
};

const Enum kLayoutKinds[] = {{"grid", int(LayoutKind::Grid)},
                             {"tile_rings", int(LayoutKind::TileRings)},
                             {"heightmap_grid", int(LayoutKind::HeightmapGrid)}};
const Enum kCornerModes[] = {{"reconstructed", int(CornerMode::Reconstructed)}, {"shared", int(CornerMode::Shared)}};
const Enum kDisplacementKinds[] = {{"none", int(DisplacementKind::None)},
                                   {"raw", int(DisplacementKind::Raw)},
                                   {"fbm", int(DisplacementKind::Fbm)},
                                   {"ridge", int(DisplacementKind::Ridge)}};
const Enum kSchemes[] = {{"constant", int(LodScheme::Constant)},
                         {"screen_sphere", int(LodScheme::ScreenSphere)},
                         {"distance_pow2", int(LodScheme::DistancePow2)},
                         {"bonaventura", int(LodScheme::Bonaventura)},
                         {"clip_diameter", int(LodScheme::ClipDiameter)},
                         {"patch_center", int(LodScheme::PatchCenter)},
                         {"geomorph", int(LodScheme::Geomorph)},
                         {"shader", int(LodScheme::Shader)}};
const Enum kEvaluates[] = {{"cpu", int(LodEvaluate::Cpu)}, {"gpu", int(LodEvaluate::Gpu)}};
const Enum kMipModes[] = {{"none", int(MipMode::None)},
                          {"per_patch", int(MipMode::PerPatch)},
                          {"per_vertex", int(MipMode::PerVertex)}};
const Enum kTexelFormats[] = {{"float", int(TexelFormat::Float)}, {"r16_float", int(TexelFormat::R16Float)}};
const Enum kHeightBounds[] = {{"global", int(HeightBounds::Global)}, {"per_patch", int(HeightBounds::PerPatch)}};
const Enum kInsideRules[] = {{"average", int(lod::InsideRule::Average)},
                             {"min", int(lod::InsideRule::Min)},
                             {"max", int(lod::InsideRule::Max)}};
const Enum kInsideFrom[] = {{"own_edges", 0}, {"fixed_edges", 1}};
const Enum kClamps[] = {{"none", int(AdjacencyClamp::None)},
                        {"integer", int(AdjacencyClamp::Integer)},
                        {"pow2", int(AdjacencyClamp::Pow2)}};
const Enum kReconstructions[] = {{"edge_vector", int(lod::Reconstruction::EdgeVector)},
                                 {"far_corner", int(lod::Reconstruction::FarCorner)},
                                 {"resampled", int(lod::Reconstruction::Resampled)}};
const Enum kPartitionings[] = {{"integer", int(Partitioning::Integer)},
                               {"pow2", int(Partitioning::Pow2)},
                               {"fractional_odd", int(Partitioning::FractionalOdd)},
                               {"fractional_even", int(Partitioning::FractionalEven)}};
const Enum kFormulas[] = {{"nvidia", int(LerpFormula::Nvidia)},     {"lerp", int(LerpFormula::Lerp)},
                          {"lerp_fma", int(LerpFormula::LerpFma)}, {"blend", int(LerpFormula::Blend)},
                          {"blend_fma", int(LerpFormula::BlendFma)}};
const Enum kOrders[] = {{"u_first", int(LerpOrder::UFirst)}, {"v_first", int(LerpOrder::VFirst)}};
const Enum kHeightUvs[] = {{"world", int(HeightUv::World)}, {"interpolated", int(HeightUv::Interpolated)}};
const Enum kKernels[] = {{"epick", int(Kernel::Epick)}, {"epeck", int(Kernel::Epeck)}, {"float", int(Kernel::FloatNaive)}};

template <size_t N>
const char* nameOf(const Enum (&table)[N], int v) {
  for (const Enum& e : table)
    if (e.value == v) return e.name;
  return "?";
}

struct Failed {};

constexpr int64_t kMaxTexels = int64_t(8193) * 8193; // a raw heightmap's texels at most


// Reads one table, remembering which keys were read so that the rest can be reported as unknown.
class Reader {
public:
  Reader(const std::string& file, const std::map<std::string, std::string>& overridden) : file_(file), overridden_(overridden) {}

  std::string error;

  [[noreturn]] void fail(const std::string& key, const toml::node* at, const std::string& msg) {
    std::ostringstream os;
    const std::string* by = nullptr; // an override that made or holds this key: "--set a.b.c=5" for a key "a"
    for (const auto& [k, given] : overridden_) {
      const bool below = key.size() > k.size() && key.compare(0, k.size(), k) == 0 && key[k.size()] == '.';
      const bool above = k.size() > key.size() && k.compare(0, key.size(), key) == 0 && k[key.size()] == '.';
      if (below || above) by = &given;
    }
    if (overridden_.count(key)) {
      os << "--set " << key << ": " << msg;
    } else if (by) {
      os << "--set " << *by << ": " << key << ": " << msg;
    } else {
      os << file_;
      if (at && at->source().begin) os << ":" << at->source().begin.line << ":" << at->source().begin.column;
      os << ": " << key << ": " << msg;
    }
    error = os.str();
    throw Failed{};
  }

  // Checks that every key of tbl is in `known`.
  void unknownKeys(const toml::table& tbl, const std::string& prefix, std::initializer_list<const char*> known) {
    for (auto&& [k, v] : tbl) {
      bool ok = false;
      for (const char* n : known) ok = ok || k.str() == n;
      if (!ok) fail(prefix + std::string(k.str()), &v, "unknown key");
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
    for (const Enum& e : table) choices += std::string(choices.empty() ? "" : " | ") + "\"" + e.name + "\"";
    fail(prefix + key, t.get(key), "unknown value \"" + s + "\" (expected " + choices + ")");
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

void readCamera(Reader& r, const toml::table& t, const std::string& p, Camera& c, bool requireEyeTarget) {
  r.unknownKeys(t, p, {"eye", "target", "up", "fov_y", "near", "far", "width", "height"});
  r.vector(t, p, "eye", &c.eye.x, 3, requireEyeTarget);
  r.vector(t, p, "target", &c.target.x, 3, requireEyeTarget);
  r.vector(t, p, "up", &c.up.x, 3);
  r.number(t, p, "fov_y", c.fovY);
  r.number(t, p, "near", c.nearZ);
  r.number(t, p, "far", c.farZ);
  r.integer(t, p, "width", c.width, 1, 65536);
  r.integer(t, p, "height", c.height, 1, 65536);
  std::string err;
  if (!detail::validateCamera(c, err)) {
    // err starts with "camera.<key>: ..."; name the key under this table.
    const size_t colon = err.find(':');
    std::string key = err.substr(0, colon);
    const std::string sub = key.substr(key.find('.') + 1);
    const toml::node* at = t.get(sub);
    if (sub == "target" && !at) at = t.get("eye");
    r.fail(p + sub, at ? at : &t, err.substr(colon + 2));
  }
}

void readScene(Reader& r, const toml::table& root, Scene& s, const std::string& baseDir) {
  r.unknownKeys(root, "", {"name", "layout", "displacement", "lod", "tessellation", "domain", "camera", "camera_path"});
  r.string(root, "", "name", s.name);

  // [layout]
  {
    const toml::table& t = *r.table(root, "", "layout", true);
    const std::string p = "layout.";
    Layout& L = s.layout;
    r.unknownKeys(t, p,
                  {"kind", "corners", "center", "patches_x", "patches_z", "patch_size", "rings",
                   "tiles_per_ring_edge", "patches_per_tile_edge", "base_patch_size", "cells_per_patch",
                   "cell_size"});
    r.enumeration(t, p, "kind", kLayoutKinds, L.kind, true);
    r.enumeration(t, p, "corners", kCornerModes, L.corners);
    float c[2] = {L.centerX, L.centerZ};
    if (r.vector(t, p, "center", c, 2)) {
      L.centerX = c[0];
      L.centerZ = c[1];
    }
    r.integer(t, p, "patches_x", L.patchesX, 1, 4096);
    r.integer(t, p, "patches_z", L.patchesZ, 1, 4096);
    if (r.number(t, p, "patch_size", L.patchSize) && !(L.patchSize > 0)) r.fail(p + "patch_size", t.get("patch_size"), "must be > 0");
    r.integer(t, p, "rings", L.rings, 1, 16);
    r.integer(t, p, "tiles_per_ring_edge", L.tilesPerRingEdge, 2, 256);
    r.integer(t, p, "patches_per_tile_edge", L.patchesPerTileEdge, 1, 64);
    if (r.number(t, p, "base_patch_size", L.basePatchSize) && !(L.basePatchSize > 0))
      r.fail(p + "base_patch_size", t.get("base_patch_size"), "must be > 0");
    r.integer(t, p, "cells_per_patch", L.cellsPerPatch, 1, 4096);
    if (r.number(t, p, "cell_size", L.cellSize) && !(L.cellSize > 0)) r.fail(p + "cell_size", t.get("cell_size"), "must be > 0");
    if (L.kind == LayoutKind::TileRings) {
      const toml::node* at = t.get("tiles_per_ring_edge") ? t.get("tiles_per_ring_edge") : &t;
      if (L.tilesPerRingEdge % 2 != 0) r.fail(p + "tiles_per_ring_edge", at, "must be even");
      if (L.rings > 1 && L.tilesPerRingEdge % 4 != 0)
        r.fail(p + "tiles_per_ring_edge", at, "must be a multiple of 4 with more than one ring (the hole is centred)");
      const double patches = double(L.tilesPerRingEdge) * L.tilesPerRingEdge * L.patchesPerTileEdge *
                             L.patchesPerTileEdge * (1 + 0.75 * (L.rings - 1));
      if (patches > 4.0e6) r.fail(p + "rings", t.get("rings") ? t.get("rings") : &t, "more than 4 million patches");
    }
    if (L.kind == LayoutKind::Grid && double(L.patchesX) * L.patchesZ > 4.0e6)
      r.fail(p + "patches_x", t.get("patches_x") ? t.get("patches_x") : &t, "more than 4 million patches");
  }

  // [displacement]
  {
    Displacement& d = s.displacement;
    const toml::table* tp = r.table(root, "", "displacement", false);
    const toml::table empty;
    const toml::table& t = tp ? *tp : empty;
    const std::string p = "displacement.";
    r.unknownKeys(t, p,
                  {"kind", "height_scale", "file", "width", "height", "bits", "seed", "octaves", "frequency",
                   "lacunarity", "gain", "resolution", "subtexel_bits", "format", "mip"});
    if (!tp) d.kind = DisplacementKind::None;
    r.enumeration(t, p, "kind", kDisplacementKinds, d.kind);
    r.number(t, p, "height_scale", d.heightScale);
    r.integer(t, p, "bits", d.bits, 8, 16);
    if (d.bits != 8 && d.bits != 16) r.fail(p + "bits", t.get("bits"), "must be 8 or 16");
    int64_t seed;
    if (r.integer(t, p, "seed", seed)) d.seed = static_cast<uint64_t>(seed);
    r.integer(t, p, "octaves", d.octaves, 1, 16);
    auto positive = [&](const char* key, float& v) {
      if (r.number(t, p, key, v) && !(v > 0)) r.fail(p + key, t.get(key), "must be > 0");
    };
    positive("frequency", d.frequency);
    positive("lacunarity", d.lacunarity);
    positive("gain", d.gain);
    r.integer(t, p, "resolution", d.resolution, 2, 8192);
    r.integer(t, p, "subtexel_bits", d.subtexelBits, 0, 23);
    r.enumeration(t, p, "format", kTexelFormats, d.format);
    r.enumeration(t, p, "mip", kMipModes, d.mip);
    if (d.mip != MipMode::None && d.kind == DisplacementKind::None)
      r.fail(p + "mip", t.get("mip"), "needs a displacement texture (displacement.kind is \"none\")");
    // heightmap_grid: the same cap as the other layouts, from the texture size before the texture is read or made.
    auto capPatches = [&](int64_t w, int64_t h) {
      if (s.layout.kind != LayoutKind::HeightmapGrid) return;
      const int64_t cpp = s.layout.cellsPerPatch, nx = (w - 1) / cpp, nz = (h - 1) / cpp;
      if (double(nx) * double(nz) <= 4.0e6) return;
      const toml::table& lt = *root.get("layout")->as_table();
      r.fail("layout.cells_per_patch", lt.get("cells_per_patch") ? lt.get("cells_per_patch") : &lt,
             "more than 4 million patches (" + std::to_string(nx) + " x " + std::to_string(nz) + " from the " +
                 std::to_string(w) + " x " + std::to_string(h) + " heightmap at cells_per_patch = " +
                 std::to_string(cpp) + ")");
    };
    if (d.kind == DisplacementKind::Raw) {
      r.string(t, p, "file", d.file, true);
      r.integer(t, p, "width", d.width, 2, 65536);
      r.integer(t, p, "height", d.height, 2, 65536);
      if (!t.get("width")) r.fail(p + "width", &t, "missing key (required for kind = \"raw\")");
      if (!t.get("height")) r.fail(p + "height", &t, "missing key (required for kind = \"raw\")");
      if (int64_t(d.width) * d.height > kMaxTexels)
        r.fail(p + "width", t.get("width"),
               std::to_string(d.width) + " x " + std::to_string(d.height) + " texels: more than " +
                   std::to_string(kMaxTexels) + " (8193 x 8193; the file is read whole)");
      capPatches(d.width, d.height);
      std::string path = d.file;
      if (!path.empty() && path[0] != '/') path = baseDir + "/" + path;
      auto texels = std::make_shared<std::vector<float>>();
      std::string err;
      if (!detail::readRawHeightmap(path, d.width, d.height, d.bits, *texels, err)) r.fail(p + "file", t.get("file"), err);
      detail::applyTexelFormat(d.format, *texels);
      d.texels = texels;
      d.texWidth = d.width;
      d.texHeight = d.height;
    } else {
      for (const char* k : {"file", "width", "height"})
        if (t.get(k)) r.fail(p + k, t.get(k), "only allowed with kind = \"raw\"");
      if (d.kind == DisplacementKind::Fbm || d.kind == DisplacementKind::Ridge) {
        capPatches(d.resolution, d.resolution);
        auto texels = std::make_shared<std::vector<float>>(detail::generateHeightfield(d));
        detail::applyTexelFormat(d.format, *texels);
        d.texels = texels;
        d.texWidth = d.texHeight = d.resolution;
      }
    }
    // The mip chain only when asked for, once, at load.
    if (d.mip != MipMode::None)
      d.mips = std::make_shared<const std::vector<MipLevel>>(
          detail::buildMipChain(*d.texels, d.texWidth, d.texHeight, d.format));
    if (s.layout.kind == LayoutKind::HeightmapGrid) {
      const toml::node* at = root.get("layout");
      if (d.kind == DisplacementKind::None)
        r.fail("layout.kind", at->as_table()->get("kind"), "\"heightmap_grid\" needs a displacement texture");
      const int cpp = s.layout.cellsPerPatch;
      if ((d.texWidth - 1) % cpp != 0 || (d.texHeight - 1) % cpp != 0 || d.texWidth <= cpp || d.texHeight <= cpp)
        r.fail("layout.cells_per_patch", at->as_table()->get("cells_per_patch") ? at->as_table()->get("cells_per_patch") : at,
               "heightmap size " + std::to_string(d.texWidth) + " x " + std::to_string(d.texHeight) +
                   " is not cells_per_patch * k + 1 with k >= 1");
    }
  }

  // [lod]
  {
    Lod& L = s.lod;
    const toml::table& t = *r.table(root, "", "lod", true);
    const std::string p = "lod.";
    r.unknownKeys(t, p,
                  {"scheme", "target_pixels", "factor", "min_factor", "max_factor", "min_distance", "max_distance",
                   "min_tess", "max_tess", "angle_correction", "rank", "edges_per_screen_height", "frustum_cull",
                   "displaced_corners", "adjacency_clamp", "reconstruction", "finest_level", "coarsest_level",
                   "literal_article_weight", "height_bounds", "inside", "inside_from", "shader", "evaluate",
                   "flush_denormals"});
    // lod.shader: the user's shader on the GPU (docs/gpu_lod.md); lod.scheme is then optional ("shader": no C++
    // reference) or a built-in scheme the shader's factors are compared with.
    if (r.string(t, p, "shader", L.shader) && !L.shader.empty()) { // "" = none (--set lod.shader='')
      const toml::node* at = t.get("shader");
      const std::string& f = L.shader;
      auto endsWith = [&](const char* ext) {
        const size_t n = std::strlen(ext);
        return f.size() > n && f.compare(f.size() - n, n, ext) == 0;
      };
      if (!endsWith(".glsl") && !endsWith(".hlsl"))
        r.fail(p + "shader", at, "\"" + f + "\": expected a file name ending in .glsl (GLSL 4.50) or .hlsl (HLSL)");
      if (f[0] != '/') L.shader = baseDir + "/" + f;
      struct stat st;
      if (::stat(L.shader.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
        r.fail(p + "shader", at, "cannot read \"" + L.shader + "\" (the path is relative to the scene file)");
      L.scheme = LodScheme::Shader;
      L.evaluate = LodEvaluate::Gpu;
    }
    r.enumeration(t, p, "scheme", kSchemes, L.scheme, L.shader.empty());
    if (L.scheme == LodScheme::Shader && L.shader.empty())
      r.fail(p + "scheme", t.get("scheme"), "\"shader\" needs lod.shader (the file with the entry point lodMain)");
    if (r.enumeration(t, p, "evaluate", kEvaluates, L.evaluate)) {
      if (!L.shader.empty() && L.evaluate != LodEvaluate::Gpu)
        r.fail(p + "evaluate", t.get("evaluate"), "lod.shader runs on the GPU only (lod.evaluate = \"gpu\")");
    }
    if (L.evaluate == LodEvaluate::Gpu && L.scheme == LodScheme::Geomorph)
      r.fail(p + "scheme", t.get("scheme"),
             "\"geomorph\" has no GPU path (lod.evaluate = \"gpu\" or lod.shader): its factors need the "
             "neighbours' levels and its domain shader the levels themselves");
    // lod.flush_denormals: "auto" (the driver's rule on the GPU path), true or false (DenormalFlush).
    if (const toml::node* at = t.get("flush_denormals")) {
      if (at->is_boolean()) L.flushDenormals = at->as_boolean()->get() ? DenormalFlush::On : DenormalFlush::Off;
      else if (at->is_string() && at->as_string()->get() == "auto") L.flushDenormals = DenormalFlush::Auto;
      else if (at->is_string())
        r.fail(p + "flush_denormals", at, "unknown value \"" + at->as_string()->get() + "\" (expected \"auto\" | true | false)");
      else r.fail(p + "flush_denormals", at, std::string("expected \"auto\", true or false, got ") + Reader::typeName(*at));
    }
    // Keys several schemes share are read once and set in every parameter struct that has the field.
    lod::ScreenSphereParams& sphere = L.screenSphere.sphere;
    if (r.number(t, p, "target_pixels", sphere.tessellatedTriWidth) && !(sphere.tessellatedTriWidth > 0))
      r.fail(p + "target_pixels", t.get("target_pixels"), "must be > 0");
    r.number(t, p, "factor", L.factor);
    float minFactor = sphere.minFactor, maxFactor = sphere.maxFactor;
    r.number(t, p, "min_factor", minFactor);
    r.number(t, p, "max_factor", maxFactor);
    if (minFactor > maxFactor)
      r.fail(p + "max_factor", t.get("max_factor") ? t.get("max_factor") : t.get("min_factor"), "must be >= lod.min_factor");
    sphere.minFactor = L.bonaventura.minFactor = L.clipDiameter.minFactor = minFactor;
    sphere.maxFactor = L.bonaventura.maxFactor = L.clipDiameter.maxFactor = maxFactor;
    float minDistance = L.distancePow2.minDistance, maxDistance = L.distancePow2.maxDistance;
    r.number(t, p, "min_distance", minDistance);
    r.number(t, p, "max_distance", maxDistance);
    if (!(maxDistance > minDistance))
      r.fail(p + "max_distance", t.get("max_distance") ? t.get("max_distance") : t.get("min_distance"),
             "must be > lod.min_distance");
    L.distancePow2.minDistance = L.bonaventura.minDistance = L.geomorph.minDistance = minDistance;
    L.distancePow2.maxDistance = L.bonaventura.maxDistance = L.geomorph.maxDistance = maxDistance;
    float minTess = L.distancePow2.minTessExponent, maxTess = L.distancePow2.maxTessExponent;
    r.number(t, p, "min_tess", minTess);
    r.number(t, p, "max_tess", maxTess);
    L.distancePow2.minTessExponent = L.bonaventura.minExponent = minTess;
    L.distancePow2.maxTessExponent = L.bonaventura.maxExponent = maxTess;
    r.boolean(t, p, "angle_correction", L.bonaventura.angleCorrection);
    if (r.number(t, p, "rank", L.bonaventura.rank) && !(L.bonaventura.rank >= 0 && L.bonaventura.rank <= 2))
      r.fail(p + "rank", t.get("rank"), "must be in [0, 2]");
    if (r.number(t, p, "edges_per_screen_height", L.clipDiameter.edgesPerScreenHeight) &&
        !(L.clipDiameter.edgesPerScreenHeight > 0))
      r.fail(p + "edges_per_screen_height", t.get("edges_per_screen_height"), "must be > 0");
    bool frustumCull = sphere.frustumCull;
    r.boolean(t, p, "frustum_cull", frustumCull);
    sphere.frustumCull = L.distancePow2.frustumCull = L.bonaventura.frustumCull = L.clipDiameter.frustumCull =
        frustumCull;
    r.boolean(t, p, "displaced_corners", L.displacedCorners);
    r.enumeration(t, p, "adjacency_clamp", kClamps, L.screenSphere.clamp);
    r.enumeration(t, p, "reconstruction", kReconstructions, L.screenSphere.reconstruction);
    // geomorph
    for (auto [key, field] : {std::pair<const char*, float*>{"finest_level", &L.geomorph.finestLevel},
                              std::pair<const char*, float*>{"coarsest_level", &L.geomorph.coarsestLevel}})
      if (r.number(t, p, key, *field) && !(*field >= 0 && *field <= 5))
        r.fail(p + key, t.get(key), "must be in [0, 5] (level 5: 2^6 = 64 segments)");
    r.boolean(t, p, "literal_article_weight", L.geomorph.literalArticleWeight);
    r.enumeration(t, p, "height_bounds", kHeightBounds, L.heightBounds);
    lod::InsideRule inside = L.screenSphere.sphere.inside;
    if (r.enumeration(t, p, "inside", kInsideRules, inside)) L.screenSphere.sphere.inside = L.clipDiameter.inside = inside;
    // "own_edges" (default): the patch's own edge factors before the neighbour rule; "fixed_edges": after it, as
    // the NVIDIA sample's constant hull shader computes Inside[] (tile rings with screen_sphere).
    int insideFrom = L.screenSphere.insideFromFixedEdges ? 1 : 0;
    if (r.enumeration(t, p, "inside_from", kInsideFrom, insideFrom)) L.screenSphere.insideFromFixedEdges = insideFrom == 1;
    // The neighbour rule's keys, set explicitly where no neighbour rule runs, are refused (the defaults never are):
    // only tile rings with more than one ring have size jumps, and patch_center never gets the rule.
    for (const char* key : {"adjacency_clamp", "reconstruction"}) {
      const toml::node* at = t.get(key);
      if (!at) continue;
      if (s.layout.kind != LayoutKind::TileRings || s.layout.rings < 2)
        r.fail(p + key, at,
               std::string("cannot apply: the layout has no size jumps (layout.kind = \"") + toString(s.layout.kind) +
                   "\"" + (s.layout.kind == LayoutKind::TileRings ? " with layout.rings = 1" : "") +
                   "); the neighbour rule runs only on tile_rings with rings >= 2");
      if (L.scheme == LodScheme::PatchCenter)
        r.fail(p + key, at, "cannot apply: lod.scheme = \"patch_center\" (a negative control) never gets the neighbour rule");
    }
  }

  // [tessellation]
  {
    const toml::table& t = *r.table(root, "", "tessellation", true);
    const std::string p = "tessellation.";
    r.unknownKeys(t, p, {"partitioning", "stage"});
    r.enumeration(t, p, "partitioning", kPartitionings, s.partitioning, true);
    std::string stage;
    if (r.string(t, p, "stage", stage) && !parseStage(stage.c_str(), s.stage))
      r.fail(p + "stage", t.get("stage"),
             "unknown value \"" + stage + "\" (expected " + joinNames(stageNames(), " | ") + ")");
  }

  // Effects that need a particular scheme, partitioning or layout.
  {
    const toml::table& lt = *root.get("lod")->as_table();
    if (s.lod.scheme == LodScheme::Geomorph) {
      if (s.partitioning != Partitioning::Integer) {
        const toml::table& tt = *root.get("tessellation")->as_table();
        r.fail("tessellation.partitioning", tt.get("partitioning"),
               std::string("lod.scheme = \"geomorph\" draws at 2^(floor(L) + 1) segments with integer partitioning; "
                           "got \"") + nameOf(kPartitionings, int(s.partitioning)) + "\" (set it to \"integer\")");
      }
      if (s.layout.kind == LayoutKind::TileRings && s.layout.rings > 1)
        r.fail("lod.scheme", lt.get("scheme"),
               "\"geomorph\" needs patches of one size (tile_rings with more than one ring has size jumps)");
    }
    if (s.displacement.mip != MipMode::None && !s.lod.shader.empty()) {
      const toml::table& dt = *root.get("displacement")->as_table();
      r.fail("displacement.mip", dt.get("mip"),
             "cannot apply with lod.shader (the mip levels are bonaventura's C++ record, which a shader does not return)");
    }
    if (s.displacement.mip != MipMode::None && s.lod.scheme != LodScheme::Bonaventura) {
      const toml::table& dt = *root.get("displacement")->as_table();
      r.fail("displacement.mip", dt.get("mip"),
             "needs lod.scheme = \"bonaventura\" (its corrected exponents are the mip levels)");
    }
  }

  // [domain]
  if (const toml::table* tp = r.table(root, "", "domain", false)) {
    const std::string p = "domain.";
    r.unknownKeys(*tp, p, {"formula", "order", "height_uv"});
    r.enumeration(*tp, p, "formula", kFormulas, s.domain.formula);
    r.enumeration(*tp, p, "order", kOrders, s.domain.order);
    r.enumeration(*tp, p, "height_uv", kHeightUvs, s.domain.heightUv);
  }

  // [camera], [[camera_path]]
  readCamera(r, *r.table(root, "", "camera", true), "camera.", s.camera, true);
  if (const toml::node* n = root.get("camera_path")) {
    const toml::array* a = n->as_array();
    if (!a) r.fail("camera_path", n, "expected an array of tables ([[camera_path]])");
    for (size_t i = 0; i < a->size(); ++i) {
      const toml::node* e = a->get(i);
      const std::string p = "camera_path[" + std::to_string(i) + "].";
      if (!e->is_table()) r.fail("camera_path[" + std::to_string(i) + "]", e, "expected a table");
      Camera c = s.camera;
      readCamera(r, *e->as_table(), p, c, false);
      s.cameraPath.push_back(c);
    }
  }
}

// Applies "KEY=VALUE" to the document.
bool applyOverride(toml::table& root, const std::string& ov, std::map<std::string, std::string>& overridden,
                   std::string& error) {
  const size_t eq = ov.find('=');
  if (eq == std::string::npos || eq == 0) {
    error = "--set " + ov + ": expected KEY=VALUE";
    return false;
  }
  std::string key = ov.substr(0, eq), value = ov.substr(eq + 1);
  while (!key.empty() && key.back() == ' ') key.pop_back();
  while (!value.empty() && value.front() == ' ') value.erase(0, 1);
  std::vector<std::string> parts;
  {
    std::string cur;
    for (char c : key) {
      if (c == '.') {
        parts.push_back(cur);
        cur.clear();
      } else {
        cur += c;
      }
    }
    parts.push_back(cur);
  }
  for (const std::string& part : parts)
    if (part.empty()) {
      error = "--set " + key + ": empty key component";
      return false;
    }
  toml::table* t = &root;
  for (size_t i = 0; i + 1 < parts.size(); ++i) {
    toml::node* n = t->get(parts[i]);
    if (!n) {
      t->insert(parts[i], toml::table{});
      n = t->get(parts[i]);
    }
    if (!n->is_table()) {
      error = "--set " + key + ": '" + parts[i] + "' is not a table";
      return false;
    }
    t = n->as_table();
  }
  toml::node* existing = t->get(parts.back());
  if (existing && existing->is_table()) {
    error = "--set " + key + ": is a table, expected a key";
    return false;
  }
  try {
    toml::table v = toml::parse("v = " + value);
    t->insert_or_assign(parts.back(), *v.get("v"));
  } catch (const toml::parse_error&) {
    t->insert_or_assign(parts.back(), value); // a bare word: a string
  }
  overridden[key] = ov;
  return true;
}

SceneResult parseImpl(const std::string& text, const std::string& source, const std::vector<std::string>& overrides,
                      const std::string& baseDir) {
  SceneResult res;
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    std::ostringstream os;
    os << source << ":" << e.source().begin.line << ":" << e.source().begin.column << ": " << e.description();
    res.error = os.str();
    return res;
  }
  std::map<std::string, std::string> overridden;
  for (const std::string& ov : overrides)
    if (!applyOverride(root, ov, overridden, res.error)) return res;
  Reader r(source, overridden);
  try {
    res.scene.source = source;
    readScene(r, root, res.scene, baseDir);
  } catch (const Failed&) {
    res.error = r.error;
    return res;
  } catch (const std::exception& e) {
    res.error = source + ": " + e.what();
    return res;
  }
  if (!detail::hashSceneContent(text, overrides, res.scene, res.error)) return res;
  res.ok = true;
  return res;
}

// Errors are one line: control bytes that came from the input (a key or an override with a newline) as \xHH.
SceneResult oneLine(SceneResult r) {
  std::string out;
  for (unsigned char c : r.error) {
    if (c >= 0x20 && c != 0x7f) {
      out += static_cast<char>(c);
      continue;
    }
    char buf[8];
    std::snprintf(buf, sizeof buf, "\\x%02x", c);
    out += buf;
  }
  r.error = out;
  return r;
}

} // namespace

SceneResult parseScene(const std::string& text, const std::string& sourceName,
                       const std::vector<std::string>& overrides, const std::string& baseDir) {
  return oneLine(parseImpl(text, sourceName, overrides, baseDir));
}

SceneResult loadScene(const std::string& path, const std::vector<std::string>& overrides) {
  struct stat st;
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
    SceneResult r;
    r.error = path + ": is a directory, not a scene file";
    return r;
  }
  std::string text;
  const int rc = detail::readBounded(path, detail::kMaxSceneBytes, text);
  if (rc <= 0) {
    SceneResult r;
    r.error = path + (rc < 0 ? ": scene file larger than " + std::to_string(detail::kMaxSceneBytes) + " bytes (16 MiB, the limit)"
                             : std::string(": cannot open scene file"));
    return r;
  }
  const size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : path.substr(0, slash == 0 ? 1 : slash);
  return oneLine(parseImpl(text, path, overrides, dir));
}

const char* toString(Classification c) {
  switch (c) {
  case Classification::Match: return "match";
  case Classification::TJunction: return "t_junction";
  case Classification::Crack: return "crack";
  }
  return "?";
}
const char* toString(LayoutKind k) { return nameOf(kLayoutKinds, int(k)); }
const char* toString(DisplacementKind k) { return nameOf(kDisplacementKinds, int(k)); }
const char* toString(LodScheme s) { return nameOf(kSchemes, int(s)); }
const char* toString(AdjacencyClamp c) { return nameOf(kClamps, int(c)); }
const char* toString(lod::Reconstruction r) { return nameOf(kReconstructions, int(r)); }
const char* toString(LerpFormula f) { return nameOf(kFormulas, int(f)); }
const char* toString(Kernel k) { return nameOf(kKernels, int(k)); }
const char* toString(MipMode m) { return nameOf(kMipModes, int(m)); }
const char* toString(TexelFormat f) { return nameOf(kTexelFormats, int(f)); }
const char* toString(HeightBounds b) { return nameOf(kHeightBounds, int(b)); }
const char* toString(LodEvaluate e) { return nameOf(kEvaluates, int(e)); }
bool parseKernel(const char* s, Kernel& out) {
  for (const Enum& e : kKernels)
    if (std::strcmp(s, e.name) == 0) {
      out = static_cast<Kernel>(e.value);
      return true;
    }
  return false;
}

} // namespace fftess::verify
