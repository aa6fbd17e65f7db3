// Quad domain: outer ring clockwise from (u=0, v=1), inner rings spiralling in, then the middle row of an even
// axis; connectivity ring by ring, then the middle strip of an odd axis. Order exactly as the D3D11 reference.
#include "generate.h"
#include "simd.h"

#include <vector>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace fftess {
namespace {

constexpr int U = 0, V = 1;

void minimumQuad(bool triangles, MeshWriter& out) {
  out.point(0, 0);
  out.point(fx::kOne, 0);
  out.point(fx::kOne, fx::kOne);
  out.point(0, fx::kOne);
  if (triangles) {
    out.triangle(0, 1, 3);
    out.triangle(1, 2, 3);
  }
}

// Rows of points with one coordinate fixed: {c, t[k]} (or {t[k], c}) for k = from, from + 1, ... (forward) or
// from, from - 1, ... (backward); count points. Four points per step with SSE2.
template <bool FixedFirst, bool Forward>
DomainPoint* row(DomainPoint* dst, float c, const float* t, int from, int count) {
  int k = 0;
#if defined(__SSE2__)
  const __m128 fixed = _mm_set1_ps(c);
  for (; k + 4 <= count; k += 4, dst += 4) {
    __m128 v = Forward ? _mm_loadu_ps(t + from + k) : _mm_loadu_ps(t + from - k - 3);
    if (!Forward) v = _mm_shuffle_ps(v, v, _MM_SHUFFLE(0, 1, 2, 3));
    const __m128 lo = FixedFirst ? _mm_unpacklo_ps(fixed, v) : _mm_unpacklo_ps(v, fixed);
    const __m128 hi = FixedFirst ? _mm_unpackhi_ps(fixed, v) : _mm_unpackhi_ps(v, fixed);
    _mm_storeu_ps(reinterpret_cast<float*>(dst), lo);
    _mm_storeu_ps(reinterpret_cast<float*>(dst) + 4, hi);
  }
#endif
  for (; k < count; ++k, ++dst) {
    const float x = t[Forward ? from + k : from - k];
    *dst = FixedFirst ? DomainPoint{c, x} : DomainPoint{x, c};
  }
  return dst;
}

// D3D11.3 spec 11.7.13-11.7.14: points from 1D tables. Every point of the quad is (u table[i], v table[j]) of one
// outer edge's table or of the two inside axes' tables, so placement runs once per axis, not once per point.
void quadPoints(const ProcessedQuad& q, MeshWriter& out) {
  DomainPoint* dst = out.points + out.numPoints;
  // Outer ring. Edges in order Ueq0, Veq0, Ueq1, Veq1; each without its last point (the next edge's first).
  // Ueq0 runs v from 1 down to 0, Veq0 u up from 0, Ueq1 v up from 0, Veq1 u down from 1.
  AxisTable t;
  for (int e = 0; e < 4; ++e) {
    fillAxisTable(q.outer[e], t);
    const int last = t.count - 1;
    switch (e) {
    case 0: dst = row<true, false>(dst, 0.0f, t.param, last, last); break;
    case 1: dst = row<false, true>(dst, 0.0f, t.param, 0, last); break;
    case 2: dst = row<true, true>(dst, 1.0f, t.param, 0, last); break;
    default: dst = row<false, false>(dst, 1.0f, t.param, last, last); break;
    }
  }
  // Inner rings, same edge order, each edge at a fixed position on the perpendicular axis.
  AxisTable tu, tv;
  fillAxisTable(q.inside[U], tu);
  fillAxisTable(q.inside[V], tv);
  const float* U_ = tu.param;
  const float* V_ = tv.param;
  const int nU = q.inside[U].numPoints, nV = q.inside[V].numPoints;
  const int rings = (nU < nV ? nU : nV) >> 1;
  for (int ring = 1; ring < rings; ++ring) {
    const int endU = nU - 1 - ring, endV = nV - 1 - ring;
    dst = row<true, false>(dst, U_[ring], V_, endV, endV - ring);
    dst = row<false, true>(dst, V_[ring], U_, ring, endU - ring);
    dst = row<true, true>(dst, U_[endU], V_, ring, endV - ring);
    dst = row<false, false>(dst, V_[endV], U_, endU, endU - ring);
  }
  // Even parity on the shorter axis leaves a degenerate innermost ring: one row of points through the middle.
  if (nU > nV && !q.inside[V].odd) {
    for (int p = rings; p <= nU - 1 - rings; ++p) *dst++ = {U_[p], 0.5f};
  } else if (nV >= nU && !q.inside[U].odd) {
    for (int p = nV - 1 - rings; p >= rings; --p) *dst++ = {0.5f, V_[p]};
  }
  out.numPoints = int(dst - out.points);
}

// Connectivity, ring by ring. The shape of the inside (both axes' point counts and parities) fixes everything from
// ring 2 inwards: those triangles only use inside points, so relative to the first inside point they are the same
// for every patch with that inside shape, whatever the outer edges and the fractions.
struct QuadShape {
  int n[2];             // inside points per axis
  bool odd[2];          // inside parities
  int numHalf[2];       // inside half points (ring 1 transitions)
  int rings;            // rings including ring 1
  int degenerateRing[2]; // per axis the row runs along: the ring whose row on it runs backwards (-1: none)

  explicit QuadShape(const ProcessedQuad& q) {
    for (int a = 0; a < 2; ++a) {
      n[a] = q.inside[a].numPoints;
      odd[a] = q.inside[a].odd;
      numHalf[a] = q.inside[a].numHalfPoints;
    }
    const int rowsToCentre[2] = {(n[U] + 1) >> 1, (n[V] + 1) >> 1};
    rings = rowsToCentre[U] < rowsToCentre[V] ? rowsToCentre[U] : rowsToCentre[V];
    // With an even inside axis, the innermost ring of the other axis is a degenerate row of points; the rows along
    // it run backwards through the point array.
    degenerateRing[U] = !odd[V] ? rowsToCentre[V] - 1 : -1;
    degenerateRing[V] = !odd[U] ? rowsToCentre[U] - 1 : -1;
  }
};

struct RingCursor {
  int insideBase, outsideBase;
  int outsidePoints[4]; // points on the current outside row of each edge
};

// Stitches ring `ring` to the ring outside it (ring 1: to the outer edges, in ruler order).
void stitchRing(const QuadShape& sh, const ProcessedQuad& q, MeshWriter& out, int ring, RingCursor& c) {
  const int insidePoints[2] = {sh.n[U] - 2 * ring, sh.n[V] - 2 * ring};
  const int ringInsideStart = c.insideBase, ringOutsideStart = c.outsideBase;
  for (int e = 0; e < 4; ++e) {
    const int along = (e + 1) & 1;
    const bool degenerate = ring == sh.degenerateRing[along];
    Row inside{c.insideBase, 1}, outside{c.outsideBase, 1};
    if (e == 3) {
      // The ring's last edge ends on the ring's first point.
      outside.redirectFrom = c.outsidePoints[e] - 1;
      outside.redirectTo = ringOutsideStart;
      if (degenerate) {
        inside.step = -1;
      } else {
        inside.redirectFrom = insidePoints[along] - 1;
        inside.redirectTo = ringInsideStart;
      }
    } else if (e == 2 && degenerate) {
      inside.step = -1;
    }
    if (ring == 1)
      stitchTransition(out, inside, sh.numHalf[along], sh.odd[along], outside, q.outer[e].numHalfPoints,
                       q.outer[e].odd);
    else
      stitchRegular(out, true, Diagonals::Mirrored, insidePoints[along], inside, outside);
    c.outsideBase += c.outsidePoints[e] - 1;
    c.insideBase += (e == 2 && degenerate) ? -(insidePoints[along] - 1) : insidePoints[along] - 1;
    c.outsidePoints[e] = insidePoints[along];
  }
}

// Rings 2.. and the middle strip of an odd shorter axis.
void quadInterior(const QuadShape& sh, const ProcessedQuad& q, MeshWriter& out, RingCursor& c) {
  for (int ring = 2; ring < sh.rings; ++ring) stitchRing(sh, q, out, ring, c);
  const int* n = sh.n;
  // Odd shorter axis: a strip of quads through the middle, between the two long sides of the last ring.
  if (n[U] > n[V] && sh.odd[V]) {
    const int quads = (((n[U] >> 1) - (n[V] >> 1)) << 1) + (sh.odd[U] ? 1 : 2);
    const int far = c.outsideBase + quads + 2;
    Row inside{far + quads, -1, 0, c.outsideBase};
    Row outside{c.outsideBase + 1, 1};
    stitchRegular(out, false, Diagonals::InsideToOutside, quads + 1, inside, outside);
  } else if (n[V] >= n[U] && sh.odd[U]) {
    const int quads = (((n[V] >> 1) - (n[U] >> 1)) << 1) + (sh.odd[V] ? 1 : 2);
    const int far = c.outsideBase + quads + 1;
    Row inside{far + quads, -1};
    Row outside{c.outsideBase, 1};
    stitchRegular(out, false, sh.odd[V] ? Diagonals::InsideToOutsideExceptMiddle : Diagonals::InsideToOutside,
                  quads + 1, inside, outside);
  }
}

// Interior index templates (rings 2.. relative to the first inside point), per thread, keyed by the inside shape
// and winding; direct-mapped. A template is written once and then copied with the base added: no per-triangle
// work for repeated shapes (a workload with factors spread over [1,16] has a few dozen shapes).
struct InteriorTemplate {
  uint32_t key = 0; // 0: empty
  std::vector<int32_t> indices;
};
constexpr int kInteriorSlots = 256;    // templates of up to kSmallInterior indices
constexpr int kLargeInteriorSlots = 4; // larger ones (up to a factor-64 interior, ~96 KB): bounded memory
constexpr size_t kSmallInterior = 4096;

uint32_t shapeKey(const QuadShape& sh, bool ccw) {
  return 1u | uint32_t(sh.n[U]) << 1 | uint32_t(sh.n[V]) << 9 | uint32_t(sh.odd[U]) << 17 |
         uint32_t(sh.odd[V]) << 18 | uint32_t(ccw) << 19;
}

// dst[k] = src[k] + base (a template placed after the patch's outer and ring-1 points).
void addBasePortable(int32_t* dst, const int32_t* src, int count, int32_t base) {
  for (int k = 0; k < count; ++k) dst[k] = src[k] + base;
}
#if defined(__x86_64__)
__attribute__((target("avx2"))) void addBaseAvx2(int32_t* dst, const int32_t* src, int count, int32_t base) {
  for (int k = 0; k < count; ++k) dst[k] = src[k] + base;
}
#endif
void addBase(int32_t* dst, const int32_t* src, int count, int32_t base) {
#if defined(__x86_64__)
  if (simd::useAvx2()) return addBaseAvx2(dst, src, count, base);
#endif
  addBasePortable(dst, src, count, base);
}

void quadTriangles(const ProcessedQuad& q, MeshWriter& out, int firstInsidePoint) {
  const QuadShape sh(q);
  RingCursor c{firstInsidePoint, 0, {}};
  for (int e = 0; e < 4; ++e) c.outsidePoints[e] = q.outer[e].numPoints;
  stitchRing(sh, q, out, 1, c);

  thread_local InteriorTemplate cache[kInteriorSlots];
  thread_local InteriorTemplate large[kLargeInteriorSlots];
  const uint32_t key = shapeKey(sh, out.ccw);
  // Interior size from the shape alone: about 6 indices per inside quad.
  const bool isLarge = size_t(6) * size_t(sh.n[U]) * size_t(sh.n[V]) > kSmallInterior;
  InteriorTemplate& slot = isLarge ? large[key % kLargeInteriorSlots] : cache[(key * 0x9e3779b1u) >> 24];
  int32_t* dst = out.indices + out.numIndices;
  if (slot.key == key) {
    const int count = int(slot.indices.size());
    addBase(dst, slot.indices.data(), count, firstInsidePoint);
    out.numIndices += count;
    return;
  }
  quadInterior(sh, q, out, c);
  slot.key = key;
  // Each slot allocates once, for the largest template it can hold (kSmallInterior, or a factor-64 interior).
  if (slot.indices.capacity() == 0) slot.indices.reserve(isLarge ? size_t(kMaxIndices) : kSmallInterior);
  slot.indices.assign(dst, out.indices + out.numIndices);
  for (int32_t& v : slot.indices) v -= firstInsidePoint;
}

} // namespace

void generateQuad(const ProcessedQuad& q, bool triangles, MeshWriter& out) {
  if (q.culled) return;
  if (q.minimum) {
    minimumQuad(triangles, out);
    return;
  }
  const int first = out.numPoints;
  quadPoints(q, out);
  if (triangles) {
    int outerPoints = 0;
    for (int e = 0; e < 4; ++e) outerPoints += q.outer[e].numPoints - 1;
    quadTriangles(q, out, first + outerPoints);
  }
}

} // namespace fftess
