#version 450
// expect: include/bad_level.glsl:5:42: error: 'uUndeclaredBias' : undeclared identifier (the included file's own
// line, resolved relative to this file, never a wrapper's or a concatenation's). fftess negative fixture
// (include_error.toml, exit 2, that one line).
#extension GL_GOOGLE_include_directive : require
layout(vertices = 4) out;

uniform vec3 uEye;
uniform float uLevelScale;

#include "include/bad_level.glsl"

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
