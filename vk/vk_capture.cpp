// Capture of a Vulkan driver's tessellator (vk_capture.h): patches grouped by (domain, spacing), drawn in batches
// within a point budget, every captured record given to its patch by the patch id it carries. See docs/oracle.md.
#include "vk_capture.h"
#include "vk_draw.h"

#include "base/splitmix64.h"

#include <algorithm>
#include <unordered_map>

namespace fftess {
namespace oracle {

namespace {

using vk::Capture;
using vk::PipelineKey;

constexpr int kMaxPatchesPerDraw = 2048;
// Domain points per draw. Lavapipe tessellates in gallium's draw module, as llvmpipe does, which numbers a draw's
// tessellated vertices with 16 bits (each patch padded to a multiple of 4): past 65536 it captures wrong vertices
// without an error (shared facts, gl_capture.cpp). Its cost per draw also grows faster than the draw: 3000 random
// patches took 5.5 s of CPU with 60000 points per draw, 1.7 s with 8000 (1.3-1.9 s from 1000 to 8000; 2026-12-02,
// this 2-core machine, fftess's compare included). A GPU has neither limit; 200000 as tests/tools/nvidia_compare.
constexpr int kCpuDrawPointBudget = 8000;
constexpr int kGpuDrawPointBudget = 200000;
// Transform feedback room per draw, in vertices per budgeted point: a triangle list has fewer than 2 triangles per
// point (6 vertices), points and lines fewer; the stream query catches anything beyond.
constexpr int kCaptureVerticesPerPoint = 8;

// pointBound's largest value (a quad with every factor 64 or more, +1 each for the fractional rounding, padded).
constexpr int kMaxPatchPoints = 4 * 64 + 65 * 65 + 3;

int padTo4(int n) { return (n + 3) & ~3; }

// The pipeline that captures a patch's D3D output primitives (quad/tri triangles, isoline lines).
Capture primitiveCapture(const Patch& p) {
  if (p.domain == Domain::Isoline) return Capture::Lines;
  // D3D triangle_cw is SPIR-V VertexOrderCw under the pipelines' upper-left domain origin (vk_draw.cpp).
  return p.topology == Topology::TriangleCw ? Capture::TrianglesCw : Capture::TrianglesCcw;
}

// The factors in the Vulkan slot order (the same as GL's): quad outer = Ueq0 Veq0 Ueq1 Veq1, inner = insideU
// insideV; tri outer[0..2] = Ueq0 Veq0 Weq0, inner[0] = inside; isolines outer[0] = density, outer[1] = detail.
void appendSlotFactors(const Patch& p, std::vector<uint32_t>& out) {
  const uint32_t* f = p.factorBits;
  uint32_t g[vk::kFactorWords] = {0, 0, 0, 0, 0, 0};
  switch (p.domain) {
  case Domain::Quad: std::copy_n(f, 6, g); break;
  case Domain::Tri: g[0] = f[0], g[1] = f[1], g[2] = f[2], g[4] = f[3]; break;
  case Domain::Isoline: g[0] = f[0], g[1] = f[1]; break;
  }
  out.insert(out.end(), g, g + vk::kFactorWords);
}

// Permutes the primitives of one draw's records (each primitive kept whole), seeded.
void shuffleRecords(std::vector<uint32_t>& records, int verticesPerPrimitive, SplitMix64& rng) {
  const size_t words = static_cast<size_t>(verticesPerPrimitive) * vk::kRecordWords;
  const size_t n = records.size() / words;
  for (size_t i = n; i > 1; --i) {
    const size_t j = rng.below(i);
    std::swap_ranges(records.begin() + static_cast<std::ptrdiff_t>((i - 1) * words),
                     records.begin() + static_cast<std::ptrdiff_t>(i * words),
                     records.begin() + static_cast<std::ptrdiff_t>(j * words));
  }
}

// Result::indices of captured primitives: each vertex's position in the point array, found by its coordinates;
// left empty when two points share coordinates or a vertex is not a point.
void deriveIndices(Result& r) {
  std::unordered_map<uint64_t, int32_t> at;
  for (int k = 0; k < r.pointCount(); ++k)
    if (!at.emplace(uint64_t(r.points[2 * k]) << 32 | r.points[2 * k + 1], k).second) return;
  std::vector<int32_t> indices;
  indices.reserve(r.primitives.size() / 2);
  for (size_t v = 0; v + 1 < r.primitives.size(); v += 2) {
    auto it = at.find(uint64_t(r.primitives[v]) << 32 | r.primitives[v + 1]);
    if (it == at.end()) return;
    indices.push_back(it->second);
  }
  r.indices = std::move(indices);
}

} // namespace

struct VkOracle::Impl {
  vk::Device device;
  vk::Drawer drawer{device}; // after 'device': destroyed before it
  int drawPointBudget = kCpuDrawPointBudget;
  uint64_t shuffleSeed = 0; // setRecordShuffle
  SplitMix64 shuffle{0};
  std::vector<uint32_t> factors, records;

  // Draws the patches sel[0..) through 'key' in batches (at most kMaxPatchesPerDraw, the sum of their padded
  // weights within the point budget), each captured vertex appended to its patch's points (Points) or primitives.
  bool drawAll(const std::vector<Patch>& patches, const std::vector<int>& sel, const std::vector<int>& weights,
               const PipelineKey& key, std::vector<Result>& results, std::string& error);
  // The records of one draw of sel[begin, end) given to their patches; false on a record the draw cannot have made.
  bool distribute(const std::vector<int>& sel, int begin, int end, Capture capture, std::vector<Result>& results,
                  std::string& error);
  bool runGroup(const std::vector<Patch>& patches, const std::vector<int>& members, std::vector<Result>& results,
                std::string& error);
};

VkOracle::VkOracle() : impl_(new Impl) {}
VkOracle::~VkOracle() = default;

std::unique_ptr<VkOracle> VkOracle::create(std::string& error, bool hardwareFirst) {
  std::unique_ptr<VkOracle> o(new VkOracle);
  Impl& m = *o->impl_;
  vk::Requirements req;
  req.captureBytes = VkDeviceSize(kCaptureVerticesPerPoint) * std::max(kGpuDrawPointBudget, kMaxPatchPoints) *
                     vk::kRecordWords * 4;
  if (!m.device.create(hardwareFirst, req, error)) return nullptr;
  m.drawPointBudget = m.device.isCpu() ? kCpuDrawPointBudget : kGpuDrawPointBudget;
  // A draw takes at least one patch whatever its weight: room for the largest patch even past the budget.
  const int points = std::max(m.drawPointBudget, kMaxPatchPoints);
  if (!m.drawer.create(kMaxPatchesPerDraw, kCaptureVerticesPerPoint * points, error)) return nullptr;
  return o;
}

const std::string& VkOracle::renderer() const { return impl_->device.name(); }
const std::string& VkOracle::version() const { return impl_->device.version(); }
bool VkOracle::isCpu() const { return impl_->device.isCpu(); }
int VkOracle::drawCalls() const { return impl_->drawer.drawCalls; }
void VkOracle::setRecordShuffle(uint64_t seed) { impl_->shuffleSeed = seed, impl_->shuffle = SplitMix64{seed}; }

bool VkOracle::Impl::drawAll(const std::vector<Patch>& patches, const std::vector<int>& sel,
                             const std::vector<int>& weights, const PipelineKey& key, std::vector<Result>& results,
                             std::string& error) {
  const int n = static_cast<int>(sel.size());
  for (int begin = 0; begin < n;) {
    int end = begin, budget = 0;
    factors.clear();
    while (end < n && end - begin < kMaxPatchesPerDraw &&
           (end == begin || budget + padTo4(weights[end]) <= drawPointBudget)) {
      budget += padTo4(weights[end]);
      appendSlotFactors(patches[sel[end++]], factors);
    }
    const int room = kCaptureVerticesPerPoint * std::max(budget, 4);
    if (!drawer.draw(key, factors.data(), end - begin, room, records, error)) return false;
    if (shuffleSeed) shuffleRecords(records, vk::verticesPerRecord(key.capture), shuffle);
    if (!distribute(sel, begin, end, key.capture, results, error)) return false;
    begin = end;
  }
  return true;
}

bool VkOracle::Impl::distribute(const std::vector<int>& sel, int begin, int end, Capture capture,
                                std::vector<Result>& results, std::string& error) {
  const int per = vk::verticesPerRecord(capture);
  const size_t primWords = static_cast<size_t>(per) * vk::kRecordWords;
  const uint32_t count = static_cast<uint32_t>(end - begin);
  for (size_t v = 0; v + primWords <= records.size(); v += primWords) {
    const uint32_t local = records[v + 2];
    if (local >= count) {
      error = "a captured vertex names patch " + std::to_string(local) + " of a draw of " + std::to_string(count) +
              " patches (gl_PrimitiveID out of range)";
      return false;
    }
    for (int k = 1; k < per; ++k)
      if (records[v + static_cast<size_t>(k) * vk::kRecordWords + 2] != local) {
        error = "a captured primitive has vertices of different patches (gl_PrimitiveID " + std::to_string(local) +
                " and " + std::to_string(records[v + static_cast<size_t>(k) * vk::kRecordWords + 2]) + ")";
        return false;
      }
    Result& r = results[sel[begin + static_cast<int>(local)]];
    std::vector<uint32_t>& out = capture == Capture::Points ? r.points : r.primitives;
    for (int k = 0; k < per; ++k) {
      out.push_back(records[v + static_cast<size_t>(k) * vk::kRecordWords]);
      out.push_back(records[v + static_cast<size_t>(k) * vk::kRecordWords + 1]);
    }
  }
  return true;
}

bool VkOracle::Impl::runGroup(const std::vector<Patch>& patches, const std::vector<int>& members,
                              std::vector<Result>& results, std::string& error) {
  const Patch& first = patches[members[0]];
  const int spacing = glSpacing(first.partitioning);
  std::vector<int> bounds;
  for (int i : members) bounds.push_back(pointBound(patches[i]));
  if (!drawAll(patches, members, bounds, PipelineKey{first.domain, spacing, Capture::Points}, results, error))
    return false;
  for (size_t j = 0; j < members.size(); ++j)
    if (results[members[j]].pointCount() > bounds[j]) {
      error = "patch '" + batchLine(patches[members[j]]) + "' gave " +
              std::to_string(results[members[j]].pointCount()) + " points, above the harness bound " +
              std::to_string(bounds[j]) + " (the per-draw limit is unsafe)";
      return false;
    }
  // Point and quad/tri line outputs have no Vulkan primitive: derived from the point array (as GlOracle does).
  std::vector<int> prim;
  for (int i : members) {
    const Patch& p = patches[i];
    Result& r = results[i];
    if (p.topology == Topology::Point) {
      r.verticesPerPrimitive = 1;
      for (int k = 0; k < r.pointCount(); ++k) r.indices.push_back(k);
    } else if (p.topology == Topology::Line && p.domain != Domain::Isoline) {
      r.verticesPerPrimitive = 2;
      for (int k = 0; k + 1 < r.pointCount(); ++k) r.indices.push_back(k), r.indices.push_back(k + 1);
    } else {
      prim.push_back(i);
    }
  }
  for (Capture c : {Capture::TrianglesCw, Capture::TrianglesCcw, Capture::Lines}) {
    std::vector<int> sel, weights;
    for (int i : prim)
      if (primitiveCapture(patches[i]) == c) sel.push_back(i), weights.push_back(results[i].pointCount());
    if (sel.empty()) continue;
    if (!drawAll(patches, sel, weights, PipelineKey{first.domain, spacing, c}, results, error)) return false;
    for (int i : sel) {
      results[i].verticesPerPrimitive = vk::verticesPerRecord(c);
      deriveIndices(results[i]);
    }
  }
  return true;
}

bool VkOracle::run(const std::vector<Patch>& patches, std::vector<Result>& results, std::string& error) {
  results.assign(patches.size(), Result{});
  impl_->drawer.drawCalls = 0;
  // Grouped by domain and spacing: one pipeline per capture of a group.
  std::map<std::pair<int, int>, std::vector<int>> groups;
  for (size_t i = 0; i < patches.size(); ++i)
    groups[{static_cast<int>(patches[i].domain), glSpacing(patches[i].partitioning)}].push_back(static_cast<int>(i));
  for (auto& kv : groups)
    if (!impl_->runGroup(patches, kv.second, results, error)) return false;
  return true;
}

} // namespace oracle
} // namespace fftess
