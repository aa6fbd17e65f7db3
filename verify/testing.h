// fftess verify: the fault-injection hook, for tests only (tests/verify/fault_injection_test.cpp and the tests that
// use a fault to make a patch culled or dropped). Product code outside verify/ never includes this header; the
// umbrella verify/verify.h does not either. A test sets CheckOptions::fault (check.h) to a Fault made here:
//   CheckOptions o;
//   Fault f;
//   f.kind = Fault::Kind::DropPatch;
//   f.patch = 3;
//   o.fault = std::make_shared<const Fault>(f);
#pragma once

#include "verify/check.h"

#include <cstdint>
#include <memory>

namespace fftess::verify {

// One deliberate perturbation, applied inside checkScene, to prove that the checker sees it (the fault-injection
// suite, tests/verify/fault_injection_test.cpp). Kind::None (the default) changes nothing and costs nothing.
struct Fault {
  enum class Kind : uint8_t {
    None,
    FactorUlp,      // hull factor of (patch, edge) moved by `direction` ulps (std::nextafter), after the LOD
    FactorStep,     // hull factor of (patch, edge) plus direction * 2^-16 (one 16.16 step), in float
    PointUlp,       // world position of edge point `point` of (patch, edge): component `axis` (0 x, 1 y, 2 z)
                    // moved by one ulp towards +inf (direction > 0) or -inf, after the domain shader
    DropPatch,      // the patch is not drawn (as if the tessellator discarded it; the LOD did not cull it)
    NanFactor,      // hull factor of (patch, edge) set to NaN
    MirrorEdge,     // the edge points of (patch, edge) are taken at 1 - t instead of t (a port that walks the
                    // edge backwards); D3D's symmetric edge tessellation makes this a no-op for many factors
    NeighbourSize,  // the LOD is told that the neighbour across (patch, edge) has relative size `size`
    CullPatch,      // the LOD culls the patch (lod::Why::culled, every factor 0) as a wrong frustum test would
  };
  Kind kind = Kind::None;
  int patch = -1;       // PatchRef::index
  int edge = 0;         // FactorIndex: Ueq0 Veq0 Ueq1 Veq1
  int point = 0;        // PointUlp: index into the edge's points (0 = the edge's start corner)
  int axis = 0;         // PointUlp
  int direction = 1;    // FactorUlp, FactorStep, PointUlp: +1 or -1
  float size = 1;       // NeighbourSize: 0.5, 1 or 2
};

} // namespace fftess::verify
