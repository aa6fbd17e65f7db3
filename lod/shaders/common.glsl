// fftess lod: shared helpers for every scheme.
//
// Shared source: compiled as C++ through GLM (lod/glsl_cpp.h) and as GLSL 4.50 by text concatenation (this file
// first). Only what both languages have: vec/mat types, structs, arrays, if/for, no out/inout, no uniforms.
// Every float literal carries an f suffix (C++ would otherwise evaluate in double). Every expression is evaluated
// in the order written; sums are left to right. Fix-bit values equal fftess::lod::Fix.

const float kHalfPi = 1.57079632679489662f;

const int kFixClampedMin = 1;
const int kFixClampedMax = 2;
const int kFixCulled = 4;
const int kFixLargerNeighbour = 8;
const int kFixSmallerNeighbour = 16;
const int kFixIntegerClamp = 32;
const int kFixPow2Clamp = 64;
const int kFixAngleCorrection = 128;
const int kFixRoundedExponent = 256;
const int kFixCoarserNeighbour = 512;
const int kFixLiteralSource = 1024;

const int kInsideAverage = 0;
const int kInsideMin = 1;
const int kInsideMax = 2;

struct LodCamera {
  mat4 view;          // world -> view (lookAt)
  mat4 proj;          // view -> clip (perspective)
  vec2 viewport;      // pixels
  vec3 eye;           // world
  bool depthZeroToOne; // clip z in [0, w] instead of [-w, w]
};

// One factor and where it came from.
struct EdgeLod {
  float factor;
  float metric;
  float unclamped;
  float exponent;
  int fixes;
};

// A patch: Ueq0 Veq0 Ueq1 Veq1 insideU insideV.
struct LodResult {
  EdgeLod e[6];
  float cornerLevel[4];
  bool culled;
};

EdgeLod makeEdgeLod(float factor, float metric, float unclamped, float exponent, int fixes) {
  EdgeLod r;
  r.factor = factor;
  r.metric = metric;
  r.unclamped = unclamped;
  r.exponent = exponent;
  r.fixes = fixes;
  return r;
}

LodResult emptyLodResult() {
  LodResult r;
  for (int i = 0; i < 6; ++i) {
    r.e[i] = makeEdgeLod(1.0f, 0.0f, 1.0f, 0.0f, 0);
  }
  for (int i = 0; i < 4; ++i) {
    r.cornerLevel[i] = 0.0f;
  }
  r.culled = false;
  return r;
}

// m * p as the columns m[0]*p.x + m[1]*p.y + m[2]*p.z + m[3]*p.w, summed left to right.
vec4 mulPoint(mat4 m, vec4 p) {
  return m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3] * p.w;
}

mat4 mulMat(mat4 a, mat4 b) {
  return mat4(mulPoint(a, b[0]), mulPoint(a, b[1]), mulPoint(a, b[2]), mulPoint(a, b[3]));
}

// (a + b) * 0.5: the same bits whichever corner comes first.
vec3 midpoint(vec3 a, vec3 b) {
  return (a + b) * 0.5f;
}

// ((c0 + c1) + c2) + c3, then * 0.25.
vec3 patchCentre(vec3 c0, vec3 c1, vec3 c2, vec3 c3) {
  return (c0 + c1 + c2 + c3) * 0.25f;
}

// sqrt(dx*dx + dy*dy + dz*dz), d = a - b: the same bits for (a, b) and (b, a).
float distanceOrdered(vec3 a, vec3 b) {
  vec3 d = a - b;
  return sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
}

float dotOrdered(vec3 a, vec3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

// clamp(x, 0, 1) by comparisons; NaN stays NaN.
float clamp01(float x) {
  float r = x;
  if (r < 0.0f) {
    r = 0.0f;
  }
  if (r > 1.0f) {
    r = 1.0f;
  }
  return r;
}

// HLSL lerp(a, b, t) = a + t * (b - a).
float lerpHlsl(float a, float b, float t) {
  return a + t * (b - a);
}

// s = clamp01((d - lo) / (hi - lo)): 0 at lo and nearer, 1 at hi and beyond.
float distanceRamp(float d, float lo, float hi) {
  return clamp01((d - lo) / (hi - lo));
}

// Clamp a raw factor into [lo, hi] by comparisons, recording which bound fired. NaN passes through.
EdgeLod clampFactor(float metric, float unclamped, float exponent, int fixes, float lo, float hi) {
  float f = unclamped;
  int fx = fixes;
  if (f < lo) {
    f = lo;
    fx = fx | kFixClampedMin;
  }
  if (f > hi) {
    f = hi;
    fx = fx | kFixClampedMax;
  }
  return makeEdgeLod(f, metric, unclamped, exponent, fx);
}

// Inside factor of one axis from its two edges: average (a + b) * 0.5, min or max.
EdgeLod insideFromEdges(EdgeLod a, EdgeLod b, int rule) {
  float f = (a.factor + b.factor) * 0.5f;
  if (rule == kInsideMin) {
    f = min(a.factor, b.factor);
  }
  if (rule == kInsideMax) {
    f = max(a.factor, b.factor);
  }
  return makeEdgeLod(f, 0.0f, f, 0.0f, 0);
}

// Fill insideU (from Veq0, Veq1) and insideV (from Ueq0, Ueq1).
LodResult withInsideFromEdges(LodResult r, int rule) {
  LodResult o = r;
  o.e[4] = insideFromEdges(r.e[1], r.e[3], rule);
  o.e[5] = insideFromEdges(r.e[0], r.e[2], rule);
  return o;
}

// Every factor set to the cull value.
LodResult culledLodResult(float culledFactor) {
  LodResult r = emptyLodResult();
  for (int i = 0; i < 6; ++i) {
    r.e[i] = makeEdgeLod(culledFactor, 0.0f, culledFactor, 0.0f, kFixCulled);
  }
  r.culled = true;
  return r;
}

// Box [bmin, bmax] against the six clip planes of proj * view (Gribb-Hartmann rows, unnormalised: only signs
// matter). True when the box lies wholly on the outer side of one plane: its corner furthest along the plane
// normal is outside. Planes: w+x, w-x, w+y, w-y, w-z (far), w+z (near; z alone with depthZeroToOne).
bool planeRejects(vec4 plane, vec3 bmin, vec3 bmax) {
  vec3 p = bmin;
  if (plane.x >= 0.0f) {
    p.x = bmax.x;
  }
  if (plane.y >= 0.0f) {
    p.y = bmax.y;
  }
  if (plane.z >= 0.0f) {
    p.z = bmax.z;
  }
  return plane.x * p.x + plane.y * p.y + plane.z * p.z + plane.w < 0.0f;
}

// The six planes of proj * view as rows (Gribb-Hartmann, unnormalised), in D3D's order: p[0] left w+x, p[1] right
// w-x, p[2] bottom w+y, p[3] top w-y, p[4] near (w+z; z alone with depthZeroToOne: D3D's [0, w] depth), p[5] far w-z.
// Each component rounded once (a sum or difference of two floats of the product's rows).
struct LodFrustum {
  vec4 p[6];
};

LodFrustum lodFrustumPlanes(LodCamera cam) {
  mat4 m = mulMat(cam.proj, cam.view);
  vec4 rx = vec4(m[0][0], m[1][0], m[2][0], m[3][0]);
  vec4 ry = vec4(m[0][1], m[1][1], m[2][1], m[3][1]);
  vec4 rz = vec4(m[0][2], m[1][2], m[2][2], m[3][2]);
  vec4 rw = vec4(m[0][3], m[1][3], m[2][3], m[3][3]);
  LodFrustum f;
  f.p[0] = rw + rx;
  f.p[1] = rw - rx;
  f.p[2] = rw + ry;
  f.p[3] = rw - ry;
  f.p[4] = rw + rz;
  if (cam.depthZeroToOne) {
    f.p[4] = rz;
  }
  f.p[5] = rw - rz;
  return f;
}

bool boxOutsideFrustum(vec3 bmin, vec3 bmax, LodCamera cam) {
  LodFrustum f = lodFrustumPlanes(cam);
  return planeRejects(f.p[0], bmin, bmax) || planeRejects(f.p[1], bmin, bmax) ||
         planeRejects(f.p[2], bmin, bmax) || planeRejects(f.p[3], bmin, bmax) ||
         planeRejects(f.p[5], bmin, bmax) || planeRejects(f.p[4], bmin, bmax);
}

// The patch box: the corners' box, y widened to [minHeight, maxHeight] when useHeightBounds.
bool patchOutsideFrustum(vec3 c0, vec3 c1, vec3 c2, vec3 c3, bool useHeightBounds, float minHeight,
                         float maxHeight, LodCamera cam) {
  vec3 bmin = min(min(c0, c1), min(c2, c3));
  vec3 bmax = max(max(c0, c1), max(c2, c3));
  if (useHeightBounds) {
    bmin.y = min(bmin.y, minHeight);
    bmax.y = max(bmax.y, maxHeight);
  }
  return boxOutsideFrustum(bmin, bmax, cam);
}

// The quad's edge endpoints in D3D order: Ueq0 = 0-2, Veq0 = 0-1, Ueq1 = 1-3, Veq1 = 2-3 (corner = u + 2v).
int edgeStartCorner(int edge) {
  int c = 0;
  if (edge == 2) {
    c = 1;
  }
  if (edge == 3) {
    c = 2;
  }
  return c;
}

int edgeEndCorner(int edge) {
  int c = 2;
  if (edge == 1) {
    c = 1;
  }
  if (edge == 2 || edge == 3) {
    c = 3;
  }
  return c;
}
