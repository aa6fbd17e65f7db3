// The scene's LOD settings -> lod/ calls, per camera. Everything camera-independent (corner heights, height bounds,
// neighbour sizes, far corners) was prepared with the terrain (layout.cpp); this file only calls lod/.
#include "verify/lod_bridge.h"
#include "verify/internal.h"

#include <cstdio>

#include <chrono>
#include <cstring>

namespace fftess::verify::detail {

// fov in radians: fovY * float(pi / 180), one float product.
lod::Camera viewCamera(const Camera& c) {
  const float fov = c.fovY * (3.14159265358979323846f / 180.0f);
  return lod::makeCamera(c.eye, c.target, c.up, fov, c.nearZ, c.farZ,
                         glm::vec2(static_cast<float>(c.width), static_cast<float>(c.height)));
}

lod::Camera toLodCamera(const Camera& c) {
  if (c.convention == CameraConvention::Gl) return detail::viewCamera(c);
  const float fov = c.fovY * (3.14159265358979323846f / 180.0f);
  return lod::makeCameraD3d(c.eye, c.target, c.up, fov, c.nearZ, c.farZ,
                            glm::vec2(static_cast<float>(c.width), static_cast<float>(c.height)));
}

lod::PatchLod patchLod(const TerrainData& t, const TerrainPatch& p, const lod::TileNeighbours& neighbours,
                       const lod::Camera& cam) {
  const Lod& L = t.scene.lod;
  const bool tile = t.adjacency;
  const lod::TileAdjacency adj{L.screenSphere.clamp, L.screenSphere.reconstruction};
  switch (L.scheme) {
  case LodScheme::ScreenSphere:
    return tile ? lod::nvidiaTile(p.lod, neighbours, cam, L.screenSphere) : lod::screenSphere(p.lod, cam, L.screenSphere.sphere);
  case LodScheme::PatchCenter: return lod::patchCenter(p.lod, cam, L.screenSphere.sphere);
  case LodScheme::DistancePow2:
    return tile ? lod::distancePow2Tile(p.lod, neighbours, cam, L.distancePow2, adj)
                : lod::distancePow2(p.lod, cam, L.distancePow2);
  case LodScheme::Bonaventura:
    return tile ? lod::bonaventuraTile(p.lod, neighbours, cam, L.bonaventura, adj)
                : lod::bonaventura(p.lod, cam, L.bonaventura);
  case LodScheme::ClipDiameter:
    return tile ? lod::clipDiameterTile(p.lod, neighbours, cam, L.clipDiameter, adj)
                : lod::clipDiameter(p.lod, cam, L.clipDiameter);
  case LodScheme::Constant:
    if (tile) return lod::constantTile(L.factor, neighbours, adj);
    {
      lod::PatchLod r;
      for (float& x : r.factors) x = L.factor;
      return r;
    }
  case LodScheme::Geomorph: break; // levels need the neighbours' levels: computeFactors
  case LodScheme::Shader: break;   // only on the GPU (computeFactorsFor)
  }
  return lod::PatchLod{};
}

void computeFactors(const TerrainData& t, const Camera& camera, std::vector<lod::PatchLod>& out, WorkStats& work,
                    const std::vector<char>* need) {
  const Lod& L = t.scene.lod;
  out.resize(t.patches.size());
  // The tile-ring neighbour rule runs for every scheme but patch_center (a negative control, left as it is) where
  // patches of different sizes meet; the clamp and the reconstruction are the scene's lod.adjacency_clamp and
  // lod.reconstruction (held in L.screenSphere for every scheme).
  const bool tile = t.adjacency;
  const lod::TileAdjacency adj{L.screenSphere.clamp, L.screenSphere.reconstruction};
  if (L.scheme == LodScheme::Constant) {
    for (size_t i = 0; i < t.patches.size(); ++i) {
      if (need && !(*need)[i]) continue;
      lod::PatchLod& r = out[i];
      if (tile) {
        r = lod::constantTile(L.factor, t.patches[i].tile, adj);
        continue;
      }
      r = lod::PatchLod{};
      for (float& x : r.factors) x = L.factor;
    }
    return;
  }
  const lod::Camera cam = toLodCamera(camera);
  if (L.scheme == LodScheme::Geomorph) {
    // Each patch's float level from its centre, then its factors from its own and its neighbours' levels (the
    // patch's own level across the terrain's border). Patches are all one size (the scene refuses size jumps).
    std::vector<float> level(t.patches.size());
    for (size_t i = 0; i < t.patches.size(); ++i) level[i] = lod::geomorphLevel(t.patches[i].lod, cam, L.geomorph);
    for (size_t i = 0; i < t.patches.size(); ++i) {
      float nl[4];
      for (int e = 0; e < 4; ++e) {
        const int n = t.patches[i].nb[e][0];
        nl[e] = n >= 0 ? level[static_cast<size_t>(n)] : level[i];
      }
      out[i] = lod::geomorph(level[i], nl);
    }
    work.lodEvaluations += static_cast<int64_t>(t.patches.size());
    return;
  }
  int64_t evaluated = 0;
  for (size_t i = 0; i < t.patches.size(); ++i) {
    if (need && !(*need)[i]) continue;
    out[i] = patchLod(t, t.patches[i], t.patches[i].tile, cam);
    ++evaluated;
  }
  work.lodEvaluations += evaluated;
}

bool usesGpu(const Scene& s) { return !s.lod.shader.empty() || s.lod.evaluate == LodEvaluate::Gpu; }

Options tessellatorOptions(const Scene& s, const CheckOptions& options) {
  Options o = options.tessellator;
  o.flushDenormals = denormalRule(s, options).flush;
  return o;
}

bool computeFactorsFor(const TerrainData& t, const Camera& camera, FactorProvider* gpu,
                       std::vector<lod::PatchLod>& out, std::vector<lod::PatchLod>* cpu, WorkStats& work,
                       std::string& error, const std::vector<char>* need) {
  const Scene& s = t.scene;
  if (!usesGpu(s)) {
    computeFactors(t, camera, out, work, need);
    return true;
  }
  if (!gpu) {
    error = std::string(s.lod.shader.empty() ? "lod.evaluate = \"gpu\"" : "lod.shader") +
            " needs a GPU factor provider (CheckOptions::factors; the fftess command line builds one)";
    return false;
  }
  if (!gpu->evaluate(LodPatches(t), toLodCamera(camera), out, error)) return false;
  if (out.size() != t.patches.size()) {
    error = "the GPU factor provider returned " + std::to_string(out.size()) + " patches, the terrain has " +
            std::to_string(t.patches.size());
    return false;
  }
  work.lodEvaluations += static_cast<int64_t>(t.patches.size());
  if (cpu && s.lod.scheme != LodScheme::Shader) {
    WorkStats ignored; // the C++ reference is not the checked evaluation
    const auto t0 = std::chrono::steady_clock::now();
    computeFactors(t, camera, *cpu, ignored);
    gpu->noteCpuSeconds(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return true;
}

// Geomorph: the level lod::geomorph recorded as the inside factors' metric (FactorWhy::metric = L); segments are
// the hull factors. Mip: lod::bonaventura's corrected, unrounded exponents: Why::cornerLevel (per_vertex) or the
// inside factor's exponent at the patch centre (per_patch); mip level = maxExponent - exponent, in float.
DomainCamera domainCamera(const TerrainData& t, const std::vector<lod::PatchLod>& factors) {
  DomainCamera out;
  const Scene& s = t.scene;
  const bool displaced = s.displacement.kind != DisplacementKind::None;
  const bool geomorph = displaced && s.lod.scheme == LodScheme::Geomorph;
  const bool mip = displaced && s.displacement.mip != MipMode::None;
  if (!geomorph && !mip) return out;
  out.patches.resize(t.patches.size());
  for (size_t i = 0; i < t.patches.size(); ++i) {
    PatchDomain& d = out.patches[i];
    const lod::PatchLod& f = factors[i];
    if (geomorph) {
      const float level = f.why.factor[4].metric;
      for (int e = 0; e < 4; ++e) {
        const int n = t.patches[i].nb[e][0];
        const float nl = n >= 0 ? factors[static_cast<size_t>(n)].why.factor[4].metric : level;
        d.morphSegments[e] = f.factors[e];
        d.morphWeight[e] = lod::geomorphWeight(level, nl, s.lod.geomorph);
      }
      d.morphSegments[4] = f.factors[4];
      d.morphWeight[4] = lod::geomorphWeight(level, level, s.lod.geomorph);
    }
    if (mip) {
      const float maxExp = s.lod.bonaventura.maxExponent;
      if (s.displacement.mip == MipMode::PerPatch) {
        d.mipLevel[0] = maxExp - f.why.factor[4].exponent;
      } else {
        for (int c = 0; c < 4; ++c) d.mipLevel[c] = maxExp - f.why.cornerLevel[c];
      }
    }
  }
  return out;
}

void neighbourRule(const TerrainData& t, const TerrainPatch& p, int e, EdgeLod& out) {
  // The factors' producer: the user's shader whenever lod.shader is set (lod.scheme is then only the comparison).
  out.scheme = t.scene.lod.shader.empty() ? t.scene.lod.scheme : LodScheme::Shader;
  const bool tileCode = t.adjacency && out.scheme != LodScheme::PatchCenter;
  out.neighbourSize = tileCode ? p.tile.size[e] : 1.0f;
  // lod/ applies its rule (and the clamp) at 2x jumps only; a larger jump (4, 0.25, ...) it treats as none.
  const bool rule = out.neighbourSize == 2.0f || out.neighbourSize == 0.5f;
  out.clamp = tileCode && rule ? t.scene.lod.screenSphere.clamp : AdjacencyClamp::None;
  out.reconstruction = t.scene.lod.screenSphere.reconstruction;
}

// view = V * (at, 1) in lod's column order (m[0]*x + m[1]*y + m[2]*z + m[3]); depth = -view.z;
// pixels = world * (projection[1][1] * viewport.y * 0.5) / depth, in double after the float view transform.
double pixelsAt(const lod::Camera& camera, const glm::vec3& at, double world) {
  const glm::mat4& v = camera.view;
  const float z = v[0].z * at.x + v[1].z * at.y + v[2].z * at.z + v[3].z;
  const double depth = -static_cast<double>(z);
  if (!(depth > 0)) return 0;
  const double focal = static_cast<double>(camera.projection[1][1]) * 0.5 * static_cast<double>(camera.viewport.y);
  return world * focal / depth;
}

} // namespace fftess::verify::detail

namespace fftess::verify {

DenormalRule denormalRule(const Scene& scene, const CheckOptions& options) {
  DenormalRule r;
  if (options.flushDenormals != DenormalFlush::Auto) {
    r.flush = options.flushDenormals == DenormalFlush::On;
    r.why = std::string("--flush-denormals ") + (r.flush ? "on" : "off");
  } else if (scene.lod.flushDenormals != DenormalFlush::Auto) {
    r.flush = scene.lod.flushDenormals == DenormalFlush::On;
    r.why = std::string("lod.flush_denormals = ") + (r.flush ? "true" : "false");
  } else if (detail::usesGpu(scene) && options.factors) {
    r.flush = options.factors->flushesDenormals(&r.why);
  } else {
    r.flush = options.tessellator.flushDenormals;
    r.why = r.flush ? "CheckOptions::tessellator.flushDenormals" : "the D3D11 reference (lod/'s C++ factors)";
  }
  return r;
}

LodPatches::LodPatches(const Terrain& terrain) : t_(&terrain.data()) {}
size_t LodPatches::size() const { return t_->patches.size(); }
LodInput LodPatches::operator[](size_t i) const {
  const detail::TerrainPatch& p = t_->patches[i];
  return LodInput{p.lod, p.tile};
}
bool LodPatches::sizeJumps() const { return t_->adjacency; }
uint64_t LodPatches::generation() const { return t_->layoutGeneration; }
LodPatches::Corner LodPatches::corner(size_t i, int c) const {
  const detail::TerrainPatch& p = t_->patches[i];
  return Corner{p.corners[c], t_->geometry[i].heights[c], glm::vec2(p.tex[c][0], p.tex[c][1])};
}
Extent LodPatches::extent() const { return t_->extent; }
const Scene& LodPatches::scene() const { return t_->scene; }

std::string lodWords(const EdgeSide& side) {
  const EdgeLod& l = side.lod;
  std::string out;
  auto add = [&](const std::string& w) {
    if (w.empty()) return;
    if (!out.empty()) out += ", ";
    out += w;
  };
  if (l.scheme == LodScheme::Constant && l.neighbourSize == 1.0f) return out; // lod/ did not run
  for (uint32_t bit = 1; bit <= lod::FixLiteralSource; bit <<= 1)
    if (l.why.fixes & bit) add(lod::fixName(static_cast<lod::Fix>(bit)));
  char ratio[48];
  std::snprintf(ratio, sizeof ratio, "neighbour %gx", double(l.neighbourSize));
  const bool beyond2x = l.neighbourSize != 1.0f && l.neighbourSize != 2.0f && l.neighbourSize != 0.5f;
  if (l.scheme == LodScheme::Shader && l.neighbourSize != 1.0f) // the shader's own rule: fftess states no clamp
    add(ratio);
  else if (beyond2x) // a jump beyond 2x (an unbalanced quadtree, a patches layout): lod/ ran no neighbour rule
    add(std::string(ratio) + ": lod/'s neighbour rule handles 2x jumps only");
  else if (l.neighbourSize == 2.0f)
    add(std::string("neighbour 2x: rebuilt ") + toString(l.reconstruction) + ", " + toString(l.clamp) + " clamp");
  else if (l.neighbourSize == 0.5f)
    add(std::string("neighbour 0.5x: ") + toString(l.clamp) + " clamp");
  if (l.culled && !(l.why.fixes & lod::FixCulled)) add("culled");
  return out;
}

lod::Camera viewCamera(const Camera& camera) { return detail::viewCamera(camera); }

} // namespace fftess::verify
