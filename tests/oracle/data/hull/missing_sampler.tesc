#version 450
// expect: missing_sampler.tesc:11:19: error: sampler 'uHeightMap' is not bound (add it to [lod.uniforms])
// fftess negative fixture (missing_sampler.toml, exit 2, that one line): the corners are raised by the heightmap
// in the shader, and the scene binds the height scale and the eye but not the texture.
layout(vertices = 4) out;

in vec2 vUV[];

uniform vec3 uEye;
uniform float uHeightScale;
uniform sampler2D uHeightMap;

vec3 raised(int i) {
  float h = textureLod(uHeightMap, vUV[i], 0.0).r * uHeightScale;
  return gl_in[i].gl_Position.xyz + vec3(0.0, h, 0.0);
}

float edgeLevel(vec3 a, vec3 b) {
  return clamp(64.0 / (1.0 + 0.1 * distance(0.5 * (a + b), uEye)), 1.0, 64.0);
}

void main() {
  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
  if (gl_InvocationID == 0) {
    vec3 p0 = raised(0), p1 = raised(1), p2 = raised(2), p3 = raised(3);
    gl_TessLevelOuter[0] = edgeLevel(p0, p2);
    gl_TessLevelOuter[1] = edgeLevel(p0, p1);
    gl_TessLevelOuter[2] = edgeLevel(p1, p3);
    gl_TessLevelOuter[3] = edgeLevel(p2, p3);
    gl_TessLevelInner[0] = max(gl_TessLevelOuter[1], gl_TessLevelOuter[3]);
    gl_TessLevelInner[1] = max(gl_TessLevelOuter[0], gl_TessLevelOuter[2]);
  }
}
