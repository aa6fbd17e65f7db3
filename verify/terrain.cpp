// Terrain layout (grid, NVIDIA tile rings, heightmap grid), neighbours, the hull-shader factors through lod/, and
// the domain-shader emulation.
#include "verify/internal.h"

#include <cmath>
#include <cstring>

namespace fftess::verify::detail {

namespace {

struct Builder {
  const Scene& s;
  Terrain& t;
  // tile rings
  int R = 1, W = 1, P = 1;
  int64_t H = 0; // half extent in base units
  std::vector<std::vector<int>> tileOrdinal; // [ring][tz*W+tx] -> first patch index, -1 in the hole
  // grid / heightmap grid
  int64_t nx = 0, nz = 0;

  int64_t ringHalf(int r) const { return static_cast<int64_t>(W) * P * (int64_t(1) << r) / 2; }

  // Patch containing base-unit cell (cx, cz), -1 outside the terrain.
  int locate(int64_t cx, int64_t cz) const {
    if (cx < 0 || cz < 0 || cx >= t.unitsX || cz >= t.unitsZ) return -1;
    if (s.layout.kind != LayoutKind::TileRings) return static_cast<int>(cz * nx + cx);
    for (int r = 0; r < R; ++r) {
      const int64_t lo = H - ringHalf(r), hi = H + ringHalf(r);
      if (cx < lo || cx >= hi || cz < lo || cz >= hi) continue;
      const int64_t size = int64_t(1) << r;
      const int64_t px = (cx - lo) / size, pz = (cz - lo) / size;
      const int tx = static_cast<int>(px / P), tz = static_cast<int>(pz / P);
      const int first = tileOrdinal[r][static_cast<size_t>(tz) * W + tx];
      if (first < 0) continue; // in the hole: an inner ring holds it
      return first + static_cast<int>((pz % P) * P + (px % P));
    }
    return -1;
  }
};

float lerpWith(LerpFormula f, float a, float b, float t) {
  switch (f) {
  case LerpFormula::Nvidia:
  case LerpFormula::Lerp: return a + t * (b - a);
  case LerpFormula::LerpFma: return std::fma(t, b - a, a);
  case LerpFormula::Blend: return a * (1.0f - t) + b * t;
  case LerpFormula::BlendFma: return std::fma(b, t, a * (1.0f - t));
  }
  return a + t * (b - a);
}

// Bilinear interpolation of four scalars c[u + 2v] in the scene's stated order.
float bilerp(const DomainShader& ds, float c0, float c1, float c2, float c3, float u, float v) {
  if (ds.order == LerpOrder::UFirst) {
    const float bottom = lerpWith(ds.formula, c0, c1, u);
    const float top = lerpWith(ds.formula, c2, c3, u);
    return lerpWith(ds.formula, bottom, top, v);
  }
  const float left = lerpWith(ds.formula, c0, c2, v);
  const float right = lerpWith(ds.formula, c1, c3, v);
  return lerpWith(ds.formula, left, right, u);
}

float heightAt(const Terrain& t, float x, float z) {
  const float tx = (x - t.extent.minX) * t.invSizeX;
  const float tz = (z - t.extent.minZ) * t.invSizeZ;
  const Displacement& d = t.scene->displacement;
  return d.heightScale * sampleBilinear(d, tx, tz);
}

} // namespace

bool buildTerrain(const Scene& s, Terrain& t, std::string& error) {
  t = Terrain{};
  t.scene = &s;
  const Layout& L = s.layout;
  if (s.displacement.kind != DisplacementKind::None &&
      (!s.displacement.texels || s.displacement.texels->size() !=
                                     static_cast<size_t>(s.displacement.texWidth) * s.displacement.texHeight ||
       s.displacement.texWidth < 1 || s.displacement.texHeight < 1)) {
    error = "displacement: texture not loaded (use loadScene / parseScene)";
    return false;
  }
  Builder b{s, t, 1, 1, 1, 0, {}, 0, 0};
  double patchWorld = 1; // world size of a base unit
  const bool reconstructed = L.corners == CornerMode::Reconstructed;

  if (L.kind == LayoutKind::TileRings) {
    b.R = L.rings;
    b.W = L.tilesPerRingEdge;
    b.P = L.patchesPerTileEdge;
    b.H = b.ringHalf(b.R - 1);
    t.unitsX = t.unitsZ = 2 * b.H;
    patchWorld = L.basePatchSize;
    t.adjacency = b.R > 1;
  } else if (L.kind == LayoutKind::Grid) {
    b.nx = L.patchesX;
    b.nz = L.patchesZ;
    t.unitsX = b.nx;
    t.unitsZ = b.nz;
    patchWorld = L.patchSize;
  } else {
    const Displacement& d = s.displacement;
    b.nx = (d.texWidth - 1) / L.cellsPerPatch;
    b.nz = (d.texHeight - 1) / L.cellsPerPatch;
    t.unitsX = b.nx;
    t.unitsZ = b.nz;
    patchWorld = static_cast<double>(L.cellsPerPatch) * L.cellSize;
  }
  t.unit = patchWorld;
  const double minX = L.centerX - 0.5 * static_cast<double>(t.unitsX) * patchWorld;
  const double minZ = L.centerZ - 0.5 * static_cast<double>(t.unitsZ) * patchWorld;
  t.extent.minX = static_cast<float>(minX);
  t.extent.minZ = static_cast<float>(minZ);
  t.extent.maxX = static_cast<float>(minX + static_cast<double>(t.unitsX) * patchWorld);
  t.extent.maxZ = static_cast<float>(minZ + static_cast<double>(t.unitsZ) * patchWorld);
  t.invSizeX = 1.0f / (t.extent.maxX - t.extent.minX);
  t.invSizeZ = 1.0f / (t.extent.maxZ - t.extent.minZ);

  // Shared vertex buffer: each corner once, from its integer position, in double, rounded to float.
  auto sharedX = [&](int64_t ux) { return static_cast<float>(minX + static_cast<double>(ux) * patchWorld); };
  auto sharedZ = [&](int64_t uz) { return static_cast<float>(minZ + static_cast<double>(uz) * patchWorld); };

  auto addPatch = [&](int ring, int tile, int patch, int64_t ux, int64_t uz, int64_t size, float ox, float oz,
                      float tileSize, int iu, int iv, int perTile) {
    TerrainPatch p;
    p.ref.index = static_cast<int>(t.patches.size());
    p.ref.ring = ring;
    p.ref.tile = tile;
    p.ref.patch = patch;
    p.ref.level = ring;
    p.ux = ux;
    p.uz = uz;
    p.size = size;
    for (int c = 0; c < 4; ++c) {
      const int du = c & 1, dv = c >> 1;
      float x, z;
      if (reconstructed) {
        // NVIDIA sample: u = iu / (vertices per tile edge - 1), position = u * tileSize + tileOrigin, in float.
        const float u = static_cast<float>(iu + du) / static_cast<float>(perTile);
        const float v = static_cast<float>(iv + dv) / static_cast<float>(perTile);
        x = u * tileSize + ox;
        z = v * tileSize + oz;
      } else {
        x = sharedX(ux + du * size);
        z = sharedZ(uz + dv * size);
      }
      p.corners[c] = Vec3{x, 0.0f, z};
      p.tex[c][0] = (x - t.extent.minX) * t.invSizeX;
      p.tex[c][1] = (z - t.extent.minZ) * t.invSizeZ;
    }
    t.patches.push_back(p);
  };

  if (L.kind == LayoutKind::TileRings) {
    b.tileOrdinal.assign(b.R, std::vector<int>(static_cast<size_t>(b.W) * b.W, -1));
    for (int r = 0; r < b.R; ++r) {
      const int64_t size = int64_t(1) << r;
      const int64_t lo = b.H - b.ringHalf(r);
      const float tileSize = static_cast<float>(b.P) * L.basePatchSize * static_cast<float>(size);
      for (int tz = 0; tz < b.W; ++tz) {
        for (int tx = 0; tx < b.W; ++tx) {
          const bool hole = r > 0 && tx >= b.W / 4 && tx < b.W - b.W / 4 && tz >= b.W / 4 && tz < b.W - b.W / 4;
          if (hole) continue;
          b.tileOrdinal[r][static_cast<size_t>(tz) * b.W + tx] = static_cast<int>(t.patches.size());
          // Tile origin as the sample's CPU code places tiles: centre + (index - width/2) * tileSize, in float.
          const float ox = L.centerX + static_cast<float>(tx - b.W / 2) * tileSize;
          const float oz = L.centerZ + static_cast<float>(tz - b.W / 2) * tileSize;
          for (int pz = 0; pz < b.P; ++pz)
            for (int px = 0; px < b.P; ++px)
              addPatch(r, tz * b.W + tx, pz * b.P + px, lo + (int64_t(tx) * b.P + px) * size,
                       lo + (int64_t(tz) * b.P + pz) * size, size, ox, oz, tileSize, px, pz, b.P);
        }
      }
    }
  } else {
    const float size = static_cast<float>(patchWorld);
    const float ox = static_cast<float>(minX), oz = static_cast<float>(minZ);
    for (int64_t z = 0; z < b.nz; ++z)
      for (int64_t x = 0; x < b.nx; ++x) {
        // Reconstructed grid: origin + i * size, in float.
        const int idx = static_cast<int>(z * b.nx + x);
        addPatch(0, 0, idx, x, z, 1, ox, oz, size, static_cast<int>(x), static_cast<int>(z), 1);
      }
  }

  // Neighbours: the patch(es) holding the base-unit cells just across each edge, at its two ends.
  for (TerrainPatch& p : t.patches) {
    const int64_t s0 = p.size;
    const int64_t cells[4][2][2] = {
        {{p.ux - 1, p.uz}, {p.ux - 1, p.uz + s0 - 1}},   // Ueq0: -x
        {{p.ux, p.uz - 1}, {p.ux + s0 - 1, p.uz - 1}},   // Veq0: -z
        {{p.ux + s0, p.uz}, {p.ux + s0, p.uz + s0 - 1}}, // Ueq1: +x
        {{p.ux, p.uz + s0}, {p.ux + s0 - 1, p.uz + s0}}, // Veq1: +z
    };
    for (int e = 0; e < 4; ++e) {
      const int n0 = b.locate(cells[e][0][0], cells[e][0][1]);
      const int n1 = b.locate(cells[e][1][0], cells[e][1][1]);
      p.nb[e][0] = n0;
      p.nb[e][1] = n1 != n0 ? n1 : -1;
    }
  }
  return true;
}

Vec3 evalDomain(const Terrain& t, const TerrainPatch& p, float u, float v) {
  const Scene& s = *t.scene;
  const Vec3* c = p.corners;
  Vec3 w;
  w.x = bilerp(s.domain, c[0].x, c[1].x, c[2].x, c[3].x, u, v);
  w.z = bilerp(s.domain, c[0].z, c[1].z, c[2].z, c[3].z, u, v);
  w.y = 0.0f; // the corners are flat (the sample's hull shader drops y); the height is added below
  if (s.displacement.kind != DisplacementKind::None) {
    float tx, tz;
    if (s.domain.heightUv == HeightUv::World) {
      tx = (w.x - t.extent.minX) * t.invSizeX;
      tz = (w.z - t.extent.minZ) * t.invSizeZ;
    } else {
      tx = bilerp(s.domain, p.tex[0][0], p.tex[1][0], p.tex[2][0], p.tex[3][0], u, v);
      tz = bilerp(s.domain, p.tex[0][1], p.tex[1][1], p.tex[2][1], p.tex[3][1], u, v);
    }
    w.y = w.y + s.displacement.heightScale * sampleBilinear(s.displacement, tx, tz);
  }
  return w;
}

lod::Camera toLodCamera(const Camera& c) {
  const float fov = c.fovY * (3.14159265358979323846f / 180.0f);
  return lod::makeCamera(glm::vec3(c.eye.x, c.eye.y, c.eye.z), glm::vec3(c.target.x, c.target.y, c.target.z),
                         glm::vec3(c.up.x, c.up.y, c.up.z), fov, c.nearZ, c.farZ,
                         glm::vec2(static_cast<float>(c.width), static_cast<float>(c.height)));
}

namespace {

lod::Patch lodPatch(const Terrain& t, const TerrainPatch& p) {
  lod::Patch lp;
  const Scene& s = *t.scene;
  const bool raise = s.lod.displacedCorners && s.displacement.kind != DisplacementKind::None;
  for (int c = 0; c < 4; ++c) {
    const float y = raise ? heightAt(t, p.corners[c].x, p.corners[c].z) : 0.0f;
    lp.corners[c] = glm::vec3(p.corners[c].x, y, p.corners[c].z);
  }
  if (s.displacement.kind != DisplacementKind::None) {
    lp.useHeightBounds = true;
    lp.minHeight = std::fmin(0.0f, s.displacement.heightScale);
    lp.maxHeight = std::fmax(0.0f, s.displacement.heightScale);
  }
  return lp;
}

// Corner indices (lod.h convention) of each edge: Ueq0 = 0-2, Veq0 = 0-1, Ueq1 = 1-3, Veq1 = 2-3.
constexpr int kEdgeCorners[4][2] = {{0, 2}, {0, 1}, {1, 3}, {2, 3}};
constexpr int kOpposite[4] = {Ueq1, Veq1, Ueq0, Veq0};

} // namespace

void computeFactors(const Terrain& t, const Camera& camera, std::vector<PatchFactors>& out) {
  const Scene& s = *t.scene;
  const Lod& L = s.lod;
  out.resize(t.patches.size());
  const lod::Camera cam = toLodCamera(camera);

  lod::ScreenSphereParams sphere;
  sphere.tessellatedTriWidth = L.targetPixels;
  sphere.minFactor = L.minFactor;
  sphere.maxFactor = L.maxFactor;
  sphere.frustumCull = L.frustumCull;

  for (size_t i = 0; i < t.patches.size(); ++i) {
    const TerrainPatch& p = t.patches[i];
    PatchFactors& f = out[i];
    if (L.scheme == LodScheme::Constant) {
      for (float& x : f.f) x = L.factor;
      continue;
    }
    const lod::Patch lp = lodPatch(t, p);
    lod::PatchLod r;
    switch (L.scheme) {
    case LodScheme::ScreenSphere:
      if (t.adjacency) {
        lod::NvidiaTileParams np;
        np.sphere = sphere;
        np.clamp = L.adjacencyClamp;
        np.reconstruction = L.reconstruction;
        lod::TileNeighbours tn;
        tn.oddU = ((p.ux / p.size) & 1) != 0;
        tn.oddV = ((p.uz / p.size) & 1) != 0;
        for (int e = 0; e < 4; ++e) {
          const int n0 = p.nb[e][0];
          if (n0 < 0) continue; // outer border
          const TerrainPatch& q = t.patches[n0];
          if (p.nb[e][1] >= 0 || q.size < p.size) {
            tn.size[e] = 0.5f;
          } else if (q.size > p.size) {
            tn.size[e] = 2.0f;
            // The far end of the larger neighbour's edge: its corner on the shared edge not shared with us.
            const int oe = kOpposite[e];
            const lod::Patch lq = lodPatch(t, q);
            const bool alongX = e == Veq0 || e == Veq1;
            const int64_t lo = alongX ? p.ux : p.uz;
            const int64_t qlo = alongX ? q.ux : q.uz;
            const int farIdx = (qlo == lo) ? kEdgeCorners[oe][1] : kEdgeCorners[oe][0];
            tn.farCorner[e] = lq.corners[farIdx];
          }
        }
        r = lod::nvidiaTile(lp, tn, cam, np);
      } else {
        r = lod::screenSphere(lp, cam, sphere);
      }
      break;
    case LodScheme::DistancePow2: {
      lod::DistancePow2Params dp;
      dp.minDistance = L.minDistance;
      dp.maxDistance = L.maxDistance;
      dp.minTessExponent = L.minTess;
      dp.maxTessExponent = L.maxTess;
      dp.frustumCull = L.frustumCull;
      r = lod::distancePow2(lp, cam, dp);
      break;
    }
    case LodScheme::Bonaventura: {
      lod::BonaventuraParams bp;
      bp.minDistance = L.minDistance;
      bp.maxDistance = L.maxDistance;
      bp.minExponent = L.minTess;
      bp.maxExponent = L.maxTess;
      bp.angleCorrection = L.angleCorrection;
      bp.rank = L.rank;
      bp.minFactor = L.minFactor;
      bp.maxFactor = L.maxFactor;
      bp.frustumCull = L.frustumCull;
      r = lod::bonaventura(lp, cam, bp);
      break;
    }
    case LodScheme::ClipDiameter: {
      lod::ClipDiameterParams cp;
      cp.edgesPerScreenHeight = L.edgesPerScreenHeight;
      cp.minFactor = L.minFactor;
      cp.maxFactor = L.maxFactor;
      cp.frustumCull = L.frustumCull;
      r = lod::clipDiameter(lp, cam, cp);
      break;
    }
    case LodScheme::PatchCenter: {
      // Deliberately broken LOD: the screen-space sphere of every edge is centred on the patch centre. Each edge
      // is measured through lod::screenSphere on a degenerate patch whose Veq0 edge is this edge moved to the
      // centre (same direction and length); the real patch decides culling.
      r = lod::screenSphere(lp, cam, sphere);
      if (r.why.culled) break;
      glm::vec3 centre = 0.25f * (lp.corners[0] + lp.corners[1] + lp.corners[2] + lp.corners[3]);
      lod::ScreenSphereParams noCull = sphere;
      noCull.frustumCull = false;
      for (int e = 0; e < 4; ++e) {
        const glm::vec3 a = lp.corners[kEdgeCorners[e][0]], bq = lp.corners[kEdgeCorners[e][1]];
        const glm::vec3 half = 0.5f * (bq - a);
        lod::Patch fake;
        fake.corners[0] = fake.corners[2] = centre - half;
        fake.corners[1] = fake.corners[3] = centre + half;
        r.factors[e] = lod::screenSphere(fake, cam, noCull).factors[Veq0];
      }
      r.factors[InsideU] = 0.5f * (r.factors[Veq0] + r.factors[Veq1]);
      r.factors[InsideV] = 0.5f * (r.factors[Ueq0] + r.factors[Ueq1]);
      break;
    }
    case LodScheme::Constant: break;
    }
    std::memcpy(f.f, r.factors, sizeof f.f);
  }
}

const EdgePoints& EdgeCache::get(float factor) {
  uint32_t bits;
  std::memcpy(&bits, &factor, sizeof bits);
  auto it = map_.find(bits);
  if (it != map_.end()) return it->second;
  return map_.emplace(bits, edgePoints(factor, partitioning_, stage_, options_)).first->second;
}

} // namespace fftess::verify::detail

namespace fftess::verify {

int patchCount(const Scene& scene) {
  detail::Terrain t;
  std::string err;
  if (!detail::buildTerrain(scene, t, err)) return 0;
  return static_cast<int>(t.patches.size());
}

PatchRef patchRef(const Scene& scene, int patchIndex) {
  detail::Terrain t;
  std::string err;
  if (!detail::buildTerrain(scene, t, err) || patchIndex < 0 || patchIndex >= static_cast<int>(t.patches.size()))
    return {};
  return t.patches[patchIndex].ref;
}

std::vector<PatchGeometry> patchGeometry(const Scene& scene) {
  detail::Terrain t;
  std::string err;
  std::vector<PatchGeometry> out;
  if (!detail::buildTerrain(scene, t, err)) return out;
  out.resize(t.patches.size());
  for (size_t i = 0; i < t.patches.size(); ++i) {
    out[i].ref = t.patches[i].ref;
    for (int c = 0; c < 4; ++c) out[i].corners[c] = t.patches[i].corners[c];
  }
  return out;
}

Extent terrainExtent(const Scene& scene) {
  detail::Terrain t;
  std::string err;
  detail::buildTerrain(scene, t, err);
  return t.extent;
}

Vec3 domainPosition(const Scene& scene, int patchIndex, float u, float v) {
  detail::Terrain t;
  std::string err;
  if (!detail::buildTerrain(scene, t, err) || patchIndex < 0 || patchIndex >= static_cast<int>(t.patches.size()))
    return {};
  return detail::evalDomain(t, t.patches[patchIndex], u, v);
}

} // namespace fftess::verify
