LodFactors lodMain(LodPatch quad, LodCamera c) {
  LodFactors r;
  r.culled = false;
  return r;
}
