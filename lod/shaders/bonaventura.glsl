// fftess lod, scheme 4: rounded-exponent power of two with camera-angle correction (Bonaventura, "Terrain and
// Ocean Rendering with Hardware Tessellation"). Needs common.glsl, and nvidia_tile.glsl for
// bonaventuraTileLod (the tile-ring neighbour rule).
//
// At a point p: e0 = lerp(maxExp, minExp, s) as in distance_pow2.glsl; a = ((pi/2 - acos|c.e|) / (pi/2)) * rank
// + 1 - rank/2 with c = (p - eye) / |p - eye| and e = up; exponent = e0 * a; factor = exp2(floor(exponent + 0.5)),
// clamped. The thesis prints the fourth corner's angle without acos: literalNoAcos reproduces that.

struct BonaventuraSettings {
  float minDistance;
  float maxDistance;
  float minExponent;
  float maxExponent;
  bool angleCorrection;
  float rank;
  vec3 up;
  float minFactor;
  float maxFactor;
  bool frustumCull;
  float culledFactor;
  bool literalFourthCornerAngle;
};

// The correction factor at p. |c.e| is clamped to 1 before acos; p == eye counts as looking along up (|c.e| = 1).
float cameraAngleCorrection(vec3 p, LodCamera cam, BonaventuraSettings s, bool literalNoAcos) {
  vec3 v = p - cam.eye;
  float len = sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  float ce = 1.0f;
  if (len > 0.0f) {
    ce = min(abs(dotOrdered(v / len, s.up)), 1.0f);
  }
  float angle = acos(ce);
  if (literalNoAcos) {
    angle = ce;
  }
  return ((kHalfPi - angle) / kHalfPi) * s.rank + 1.0f - s.rank * 0.5f;
}

// The corrected, unrounded exponent at p.
float bonaventuraExponent(vec3 p, LodCamera cam, BonaventuraSettings s, bool literalNoAcos) {
  float d = distanceOrdered(p, cam.eye);
  float e = lerpHlsl(s.maxExponent, s.minExponent, distanceRamp(d, s.minDistance, s.maxDistance));
  if (s.angleCorrection) {
    e = e * cameraAngleCorrection(p, cam, s, literalNoAcos);
  }
  return e;
}

EdgeLod bonaventuraAt(vec3 p, LodCamera cam, BonaventuraSettings s) {
  float d = distanceOrdered(p, cam.eye);
  float e = bonaventuraExponent(p, cam, s, false);
  float rounded = floor(e + 0.5f);
  int fx = kFixRoundedExponent;
  if (s.angleCorrection) {
    fx = fx | kFixAngleCorrection;
  }
  return clampFactor(d, exp2(rounded), e, fx, s.minFactor, s.maxFactor);
}

LodResult bonaventuraLod(vec3 c0, vec3 c1, vec3 c2, vec3 c3, bool useHeightBounds, float minHeight,
                         float maxHeight, LodCamera cam, BonaventuraSettings s) {
  if (s.frustumCull && patchOutsideFrustum(c0, c1, c2, c3, useHeightBounds, minHeight, maxHeight, cam)) {
    return culledLodResult(s.culledFactor);
  }
  LodResult r = emptyLodResult();
  r.e[0] = bonaventuraAt(midpoint(c0, c2), cam, s);
  r.e[1] = bonaventuraAt(midpoint(c0, c1), cam, s);
  r.e[2] = bonaventuraAt(midpoint(c1, c3), cam, s);
  r.e[3] = bonaventuraAt(midpoint(c2, c3), cam, s);
  EdgeLod inside = bonaventuraAt(patchCentre(c0, c1, c2, c3), cam, s);
  r.e[4] = inside;
  r.e[5] = inside;
  r.cornerLevel[0] = bonaventuraExponent(c0, cam, s, false);
  r.cornerLevel[1] = bonaventuraExponent(c1, cam, s, false);
  r.cornerLevel[2] = bonaventuraExponent(c2, cam, s, false);
  r.cornerLevel[3] = bonaventuraExponent(c3, cam, s, s.literalFourthCornerAngle);
  return r;
}

// With the tile-ring neighbour rule (nvidia_tile.glsl): the rebuilt edge's factor is bonaventuraAt of its midpoint
// (angle correction, rounding and clamps included). Corner levels stay the patch's own.
LodResult bonaventuraTileLod(vec3 c0, vec3 c1, vec3 c2, vec3 c3, bool useHeightBounds, float minHeight,
                             float maxHeight, TileNeighbourInfo n, LodCamera cam, BonaventuraSettings s,
                             AdjacencySettings adj) {
  LodResult own = bonaventuraLod(c0, c1, c2, c3, useHeightBounds, minHeight, maxHeight, cam, s);
  if (own.culled) {
    return own;
  }
  LodResult r = own;
  for (int e = 0; e < 4; ++e) {
    EdgeLod rebuilt = own.e[e];
    if (n.size[e] == 2.0f) {
      RebuiltEdge big = largerNeighbourEdgeOf(e, c0, c1, c2, c3, n, adj.rebuild);
      rebuilt = bonaventuraAt(midpoint(big.a, big.b), cam, s);
    }
    r.e[e] = neighbourRuleEdge(own.e[e], rebuilt, n.size[e], adj.clampMode);
  }
  return r;
}
