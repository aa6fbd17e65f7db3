#version 450
// The evaluation shader that goes with frustum_heightmap.tesc (lod.evaluation_shader): fftess reads its domain
// (quads) and spacing (equal_spacing = tessellation.partitioning "integer") and refuses a scene that says otherwise.
// u runs from control point 0 to 1, v from 0 to 3 (the loop p0 p1 p2 p3). fftess example; our code.

layout(quads, equal_spacing, cw) in;

layout(location = 0) in vec2 inUV[];
layout(location = 0) out vec2 outUV;

layout(std140, binding = 0) uniform TerrainBlock {
  mat4 projection;
  mat4 modelview;
  vec4 frustumPlanes[6];
  vec2 viewportSize;
  float pixelsPerEdge;
  float cullMargin;
} ubo;

layout(binding = 1) uniform sampler2D uHeightMap;
uniform float uHeightScale;

void main() {
  float u = gl_TessCoord.x;
  float v = gl_TessCoord.y;
  vec2 uv0 = mix(inUV[0], inUV[1], u);
  vec2 uv1 = mix(inUV[3], inUV[2], u);
  outUV = mix(uv0, uv1, v);
  vec4 p0 = mix(gl_in[0].gl_Position, gl_in[1].gl_Position, u);
  vec4 p1 = mix(gl_in[3].gl_Position, gl_in[2].gl_Position, u);
  vec4 pos = mix(p0, p1, v);
  pos.y += textureLod(uHeightMap, outUV, 0.0).r * uHeightScale;
  gl_Position = ubo.projection * ubo.modelview * pos;
}
