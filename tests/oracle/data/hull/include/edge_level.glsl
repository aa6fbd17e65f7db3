// Included by ../include.tesc (#include "include/edge_level.glsl"): the level of one edge from its midpoint's
// distance to the eye, clamped to [1, 64]. Needs uniform vec3 uEye and float uLevelScale. fftess test fixture.
float edgeLevel(vec4 a, vec4 b) {
  vec3 mid = 0.5 * (a.xyz + b.xyz);
  return clamp(uLevelScale / (1.0 + distance(mid, uEye)), 1.0, 64.0);
}
