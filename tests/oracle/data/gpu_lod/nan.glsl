LodFactors lodMain(LodPatch quad, TileNeighbourInfo n, LodCamera c, LodSettings s) {
  LodFactors r;
  float z = quad.corners[0].x - quad.corners[0].x;
  for (int i = 0; i < 6; ++i) { r.factor[i] = 4.0; }
  if (quad.corners[0].x > 10.0) { r.factor[1] = z / z; }
  r.culled = false;
  return r;
}
