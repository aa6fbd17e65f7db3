LodFactors lodMain(LodPatch quad, LodCamera c) {
  LodFactors r;
  for (int i = 0; i < 6; ++i) { r.factor[i] = 4.0; }
  r.culled = false;
  return r;
}
