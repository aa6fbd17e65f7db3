#version 450
// expect: syntax_error.tesc:19:5: error: syntax error, unexpected IDENTIFIER, expecting COMMA or SEMICOLON
// (glslang 12.0's message, one line, no summary; glslang 12.0 gives no column here, so the front end on branch
// front prints syntax_error.tesc:19: without one; 5 is the unexpected token's). fftess negative fixture
// (syntax_error.toml, exit 2): line 18 lacks its ';'; everything the shader uses is bound.
layout(vertices = 4) out;

uniform vec3 uEye;

float edgeLevel(vec4 a, vec4 b) {
  vec3 mid = 0.5 * (a.xyz + b.xyz);
  return clamp(64.0 / (1.0 + 0.1 * distance(mid, uEye)), 1.0, 64.0);
}

void main() {
  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
  if (gl_InvocationID == 0) {
    float f = edgeLevel(gl_in[0].gl_Position, gl_in[2].gl_Position)
    gl_TessLevelOuter[0] = f;
    gl_TessLevelOuter[1] = edgeLevel(gl_in[0].gl_Position, gl_in[1].gl_Position);
    gl_TessLevelOuter[2] = edgeLevel(gl_in[1].gl_Position, gl_in[3].gl_Position);
    gl_TessLevelOuter[3] = edgeLevel(gl_in[2].gl_Position, gl_in[3].gl_Position);
    gl_TessLevelInner[0] = max(gl_TessLevelOuter[1], gl_TessLevelOuter[3]);
    gl_TessLevelInner[1] = max(gl_TessLevelOuter[0], gl_TessLevelOuter[2]);
  }
}
