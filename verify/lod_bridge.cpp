// The scene's LOD settings -> lod/ calls, per camera. Everything camera-independent (corner heights, height bounds,
// neighbour sizes, far corners) was prepared with the terrain (layout.cpp); this file only calls lod/.
#include "verify/internal.h"

#include <cstring>

namespace fftess::verify::detail {

lod::Camera toLodCamera(const Camera& c) {
  const float fov = c.fovY * (3.14159265358979323846f / 180.0f);
  return lod::makeCamera(c.eye, c.target, c.up, fov, c.nearZ, c.farZ,
                         glm::vec2(static_cast<float>(c.width), static_cast<float>(c.height)));
}

void computeFactors(const TerrainData& t, const Camera& camera, std::vector<lod::PatchLod>& out, WorkStats& work) {
  const Lod& L = t.scene.lod;
  out.resize(t.patches.size());
  // The tile-ring neighbour rule runs for every scheme but patch_center (a negative control, left as it is) where
  // patches of different sizes meet; the clamp and the reconstruction are the scene's lod.adjacency_clamp and
  // lod.reconstruction (held in L.screenSphere for every scheme).
  const bool tile = t.adjacency;
  const lod::TileAdjacency adj{L.screenSphere.clamp, L.screenSphere.reconstruction};
  if (L.scheme == LodScheme::Constant) {
    for (size_t i = 0; i < t.patches.size(); ++i) {
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
  for (size_t i = 0; i < t.patches.size(); ++i) {
    const TerrainPatch& p = t.patches[i];
    switch (L.scheme) {
    case LodScheme::ScreenSphere:
      out[i] = tile ? lod::nvidiaTile(p.lod, p.tile, cam, L.screenSphere)
                    : lod::screenSphere(p.lod, cam, L.screenSphere.sphere);
      break;
    case LodScheme::PatchCenter: out[i] = lod::patchCenter(p.lod, cam, L.screenSphere.sphere); break;
    case LodScheme::DistancePow2:
      out[i] = tile ? lod::distancePow2Tile(p.lod, p.tile, cam, L.distancePow2, adj)
                    : lod::distancePow2(p.lod, cam, L.distancePow2);
      break;
    case LodScheme::Bonaventura:
      out[i] = tile ? lod::bonaventuraTile(p.lod, p.tile, cam, L.bonaventura, adj)
                    : lod::bonaventura(p.lod, cam, L.bonaventura);
      break;
    case LodScheme::ClipDiameter:
      out[i] = tile ? lod::clipDiameterTile(p.lod, p.tile, cam, L.clipDiameter, adj)
                    : lod::clipDiameter(p.lod, cam, L.clipDiameter);
      break;
    case LodScheme::Constant: break;
    }
  }
  work.lodEvaluations += static_cast<int64_t>(t.patches.size());
}

void neighbourRule(const TerrainData& t, const TerrainPatch& p, int e, EdgeLod& out) {
  out.scheme = t.scene.lod.scheme;
  const bool tileCode = t.adjacency && out.scheme != LodScheme::PatchCenter;
  out.neighbourSize = tileCode ? p.tile.size[e] : 1.0f;
  out.clamp = tileCode && out.neighbourSize != 1.0f ? t.scene.lod.screenSphere.clamp : AdjacencyClamp::None;
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
  if (l.neighbourSize == 2.0f)
    add(std::string("neighbour 2x: rebuilt ") + toString(l.reconstruction) + ", " + toString(l.clamp) + " clamp");
  else if (l.neighbourSize == 0.5f)
    add(std::string("neighbour 0.5x: ") + toString(l.clamp) + " clamp");
  if (l.culled && !(l.why.fixes & lod::FixCulled)) add("culled");
  return out;
}

} // namespace fftess::verify
