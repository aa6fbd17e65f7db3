#version 410 core
// Distance-based tessellation levels, written in the form of the LearnOpenGL terrain tutorial's control shader:
// plain uniforms for the camera and the distance range, a uniform block for the levels, the corners passed through
// from the vertex shader with their texture coordinates. fftess example (docs/examples/hull/README.md); our code.
//
// Each outer level comes from the distance between the eye and the midpoint of its edge, in view space, so the two
// patches sharing an edge compute the same level from the same two corners. The inner levels are the means of the
// opposite outer levels.

layout(vertices = 4) out;

in vec2 vTexCoord[];
out vec2 tcTexCoord[];

uniform mat4 uModel;
uniform mat4 uView;
uniform float uMinDistance;
uniform float uMaxDistance;

layout(std140) uniform LodBlock {
  float minTessLevel;
  float maxTessLevel;
};

float levelAt(vec4 a, vec4 b) {
  vec4 mid = (a + b) * 0.5;
  vec3 eyeSpace = (uView * uModel * mid).xyz;
  float t = clamp((length(eyeSpace) - uMinDistance) / (uMaxDistance - uMinDistance), 0.0, 1.0);
  return mix(maxTessLevel, minTessLevel, t);
}

void main() {
  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
  tcTexCoord[gl_InvocationID] = vTexCoord[gl_InvocationID];

  if (gl_InvocationID == 0) {
    // Corners: 0 (u0 v0), 1 (u1 v0), 2 (u0 v1), 3 (u1 v1); outer 0..3 are the edges u = 0, v = 0, u = 1, v = 1.
    vec4 p00 = gl_in[0].gl_Position;
    vec4 p10 = gl_in[1].gl_Position;
    vec4 p01 = gl_in[2].gl_Position;
    vec4 p11 = gl_in[3].gl_Position;

    gl_TessLevelOuter[0] = levelAt(p00, p01);
    gl_TessLevelOuter[1] = levelAt(p00, p10);
    gl_TessLevelOuter[2] = levelAt(p10, p11);
    gl_TessLevelOuter[3] = levelAt(p01, p11);

    gl_TessLevelInner[0] = 0.5 * (gl_TessLevelOuter[1] + gl_TessLevelOuter[3]);
    gl_TessLevelInner[1] = 0.5 * (gl_TessLevelOuter[0] + gl_TessLevelOuter[2]);
  }
}
