#version 450
// A complete tessellation control shader that takes its edge rule from include/edge_level.glsl, resolved relative to
// this file; compiles and binds with include.toml (a positive control for the include fixtures). fftess test fixture.
#extension GL_GOOGLE_include_directive : require
layout(vertices = 4) out;

uniform vec3 uEye;
uniform float uLevelScale;

#include "include/edge_level.glsl"

void main() {
  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
  if (gl_InvocationID == 0) {
    gl_TessLevelOuter[0] = edgeLevel(gl_in[0].gl_Position, gl_in[2].gl_Position);
    gl_TessLevelOuter[1] = edgeLevel(gl_in[0].gl_Position, gl_in[1].gl_Position);
    gl_TessLevelOuter[2] = edgeLevel(gl_in[1].gl_Position, gl_in[3].gl_Position);
    gl_TessLevelOuter[3] = edgeLevel(gl_in[2].gl_Position, gl_in[3].gl_Position);
    gl_TessLevelInner[0] = max(gl_TessLevelOuter[1], gl_TessLevelOuter[3]);
    gl_TessLevelInner[1] = max(gl_TessLevelOuter[0], gl_TessLevelOuter[2]);
  }
}
