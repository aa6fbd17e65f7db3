// fftess lod, scheme 6: geomorphing tween factors (the hardware geomorphing article). Needs common.glsl.
//
// A patch's float level L = lerp(finest, coarsest, s) (s from its centre's distance): floor(L) is the level,
// L - floor(L) the tween. The patch is drawn with 2^(floor(L) + 1) segments per side (integer partitioning);
// the vertices the last level inserts morph from the midpoint of their two neighbours (tween 0) to their true
// height (tween 1). A border takes the coarser side's level, min(L, Ln), so both sides compute it alike.
// Levels are clamped to [0, 5] (64 segments at most).

struct GeomorphSettings {
  float minDistance;
  float maxDistance;
  float finestLevel;
  float coarsestLevel;
  bool literalArticleWeight; // inserted-vertex weight (1 - tweenNeighbour) * tweenSelf
};

float geomorphLevelAt(vec3 p, LodCamera cam, GeomorphSettings s) {
  float d = distanceOrdered(p, cam.eye);
  return lerpHlsl(s.finestLevel, s.coarsestLevel, distanceRamp(d, s.minDistance, s.maxDistance));
}

// floor(L) clamped to [0, 5] (NaN: 0).
float geomorphWhole(float level) {
  float w = floor(level);
  if (!(w >= 0.0f)) {
    w = 0.0f;
  }
  if (w > 5.0f) {
    w = 5.0f;
  }
  return w;
}

// L - floor(L) inside [0, 6); 0 below level 0 (and for NaN), 1 at and above level 6.
float geomorphTween(float level) {
  float t = level - floor(level);
  if (!(level >= 0.0f)) {
    t = 0.0f;
  }
  if (level >= 6.0f) {
    t = 1.0f;
  }
  return t;
}

LodResult geomorphLod(float level, float n0, float n1, float n2, float n3) {
  LodResult r = emptyLodResult();
  for (int i = 0; i < 4; ++i) {
    float n = n0;
    if (i == 1) {
      n = n1;
    }
    if (i == 2) {
      n = n2;
    }
    if (i == 3) {
      n = n3;
    }
    float edgeLevel = min(level, n);
    int fx = 0;
    if (n < level) {
      fx = kFixCoarserNeighbour;
    }
    float w = geomorphWhole(edgeLevel);
    r.e[i] = makeEdgeLod(exp2(w + 1.0f), edgeLevel, exp2(w + 1.0f), w + 1.0f, fx);
  }
  float wi = geomorphWhole(level);
  EdgeLod inside = makeEdgeLod(exp2(wi + 1.0f), level, exp2(wi + 1.0f), wi + 1.0f, 0);
  r.e[4] = inside;
  r.e[5] = inside;
  return r;
}

// The weight of an inserted vertex's true height on the border between a patch at `level` and its neighbour at
// `neighbourLevel` (pass the patch's own level for its interior): the tween of the border level min(level,
// neighbourLevel), which both sides compute alike; or, with literalArticleWeight, the article's
// (1 - tween(neighbourLevel)) * tween(level), product rounded once.
float geomorphWeight(float level, float neighbourLevel, GeomorphSettings s) {
  float w = geomorphTween(min(level, neighbourLevel));
  if (s.literalArticleWeight) {
    w = (1.0f - geomorphTween(neighbourLevel)) * geomorphTween(level);
  }
  return w;
}

// An inserted vertex's morphed height: m = (previous + next) * 0.5, then m + weight * (height - m), each operation
// rounded to float in that order (the sum, the halving, the difference, the product, the sum).
float geomorphHeight(float height, float previousHeight, float nextHeight, float weight) {
  float m = (previousHeight + nextHeight) * 0.5f;
  return m + weight * (height - m);
}

struct GeomorphBorder {
  int segments;
  float heights[65];
};

// The heights one side gives the vertices of a shared border. fine[i]: true height at t = i / 64.
// Vertex k (t = k / n): even k keeps its true height; odd k: m = (h[k-1] + h[k+1]) * 0.5, height = m + w * (h - m),
// w = tween of min(level, neighbourLevel) (or the article's (1 - tweenNeighbour) * tweenSelf).
GeomorphBorder geomorphBorderHeights(float level, float neighbourLevel, float fine[65], GeomorphSettings s) {
  GeomorphBorder b;
  float edgeLevel = min(level, neighbourLevel);
  int n = int(exp2(geomorphWhole(edgeLevel) + 1.0f));
  int step = 64 / n;
  float w = geomorphWeight(level, neighbourLevel, s);
  b.segments = n;
  for (int k = 0; k < 65; ++k) {
    b.heights[k] = 0.0f;
  }
  for (int k = 0; k <= n; ++k) {
    float h = fine[k * step];
    if (k - (k / 2) * 2 == 1) {
      h = geomorphHeight(h, fine[(k - 1) * step], fine[(k + 1) * step], w);
    }
    b.heights[k] = h;
  }
  return b;
}
