// fftess lod, scheme 5: clip-space sphere diameter (the "recommended method" of the tessellation-basics
// article). Needs common.glsl, and nvidia_tile.glsl for
// clipDiameterTileLod (the tile-ring neighbour rule).
//
// Per edge: clip = P * (V * (midpoint, 1)); metric = diameter * P[1][1] / clip.w (the sphere's diameter in NDC
// units); factor = max(minFactor, metric * edgesPerScreenHeight), then min(maxFactor, ..). A midpoint on or behind
// the eye plane (clip.w <= 0, or NaN) gets minFactor.

struct ClipDiameterSettings {
  float edgesPerScreenHeight;
  float minFactor;
  float maxFactor;
  int insideRule;
  bool frustumCull;
  float culledFactor;
};

EdgeLod clipDiameterEdge(vec3 p0, vec3 p1, LodCamera cam, ClipDiameterSettings s) {
  vec3 centre = midpoint(p0, p1);
  float diameter = distanceOrdered(p0, p1);
  vec4 clip = mulPoint(cam.proj, mulPoint(cam.view, vec4(centre, 1.0f)));
  float metric = diameter * cam.proj[1][1] / clip.w;
  float f = metric * s.edgesPerScreenHeight;
  if (!(clip.w > 0.0f)) {
    return makeEdgeLod(s.minFactor, metric, f, 0.0f, kFixClampedMin);
  }
  return clampFactor(metric, f, 0.0f, 0, s.minFactor, s.maxFactor);
}

LodResult clipDiameterLod(vec3 c0, vec3 c1, vec3 c2, vec3 c3, bool useHeightBounds, float minHeight,
                          float maxHeight, LodCamera cam, ClipDiameterSettings s) {
  if (s.frustumCull && patchOutsideFrustum(c0, c1, c2, c3, useHeightBounds, minHeight, maxHeight, cam)) {
    return culledLodResult(s.culledFactor);
  }
  LodResult r = emptyLodResult();
  r.e[0] = clipDiameterEdge(c0, c2, cam, s);
  r.e[1] = clipDiameterEdge(c0, c1, cam, s);
  r.e[2] = clipDiameterEdge(c1, c3, cam, s);
  r.e[3] = clipDiameterEdge(c2, c3, cam, s);
  return withInsideFromEdges(r, s.insideRule);
}

// With the tile-ring neighbour rule (nvidia_tile.glsl): the rebuilt edge's factor is clipDiameterEdge of its ends.
LodResult clipDiameterTileLod(vec3 c0, vec3 c1, vec3 c2, vec3 c3, bool useHeightBounds, float minHeight,
                              float maxHeight, TileNeighbourInfo n, LodCamera cam, ClipDiameterSettings s,
                              AdjacencySettings adj) {
  LodResult own = clipDiameterLod(c0, c1, c2, c3, useHeightBounds, minHeight, maxHeight, cam, s);
  if (own.culled) {
    return own;
  }
  LodResult r = own;
  for (int e = 0; e < 4; ++e) {
    EdgeLod rebuilt = own.e[e];
    if (n.size[e] == 2.0f) {
      RebuiltEdge big = largerNeighbourEdgeOf(e, c0, c1, c2, c3, n, adj.rebuild);
      rebuilt = clipDiameterEdge(big.a, big.b, cam, s);
    }
    r.e[e] = neighbourRuleEdge(own.e[e], rebuilt, n.size[e], adj.clampMode);
  }
  return r;
}
