// fftess lod, scheme 2: non-uniform patches in tile rings (NVIDIA DX11 terrain sample). Needs common.glsl and
// screen_sphere.glsl.
//
// Where a patch meets a neighbour twice its size, it rebuilds the neighbour's edge (its own edge extended by its
// own length: beyond the end corner for an even index along the edge, before the start corner for an odd one),
// takes that edge's sphere factor and halves it. The adjacency clamp then rounds both sides of the jump alike:
// integer (larger side up to even, smaller = larger / 2) or power of two (larger side up to 4, 8, .., 64,
// smaller = larger / 2). Inside factors come from the patch's own edge factors, before any adjacency fix.

const int kClampNone = 0;
const int kClampInteger = 1;
const int kClampPow2 = 2;

const int kRebuildEdgeVector = 0;
const int kRebuildFarCorner = 1;

struct TileSettings {
  ScreenSphereSettings sphere;
  int clampMode;      // kClampNone / kClampInteger / kClampPow2
  int rebuild;        // kRebuildEdgeVector / kRebuildFarCorner
};

struct TileNeighbourInfo {
  float size[4];      // per edge: 0.5, 1 or 2
  bool oddU;
  bool oddV;
  vec3 farCorner[4];  // kRebuildFarCorner: the far end of the larger neighbour's edge
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

// The larger side's factor of a jump after the clamp: F, 2 * ceil(F * 0.5), or roundUpPow2From4(F).
float largerSideFactor(float f, int clampMode) {
  float r = f;
  if (clampMode == kClampInteger) {
    r = ceil(f * 0.5f) * 2.0f;
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

// Edge e of the patch, from p0 (start corner) to p1 (end corner), given its neighbour.
EdgeLod tileEdge(int e, vec3 p0, vec3 p1, TileNeighbourInfo n, LodCamera cam, TileSettings s) {
  float size = n.size[e];
  bool odd = n.oddV;
  if (e == 1 || e == 3) {
    odd = n.oddU;
  }
  if (size == 2.0f) {
    vec3 a = p0;
    vec3 b = p1;
    if (s.rebuild == kRebuildFarCorner) {
      if (odd) {
        a = n.farCorner[e];
      } else {
        b = n.farCorner[e];
      }
    } else {
      vec3 edge = p1 - p0;
      if (odd) {
        a = p0 - edge;
        a.y = p0.y;
      } else {
        b = p1 + edge;
        b.y = p1.y;
      }
    }
    EdgeLod big = screenSphereEdge(a, b, cam, s.sphere);
    float larger = largerSideFactor(big.factor, s.clampMode);
    return makeEdgeLod(larger * 0.5f, big.metric, big.unclamped, 0.0f,
                       big.fixes | kFixLargerNeighbour | clampFix(s.clampMode));
  }
  EdgeLod own = screenSphereEdge(p0, p1, cam, s.sphere);
  if (size == 0.5f) {
    return makeEdgeLod(largerSideFactor(own.factor, s.clampMode), own.metric, own.unclamped, 0.0f,
                       own.fixes | kFixSmallerNeighbour | clampFix(s.clampMode));
  }
  return own;
}

LodResult nvidiaTileLod(vec3 c0, vec3 c1, vec3 c2, vec3 c3, bool useHeightBounds, float minHeight,
                        float maxHeight, TileNeighbourInfo n, LodCamera cam, TileSettings s) {
  if (s.sphere.frustumCull && patchOutsideFrustum(c0, c1, c2, c3, useHeightBounds, minHeight, maxHeight, cam)) {
    return culledLodResult(s.sphere.culledFactor);
  }
  // Inside factors from the patch's own edges.
  ScreenSphereSettings noCull = s.sphere;
  noCull.frustumCull = false;
  LodResult own = screenSphereLod(c0, c1, c2, c3, false, 0.0f, 0.0f, cam, noCull);
  LodResult r = own;
  r.e[0] = tileEdge(0, c0, c2, n, cam, s);
  r.e[1] = tileEdge(1, c0, c1, n, cam, s);
  r.e[2] = tileEdge(2, c1, c3, n, cam, s);
  r.e[3] = tileEdge(3, c2, c3, n, cam, s);
  return r;
}
