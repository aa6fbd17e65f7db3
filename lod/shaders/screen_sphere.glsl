// fftess lod, scheme 1: screen-space sphere (NVIDIA DX11 terrain tessellation sample). Needs common.glsl.
//
// Per edge: a sphere centred on the edge midpoint whose diameter is the edge length is moved to view space; a
// second point one diameter along view-space x stands for its far side; both are projected and divided by w;
// the pixel distance between them over the target triangle width is the factor, clamped to [minFactor, maxFactor].

// Where the sphere sits (ScreenSphereSettings.sphereCentre; lod/lod_fields.h's codes).
const int kCentreHalfSum = 0;
const int kCentreAroundQuadScaled = 1;

struct ScreenSphereSettings {
  float triWidth;   // pixels per tessellated triangle edge
  float minFactor;
  float maxFactor;
  int insideRule;   // kInsideAverage / kInsideMin / kInsideMax
  bool frustumCull;
  float culledFactor;
  int sphereCentre; // kCentreHalfSum / kCentreAroundQuadScaled
};

// Projected diameter, in pixels, of the sphere of that centre and diameter.
// view0 = V * (centre, 1); view1 = view0 with x + diameter; clip = P * view; ndc = clip.xy / clip.w;
// pixels = (ndc1 - ndc0) * viewport * 0.5; result = sqrt(px*px + py*py).
float sphereDiameterPixelsAt(vec3 centre, float diameter, LodCamera cam) {
  vec4 view0 = mulPoint(cam.view, vec4(centre, 1.0f));
  vec4 view1 = view0;
  view1.x = view1.x + diameter;
  vec4 clip0 = mulPoint(cam.proj, view0);
  vec4 clip1 = mulPoint(cam.proj, view1);
  float px = (clip1.x / clip1.w - clip0.x / clip0.w) * (cam.viewport.x * 0.5f);
  float py = (clip1.y / clip1.w - clip0.y / clip0.w) * (cam.viewport.y * 0.5f);
  return sqrt(px * px + py * py);
}

// The sphere spanning p0-p1: centre midpoint(p0, p1), diameter distanceOrdered(p0, p1).
float sphereDiameterPixels(vec3 p0, vec3 p1, LodCamera cam) {
  vec3 centre = midpoint(p0, p1);
  float diameter = distanceOrdered(p0, p1);
  return sphereDiameterPixelsAt(centre, diameter, cam);
}

// The sphere's centre for the edge p0-p1 (p0, p1 in lod's edge order), by ScreenSphereSettings.sphereCentre:
//   kCentreHalfSum: midpoint(p0, p1) = (p0 + p1) * 0.5, the same operations on the same bits from both sides;
//   kCentreAroundQuadScaled (a negative control for --gpu-float, not a scheme to ship): (from * 3 + to * 3) * (1/6),
//   where from, to are the edge's ends in the order the patch passes them going around its quad (Veq0 c0->c1, Ueq1
//   c1->c3, Veq1 c3->c2, Ueq0 c2->c0): the two patches sharing an edge pass its ends in opposite orders and add the
//   same two rounded products in opposite orders (the same bits in lod/'s C++ build, where + is commutative), but a
//   compiler that fuses one product into the add (an FMA, which GLSL allows per expression) rounds a different
//   product on each side.
vec3 sphereCentreOf(vec3 p0, vec3 p1, vec3 from, vec3 to, int mode) {
  if (mode == kCentreAroundQuadScaled) {
    return (from * 3.0f + to * 3.0f) * 0.166666672f;
  }
  return midpoint(p0, p1);
}

// The factor of edge p0-p1 with the sphere centred by sphereCentreOf (from, to: the ends in the patch's order around
// its quad): diameterPixels / triWidth, clamped.
EdgeLod screenSphereEdgeAround(vec3 p0, vec3 p1, vec3 from, vec3 to, LodCamera cam, ScreenSphereSettings s) {
  vec3 centre = sphereCentreOf(p0, p1, from, to, s.sphereCentre);
  float diameter = distanceOrdered(p0, p1);
  float px = sphereDiameterPixelsAt(centre, diameter, cam);
  return clampFactor(px, px / s.triWidth, 0.0f, 0, s.minFactor, s.maxFactor);
}

// The factor of one edge: diameterPixels / triWidth, clamped.
// (kCentreAroundQuadScaled: from = p0, to = p1.)
EdgeLod screenSphereEdge(vec3 p0, vec3 p1, LodCamera cam, ScreenSphereSettings s) {
  return screenSphereEdgeAround(p0, p1, p0, p1, cam, s);
}

LodResult screenSphereLod(vec3 c0, vec3 c1, vec3 c2, vec3 c3, bool useHeightBounds, float minHeight,
                          float maxHeight, LodCamera cam, ScreenSphereSettings s) {
  if (s.frustumCull && patchOutsideFrustum(c0, c1, c2, c3, useHeightBounds, minHeight, maxHeight, cam)) {
    return culledLodResult(s.culledFactor);
  }
  LodResult r = emptyLodResult();
  r.e[0] = screenSphereEdgeAround(c0, c2, c2, c0, cam, s);
  r.e[1] = screenSphereEdgeAround(c0, c1, c0, c1, cam, s);
  r.e[2] = screenSphereEdgeAround(c1, c3, c1, c3, cam, s);
  r.e[3] = screenSphereEdgeAround(c2, c3, c3, c2, cam, s);
  return withInsideFromEdges(r, s.insideRule);
}

// Deliberately broken variant (a negative control for the verifier, not a scheme to ship): every edge's sphere sits
// at the patch centre instead of the edge midpoint: the edge p0-p1 is moved to centre - (p1 - p0) * 0.5 ..
// centre + (p1 - p0) * 0.5 (same direction and length), so two patches sharing an edge measure it at different
// places and disagree. Culling as screenSphereLod; inside factors from the edges by the inside rule.
EdgeLod patchCenterEdge(vec3 centre, vec3 p0, vec3 p1, LodCamera cam, ScreenSphereSettings s) {
  vec3 halfEdge = (p1 - p0) * 0.5f;
  return screenSphereEdge(centre - halfEdge, centre + halfEdge, cam, s);
}

LodResult patchCenterLod(vec3 c0, vec3 c1, vec3 c2, vec3 c3, bool useHeightBounds, float minHeight,
                         float maxHeight, LodCamera cam, ScreenSphereSettings s) {
  if (s.frustumCull && patchOutsideFrustum(c0, c1, c2, c3, useHeightBounds, minHeight, maxHeight, cam)) {
    return culledLodResult(s.culledFactor);
  }
  vec3 centre = patchCentre(c0, c1, c2, c3);
  LodResult r = emptyLodResult();
  r.e[0] = patchCenterEdge(centre, c0, c2, cam, s);
  r.e[1] = patchCenterEdge(centre, c0, c1, cam, s);
  r.e[2] = patchCenterEdge(centre, c1, c3, cam, s);
  r.e[3] = patchCenterEdge(centre, c2, c3, cam, s);
  return withInsideFromEdges(r, s.insideRule);
}
