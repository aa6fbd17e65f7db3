#version 450
layout(vertices = 4) out;

uniform float uFactor;

void main() {
  float f = uFactor * 2.0
  gl_TessLevelOuter[0] = f;
  gl_TessLevelOuter[1] = undeclared;
}
