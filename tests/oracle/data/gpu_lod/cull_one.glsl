// A wrong LOD (issue 18): a constant factor 8, but the patch whose first corner is at x = 0, z = 0 is culled (factor
// 0, culled = true) wherever it is. tests/oracle/gpu_lod_test.cmake, CASE=visibility.
LodFactors lodMain(LodPatch quad, TileNeighbourInfo neighbours, LodCamera camera, LodSettings settings) {
  LodFactors r;
  bool wrong = quad.corners[0].x == 0.0 && quad.corners[0].z == 0.0;
  for (int i = 0; i < 6; ++i) { r.factor[i] = wrong ? 0.0 : 8.0; }
  r.culled = wrong;
  return r;
}
