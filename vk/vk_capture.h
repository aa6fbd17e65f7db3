// fftess Vulkan oracle: captures what a Vulkan driver's tessellator produces for D3D11 hardware-stage patches, the
// Vulkan twin of gl/gl_capture.h's GlOracle (same Patch and Result types). Lavapipe (Mesa's CPU Vulkan driver) runs
// the same reference tessellator as llvmpipe; on a GPU this is the tessellator that DXVK and vkd3d-proton run D3D
// hull and domain shaders on. See docs/oracle.md "Vulkan" and docs/compare.md "Vulkan".
//
// Headless (no surface): VK_EXT_transform_feedback with rasterizer discard, factors as raw bits from a storage
// buffer in the tessellation control shader. Order-free: no assumption on the order in which the driver emits
// patches, points or primitives; records are grouped by patch id (gl_PrimitiveID within the draw).
#pragma once

#include "gl/gl_capture.h" // oracle::Patch, Result, pointBound, glSpacing, batchLine

#include <memory>
#include <string>
#include <vector>

namespace fftess {
namespace oracle {

class VkOracle {
public:
  ~VkOracle();
  VkOracle(const VkOracle&) = delete;
  VkOracle& operator=(const VkOracle&) = delete;

  // Creates the Vulkan device, pipelines on demand. Returns null and sets 'error' (the Vulkan call and its VkResult,
  // or why no device fits) when impossible. hardwareFirst: devices that are not VK_PHYSICAL_DEVICE_TYPE_CPU first (a
  // GPU), then the CPU ones; default: the CPU ones (lavapipe, the reference) first.
  static std::unique_ptr<VkOracle> create(std::string& error, bool hardwareFirst = false);

  // The device's name (e.g. "llvmpipe (LLVM 15.0.6, 256 bits)", "NVIDIA H200") and "Vulkan A.B.C, DRIVER INFO".
  const std::string& renderer() const;
  const std::string& version() const;
  bool isCpu() const; // VK_PHYSICAL_DEVICE_TYPE_CPU: lavapipe

  // Tessellates every patch; results[i] belongs to patches[i]:
  //   points: the domain points of a point_mode draw, in the order the driver emitted them for that patch;
  //   primitives (quad/tri triangle_cw/ccw, isoline line): the driver's primitives as coordinates, in its order, the
  //     vertices of each in the driver's order under the D3D winding mapping (vk_capture.cpp: the domain origin);
  //   indices: Point 0..P-1; quad/tri Line (i, i+1) of the point array as GL gives them (D3D joins the points in
  //     generation order; Vulkan has no such output); triangles and isoline lines: each vertex looked up in the
  //     point array by its coordinates when that is unambiguous (all points distinct, every vertex found), else
  //     empty.
  // Returns false and sets 'error' when the driver did something the harness cannot trust (a Vulkan error, a
  // transform feedback overflow, a record with a patch id outside its draw, more points than the bound).
  bool run(const std::vector<Patch>& patches, std::vector<Result>& results, std::string& error);

  int drawCalls() const; // of the last run()

  // Test hook for the order-free grouping: with a seed other than 0, each draw's captured primitives (points, lines,
  // triangles, each kept whole) are permuted (seeded Fisher-Yates, base/splitmix64.h) before they are given to their
  // patches, as a driver with another emission order would give them. 0 (the default): the driver's order.
  void setRecordShuffle(uint64_t seed);

  struct Impl;

private:
  VkOracle();
  std::unique_ptr<Impl> impl_;
};

} // namespace oracle
} // namespace fftess
