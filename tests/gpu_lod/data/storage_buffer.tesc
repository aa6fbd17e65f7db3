#version 450
layout(vertices = 4) out;
layout(std430, binding = 3) readonly buffer LodData { float bias[]; };
in VS_OUT { vec3 pos; vec2 uv; } tcIn[];
void main() {
  gl_TessLevelOuter[gl_InvocationID] = clamp(tcIn[gl_InvocationID].pos.x + bias[gl_PrimitiveID], 1.0, 64.0);
}
