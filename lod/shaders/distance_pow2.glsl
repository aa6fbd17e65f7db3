// fftess lod, scheme 3: distance-based power of two (Luna, "3D Game Programming with DirectX 11", terrain
// chapter; Richards). Needs common.glsl, and nvidia_tile.glsl for
// distancePow2TileLod (the tile-ring neighbour rule).
//
// factor = exp2(lerp(maxExp, minExp, s)), s = clamp01((d - minDist) / (maxDist - minDist)), d = distance from
// the edge midpoint (edges) or the patch centre (inside) to the eye. Culled patches get 0.

struct DistancePow2Settings {
  float minDistance;
  float maxDistance;
  float minExponent;
  float maxExponent;
  bool frustumCull;
};

EdgeLod distancePow2At(vec3 p, LodCamera cam, DistancePow2Settings s) {
  float d = distanceOrdered(p, cam.eye);
  float e = lerpHlsl(s.maxExponent, s.minExponent, distanceRamp(d, s.minDistance, s.maxDistance));
  float f = exp2(e);
  return makeEdgeLod(f, d, f, e, 0);
}

LodResult distancePow2Lod(vec3 c0, vec3 c1, vec3 c2, vec3 c3, bool useHeightBounds, float minHeight,
                          float maxHeight, LodCamera cam, DistancePow2Settings s) {
  if (s.frustumCull && patchOutsideFrustum(c0, c1, c2, c3, useHeightBounds, minHeight, maxHeight, cam)) {
    return culledLodResult(0.0f);
  }
  LodResult r = emptyLodResult();
  r.e[0] = distancePow2At(midpoint(c0, c2), cam, s);
  r.e[1] = distancePow2At(midpoint(c0, c1), cam, s);
  r.e[2] = distancePow2At(midpoint(c1, c3), cam, s);
  r.e[3] = distancePow2At(midpoint(c2, c3), cam, s);
  EdgeLod inside = distancePow2At(patchCentre(c0, c1, c2, c3), cam, s);
  r.e[4] = inside;
  r.e[5] = inside;
  return r;
}

// With the tile-ring neighbour rule (nvidia_tile.glsl): the rebuilt edge's factor is distancePow2At of its midpoint.
LodResult distancePow2TileLod(vec3 c0, vec3 c1, vec3 c2, vec3 c3, bool useHeightBounds, float minHeight,
                              float maxHeight, TileNeighbourInfo n, LodCamera cam, DistancePow2Settings s,
                              AdjacencySettings adj) {
  LodResult own = distancePow2Lod(c0, c1, c2, c3, useHeightBounds, minHeight, maxHeight, cam, s);
  if (own.culled) {
    return own;
  }
  LodResult r = own;
  for (int e = 0; e < 4; ++e) {
    EdgeLod rebuilt = own.e[e];
    if (n.size[e] == 2.0f) {
      RebuiltEdge big = largerNeighbourEdgeOf(e, c0, c1, c2, c3, n, adj.rebuild);
      rebuilt = distancePow2At(midpoint(big.a, big.b), cam, s);
    }
    r.e[e] = neighbourRuleEdge(own.e[e], rebuilt, n.size[e], adj.clampMode);
  }
  return r;
}
