// What accuracy costs in time, tessellator side: full tessellation vs points only vs the edge query vs the trace,
// hw vs HLSL stage, uniform vs terrain-like factors, and issue 11's cases (a) and (b) (bench/cases.h).
// Run: fftess bench --micro [--benchmark_filter=REGEX].
#include "tessellator/names.h"
#include "tessellator/tessellator.h"
#include "tessellator/trace.h"

#include "bench/cases.h"

#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

namespace {

using namespace fftess;

Partitioning partitioningArg(int64_t i) {
  static const Partitioning p[] = {Partitioning::Integer, Partitioning::Pow2, Partitioning::FractionalOdd,
                                   Partitioning::FractionalEven};
  return p[i];
}

void setLabel(benchmark::State& state, Partitioning p, float f) {
  state.SetLabel(std::string(toString(p)) + " factor " + std::to_string(f));
}

// Full quad tessellation (points and triangles), every factor equal.
void BM_TessellateQuad(benchmark::State& state) {
  const Partitioning part = partitioningArg(state.range(0));
  const float f = static_cast<float>(state.range(1)) + (part == Partitioning::FractionalOdd ? 0.5f : 0.0f);
  Patch p;
  p.partitioning = part;
  p.primitive = static_cast<OutputPrimitive>(state.range(2));
  for (float& x : p.factors) x = f;
  Tessellator t;
  int64_t points = 0;
  for (auto _ : state) {
    points += t.tessellate(p);
    benchmark::DoNotOptimize(t.indices().data());
  }
  state.SetItemsProcessed(points);
  state.counters["patches/s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  setLabel(state, part, f);
}
// args: partitioning, factor, primitive (0 point, 2 triangle_cw)
BENCHMARK(BM_TessellateQuad)
    ->ArgsProduct({{0, 2, 3}, {4, 16, 64}, {2}})
    ->ArgsProduct({{0}, {64}, {0}})
    ->ArgNames({"part", "factor", "prim"});

// Terrain-like: factors spread 1..16 with fractional parts, fractional_even (the NVIDIA sample's setting).
void BM_TessellateQuadTerrainLike(benchmark::State& state) {
  std::vector<Patch> patches(256);
  uint32_t s = 12345;
  auto rnd = [&] { s = s * 1664525u + 1013904223u; return static_cast<float>(s >> 8) / 16777216.0f; };
  for (Patch& p : patches) {
    p.partitioning = Partitioning::FractionalEven;
    p.primitive = state.range(0) ? OutputPrimitive::TriangleCw : OutputPrimitive::Point;
    for (float& x : p.factors) x = 1.0f + 15.0f * rnd();
  }
  Tessellator t;
  size_t i = 0;
  int64_t points = 0;
  for (auto _ : state) {
    points += t.tessellate(patches[i++ & 255]);
    benchmark::DoNotOptimize(t.points().data());
  }
  state.SetItemsProcessed(points);
  state.counters["patches/s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_TessellateQuadTerrainLike)->Arg(0)->Arg(1)->ArgName("triangles");

// The HLSL stage (preconditioning) alone, and HLSL + hardware stage.
void BM_HlslFactorsOnly(benchmark::State& state) {
  const float f[6] = {13.7f, 5.2f, 33.1f, 7.9f, 1.0f, 1.0f};
  Stage st;
  st.hlsl = true;
  for (auto _ : state) benchmark::DoNotOptimize(processHlslFactors(Domain::Quad, Partitioning::Pow2, st, f));
}
BENCHMARK(BM_HlslFactorsOnly);

void BM_TessellateQuadStage(benchmark::State& state) {
  Patch p;
  p.partitioning = Partitioning::FractionalOdd;
  p.stage.hlsl = state.range(0) != 0;
  const float f[6] = {13.7f, 5.2f, 33.1f, 7.9f, 1.0f, 1.0f};
  for (int i = 0; i < 6; ++i) p.factors[i] = f[i];
  if (!p.stage.hlsl) p.factors[4] = p.factors[5] = 20.0f;
  Tessellator t;
  for (auto _ : state) benchmark::DoNotOptimize(t.tessellate(p));
}
BENCHMARK(BM_TessellateQuadStage)->Arg(0)->Arg(1)->ArgName("hlsl");

// One outer edge only: what the crack verifier pays per edge instead of a full patch.
void BM_EdgePoints(benchmark::State& state) {
  const Partitioning part = partitioningArg(state.range(0));
  const float f = static_cast<float>(state.range(1)) + 0.3f;
  for (auto _ : state) benchmark::DoNotOptimize(edgePoints(f, part));
  setLabel(state, part, f);
}
BENCHMARK(BM_EdgePoints)->ArgsProduct({{0, 3}, {4, 64}})->ArgNames({"part", "factor"});

// The edge trace behind `fftess explain`.
void BM_TraceEdge(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(traceEdge(44.0f, Partitioning::Integer));
}
BENCHMARK(BM_TraceEdge);

// Issue 11's two cases, the whole patch set per iteration through one Tessellator (outputs written into its
// buffers). Compare with Microsoft's reference side by side as docs/tessellator.md describes.
void runCase(benchmark::State& state, const std::vector<Patch>& patches) {
  Tessellator t;
  int64_t points = 0;
  for (auto _ : state) {
    for (const Patch& p : patches) {
      points += t.tessellate(p);
      benchmark::DoNotOptimize(t.indices().data());
    }
    benchmark::ClobberMemory();
  }
  const double n = static_cast<double>(state.iterations()) * static_cast<double>(patches.size());
  state.counters["patches/s"] = benchmark::Counter(n, benchmark::Counter::kIsRate);
  state.counters["points/s"] = benchmark::Counter(static_cast<double>(points), benchmark::Counter::kIsRate);
}

// (a) 2,000 quad integer triangle_cw hw patches, all six factors 64.
void BM_case_a_quad_integer_64(benchmark::State& state) { runCase(state, bench::caseA()); }
BENCHMARK(BM_case_a_quad_integer_64)->Unit(benchmark::kMillisecond);

// (b) 20,000 quad fractional_even triangle_cw hw patches, factors uniform in [1,16] (splitmix64, bench/cases.h).
void BM_case_b_quad_fractional_even_1_16(benchmark::State& state) { runCase(state, bench::caseB()); }
BENCHMARK(BM_case_b_quad_fractional_even_1_16)->Unit(benchmark::kMillisecond);

} // namespace
