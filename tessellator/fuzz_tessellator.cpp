// libFuzzer target: any 29 bytes are a patch (domain, partitioning, primitive, stage, six raw float factors, option).
// Checks what must hold for every input: no crash or sanitizer report, sizes equal the closed-form counts, indices
// in range, coordinates in [0,1], every outer edge equal to the edge query.
// Build: cmake -S . -B build-fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DFFTESS_FUZZ=ON
//        cmake --build build-fuzz --target fuzz_tessellator && build-fuzz/tessellator/fuzz_tessellator -max_total_time=60
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "names.h"
#include "tessellator.h"

using namespace fftess;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 29) return 0;
  static Tessellator t;
  Patch p;
  p.domain = Domain(data[0] % 3);
  p.partitioning = Partitioning(data[1] % 4);
  p.primitive = OutputPrimitive(data[2] % 4);
  const std::vector<std::string>& stages = stageNames();
  parseStage(stages[data[3] % stages.size()].c_str(), p.stage);
  std::memcpy(p.factors, data + 4, sizeof p.factors);
  Options o;
  o.flushDenormals = data[28] & 1;
  const int n = t.tessellate(p, o);
  const OutputCounts c = outputCounts(p, o);
  if (n != c.points || int(t.indices().size()) != c.indices) std::abort();
  for (int32_t i : t.indices())
    if (i < 0 || i >= n) std::abort();
  for (const DomainPoint& q : t.points())
    if (!(q.u >= 0 && q.u <= 1 && q.v >= 0 && q.v <= 1)) std::abort();
  if (n > 0 && p.domain != Domain::Isoline) {
    const int edges = p.domain == Domain::Quad ? 4 : 3;
    for (int e = 0; e < edges; ++e) {
      const EdgePoints ep = edgePoints(p.factors[e], p.partitioning, p.stage, o);
      if (ep.culled || ep.count < 2 || ep.fixed[0] != 0 || ep.fixed[ep.count - 1] != 0x10000) std::abort();
    }
  }
  return 0;
}
