// The prepared terrain: layout (grid, NVIDIA tile rings, heightmap grid), neighbours, and every quantity the LOD
// needs that does not depend on the camera (corner heights, height bounds, neighbour sizes, far corners), built
// once per scene.
#include "verify/terrain.h"
#include "verify/internal.h"

#include <atomic>
#include <cfloat>
#include <cstdio>
#include <cmath>

namespace fftess::verify {

namespace detail {

namespace {

struct Builder {
  const Scene& s;
  TerrainData& t;
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

} // namespace

const char* patchSizeKey(const Scene& s) {
  switch (s.layout.kind) {
  case LayoutKind::TileRings: return "layout.base_patch_size";
  case LayoutKind::Grid: return "layout.patch_size";
  case LayoutKind::HeightmapGrid: return "layout.cell_size";
  case LayoutKind::Quadtree: return "layout.root_size";
  case LayoutKind::Patches: return "layout.file";
  }
  return "layout";
}

// The terrain's float geometry must be finite and resolve every patch: a patch size that vanishes at the scene's
// coordinates (denormal, or below 2^-20 of the largest coordinate) or an extent that overflows float is bad input.
// Non-finite geometry would otherwise reach the LOD and CGAL (whose exact predicates cannot take inf or nan).
bool geometryFits(const Scene& s, double patchWorld, double minX, double minZ, const TerrainData& t,
                  std::string& error) {
  const Layout& L = s.layout;
  const char* key = patchSizeKey(s);
  const double given = L.kind == LayoutKind::TileRings ? L.basePatchSize
                       : L.kind == LayoutKind::Grid    ? L.patchSize
                       : L.kind == LayoutKind::Quadtree ? L.rootSize
                                                       : L.cellSize;
  char buf[320];
  const bool finiteExtent = std::isfinite(t.extent.minX) && std::isfinite(t.extent.maxX) &&
                            std::isfinite(t.extent.minZ) && std::isfinite(t.extent.maxZ) &&
                            std::isfinite(t.invSizeX) && std::isfinite(t.invSizeZ) && t.invSizeX > 0 &&
                            t.invSizeZ > 0;
  const double maxAbs = std::fmax(std::fmax(std::fabs(minX), std::fabs(minX + double(t.unitsX) * patchWorld)),
                                  std::fmax(std::fabs(minZ), std::fabs(minZ + double(t.unitsZ) * patchWorld)));
  if (s.displacement.kind != DisplacementKind::None && !(std::fabs(s.displacement.heightScale) < 0x1p60)) {
    std::snprintf(buf, sizeof buf,
                  "displacement.height_scale: %g overflows float in the LOD's squared distances (must be below 2^60)",
                  double(s.displacement.heightScale));
    error = buf;
    return false;
  }
  // 2^60: beyond it squared distances (the LOD's edge lengths and view distances) overflow float.
  if ((!finiteExtent || !(maxAbs < 0x1p60)) && !(patchWorld < 1)) {
    std::snprintf(buf, sizeof buf, "%s: %g overflows float: the terrain spans %g x %g world units (coordinates must stay below 2^60 "
                  "so that squared distances stay finite)",
                  key, given,
                  double(t.unitsX) * patchWorld, double(t.unitsZ) * patchWorld);
    error = buf;
    return false;
  }
  // 2^-63: below it a patch's squared edge length (the LOD's distances) underflows float.
  if (!finiteExtent || !(patchWorld >= 0x1p-63) || !(patchWorld >= maxAbs * 0x1p-20)) {
    std::snprintf(buf, sizeof buf,
                  "%s: %g vanishes in float at the scene's coordinates (a patch of %g world units at |x|, |z| up to "
                  "%g; it must be at least 2^-20 of that, and at least 2^-63 so that its squared edge length stays a "
                  "normal float)",
                  key, given, patchWorld, maxAbs);
    error = buf;
    return false;
  }
  return true;
}

namespace {

// The layout's size: its extent in base units (the smallest patch size), the builder's counts (tile rings: rings,
// tiles per ring edge, patches per tile edge, half extent; grids: patches per side), whether sizes jump; returns the
// world size of a base unit.
double sizeLayout(const Scene& s, Builder& b, TerrainData& t) {
  const Layout& L = s.layout;
  double patchWorld = 1;
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
  return patchWorld;
}

// Neighbours: the patch(es) holding the base-unit cells just across each edge, at its two ends (TerrainPatch::nb).
void linkNeighbours(const Builder& b, TerrainData& t) {
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
}

bool buildLayout(const Scene& s, TerrainData& t, std::string& error) {
  const Layout& L = s.layout;
  if (s.displacement.kind != DisplacementKind::None &&
      (!s.displacement.texels || s.displacement.texels->size() !=
                                     static_cast<size_t>(s.displacement.texWidth) * s.displacement.texHeight ||
       s.displacement.texWidth < 1 || s.displacement.texHeight < 1)) {
    error = "displacement: texture not loaded (use loadScene / parseScene)";
    return false;
  }
  if (L.kind == LayoutKind::Patches) return buildPatchesLayout(s, t, error);
  Builder b{s, t, 1, 1, 1, 0, {}, 0, 0};
  const bool reconstructed = L.corners == CornerMode::Reconstructed;

  const double patchWorld = sizeLayout(s, b, t); // world size of a base unit
  t.unit = patchWorld;
  const double minX = L.centerX - 0.5 * static_cast<double>(t.unitsX) * patchWorld;
  const double minZ = L.centerZ - 0.5 * static_cast<double>(t.unitsZ) * patchWorld;
  t.extent.minX = static_cast<float>(minX);
  t.extent.minZ = static_cast<float>(minZ);
  t.extent.maxX = static_cast<float>(minX + static_cast<double>(t.unitsX) * patchWorld);
  t.extent.maxZ = static_cast<float>(minZ + static_cast<double>(t.unitsZ) * patchWorld);
  t.invSizeX = 1.0f / (t.extent.maxX - t.extent.minX);
  t.invSizeZ = 1.0f / (t.extent.maxZ - t.extent.minZ);
  if (!geometryFits(s, patchWorld, minX, minZ, t, error)) return false;

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
      p.corners[c] = glm::vec3(x, 0.0f, z);
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

  linkNeighbours(b, t);
  listEndNeighbours(t);
  return true;
}


} // namespace

// lod.height_bounds = "per_patch" (Luna's BoundsY): the lowest and highest texel value any bilinear sample of the
// patch can blend, on every level the scene samples. The patch's texture coordinates span [a, b] (its corners',
// per axis); a sample at s = tx * w - 0.5 reads texels floor(s) and floor(s) + 1, so the texels floor(a * w - 0.5)
// .. floor(b * w - 0.5) + 1 (clamped), widened by one texel each way for the domain shader's rounding of tx.
// Returns [lo, hi] of the texel values (0..1 before height_scale).
void patchTexelRange(const Displacement& d, const TerrainPatch& p, float& lo, float& hi) {
  float a[2] = {p.tex[0][0], p.tex[0][1]}, b[2] = {a[0], a[1]};
  for (int c = 1; c < 4; ++c)
    for (int k = 0; k < 2; ++k) {
      a[k] = std::fmin(a[k], p.tex[c][k]);
      b[k] = std::fmax(b[k], p.tex[c][k]);
    }
  lo = INFINITY;
  hi = -INFINITY;
  const int levels = 1 + (d.mips ? static_cast<int>(d.mips->size()) : 0);
  for (int l = 0; l < levels; ++l) {
    const std::vector<float>& tex = l == 0 ? *d.texels : (*d.mips)[static_cast<size_t>(l - 1)].texels;
    const int w = l == 0 ? d.texWidth : (*d.mips)[static_cast<size_t>(l - 1)].width;
    const int h = l == 0 ? d.texHeight : (*d.mips)[static_cast<size_t>(l - 1)].height;
    auto range = [](float x0, float x1, int n, int& i0, int& i1) {
      const float s0 = std::floor(x0 * static_cast<float>(n) - 0.5f) - 1.0f;
      const float s1 = std::floor(x1 * static_cast<float>(n) - 0.5f) + 2.0f;
      i0 = !(s0 > 0.0f) ? 0 : s0 >= static_cast<float>(n - 1) ? n - 1 : static_cast<int>(s0);
      i1 = !(s1 > 0.0f) ? 0 : s1 >= static_cast<float>(n - 1) ? n - 1 : static_cast<int>(s1);
    };
    int x0, x1, z0, z1;
    range(a[0], b[0], w, x0, x1);
    range(a[1], b[1], h, z0, z1);
    for (int z = z0; z <= z1; ++z)
      for (int x = x0; x <= x1; ++x) {
        const float v = tex[static_cast<size_t>(z) * w + x];
        lo = std::fmin(lo, v);
        hi = std::fmax(hi, v);
      }
  }
}

// What lod/ sees of each patch: its corners raised to the heights the vertex shader samples (lod.displaced_corners)
// and the culling box's height bounds; on tile rings with adjacency, the neighbour sizes, parity, far corners and
// (lod.reconstruction = "resampled" with raised corners) the heights at the rebuilt corners.
void prepareLod(TerrainData& t) {
  const Scene& s = t.scene;
  const bool displaced = s.displacement.kind != DisplacementKind::None;
  const bool raise = s.lod.displacedCorners && displaced;
  for (TerrainPatch& p : t.patches) {
    PatchGeometry& g = t.geometry[static_cast<size_t>(p.ref.index)];
    for (int c = 0; c < 4; ++c) {
      g.heights[c] = displaced ? heightAt(t, p.corners[c].x, p.corners[c].z, t.work) : 0.0f;
      p.lod.corners[c] = glm::vec3(p.corners[c].x, raise ? g.heights[c] : 0.0f, p.corners[c].z);
    }
    patchHeightBounds(s, p);
  }
  if (!t.adjacency) return;
  prepareNeighbours(t);
}

void patchHeightBounds(const Scene& s, TerrainPatch& p) {
  if (s.displacement.kind == DisplacementKind::None) return;
  p.lod.useHeightBounds = true;
  if (s.lod.heightBounds == HeightBounds::PerPatch) {
    float lo, hi;
    patchTexelRange(s.displacement, p, lo, hi);
    const float a = s.displacement.heightScale * lo, b = s.displacement.heightScale * hi;
    p.lod.minHeight = std::fmin(a, b);
    p.lod.maxHeight = std::fmax(a, b);
  } else {
    p.lod.minHeight = std::fmin(0.0f, s.displacement.heightScale);
    p.lod.maxHeight = std::fmax(0.0f, s.displacement.heightScale);
  }
}

// The hole check's box (TerrainPatch::surfaceMinY/MaxY): the texels a patch's footprint can sample on every level
// the scene samples (patchTexelRange: one texel of margin each side for the bilinear pair and the rounding of the
// texture coordinate), times height_scale, padded by 2^-10 of height_scale (filter-weight rounding; any sampled
// height lies between its texels).
void prepareSurfaceBounds(TerrainData& t) {
  if (t.scene.displacement.kind == DisplacementKind::None) return;
  for (TerrainPatch& p : t.patches) patchSurfaceBounds(t.scene.displacement, p);
}

void patchSurfaceBounds(const Displacement& d, TerrainPatch& p) {
  if (d.kind == DisplacementKind::None) return;
  const double hs = d.heightScale;
  const double pad = std::fabs(hs) * 0x1p-10;
  float lo, hi;
  patchTexelRange(d, p, lo, hi);
  const double a = hs * lo, b = hs * hi;
  p.surfaceMinY = static_cast<float>(std::fmin(a, b) - pad);
  p.surfaceMaxY = static_cast<float>(std::fmax(a, b) + pad);
}

bool patchCornersFinite(const TerrainPatch& p, std::string& error) {
  for (const glm::vec3& c : p.corners)
    if (!std::isfinite(c.x) || !std::isfinite(c.z)) {
      error = "layout: patch " + std::to_string(p.ref.index) + " has a non-finite corner (the layout overflows float)";
      return false;
    }
  return true;
}

bool patchCornersFit(const Scene& s, const TerrainPatch& p, std::string& error) {
  if (!patchCornersFinite(p, error)) return false;
  if (!(p.corners[1].x > p.corners[0].x) || !(p.corners[3].x > p.corners[2].x) ||
      !(p.corners[2].z > p.corners[0].z) || !(p.corners[3].z > p.corners[1].z)) {
    char buf[300];
    std::snprintf(buf, sizeof buf,
                  "%s: patch %d has zero area in float (corners x %.9g .. %.9g, z %.9g .. %.9g): the patch size "
                  "vanishes at the scene's coordinates",
                  patchSizeKey(s), p.ref.index, double(p.corners[0].x), double(p.corners[1].x),
                  double(p.corners[0].z), double(p.corners[2].z));
    error = buf;
    return false;
  }
  return true;
}

namespace {

std::atomic<int64_t> gTerrainBuilds{0};

} // namespace

} // namespace detail

WorkStats& WorkStats::operator+=(const WorkStats& o) {
  terrainBuilds += o.terrainBuilds;
  heightSamples += o.heightSamples;
  domainEvaluations += o.domainEvaluations;
  lodEvaluations += o.lodEvaluations;
  edgeQueries += o.edgeQueries;
  cgalCalls += o.cgalCalls;
  fullTessellations += o.fullTessellations;
  sharedEdgePoints += o.sharedEdgePoints;
  visibilityEvaluations += o.visibilityEvaluations;
  layoutSelections += o.layoutSelections;
  layoutNodes += o.layoutNodes;
  cacheHits += o.cacheHits;
  seamHits += o.seamHits;
  cacheMisses += o.cacheMisses;
  seamProofs += o.seamProofs;
  boxTests += o.boxTests;
  return *this;
}

int64_t terrainBuildCount() { return detail::gTerrainBuilds.load(); }

TerrainResult prepareTerrain(const Scene& scene) {
  TerrainResult r;
  auto data = std::make_shared<detail::TerrainData>();
  data->scene = scene;
  if (scene.layout.kind == LayoutKind::Quadtree) {
    if (!detail::prepareQuadtree(*data, r.error)) return r;
    data->work.terrainBuilds = 1;
    ++detail::gTerrainBuilds;
    r.terrain.data_ = std::move(data);
    r.ok = true;
    return r;
  }
  if (!detail::buildLayout(data->scene, *data, r.error)) return r;
  for (const detail::TerrainPatch& p : data->patches)
    if (!detail::patchCornersFinite(p, r.error)) return r;
  for (const detail::TerrainPatch& p : data->patches)
    if (!detail::patchCornersFit(data->scene, p, r.error)) return r;
  data->geometry.resize(data->patches.size());
  for (size_t i = 0; i < data->patches.size(); ++i) {
    data->geometry[i].ref = data->patches[i].ref;
    for (int c = 0; c < 4; ++c) data->geometry[i].corners[c] = data->patches[i].corners[c];
  }
  detail::prepareLod(*data);
  detail::prepareSurfaceBounds(*data);
  data->tree = detail::buildPatchTree(*data);
  data->work.terrainBuilds = 1;
  ++detail::gTerrainBuilds;
  r.terrain.data_ = std::move(data);
  r.ok = true;
  return r;
}

const Scene& Terrain::scene() const { return data_->scene; }
int Terrain::patchCount() const { return data_ ? static_cast<int>(data_->patches.size()) : 0; }
const std::vector<PatchGeometry>& Terrain::patches() const { return data_->geometry; }
const Extent& Terrain::extent() const { return data_->extent; }
const WorkStats& Terrain::stats() const { return data_->work; }
bool Terrain::cameraDependent() const { return data_ && data_->quadtree != nullptr; }

Terrain layoutFor(const Terrain& terrain, const Camera& camera) {
  if (!terrain.cameraDependent()) return terrain;
  auto data = std::make_shared<detail::TerrainData>();
  WorkStats work;
  detail::cameraLayout(terrain.data(), camera, *data, work);
  data->work = work;
  Terrain out;
  out.data_ = std::move(data);
  return out;
}

} // namespace fftess::verify
