LodFactors lodMain(LodPatch quad, TileNeighbourInfo n, LodCamera c, LodSettings s) {
  LodFactors r;
  r.factor[0] = undefinedThing;
  r.culled = false;
  return r;
}
