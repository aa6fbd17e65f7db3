#version 450
// Screen-space tessellation levels with a frustum test that reads the heightmap, in the form of Sascha Willems'
// Vulkan terrain sample's control shader: one uniform block with the matrices, the frustum planes and the tuning
// values, the heightmap as a combined image sampler, the four corners arriving as a loop. fftess example
// (docs/examples/hull/README.md); our code.
//
// Control points: a loop around the patch, p0 -> p1 -> p2 -> p3; the evaluation shader (frustum_heightmap.tese)
// runs u from p0 to p1 and v from p0 to p3, so outer 0..3 (edges u = 0, v = 0, u = 1, v = 1) are the edges p3-p0,
// p0-p1, p1-p2, p2-p3. The positions are flat (y = 0); the heights come from the heightmap here and in the TES.

layout(vertices = 4) out;

layout(location = 0) in vec2 inUV[];
layout(location = 0) out vec2 outUV[4];

layout(std140, binding = 0) uniform TerrainBlock {
  mat4 projection;
  mat4 modelview;
  vec4 frustumPlanes[6]; // world space, inward normals, normalised: dot(n, p) + w >= 0 inside
  vec2 viewportSize;     // pixels
  float pixelsPerEdge;   // wanted screen length of one tessellated edge
  float cullMargin;      // world units added around the sampled corners (the surface between them may rise higher)
} ubo;

layout(binding = 1) uniform sampler2D uHeightMap;
uniform float uHeightScale;

// Level of one edge: a sphere of the edge's length around its midpoint, its diameter in pixels on screen.
float screenLevel(vec4 a, vec4 b) {
  vec4 centre = vec4(0.5 * (a.xyz + b.xyz), 1.0);
  float diameter = distance(a.xyz, b.xyz);
  vec4 viewPos = ubo.modelview * centre;
  float depth = max(length(viewPos.xyz), diameter);
  float pixels = diameter * ubo.projection[1][1] * 0.5 * ubo.viewportSize.y / depth;
  return clamp(pixels / ubo.pixelsPerEdge, 1.0, 64.0);
}

// The displaced corners' bounding sphere, widened by the margin, against the six planes.
bool patchVisible() {
  vec3 p[4];
  for (int i = 0; i < 4; ++i) {
    float h = textureLod(uHeightMap, inUV[i], 0.0).r * uHeightScale;
    p[i] = gl_in[i].gl_Position.xyz + vec3(0.0, h, 0.0);
  }
  vec3 centre = 0.25 * (p[0] + p[1] + p[2] + p[3]);
  float radius = 0.0;
  for (int i = 0; i < 4; ++i) {
    radius = max(radius, distance(centre, p[i]));
  }
  radius += ubo.cullMargin;
  for (int i = 0; i < 6; ++i) {
    if (dot(ubo.frustumPlanes[i].xyz, centre) + ubo.frustumPlanes[i].w < -radius) {
      return false;
    }
  }
  return true;
}

void main() {
  if (gl_InvocationID == 0) {
    if (!patchVisible()) {
      gl_TessLevelOuter[0] = 0.0;
      gl_TessLevelOuter[1] = 0.0;
      gl_TessLevelOuter[2] = 0.0;
      gl_TessLevelOuter[3] = 0.0;
      gl_TessLevelInner[0] = 0.0;
      gl_TessLevelInner[1] = 0.0;
    } else {
      gl_TessLevelOuter[0] = screenLevel(gl_in[3].gl_Position, gl_in[0].gl_Position);
      gl_TessLevelOuter[1] = screenLevel(gl_in[0].gl_Position, gl_in[1].gl_Position);
      gl_TessLevelOuter[2] = screenLevel(gl_in[1].gl_Position, gl_in[2].gl_Position);
      gl_TessLevelOuter[3] = screenLevel(gl_in[2].gl_Position, gl_in[3].gl_Position);
      gl_TessLevelInner[0] = 0.5 * (gl_TessLevelOuter[1] + gl_TessLevelOuter[3]);
      gl_TessLevelInner[1] = 0.5 * (gl_TessLevelOuter[0] + gl_TessLevelOuter[2]);
    }
  }
  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
  outUV[gl_InvocationID] = inUV[gl_InvocationID];
}
