// A user shader that returns denormal outer factors for one patch (the one with its first corner at x = z = 0): 1e-40
// (bits 0x000116C2, written as bits so no compiler folds it). Every other factor is 1, so with the denormal kept
// (the D3D11 reference: the clamp makes it 1) the terrain is watertight; a driver that flushes denormals (llvmpipe)
// culls the patch and draws a hole. tests/oracle/gpu_lod_test.cmake CASE=denormal; docs/gpu_lod.md.
LodFactors lodMain(LodPatch quad, TileNeighbourInfo n, LodCamera c, LodSettings s) {
  LodFactors r;
  for (int i = 0; i < 6; ++i) { r.factor[i] = 1.0; }
  if (quad.corners[0].x == 0.0 && quad.corners[0].z == 0.0) {
    for (int i = 0; i < 4; ++i) { r.factor[i] = uintBitsToFloat(0x000116C2u); }
  }
  r.culled = false;
  return r;
}
