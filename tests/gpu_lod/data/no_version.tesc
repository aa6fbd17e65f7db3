layout(vertices = 4) out;

void main() {
  gl_TessLevelOuter[0] = 1.0;
}
