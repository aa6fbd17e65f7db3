#version 310 es
#extension GL_EXT_tessellation_shader : require
// twin.tesc in GLSL ES 3.10 (the form of GameWorks' es3aep samples): the same rule, so the same findings. The twin of
// twin.glsl as a tessellation control shader (tests/oracle/hull_test.cmake CASE=twin): the same distance
// rule, float operation for float operation, on control points that arrive as a loop (corners 0, 2, 3, 1: p0 (0,0),
// p1 (1,0), p2 (1,1), p3 (0,1) in this shader's domain, whose u runs along world +z). If fftess maps the control points
// and the levels right, both files give the same factors, so the same verdict line on tile rings.
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
  if (gl_InvocationID == 0) {
    vec3 p0 = vPos[0];
    vec3 p1 = vPos[1];
    vec3 p2 = vPos[2];
    vec3 p3 = vPos[3];
    gl_TessLevelOuter[0] = edgeFactor(p0, p3); // u = 0
    gl_TessLevelOuter[1] = edgeFactor(p0, p1); // v = 0
    gl_TessLevelOuter[2] = edgeFactor(p1, p2); // u = 1
    gl_TessLevelOuter[3] = edgeFactor(p3, p2); // v = 1
    gl_TessLevelInner[0] = max(gl_TessLevelOuter[1], gl_TessLevelOuter[3]); // along u: the edges v = 0 and v = 1
    gl_TessLevelInner[1] = max(gl_TessLevelOuter[0], gl_TessLevelOuter[2]);
  }
}
