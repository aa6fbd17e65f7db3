// A lodMain file with a leftover uniform (tests/oracle/gpu_lod_test.cmake CASE=bad): on the compute path it would read
// 0, so fftess refuses it at its declaration (uniform.glsl:4:15).

uniform float uScale;

LodFactors lodMain(LodPatch quad, TileNeighbourInfo neighbours, LodCamera camera, LodSettings settings) {
  LodFactors r;
  for (int i = 0; i < 6; ++i) { r.factor[i] = 4.0 * uScale + 1.0; }
  r.culled = false;
  return r;
}
