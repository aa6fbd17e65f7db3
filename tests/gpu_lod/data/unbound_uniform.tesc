#version 450
layout(vertices = 4) out;

uniform vec3 gEyePosW;
uniform float gBound;

void main() {
  if (gl_InvocationID == 0) {
    float d = distance(gEyePosW, gl_in[0].gl_Position.xyz) * gBound;
    gl_TessLevelOuter[0] = d;
    gl_TessLevelOuter[1] = d;
    gl_TessLevelOuter[2] = d;
    gl_TessLevelOuter[3] = d;
    gl_TessLevelInner[0] = d;
    gl_TessLevelInner[1] = d;
  }
}
