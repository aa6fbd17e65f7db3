#version 450
// A triangle domain with the default spacing.
layout(triangles) in;
void main() { gl_Position = vec4(gl_TessCoord, 1.0); }
