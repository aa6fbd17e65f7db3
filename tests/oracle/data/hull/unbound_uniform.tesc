#version 450
// expect: unbound_uniform.tesc:8:15: error: uniform 'uLodBias' is not bound (add it to [lod.uniforms])
// fftess negative fixture (unbound_uniform.toml, exit 2, that one line): a distance rule with a bias the scene
// forgets to bind (unbound, it would silently read 0).
layout(vertices = 4) out;

uniform vec3 uEye;
uniform float uLodBias;

float edgeLevel(vec4 a, vec4 b) {
  vec3 mid = 0.5 * (a.xyz + b.xyz);
  return clamp(64.0 / (1.0 + 0.1 * distance(mid, uEye)) + uLodBias, 1.0, 64.0);
}

void main() {
  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
  if (gl_InvocationID == 0) {
    gl_TessLevelOuter[0] = edgeLevel(gl_in[0].gl_Position, gl_in[2].gl_Position);
    gl_TessLevelOuter[1] = edgeLevel(gl_in[0].gl_Position, gl_in[1].gl_Position);
    gl_TessLevelOuter[2] = edgeLevel(gl_in[1].gl_Position, gl_in[3].gl_Position);
    gl_TessLevelOuter[3] = edgeLevel(gl_in[2].gl_Position, gl_in[3].gl_Position);
    gl_TessLevelInner[0] = max(gl_TessLevelOuter[1], gl_TessLevelOuter[3]);
    gl_TessLevelInner[1] = max(gl_TessLevelOuter[0], gl_TessLevelOuter[2]);
  }
}
