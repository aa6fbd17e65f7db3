// The sections of a scene file, each read and validated in one function (declared in verify/scene_reader.h), in the
// order readScene (scene.cpp) calls them: [layout], [displacement] (and its texture: read, generated, formatted,
// mip chain), [lod], [tessellation], what needs a particular scheme, [domain], [camera] and [[camera_path]]. Every
// error names the key and the file position (Reader::fail) and ends the parse at the first bad key.
#include "verify/scene.h"
#include "verify/internal.h"
#include "verify/scene_reader.h"

#include <cstring>
#include <memory>
#include <string>
#include <sys/stat.h>
#include <utility>
#include <vector>

namespace fftess::verify::detail {

namespace {

// heightmap_grid: the same cap as the other layouts, from the texture size before the texture is read or made.
void capHeightmapPatches(Reader& r, const toml::table& root, const Scene& s, int64_t w, int64_t h) {
  if (s.layout.kind != LayoutKind::HeightmapGrid) return;
  const int64_t cpp = s.layout.cellsPerPatch, nx = (w - 1) / cpp, nz = (h - 1) / cpp;
  if (double(nx) * double(nz) <= 4.0e6) return;
  const toml::table& lt = *root.get("layout")->as_table();
  r.fail("layout.cells_per_patch", lt.get("cells_per_patch") ? lt.get("cells_per_patch") : &lt,
         "more than 4 million patches (" + std::to_string(nx) + " x " + std::to_string(nz) + " from the " +
             std::to_string(w) + " x " + std::to_string(h) + " heightmap at cells_per_patch = " +
             std::to_string(cpp) + ")");
}

// The texture of a displacement (t: its table, maybe empty): the RAW file read or the generator baked, the texel
// format applied, the mip chain built when displacement.mip asks for it, and heightmap_grid's size rule.
void readTexture(Reader& r, const toml::table& root, const toml::table& t, Scene& s, const std::string& baseDir) {
  Displacement& d = s.displacement;
  const std::string p = "displacement.";
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
    capHeightmapPatches(r, root, s, d.width, d.height);
    std::string path = d.file;
    if (!path.empty() && path[0] != '/') path = baseDir + "/" + path;
    auto texels = std::make_shared<std::vector<float>>();
    std::string err;
    if (!readRawHeightmap(path, d.width, d.height, d.bits, *texels, err)) r.fail(p + "file", t.get("file"), err);
    applyTexelFormat(d.format, *texels);
    d.texels = texels;
    d.texWidth = d.width;
    d.texHeight = d.height;
  } else {
    for (const char* k : {"file", "width", "height"})
      if (t.get(k)) r.fail(p + k, t.get(k), "only allowed with kind = \"raw\"");
    if (d.kind == DisplacementKind::Fbm || d.kind == DisplacementKind::Ridge) {
      capHeightmapPatches(r, root, s, d.resolution, d.resolution);
      auto texels = std::make_shared<std::vector<float>>(generateHeightfield(d));
      applyTexelFormat(d.format, *texels);
      d.texels = texels;
      d.texWidth = d.texHeight = d.resolution;
    }
  }
  // The mip chain only when asked for, once, at load.
  if (d.mip != MipMode::None)
    d.mips = std::make_shared<const std::vector<MipLevel>>(
        buildMipChain(*d.texels, d.texWidth, d.texHeight, d.format));
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

} // namespace

void readDisplacement(Reader& r, const toml::table& root, Scene& s, const std::string& baseDir) {
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
  readTexture(r, root, t, s, baseDir);
}

namespace {

// lod.shader, lod.scheme, lod.evaluate and lod.flush_denormals: where the factors come from.
void readLodSource(Reader& r, const toml::table& t, Lod& L, const std::string& baseDir) {
  const std::string p = "lod.";
  // lod.shader: the user's shader on the GPU (docs/gpu_lod.md); lod.scheme is then optional ("shader": no C++
  // reference) or a built-in scheme the shader's factors are compared with.
  if (r.string(t, p, "shader", L.shader) && !L.shader.empty()) { // "" = none (--set lod.shader='')
    const toml::node* at = t.get("shader");
    const std::string& f = L.shader;
    auto endsWith = [&](const char* ext) {
      const size_t n = std::strlen(ext);
      return f.size() > n && f.compare(f.size() - n, n, ext) == 0;
    };
    if (!endsWith(".glsl") && !endsWith(".hlsl") && !endsWith(".tesc") && !endsWith(".fx"))
      r.fail(p + "shader", at,
             "\"" + f + "\": expected a file name ending in .glsl or .tesc (GLSL: a lodMain file or a tessellation "
             "control shader) or .hlsl or .fx (HLSL: a lodMain file or a hull shader)");
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
      r.fail(p + "flush_denormals", at, "unknown value \"" + at->as_string()->get() + "\" (expected \"auto\" | true | false" +
                                                 Reader::didYouMean(at->as_string()->get(), {"auto"}) + ")");
    else r.fail(p + "flush_denormals", at, std::string("expected \"auto\", true or false, got ") + Reader::typeName(*at));
  }
}

// Keys several schemes share are read once and set in every parameter struct that has the field.
void readLodParams(Reader& r, const toml::table& t, Lod& L) {
  const std::string p = "lod.";
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
  // "half_sum" (default): the edge's midpoint; "around_quad_scaled": --gpu-float's negative control (lod.h SphereCentre).
  r.enumeration(t, p, "sphere_centre", kSphereCentres, L.screenSphere.sphere.sphereCentre);
}

// The neighbour rule's keys, set explicitly where no neighbour rule runs, are refused (the defaults never are):
// only tile rings with more than one ring have size jumps, and patch_center never gets the rule.
void refuseNeighbourRuleKeys(Reader& r, const toml::table& t, const Scene& s) {
  const std::string p = "lod.";
  for (const char* key : {"adjacency_clamp", "reconstruction"}) {
    const toml::node* at = t.get(key);
    if (!at) continue;
    if (!layoutHasSizeJumps(s.layout))
      r.fail(p + key, at,
             std::string("cannot apply: the layout has no size jumps (layout.kind = \"") + toString(s.layout.kind) +
                 "\"" + (s.layout.kind == LayoutKind::TileRings ? " with layout.rings = 1" : "") +
                 "); the neighbour rule runs only where patches of different sizes meet: tile_rings with rings >= 2, quadtree with max_depth >= 1, patches of several sizes");
    if (s.lod.scheme == LodScheme::PatchCenter)
      r.fail(p + key, at, "cannot apply: lod.scheme = \"patch_center\" (a negative control) never gets the neighbour rule");
  }
}

} // namespace

void readLod(Reader& r, const toml::table& root, Scene& s, const std::string& baseDir) {
  const toml::table& t = *r.table(root, "", "lod", true);
  const std::string p = "lod.";
  r.unknownKeys(t, p,
                {"scheme", "target_pixels", "factor", "min_factor", "max_factor", "min_distance", "max_distance",
                 "min_tess", "max_tess", "angle_correction", "rank", "edges_per_screen_height", "frustum_cull",
                 "displaced_corners", "adjacency_clamp", "reconstruction", "finest_level", "coarsest_level",
                 "literal_article_weight", "height_bounds", "inside", "inside_from", "sphere_centre", "shader", "evaluate",
                 "flush_denormals", "entry", "evaluation_shader", "uniforms", "inputs", "control_points",
                 "corner_order", "domain_u", "domain_v"});
  readLodSource(r, t, s.lod, baseDir);
  readHullKeys(r, t, s.lod, baseDir);
  readLodParams(r, t, s.lod);
  refuseNeighbourRuleKeys(r, t, s);
}

void readTessellation(Reader& r, const toml::table& root, Scene& s) {
  const toml::table& t = *r.table(root, "", "tessellation", true);
  const std::string p = "tessellation.";
  r.unknownKeys(t, p, {"partitioning", "stage"});
  r.enumeration(t, p, "partitioning", kPartitionings, s.partitioning, true);
  std::string stage;
  if (r.string(t, p, "stage", stage) && !parseStage(stage.c_str(), s.stage))
    r.fail(p + "stage", t.get("stage"),
           "unknown value \"" + stage + "\" (expected " + joinNames(stageNames(), " | ") +
               Reader::didYouMean(stage, stageNames()) + ")");
}

void checkSchemeEffects(Reader& r, const toml::table& root, const Scene& s) {
  const toml::table& lt = *root.get("lod")->as_table();
  if (s.lod.scheme == LodScheme::Geomorph) {
    if (s.partitioning != Partitioning::Integer) {
      const toml::table& tt = *root.get("tessellation")->as_table();
      r.fail("tessellation.partitioning", tt.get("partitioning"),
             std::string("lod.scheme = \"geomorph\" draws at 2^(floor(L) + 1) segments with integer partitioning; "
                         "got \"") + nameOf(kPartitionings, int(s.partitioning)) + "\" (set it to \"integer\")");
    }
    if (layoutHasSizeJumps(s.layout))
      r.fail("lod.scheme", lt.get("scheme"),
             std::string("\"geomorph\" needs patches of one size (layout.kind = \"") + toString(s.layout.kind) +
                 "\" has size jumps)");
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

void readDomain(Reader& r, const toml::table& root, Scene& s) {
  // [domain]
  if (const toml::table* tp = r.table(root, "", "domain", false)) {
    const std::string p = "domain.";
    r.unknownKeys(*tp, p, {"formula", "order", "height_uv"});
    r.enumeration(*tp, p, "formula", kFormulas, s.domain.formula);
    r.enumeration(*tp, p, "order", kOrders, s.domain.order);
    r.enumeration(*tp, p, "height_uv", kHeightUvs, s.domain.heightUv);
  }
}

namespace {

void readCamera(Reader& r, const toml::table& t, const std::string& p, Camera& c, bool requireEyeTarget) {
  r.unknownKeys(t, p, {"eye", "target", "up", "fov_y", "near", "far", "width", "height", "convention"});
  r.vector(t, p, "eye", &c.eye.x, 3, requireEyeTarget);
  r.vector(t, p, "target", &c.target.x, 3, requireEyeTarget);
  r.vector(t, p, "up", &c.up.x, 3);
  r.number(t, p, "fov_y", c.fovY);
  r.number(t, p, "near", c.nearZ);
  r.number(t, p, "far", c.farZ);
  r.integer(t, p, "width", c.width, 1, 65536);
  r.integer(t, p, "height", c.height, 1, 65536);
  r.enumeration(t, p, "convention", kCameraConventions, c.convention); // "gl" | "d3d": the LOD's clip space
  std::string err;
  if (!validateCamera(c, err)) {
    // err starts with "camera.<key>: ..."; name the key under this table.
    const size_t colon = err.find(':');
    std::string key = err.substr(0, colon);
    const std::string sub = key.substr(key.find('.') + 1);
    const toml::node* at = t.get(sub);
    if (sub == "target" && !at) at = t.get("eye");
    r.fail(p + sub, at ? at : &t, err.substr(colon + 2));
  }
}

} // namespace

void readCameras(Reader& r, const toml::table& root, Scene& s) {
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

} // namespace fftess::verify::detail
