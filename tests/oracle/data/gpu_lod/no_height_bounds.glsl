// docs/examples/lod_distance.glsl with a bug (issue 18): its frustum test leaves out the height bounds (the box spans
// the corners' heights only), so on displaced terrain it culls patches whose surface rises into view.
// tests/oracle/gpu_lod_test.cmake, CASE=visibility.

float edgeFactor(vec3 a, vec3 b, LodCamera cam, LodSettings s) {
  vec3 mid = (a + b) * 0.5;
  float d = distance(mid, cam.eye);
  float t = clamp((d - s.minDistance) / (s.maxDistance - s.minDistance), 0.0, 1.0);
  return exp2(mix(s.maxTess, s.minTess, t));
}

// The larger side's factor at a 2x jump: the scene's clamp (none, integer, power of two).
float largerSide(float f, int clampMode) {
  if (clampMode == kClampInteger) {
    return clamp(ceil(f * 0.5) * 2.0, 4.0, 64.0);
  }
  if (clampMode == kClampPow2) {
    float p = 4.0;
    while (p < 64.0 && p < f) { p *= 2.0; }
    return p;
  }
  return f;
}

bool outsideFrustum(LodPatch p, LodCamera cam) {
  vec3 lo = min(min(p.corners[0], p.corners[1]), min(p.corners[2], p.corners[3]));
  vec3 hi = max(max(p.corners[0], p.corners[1]), max(p.corners[2], p.corners[3]));
  mat4 m = cam.proj * cam.view;
  // Gribb-Hartmann planes as rows of m; the box is outside when its most positive corner is behind a plane.
  vec4 rows[4] = vec4[4](vec4(m[0][0], m[1][0], m[2][0], m[3][0]), vec4(m[0][1], m[1][1], m[2][1], m[3][1]),
                         vec4(m[0][2], m[1][2], m[2][2], m[3][2]), vec4(m[0][3], m[1][3], m[2][3], m[3][3]));
  vec4 planes[6] = vec4[6](rows[3] + rows[0], rows[3] - rows[0], rows[3] + rows[1], rows[3] - rows[1],
                           rows[3] - rows[2], cam.depthZeroToOne ? rows[2] : rows[3] + rows[2]);
  for (int i = 0; i < 6; ++i) {
    vec3 far = mix(lo, hi, greaterThanEqual(planes[i].xyz, vec3(0.0)));
    if (dot(planes[i].xyz, far) + planes[i].w < 0.0) { return true; }
  }
  return false;
}

LodFactors lodMain(LodPatch quad, TileNeighbourInfo neighbours, LodCamera camera, LodSettings settings) {
  LodFactors r;
  if (settings.frustumCull && outsideFrustum(quad, camera)) {
    for (int i = 0; i < 6; ++i) { r.factor[i] = 0.0; }
    r.culled = true;
    return r;
  }
  const ivec2 ends[4] = ivec2[4](ivec2(0, 2), ivec2(0, 1), ivec2(1, 3), ivec2(2, 3)); // Ueq0 Veq0 Ueq1 Veq1
  for (int e = 0; e < 4; ++e) {
    vec3 a = quad.corners[ends[e].x];
    vec3 b = quad.corners[ends[e].y];
    float f = edgeFactor(a, b, camera, settings);
    if (neighbours.size[e] == 2.0) {
      // This is the smaller side: the neighbour's edge is this edge extended by its own length, beyond b (even
      // index along the edge) or before a (odd); its far end as lod.reconstruction says.
      bool odd = (e == 0 || e == 2) ? neighbours.oddV : neighbours.oddU;
      vec3 far = odd ? a - (b - a) : b + (b - a);
      far.y = odd ? a.y : b.y;
      if (settings.rebuild == kRebuildResampled) { far.y = neighbours.rebuiltHeight[e]; }
      if (settings.rebuild == kRebuildFarCorner) { far = neighbours.farCorner[e]; }
      float big = odd ? edgeFactor(far, b, camera, settings) : edgeFactor(a, far, camera, settings);
      f = largerSide(big, settings.clampMode) * 0.5;
    } else if (neighbours.size[e] == 0.5) {
      f = largerSide(f, settings.clampMode);
    }
    r.factor[e] = f;
  }
  vec3 centre = (quad.corners[0] + quad.corners[1] + quad.corners[2] + quad.corners[3]) * 0.25;
  float d = distance(centre, camera.eye);
  float t = clamp((d - settings.minDistance) / (settings.maxDistance - settings.minDistance), 0.0, 1.0);
  r.factor[4] = exp2(mix(settings.maxTess, settings.minTess, t));
  r.factor[5] = r.factor[4];
  r.culled = false;
  return r;
}
