LodFactors somethingElse(LodPatch quad) { LodFactors r; return r; }
