#version 450
#extension GL_GOOGLE_include_directive : require
// A distance TCS with plain uniforms, a UBO and the heightmap, and an #include.
layout(vertices = 4) out;

#include "includes/camera.glsl"

uniform float uMinTess;
uniform float uMaxTess;
uniform float uUnused;
uniform sampler2D uHeightMap;

layout(std140) uniform Terrain {
  float heightScale;
  float notRead;
};

in vec2 vUv[];
in Corner { vec3 worldPos; } tcIn[];
out vec2 tcUv[];

float level(vec3 p) {
  float h = texture(uHeightMap, vUv[0]).r * heightScale;
  float d = distance(uEye, p + vec3(0.0, h, 0.0));
  return mix(uMaxTess, uMinTess, clamp(d / 100.0, 0.0, 1.0));
}

void main() {
  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
  tcUv[gl_InvocationID] = vUv[gl_InvocationID];
  if (gl_InvocationID == 0) {
    gl_TessLevelOuter[0] = level(tcIn[0].worldPos);
    gl_TessLevelOuter[1] = level(tcIn[1].worldPos);
    gl_TessLevelOuter[2] = level(tcIn[2].worldPos);
    gl_TessLevelOuter[3] = level(tcIn[3].worldPos);
    gl_TessLevelInner[0] = gl_TessLevelOuter[0];
    gl_TessLevelInner[1] = gl_TessLevelOuter[1];
  }
}
