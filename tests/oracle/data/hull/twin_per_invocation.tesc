#version 450
// twin.tesc with each invocation writing the level of one edge, gl_TessLevelOuter[gl_InvocationID] (a common form),
// then a barrier before invocation 0 computes the inside levels (tests/oracle/hull_test.cmake CASE=twin). The same
// rule, so the same findings as twin.glsl. llvmpipe (Mesa 22.3) loses such dynamically indexed writes from several
// invocations: fftess makes them constant-index there (docs/gpu_lod.md); without that, outer 0..2 read 0: holes.
layout(vertices = 4) out;

uniform vec3 uEye;
uniform float uMinDistance;
uniform float uMaxDistance;
uniform float uMinTess;
uniform float uMaxTess;

in vec3 vPos[];

float edgeFactor(vec3 a, vec3 b) {
  vec3 mid = (a + b) * 0.5;
  float d = distance(mid, uEye);
  float t = clamp((d - uMinDistance) / (uMaxDistance - uMinDistance), 0.0, 1.0);
  return exp2(mix(uMaxTess, uMinTess, t));
}

void main() {
  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
  // control points p0 (0,0) p1 (1,0) p2 (1,1) p3 (0,1): outer 0 (u = 0) p0-p3, 1 (v = 0) p0-p1, 2 (u = 1) p1-p2,
  // 3 (v = 1) p3-p2
  const ivec2 ends[4] = ivec2[4](ivec2(0, 3), ivec2(0, 1), ivec2(1, 2), ivec2(3, 2));
  ivec2 e = ends[gl_InvocationID];
  gl_TessLevelOuter[gl_InvocationID] = edgeFactor(vPos[e.x], vPos[e.y]);
  barrier();
  if (gl_InvocationID == 0) {
    gl_TessLevelInner[0] = max(gl_TessLevelOuter[1], gl_TessLevelOuter[3]);
    gl_TessLevelInner[1] = max(gl_TessLevelOuter[0], gl_TessLevelOuter[2]);
  }
}
