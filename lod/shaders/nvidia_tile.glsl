// fftess lod, scheme 2: non-uniform patches in tile rings (NVIDIA DX11 terrain sample), and the same neighbour rule
// for every other scheme. Needs common.glsl and screen_sphere.glsl; distance_pow2.glsl, bonaventura.glsl and
// clip_diameter.glsl (after this file) use its helpers for their own *TileLod.
//
// The neighbour rule: where a patch meets a neighbour twice its size, it rebuilds the neighbour's edge (its own
// edge extended by its own length: beyond the end corner for an even index along the edge, before the start corner
// for an odd one), evaluates the base scheme's own edge factor for that rebuilt edge and halves it. The larger side
// of the jump keeps its own edge factor. The adjacency clamp then rounds both sides of the jump alike: integer
// (larger side up to even, in [4, 64]; smaller = larger / 2) or power of two (larger side up to 4, 8, .., 64;
// smaller = larger / 2). Inside factors, culling and every edge without a jump stay the base scheme's own.

const int kClampNone = 0;
const int kClampInteger = 1;
const int kClampPow2 = 2;

const int kRebuildEdgeVector = 0;
const int kRebuildFarCorner = 1;
const int kRebuildResampled = 2;

struct TileSettings {
  ScreenSphereSettings sphere;
  int clampMode;      // kClampNone / kClampInteger / kClampPow2
  int rebuild;        // kRebuildEdgeVector / kRebuildFarCorner / kRebuildResampled
  bool insideFromFixedEdges; // inside factors from the edges after the neighbour rule (the sample's own order)
};

// The neighbour rule's own settings, for the base schemes other than the screen-space sphere.
struct AdjacencySettings {
  int clampMode;      // kClampNone / kClampInteger / kClampPow2
  int rebuild;        // kRebuildEdgeVector / kRebuildFarCorner / kRebuildResampled
};

struct TileNeighbourInfo {
  float size[4];          // per edge: 0.5, 1 or 2
  bool oddU;
  bool oddV;
  vec3 farCorner[4];      // kRebuildFarCorner: the far end of the larger neighbour's edge
  float rebuiltHeight[4]; // kRebuildResampled: the height sampled at rebuiltCorner's x/z
};

// The two ends of the larger neighbour's edge as the smaller patch rebuilds it (a, b in this patch's edge order).
struct RebuiltEdge {
  vec3 a;
  vec3 b;
};

// Smallest of 4, 8, 16, 32, 64 that is >= f (4 for f <= 4 and for NaN).
float roundUpPow2From4(float f) {
  float p = 4.0f;
  if (f > 4.0f) {
    p = 8.0f;
  }
  if (f > 8.0f) {
    p = 16.0f;
  }
  if (f > 16.0f) {
    p = 32.0f;
  }
  if (f > 32.0f) {
    p = 64.0f;
  }
  return p;
}

// The integer clamp's larger side: ceil(f * 0.5) * 2 (rounded up to even), then raised to 4 and lowered to 64 by
// comparisons, so the smaller side (half of it) is an integer in [2, 32]. NaN stays NaN (ceil, the product and both
// comparisons pass it through): a NaN factor is never turned into a valid one here.
float roundUpEvenFrom4(float f) {
  float r = ceil(f * 0.5f) * 2.0f;
  if (r < 4.0f) {
    r = 4.0f;
  }
  if (r > 64.0f) {
    r = 64.0f;
  }
  return r;
}

// The larger side's factor of a jump after the clamp: F, roundUpEvenFrom4(F) or roundUpPow2From4(F).
float largerSideFactor(float f, int clampMode) {
  float r = f;
  if (clampMode == kClampInteger) {
    r = roundUpEvenFrom4(f);
  }
  if (clampMode == kClampPow2) {
    r = roundUpPow2From4(f);
  }
  return r;
}

int clampFix(int clampMode) {
  int fx = 0;
  if (clampMode == kClampInteger) {
    fx = kFixIntegerClamp;
  }
  if (clampMode == kClampPow2) {
    fx = kFixPow2Clamp;
  }
  return fx;
}

// The far end of the larger neighbour's edge by the edge vector, in float: edge = p1 - p0; even (the patch is the
// first half of the larger edge): p1 + edge; odd: p0 - edge. Its y is then set to the y of the corner it was moved
// from (p1, resp. p0). verify's layout calls this same function (lod::rebuiltCorner) to know where to sample the
// height for kRebuildResampled, so both use the same x/z bits.
vec3 rebuiltCorner(vec3 p0, vec3 p1, bool odd) {
  vec3 edge = p1 - p0;
  vec3 r = p1 + edge;
  r.y = p1.y;
  if (odd) {
    r = p0 - edge;
    r.y = p0.y;
  }
  return r;
}

// Edge e (p0 = start corner, p1 = end corner) of a patch whose neighbour across it is twice its size: the larger
// neighbour's edge as this patch rebuilds it. kRebuildEdgeVector: rebuiltCorner; kRebuildFarCorner: the neighbour's
// own corner n.farCorner[e]; kRebuildResampled: rebuiltCorner's x/z with the height n.rebuiltHeight[e].
RebuiltEdge largerNeighbourEdge(int e, vec3 p0, vec3 p1, TileNeighbourInfo n, int rebuild) {
  bool odd = n.oddV;
  if (e == 1 || e == 3) {
    odd = n.oddU;
  }
  vec3 farEnd = rebuiltCorner(p0, p1, odd);
  if (rebuild == kRebuildFarCorner) {
    farEnd = n.farCorner[e];
  }
  if (rebuild == kRebuildResampled) {
    farEnd.y = n.rebuiltHeight[e];
  }
  RebuiltEdge r;
  r.a = p0;
  r.b = farEnd;
  if (odd) {
    r.a = farEnd;
    r.b = p1;
  }
  return r;
}

// Edge e's corners in D3D order (common.glsl's edgeStartCorner / edgeEndCorner) without array parameters.
vec3 cornerOf(int i, vec3 c0, vec3 c1, vec3 c2, vec3 c3) {
  vec3 c = c0;
  if (i == 1) {
    c = c1;
  }
  if (i == 2) {
    c = c2;
  }
  if (i == 3) {
    c = c3;
  }
  return c;
}

RebuiltEdge largerNeighbourEdgeOf(int e, vec3 c0, vec3 c1, vec3 c2, vec3 c3, TileNeighbourInfo n, int rebuild) {
  return largerNeighbourEdge(e, cornerOf(edgeStartCorner(e), c0, c1, c2, c3),
                             cornerOf(edgeEndCorner(e), c0, c1, c2, c3), n, rebuild);
}

// One edge after the neighbour rule. own: the base scheme's factor of this edge; rebuilt: the base scheme's factor of
// the larger neighbour's rebuilt edge (read only when size == 2).
//   size 2 (this is the smaller side): larger(rebuilt) * 0.5, the rebuilt edge's record, + FixLargerNeighbour;
//   size 0.5 (this is the larger side): larger(own), own's record, + FixSmallerNeighbour;
//   otherwise: own, unchanged.
EdgeLod neighbourRuleEdge(EdgeLod own, EdgeLod rebuilt, float size, int clampMode) {
  if (size == 2.0f) {
    float larger = largerSideFactor(rebuilt.factor, clampMode);
    return makeEdgeLod(larger * 0.5f, rebuilt.metric, rebuilt.unclamped, rebuilt.exponent,
                       rebuilt.fixes | kFixLargerNeighbour | clampFix(clampMode));
  }
  if (size == 0.5f) {
    return makeEdgeLod(largerSideFactor(own.factor, clampMode), own.metric, own.unclamped, own.exponent,
                       own.fixes | kFixSmallerNeighbour | clampFix(clampMode));
  }
  return own;
}

// Constant factor (every edge and inside = factor), with the neighbour rule: the rebuilt edge's factor is factor too.
LodResult constantTileLod(float factor, TileNeighbourInfo n, AdjacencySettings adj) {
  LodResult r = emptyLodResult();
  EdgeLod own = makeEdgeLod(factor, 0.0f, factor, 0.0f, 0);
  for (int e = 0; e < 6; ++e) {
    r.e[e] = own;
  }
  for (int e = 0; e < 4; ++e) {
    r.e[e] = neighbourRuleEdge(own, own, n.size[e], adj.clampMode);
  }
  return r;
}

LodResult nvidiaTileLod(vec3 c0, vec3 c1, vec3 c2, vec3 c3, bool useHeightBounds, float minHeight,
                        float maxHeight, TileNeighbourInfo n, LodCamera cam, TileSettings s) {
  LodResult own = screenSphereLod(c0, c1, c2, c3, useHeightBounds, minHeight, maxHeight, cam, s.sphere);
  if (own.culled) {
    return own;
  }
  LodResult r = own;
  for (int e = 0; e < 4; ++e) {
    EdgeLod rebuilt = own.e[e];
    if (n.size[e] == 2.0f) {
      RebuiltEdge big = largerNeighbourEdgeOf(e, c0, c1, c2, c3, n, s.rebuild);
      // The larger patch passes its edge (opposite e) around its quad from a to b for e = Ueq0, Veq1, else b to a.
      bool forward = e == 0 || e == 3;
      rebuilt = screenSphereEdgeAround(big.a, big.b, forward ? big.a : big.b, forward ? big.b : big.a, cam, s.sphere);
    }
    r.e[e] = neighbourRuleEdge(own.e[e], rebuilt, n.size[e], s.clampMode);
  }
  if (s.insideFromFixedEdges) {
    r = withInsideFromEdges(r, s.sphere.insideRule);
  }
  return r;
}
