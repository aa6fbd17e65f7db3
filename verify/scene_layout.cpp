// [layout] of a scene file (declared in verify/scene_reader.h): the layout kind and each kind's keys, validated
// here; layout.kind = "patches" also reads its file (scene_patches.cpp). Every error names the key and its position.
#include "verify/scene.h"
#include "verify/scene_reader.h"

#include <string>
#include <sys/stat.h>

namespace fftess::verify::detail {

namespace {

void readQuadtreeKeys(Reader& r, const toml::table& t, Layout& L) {
  const std::string p = "layout.";
  auto positive = [&](const char* key, float& v) {
    if (r.number(t, p, key, v) && !(v > 0 && std::isfinite(v))) r.fail(p + key, t.get(key), "must be > 0 and finite");
  };
  positive("root_size", L.rootSize);
  r.integer(t, p, "roots_x", L.rootsX, 1, 64);
  r.integer(t, p, "roots_z", L.rootsZ, 1, 64);
  r.integer(t, p, "max_depth", L.maxDepth, 0, 10);
  r.enumeration(t, p, "split", kQuadtreeSplits, L.split);
  positive("lod_distance", L.lodDistance);
  if (r.number(t, p, "lod_distance_ratio", L.lodDistanceRatio) &&
      !(L.lodDistanceRatio >= 1 && std::isfinite(L.lodDistanceRatio)))
    r.fail(p + "lod_distance_ratio", t.get("lod_distance_ratio"), "must be >= 1 and finite");
  positive("max_pixel_error", L.maxPixelError);
  positive("geometric_error", L.geometricError);
  r.enumeration(t, p, "balance", kQuadtreeBalances, L.balance);
  // The node pyramid is prepared once: roots * (4^(depth + 1) - 1) / 3 nodes.
  const double nodes = double(L.rootsX) * L.rootsZ * (std::pow(4.0, L.maxDepth + 1) - 1) / 3;
  if (nodes > double(1 << 22))
    r.fail(p + "max_depth", t.get("max_depth") ? t.get("max_depth") : &t,
           "more than 4 million quadtree nodes (" + std::to_string(static_cast<long long>(nodes)) + " for " +
               std::to_string(L.rootsX) + " x " + std::to_string(L.rootsZ) + " roots at depth " +
               std::to_string(L.maxDepth) + ")");
}

} // namespace

bool layoutHasSizeJumps(const Layout& L) {
  switch (L.kind) {
  case LayoutKind::TileRings: return L.rings >= 2;
  case LayoutKind::Quadtree: return L.maxDepth >= 1;
  case LayoutKind::Patches:
    if (!L.patchList) return false;
    for (const LayoutPatch& p : *L.patchList)
      if (p.corners[1].x - p.corners[0].x != L.patchList->front().corners[1].x - L.patchList->front().corners[0].x)
        return true;
    return false;
  default: return false;
  }
}

void readLayout(Reader& r, const toml::table& root, Scene& s, const std::string& baseDir) {
  const toml::table& t = *r.table(root, "", "layout", true);
  const std::string p = "layout.";
  Layout& L = s.layout;
  r.unknownKeys(t, p,
                {"kind", "corners", "center", "patches_x", "patches_z", "patch_size", "rings",
                 "tiles_per_ring_edge", "patches_per_tile_edge", "base_patch_size", "cells_per_patch",
                 "cell_size", "root_size", "roots_x", "roots_z", "max_depth", "split", "lod_distance",
                 "lod_distance_ratio", "max_pixel_error", "geometric_error", "balance", "file"});
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
  if (L.kind == LayoutKind::Quadtree) readQuadtreeKeys(r, t, L);
  if (L.kind == LayoutKind::Patches) {
    std::string file;
    r.string(t, p, "file", file, true);
    std::string path = file;
    if (!path.empty() && path[0] != '/') path = baseDir + "/" + path;
    struct stat st {};
    if (file.empty() || ::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
      r.fail(p + "file", t.get("file"), "cannot read \"" + path + "\" (the path is relative to the scene file)");
    L.file = path;
    readPatchesFile(r, t, L);
  }
}

} // namespace fftess::verify::detail
