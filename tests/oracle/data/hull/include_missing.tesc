#version 450
// expect: include_missing.tesc:11:1: error: '#include' : Could not process include directive for header name:
// include/no_such_file.glsl (glslang's message), first; glslang goes on, so its follow-on errors for the missing
// edgeLevel (lines 16-19, col 28) may follow. fftess negative fixture (include_missing.toml, exit 2).
#extension GL_GOOGLE_include_directive : require
layout(vertices = 4) out;

uniform vec3 uEye;
uniform float uLevelScale;

#include "include/no_such_file.glsl"

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
