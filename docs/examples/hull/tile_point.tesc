#version 450
// One control point per tile, in the form of NVIDIA GameWorks' OpenGL ES 3.1 AEP terrain tessellation sample: the
// vertex shader sends only each tile's origin (its -x, -z corner) and size, and the control shader rebuilds the four
// corners, reads their heights, culls the tile's box against the view in clip space and gives each edge the screen
// size of a sphere around it. fftess example (docs/examples/hull/README.md); our code.
//
// Rebuilt corners: c00 = origin, c10 = origin + (size, 0, 0), c01 = origin + (0, 0, size), c11 = both; the domain's
// u runs along +x and v along +z, so outer 0..3 are the edges x = min, z = min, x = max, z = max. The corners are
// exact in float only where origin + size is (tile sizes and origins of few significant bits, as in the scenes).

layout(vertices = 1) out;

in vec3 vTileOrigin[]; // world x, 0, z of the tile's -x, -z corner
in float vTileSize[];  // world size of the tile along x and z

patch out vec4 tcCorner[4]; // the displaced corners, for the evaluation shader

uniform mat4 uView;
uniform mat4 uProj;
uniform mat4 uViewProj;
uniform vec2 uViewport;       // pixels
uniform float uNear;          // the projection's near distance
uniform float uTrianglePixels; // wanted screen size of one tessellated edge
uniform sampler2D uHeightMap;
uniform float uHeightScale;
uniform vec2 uTerrainOrigin;  // world x, z where the heightmap starts
uniform vec2 uTerrainSize;    // world size the heightmap covers

float heightAt(vec3 p) {
  vec2 uv = (p.xz - uTerrainOrigin) / uTerrainSize;
  return textureLod(uHeightMap, uv, 0.0).r * uHeightScale;
}

vec2 toPixels(vec4 clip) {
  return clip.xy / max(clip.w, uNear) * 0.5 * uViewport;
}

// The diameter of a sphere of the edge's length around its midpoint, projected to pixels, per uTrianglePixels.
float sphereLevel(vec3 a, vec3 b) {
  vec4 centre = uView * vec4(0.5 * (a + b), 1.0);
  vec4 side = centre + vec4(distance(a, b), 0.0, 0.0, 0.0);
  float pixels = distance(toPixels(uProj * centre), toPixels(uProj * side));
  return clamp(pixels / uTrianglePixels, 1.0, 64.0);
}

// The tile's box (its x/z square, y over the heightmap's whole range) is outside when all eight corners lie beyond
// one clip plane.
bool tileOutside(vec3 lo, vec3 hi) {
  ivec3 below = ivec3(0), above = ivec3(0);
  for (int i = 0; i < 8; ++i) {
    vec3 p = vec3((i & 1) != 0 ? hi.x : lo.x, (i & 2) != 0 ? hi.y : lo.y, (i & 4) != 0 ? hi.z : lo.z);
    vec4 c = uViewProj * vec4(p, 1.0);
    below += ivec3(lessThan(c.xyz, vec3(-c.w)));
    above += ivec3(greaterThan(c.xyz, vec3(c.w)));
  }
  return any(equal(below, ivec3(8))) || any(equal(above, ivec3(8)));
}

void main() {
  vec3 origin = vTileOrigin[0];
  float size = vTileSize[0];
  vec3 c00 = origin;
  vec3 c10 = origin + vec3(size, 0.0, 0.0);
  vec3 c01 = origin + vec3(0.0, 0.0, size);
  vec3 c11 = origin + vec3(size, 0.0, size);
  c00.y = heightAt(c00);
  c10.y = heightAt(c10);
  c01.y = heightAt(c01);
  c11.y = heightAt(c11);
  tcCorner[0] = vec4(c00, 1.0);
  tcCorner[1] = vec4(c10, 1.0);
  tcCorner[2] = vec4(c01, 1.0);
  tcCorner[3] = vec4(c11, 1.0);
  gl_out[gl_InvocationID].gl_Position = vec4(origin, 1.0);

  vec3 lo = vec3(origin.x, min(0.0, uHeightScale), origin.z);
  vec3 hi = vec3(origin.x + size, max(0.0, uHeightScale), origin.z + size);
  if (tileOutside(lo, hi)) {
    gl_TessLevelOuter[0] = 0.0;
    gl_TessLevelOuter[1] = 0.0;
    gl_TessLevelOuter[2] = 0.0;
    gl_TessLevelOuter[3] = 0.0;
    gl_TessLevelInner[0] = 0.0;
    gl_TessLevelInner[1] = 0.0;
    return;
  }
  gl_TessLevelOuter[0] = sphereLevel(c00, c01);
  gl_TessLevelOuter[1] = sphereLevel(c00, c10);
  gl_TessLevelOuter[2] = sphereLevel(c10, c11);
  gl_TessLevelOuter[3] = sphereLevel(c01, c11);
  gl_TessLevelInner[0] = max(gl_TessLevelOuter[1], gl_TessLevelOuter[3]);
  gl_TessLevelInner[1] = max(gl_TessLevelOuter[0], gl_TessLevelOuter[2]);
}
