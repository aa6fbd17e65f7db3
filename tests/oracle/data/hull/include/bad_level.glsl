// Included by ../include_error.tesc: uses a name nobody declares (line 5). fftess negative fixture.
float edgeLevel(vec4 a, vec4 b) {
  vec3 mid = 0.5 * (a.xyz + b.xyz);
  float d = distance(mid, uEye);
  return clamp(uLevelScale / (1.0 + d) * uUndeclaredBias, 1.0, 64.0);
}
