#version 450
#extension GL_GOOGLE_include_directive : require
layout(vertices = 4) out;

#include "includes/broken.glsl"

void main() {
  gl_TessLevelOuter[0] = factor();
}
