// fftess tessellator: a bit-exact CPU emulator of the Direct3D 11 fixed-function tessellator.
//
// This header is the contract of the module (standard library only).
//
// Two stages, both public:
//   * the hardware stage ("hw"): tessellation factors exactly as a hull shader hands them to the fixed-function
//     unit (D3D11.3 functional spec, section 11.7); clamping, culling, rounding, parity and 16.16 fixed-point
//     placement happen here;
//   * the HLSL stage: the tess-factor preconditioning that the HLSL compiler inserts at the end of a hull shader
//     (ProcessQuadTessFactorsAvg/Min/Max, ProcessTriTessFactors*, ProcessIsolineTessFactors): inside-factor
//     reduction, inside scale, pow2 / integer rounding, "picture frame" rules. It returns rounded and unrounded
//     factors and then runs the hardware stage.
//
// "Bit-exact" means: the same u/v float bits in the same order, and the same index array, as Microsoft's D3D11
// reference tessellator (CHWTessellator / CHLSLTessellator), for every float input including NaN, +-Inf, +-0,
// denormals, negatives and values above 64. See docs/tessellator.md for the list of surprising inputs.
//
// Buffers: Tessellator owns reusable output buffers sized for the largest patch once, at construction; tessellating
// a patch allocates nothing, except that each thread keeps index templates of recent patch shapes, each slot
// allocated once on first use (at most ~4.5 MB per thread). Edge queries and traces return fixed-size values (no
// allocation at all). Many patches on several threads into caller-owned arrays: tessellator/parallel.h.
//
// Beside the contract, in their own headers: tessellator/names.h (the batch-format names of the enums, parsing and
// printing), tessellator/trace.h (every 16.16 step of one outer edge, for `fftess explain`),
// tessellator/edge_analysis.h (an edge beside two half-length edges: where and why they do not meet) and
// tessellator/batch.h (the batch text format).
#pragma once

#include <cstdint>
#include <vector>

namespace fftess {

enum class Domain : uint8_t { Quad, Tri, Isoline };
enum class Partitioning : uint8_t { Integer, Pow2, FractionalOdd, FractionalEven };
enum class OutputPrimitive : uint8_t { Point, Line, TriangleCw, TriangleCcw };

// Inside-factor reduction of the HLSL stage (ProcessQuadTessFactors{Min,Max,Avg}).
enum class Reduction : uint8_t { Min, Max, Average };
// Quad only: reduce all four edges into one inside factor (OneAxis) or Ueq0/Ueq1 and Veq0/Veq1 separately (TwoAxis).
enum class ReductionAxes : uint8_t { OneAxis, TwoAxis };

// Which stage the factors enter. Hw: the fixed-function unit only. Hlsl: preconditioning, then the hardware stage.
struct Stage {
  bool hlsl = false;
  Reduction reduction = Reduction::Average;    // hlsl only
  ReductionAxes axes = ReductionAxes::TwoAxis; // hlsl + quad only
};

// Factor order, in D3D's words:
//   quad:    Ueq0 Veq0 Ueq1 Veq1 insideU insideV     (hlsl stage: the last two are the inside scales, 0..1)
//   tri:     Ueq0 Veq0 Weq0 inside                    (hlsl stage: inside scale; factors[4..5] ignored)
//   isoline: density detail                           (line count along v, segments per line along u; rest ignored)
// Note: HLSL's ProcessIsolineTessFactors takes (detail, density); fftess always takes density first.
enum FactorIndex : int { Ueq0 = 0, Veq0 = 1, Ueq1 = 2, Veq1 = 3, InsideU = 4, InsideV = 5 };
enum TriFactorIndex : int { TriUeq0 = 0, TriVeq0 = 1, TriWeq0 = 2, TriInside = 3 };
enum IsolineFactorIndex : int { IsolineDensity = 0, IsolineDetail = 1 };

struct Patch {
  Domain domain = Domain::Quad;
  Partitioning partitioning = Partitioning::Integer;
  OutputPrimitive primitive = OutputPrimitive::TriangleCw;
  Stage stage{};
  float factors[6] = {1, 1, 1, 1, 1, 1};
};

struct Options {
  // Flush denormal inputs to (signed) zero before anything else. Off by default = exactly the reference, where a
  // positive denormal outer factor is not culled (measured: NVIDIA hardware agrees). On = what Mesa's llvmpipe
  // does (the patch is culled).
  bool flushDenormals = false;
};

struct DomainPoint {
  float u;
  float v; // tri: w = 1 - u - v is the caller's to compute
};

// The six factors after the HLSL stage: 'rounded' are handed to the hardware stage, 'unrounded' are the values
// after clamping but before pow2/integer rounding (what engines use for geomorphing). Same factor order as Patch.
// A culled patch (an edge factor not > 0) gives rounded = 0 and unrounded = the raw edge factors, as HLSL does.
struct HlslFactors {
  float rounded[6] = {0, 0, 0, 0, 0, 0};
  float unrounded[6] = {0, 0, 0, 0, 0, 0};
};

// Runs only the HLSL preconditioning of the given domain and partitioning. factors as in Patch.
// domain: any; stage.reduction / stage.axes select the HLSL intrinsic; options.flushDenormals applies to inputs.
HlslFactors processHlslFactors(Domain domain, Partitioning partitioning, const Stage& stage, const float factors[6],
                               const Options& options = {});

// The largest outputs of one patch (quad, every factor 64).
constexpr int kMaxPoints = 65 * 65;
constexpr int kMaxIndices = 64 * 64 * 2 * 3;

// Tessellates patches into its own reusable buffers.
// tessellate() replaces the previous result; points() / indices() stay valid until the next call.
// Topology of the result:
//   TriangleCw / TriangleCcw: 3 indices per triangle; Ccw is Cw with the 2nd and 3rd index of each triangle swapped.
//   Line (quad, tri): the points joined in generation order (2 indices per segment), as the reference does.
//   Line (isoline): 2 indices per segment of each isoline. Point: one index per point.
//   A culled patch yields no points and no indices.
class Tessellator {
public:
  Tessellator();

  // patch: any values (NaN, Inf, denormals, negatives: all defined). Returns the number of points.
  int tessellate(const Patch& patch, const Options& options = {});

  const std::vector<DomainPoint>& points() const { return points_; }
  const std::vector<int32_t>& indices() const { return indices_; }
  // Factors after the HLSL stage of the last call (all zero after a hw-stage call).
  const HlslFactors& hlslFactors() const { return hlsl_; }

private:
  std::vector<DomainPoint> points_;
  std::vector<int32_t> indices_;
  HlslFactors hlsl_;
};

// ---------------------------------------------------------------------------------------------------------------
// Edge query: the points along one outer edge, without tessellating the rest of the patch.
//
// D3D11.3 spec 11.7: each outer edge's points depend only on that edge's factor and the partitioning, and are
// symmetric about the edge's midpoint. So an edge is fully described by (factor, partitioning, stage).
// The returned parameters are in increasing order from 0 to 1, both endpoints included, and bitwise equal to the
// coordinates the full tessellation gives the points of that edge (quad Ueq0: v of the points with u == 0, ...).
// The culling of the whole patch (any outer factor not > 0) is reported but the other edges are not known here:
// a caller checking a patch must look at all its outer factors.
// For the quad/tri HLSL stage, an edge's factor goes through the same per-edge preconditioning (clean up to >= 1,
// pow2/integer rounding, clamp) as in processHlslFactors; inside factors never move an outer edge.
constexpr int kMaxEdgePoints = 65;

struct EdgePoints {
  bool culled = false;         // factor not > 0 (NaN, +-0, negative, -Inf): the whole patch would be culled
  float processedFactor = 0;   // factor as the fixed-function unit uses it (after clamp, and ceil for integer/pow2)
  uint32_t fixedFactor = 0;    // processedFactor in 16.16
  bool oddParity = false;      // parity the edge is placed with (integer/pow2: from the factor's integer value)
  int count = 0;               // number of points, both endpoints included (0 when culled)
  uint32_t fixed[kMaxEdgePoints] = {}; // 16.16 parameter along the edge, fixed[0] = 0, fixed[count-1] = 0x10000
  float param[kMaxEdgePoints] = {};    // the same as floats, exactly as the tessellator outputs them
};

// factor: any float. partitioning: any. stage: hw or hlsl (reduction/axes are irrelevant to outer edges).
// Domain::Isoline is not an edge domain: use Quad or Tri semantics (identical for outer edges).
EdgePoints edgePoints(float factor, Partitioning partitioning, const Stage& stage = {}, const Options& options = {});
// edgePoints(...).culled without placing the points (the same stages, the same rule): whether the patch this outer
// edge factor belongs to is discarded. Same parameter constraints as edgePoints.
bool edgeCulled(float factor, Partitioning partitioning, const Stage& stage = {}, const Options& options = {});

// Closed-form output sizes, independent of the tessellation code (used by the invariant tests and for buffer
// planning): the number of points and indices tessellate() produces for this patch.
struct OutputCounts {
  int points = 0;
  int indices = 0;
};
OutputCounts outputCounts(const Patch& patch, const Options& options = {});

} // namespace fftess
