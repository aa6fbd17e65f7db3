// fftess prove: a shared edge pair classified for concrete factors without a camera (classifyPairFactors), as
// check.cpp's checkEdgePair classifies it when the domain needs no camera state (proveScene refuses geomorph and
// mip): both sides' edge points (fftess::edgePoints, then the domain-shader emulation), the part of side a that side
// b covers, bits compared, then (not a match) classifyExact.
#include "verify/prove_internal.h"

#include <algorithm>

namespace fftess::verify::detail {

namespace {

void edgeWorldPoints(const TerrainData& t, const TerrainPatch& p, int e, const EdgePoints& E,
                     std::vector<glm::vec3>& out, std::vector<DomainPoint>* dom, WorkStats& work) {
  out.resize(static_cast<size_t>(E.count));
  if (dom) dom->resize(static_cast<size_t>(E.count));
  for (int j = 0; j < E.count; ++j) {
    const DomainPoint d = edgeDomain(e, E.param[j]);
    if (dom) (*dom)[static_cast<size_t>(j)] = d;
    out[static_cast<size_t>(j)] = evalDomain(t, p, d.u, d.v, nullptr, work);
  }
}

} // namespace

Classification classifyPairFactors(const TerrainData& t, size_t ia, int e, size_t ib, float fa, float fb,
                                   ProveScratch& s, Kernel kernel) {
  WorkStats work;
  const TerrainPatch& A = t.patches[ia];
  const TerrainPatch& B = t.patches[ib];
  const int eb = kOpposite[e];
  const EdgePoints& pa = s.edges.get(fa, work);
  const EdgePoints& pbp = s.edges.get(fb, work);
  if (pa.culled || pbp.culled) return Classification::Match; // a side not drawn: the check skips the pair
  edgeWorldPoints(t, A, e, pa, s.pa, &s.da, work);
  edgeWorldPoints(t, B, eb, pbp, s.pb, nullptr, work);
  // The part of A's edge that B covers (checkEdgePair's rule, in base units, exact in double).
  const bool alongX = e == Veq0 || e == Veq1;
  const int64_t off = B.size != A.size ? (alongX ? B.ux - A.ux : B.uz - A.uz) : 0;
  const double sizeA = static_cast<double>(A.size), lo = static_cast<double>(off);
  const double hi = static_cast<double>(off + std::min(B.size, A.size));
  auto unitsA = [&](int j) {
    const DomainPoint& d = s.da[static_cast<size_t>(j)];
    return static_cast<double>(e == Ueq0 || e == Ueq1 ? d.v : d.u) * sizeA;
  };
  int first = 0, last = pa.count;
  while (first < pa.count && unitsA(first) < lo) ++first;
  while (last > first && unitsA(last - 1) > hi) --last;
  const int na = last - first;
  const glm::vec3* a = s.pa.data() + first;
  bool match = na == pbp.count;
  for (int j = 0; match && j < na; ++j) match = sameBits(a[j], s.pb[static_cast<size_t>(j)]);
  if (match) return Classification::Match;
  for (const glm::vec3& q : s.pa)
    if (!finite(q)) return Classification::Crack; // the check reports an error: never a proof
  for (const glm::vec3& q : s.pb)
    if (!finite(q)) return Classification::Crack;
  return classifyExact(kernel, a, na, s.pa.data(), pa.count, s.pb.data(), pbp.count, nullptr).classification;
}

} // namespace fftess::verify::detail
