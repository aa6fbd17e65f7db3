// An example lod.shader in HLSL: the screen-space sphere rule of NVIDIA's DX11 terrain tessellation sample, written
// here from its description (whitepaper "DirectX 11 Terrain Tessellation"), not from the sample's code: per edge a
// sphere on the edge midpoint with the edge length as diameter, projected; factor = its diameter in pixels /
// settings.targetPixels, clamped to [minFactor, maxFactor]; inside factors the average of the two edges along each
// axis; patches outside the frustum get -1. At a tile-ring jump the smaller side rebuilds the larger neighbour's edge
// and writes half its factor; both sides round with the clamp the scene asks for (settings.clampMode =
// lod.adjacency_clamp: the power-of-two workaround is kClampPow2). fftess puts the interface types first
// (LodPatch, TileNeighbourInfo, LodCamera, LodSettings, LodFactors) and compiles this file with glslang's HLSL front
// end to SPIR-V, then spirv-cross back to GLSL; docs/gpu_lod.md.

float sphereFactor(float3 p0, float3 p1, LodCamera cam, LodSettings s) {
  float3 centre = (p0 + p1) * 0.5;
  float diameter = distance(p0, p1);
  float4 view0 = mul(cam.view, float4(centre, 1.0));
  float4 view1 = view0 + float4(diameter, 0.0, 0.0, 0.0);
  float4 clip0 = mul(cam.proj, view0);
  float4 clip1 = mul(cam.proj, view1);
  float2 pixels = (clip1.xy / clip1.w - clip0.xy / clip0.w) * cam.viewport * 0.5;
  return clamp(length(pixels) / s.targetPixels, s.minFactor, s.maxFactor);
}

float largerSide(float f, int clampMode) {
  if (clampMode == kClampInteger) return clamp(ceil(f * 0.5) * 2.0, 4.0, 64.0);
  if (clampMode == kClampPow2) {
    float p = 4.0;
    [loop] while (p < 64.0 && p < f) p *= 2.0;
    return p;
  }
  return f;
}

bool outsideFrustum(LodPatch q, LodCamera cam) {
  float3 lo = min(min(q.corners[0], q.corners[1]), min(q.corners[2], q.corners[3]));
  float3 hi = max(max(q.corners[0], q.corners[1]), max(q.corners[2], q.corners[3]));
  if (q.useHeightBounds) {
    lo.y = min(lo.y, q.minHeight);
    hi.y = max(hi.y, q.maxHeight);
  }
  float4x4 m = mul(cam.proj, cam.view); // rows of m are the Gribb-Hartmann planes
  float4 planes[6] = {m[3] + m[0], m[3] - m[0], m[3] + m[1], m[3] - m[1], m[3] - m[2],
                      cam.depthZeroToOne ? m[2] : m[3] + m[2]};
  [unroll] for (int i = 0; i < 6; ++i) {
    float3 far = float3(planes[i].x >= 0 ? hi.x : lo.x, planes[i].y >= 0 ? hi.y : lo.y, planes[i].z >= 0 ? hi.z : lo.z);
    if (dot(planes[i].xyz, far) + planes[i].w < 0) return true;
  }
  return false;
}

static const int2 kEdgeEnds[4] = {int2(0, 2), int2(0, 1), int2(1, 3), int2(2, 3)}; // Ueq0 Veq0 Ueq1 Veq1

LodFactors lodMain(LodPatch quad, TileNeighbourInfo neighbours, LodCamera camera, LodSettings settings) {
  LodFactors r;
  if (settings.frustumCull && outsideFrustum(quad, camera)) {
    [unroll] for (int i = 0; i < 6; ++i) r.factor[i] = -1.0;
    r.culled = true;
    return r;
  }
  float own[4];
  [unroll] for (int e = 0; e < 4; ++e) {
    float3 a = quad.corners[kEdgeEnds[e].x];
    float3 b = quad.corners[kEdgeEnds[e].y];
    own[e] = sphereFactor(a, b, camera, settings);
    float f = own[e];
    if (neighbours.size[e] == 2.0) {
      bool odd = (e == 0 || e == 2) ? neighbours.oddV : neighbours.oddU;
      float3 far = odd ? a - (b - a) : b + (b - a);
      far.y = odd ? a.y : b.y;
      if (settings.rebuild == kRebuildResampled) far.y = neighbours.rebuiltHeight[e];
      if (settings.rebuild == kRebuildFarCorner) far = neighbours.farCorner[e];
      float big = odd ? sphereFactor(far, b, camera, settings) : sphereFactor(a, far, camera, settings);
      f = largerSide(big, settings.clampMode) * 0.5;
    } else if (neighbours.size[e] == 0.5) {
      f = largerSide(f, settings.clampMode);
    }
    r.factor[e] = f;
  }
  r.factor[4] = (own[1] + own[3]) * 0.5; // insideU from Veq0, Veq1
  r.factor[5] = (own[0] + own[2]) * 0.5; // insideV from Ueq0, Ueq1
  r.culled = false;
  return r;
}
