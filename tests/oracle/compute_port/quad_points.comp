#version 430
// A small D3D11 tessellator port: the domain points of quad patches for integer, pow2 and fractional_even
// partitioning (hardware stage), one invocation per patch. Written from the rules of D3D11.3 spec 11.7 as docs/
// tessellator.md spells them out (16.16 factors, half-edge placements on floor and ceil of half the factor blended by
// its fraction, 16.16 reciprocal table, mirrored second half, exact middle). Output: a point list per patch, in this
// port's own order (outer edges, then the interior grid); `fftess compare` checks it order-insensitively.
// bug: 0 none; 1 float division instead of the 16.16 reciprocal table; 2 no mirroring of the second half.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Patches { uint patchWords[]; }; // 8 per patch: 6 factor bits, partitioning
layout(std430, binding = 1) writeonly buffer Points { uvec2 points[]; };    // kMaxPoints per patch: u, v bits
layout(std430, binding = 2) writeonly buffer Counts { uint counts[]; };
uniform uint patchCount;
uniform uint bug;
const uint kMaxPoints = 4225u;
const uint kOne = 0x10000u;
const uint kHalf = 0x8000u;

struct Axis {
  bool odd;
  uint frac, recipFloor, recipCeil;
  int numHalf, split, num, floorSeg, ceilSeg;
};

uint fixedCeil(uint x) { return (x & 0xffffu) != 0u ? (x & 0x7fff0000u) + kOne : x; }

// float in [1, 64] -> 16.16, round to nearest, ties to even.
uint toFixed(float f) {
  uint b = floatBitsToUint(f);
  int e = int((b >> 23) & 0xffu) - 127;
  uint m = (b & 0x7fffffu) | 0x800000u;
  int drop = 7 - e;
  if (drop <= 0) return m << uint(-drop);
  uint keep = 1u << uint(drop), rest = m & (keep - 1u), halfKeep = keep >> 1;
  if ((m & keep) != 0u || rest > halfKeep) m += halfKeep;
  return m >> uint(drop);
}

uint reciprocal(int n) { return n <= 0 ? 0xffffffffu : (65536u + uint(n) / 2u) / uint(n); }
int withoutHighestBit(int v) { return v <= 0 ? 0 : v & ~(1 << findMSB(v)); }

Axis makeAxis(uint f, bool odd) {
  Axis a;
  a.odd = odd;
  uint half0 = (f + 1u) / 2u;
  a.num = odd ? int((fixedCeil(kHalf + half0) * 2u) >> 16) : int((fixedCeil(half0) * 2u) >> 16) + 1;
  uint h = half0;
  if (odd || h == kHalf) h += kHalf;
  uint fl = h & 0x7fff0000u, ce = fixedCeil(h);
  a.frac = h - fl;
  a.numHalf = int(ce >> 16);
  int flInt = int(fl >> 16);
  if (ce == fl) a.split = a.numHalf + 1;
  else if (odd) a.split = fl == kOne ? 0 : (withoutHighestBit(flInt - 1) << 1) + 1;
  else a.split = (withoutHighestBit(flInt) << 1) + 1;
  a.floorSeg = int((fl * 2u) >> 16) - (odd ? 1 : 0);
  a.ceilSeg = int((ce * 2u) >> 16) - (odd ? 1 : 0);
  a.recipFloor = reciprocal(a.floorSeg);
  a.recipCeil = reciprocal(a.ceilSeg);
  return a;
}

uint place(Axis a, int index) {
  int p = index;
  bool mirrored = false;
  if (p >= a.numHalf && bug != 2u) {
    p = 2 * a.numHalf - p - (a.odd ? 1 : 0);
    mirrored = true;
  }
  if (!a.odd && p == a.numHalf) return floatBitsToUint(0.5);
  uint onCeil = uint(p);
  uint onFloor = (a.frac != 0u && p > a.split) ? onCeil - 1u : onCeil;
  if (bug == 1u) {
    float lf = a.floorSeg > 0 ? float(onFloor) / float(a.floorSeg) : 0.0;
    float lc = float(onCeil) / float(a.ceilSeg);
    float fr = float(a.frac) * (1.0 / 65536.0);
    float loc = fr == 0.0 ? lc : lf * (1.0 - fr) + lc * fr;
    return floatBitsToUint(mirrored ? 1.0 - loc : loc);
  }
  uint blend = onFloor * a.recipFloor * (kOne - a.frac) + onCeil * a.recipCeil * a.frac;
  uint x = (blend + kHalf) >> 16;
  if (mirrored) x = kOne - x;
  return floatBitsToUint(float(x >> 16) + float(x & 0xffffu) * (1.0 / 65536.0));
}

void main() {
  uint id = gl_GlobalInvocationID.x;
  if (id >= patchCount) return;
  float f[6];
  for (int k = 0; k < 6; ++k) f[k] = uintBitsToFloat(patchWords[id * 8u + uint(k)]);
  bool fe = patchWords[id * 8u + 6u] == 3u; // 0 integer, 1 pow2 (the hardware's integer), 3 fractional_even
  uint base = id * kMaxPoints, n = 0u;
  for (int e = 0; e < 4; ++e)
    if (!(f[e] > 0.0)) { // NaN, zero, negative: culled
      counts[id] = 0u;
      return;
    }
  float lower = fe ? 2.0 : 1.0;
  bool allOne = true;
  Axis outer[4];
  for (int e = 0; e < 4; ++e) {
    float x = min(max(f[e], lower), 64.0);
    if (!fe) x = ceil(x);
    uint fx = toFixed(x);
    allOne = allOne && fx == kOne;
    outer[e] = makeAxis(fx, !fe && (int(x) & 1) == 1);
  }
  Axis inside[2];
  for (int a = 0; a < 2; ++a) {
    float x = isnan(f[4 + a]) ? lower : min(max(f[4 + a], lower), 64.0);
    if (!fe) x = ceil(x);
    bool odd = !fe && !((int(x) & 1) == 0 || x == 1.0);
    uint fx = toFixed(x);
    allOne = allOne && fx == kOne;
    inside[a] = makeAxis(fx, odd);
    inside[a].num = max(inside[a].num, odd ? 4 : 3); // at least one interior ring (degenerate for a factor of 1)
  }
  uint zero = 0u, one = floatBitsToUint(1.0);
  if (!fe && allOne) {
    points[base + 0u] = uvec2(zero, zero);
    points[base + 1u] = uvec2(one, zero);
    points[base + 2u] = uvec2(one, one);
    points[base + 3u] = uvec2(zero, one);
    counts[id] = 4u;
    return;
  }
  // Outer edges, each without one end (the next edge's): Ueq0 (u = 0), Veq0 (v = 0), Ueq1 (u = 1), Veq1 (v = 1).
  for (int k = 1; k < outer[0].num; ++k) points[base + n++] = uvec2(zero, place(outer[0], k));
  for (int k = 0; k < outer[1].num - 1; ++k) points[base + n++] = uvec2(place(outer[1], k), zero);
  for (int k = 0; k < outer[2].num - 1; ++k) points[base + n++] = uvec2(one, place(outer[2], k));
  for (int k = 1; k < outer[3].num; ++k) points[base + n++] = uvec2(place(outer[3], k), one);
  // Interior: every inside point of the U axis with every inside point of the V axis (the rings cover the grid).
  for (int j = 1; j < inside[1].num - 1; ++j) {
    uint v = place(inside[1], j);
    for (int i = 1; i < inside[0].num - 1; ++i) points[base + n++] = uvec2(place(inside[0], i), v);
  }
  counts[id] = n;
}
