// A lodMain file with a leftover HLSL global (tests/oracle/gpu_lod_test.cmake CASE=bad): glslang puts it in the
// $Global uniform block, which nothing sets, so fftess refuses it at its declaration (uniform.hlsl:4:7).

float gScale;

LodFactors lodMain(LodPatch quad, TileNeighbourInfo neighbours, LodCamera camera, LodSettings settings) {
  LodFactors r;
  for (int i = 0; i < 6; ++i) { r.factor[i] = 4.0 * gScale + 1.0; }
  r.culled = false;
  return r;
}
