// The twin of twin.tesc as a lodMain file (tests/oracle/hull_test.cmake CASE=twin): the distance rule of
// docs/examples/lod_distance.glsl without its culling and neighbour rule, fftess's corner order (corners[u + 2v]).

float edgeFactor(vec3 a, vec3 b, LodCamera cam, LodSettings s) {
  vec3 mid = (a + b) * 0.5;
  float d = distance(mid, cam.eye);
  float t = clamp((d - s.minDistance) / (s.maxDistance - s.minDistance), 0.0, 1.0);
  return exp2(mix(s.maxTess, s.minTess, t));
}

LodFactors lodMain(LodPatch quad, TileNeighbourInfo neighbours, LodCamera camera, LodSettings settings) {
  LodFactors r;
  r.factor[0] = edgeFactor(quad.corners[0], quad.corners[2], camera, settings); // Ueq0
  r.factor[1] = edgeFactor(quad.corners[0], quad.corners[1], camera, settings); // Veq0
  r.factor[2] = edgeFactor(quad.corners[1], quad.corners[3], camera, settings); // Ueq1
  r.factor[3] = edgeFactor(quad.corners[2], quad.corners[3], camera, settings); // Veq1
  r.factor[4] = max(r.factor[1], r.factor[3]); // insideU: along u, the edges Veq0 and Veq1
  r.factor[5] = max(r.factor[0], r.factor[2]);
  r.culled = false;
  return r;
}
