#version 450
layout(vertices = 4) out;

void main() {
  gl_TessLevelOuter[0] = uFar;
  gl_TessLevelOuter[1] = 1.0 + vec2(1.0);
}
