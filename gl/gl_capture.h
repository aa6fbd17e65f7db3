// fftess GL oracle: captures what a real OpenGL tessellator (Mesa's llvmpipe, which runs Microsoft's D3D11
// reference tessellator inside) produces for D3D11 hardware-stage patches.
//
// Independent of the fftess emulator on purpose: its own patch types, its own batch parser, no link to
// fftess_tessellator. See docs/oracle.md for what is observed, what is rebuilt, and what is compared.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace fftess {
namespace oracle {

enum class Domain : uint8_t { Quad, Tri, Isoline };
enum class Partitioning : uint8_t { Integer, Pow2, FractionalOdd, FractionalEven };
enum class Topology : uint8_t { Point, Line, TriangleCw, TriangleCcw };

// One hardware-stage patch. Factors as IEEE-754 bits, in the batch order:
//   quad: Ueq0 Veq0 Ueq1 Veq1 insideU insideV; tri: Ueq0 Veq0 Weq0 inside; isoline: density detail.
struct Patch {
  Domain domain = Domain::Quad;
  Partitioning partitioning = Partitioning::Integer;
  Topology topology = Topology::TriangleCw;
  uint32_t factorBits[6] = {0x3f800000u, 0x3f800000u, 0x3f800000u, 0x3f800000u, 0x3f800000u, 0x3f800000u};
};

// What the oracle gives back for one patch, in the batch output format's terms.
//   points:  the domain points, 2 words (u bits, v bits) per point, in the order the tessellator emits them
//            (observed: a point_mode draw captures one vertex per domain point, in order).
//   indices: CaptureOrder::Strict: TriangleCw/Ccw and isoline Line: the primitive list (observed: vertex ids numbered
//            by the TES invocation order, cross-checked against the point array, see docs/oracle.md); Point: 0..P-1;
//            quad/tri Line: (i, i+1) for consecutive points (D3D's "points joined in generation order"; GL has no
//            such topology, so it is derived from the observed point array, not observed).
//            CaptureOrder::Free: TriangleCw/Ccw and isoline Line: each primitive vertex's index in the point array
//            found by its coordinates, where that is unambiguous (records::indicesByCoordinates), else empty; Point:
//            0..P-1; quad/tri Line: empty (the generation order is not observable without an order assumption).
//   primitives: the observed primitives as coordinates, (u,v) bits per vertex, vertices per primitive = 3 for
//            triangles, 2 for isoline lines (empty for Point and quad/tri Line). Independent of the vertex ids.
//            Strict: in the driver's primitive order; Free: grouped by patch, in the order the driver wrote them.
struct Result {
  std::vector<uint32_t> points;
  std::vector<int32_t> indices;
  std::vector<uint32_t> primitives;
  int verticesPerPrimitive = 1;
  int pointCount() const { return static_cast<int>(points.size() / 2); }
};

// How run() relates the captured records to patches and points.
enum class CaptureOrder : uint8_t {
  // The reference's order (llvmpipe): records in gl_PrimitiveID order, the TES run once per point in point_mode
  // order, vertex ids observed and cross-checked (every check of docs/oracle.md). A driver that emits in its own
  // order fails the run (GlOracle::orderMismatch()). The oracle tests need it (index arrays as observed).
  Strict,
  // Any driver: records grouped by patch id whatever their order (a patch id outside the draw is still an error),
  // primitives kept as coordinates, no vertex ids and no point matching (what tests/tools/nvidia_compare does).
  Free,
};

struct RunOptions {
  CaptureOrder order = CaptureOrder::Strict;
  // Test hook, 0 = off: each draw's records are permuted (seeded by this and the draw's number) and each triangle
  // rotated to another first vertex before they are grouped, as a driver with its own order would emit them
  // (records::permute). Free gives the same multisets; Strict fails with orderMismatch().
  uint64_t permuteSeed = 0;
};

// Headless OpenGL 4.5 core context (EGL device platform, else surfaceless Mesa) with the programs and buffers the
// capture needs. Not thread-safe; one per thread.
class GlOracle {
public:
  ~GlOracle();
  GlOracle(const GlOracle&) = delete;
  GlOracle& operator=(const GlOracle&) = delete;

  // Creates the context. Returns null and sets 'error' (what failed, with the EGL/GL error) when impossible.
  // hardwareFirst: EGL devices that are not Mesa's software device first (a GPU), then the software ones (the
  // default order is llvmpipe first: the oracle).
  static std::unique_ptr<GlOracle> create(std::string& error, bool hardwareFirst = false);

  // GL_RENDERER / GL_VERSION of the context (e.g. "llvmpipe (LLVM 15.0.6, 256 bits)").
  const std::string& renderer() const { return renderer_; }
  const std::string& version() const { return version_; }
  bool isLlvmpipe() const { return renderer_.find("llvmpipe") != std::string::npos; }

  // Tessellates every patch; results[i] belongs to patches[i]. Returns false and sets 'error' if the driver did
  // something the harness cannot trust (GL error, transform feedback overflow, a record naming a patch outside its
  // draw, more points than the bound; Strict also: a vertex id that does not match the observed point array, ...).
  // Patches are grouped per program and drawn many per draw call. options.order: see CaptureOrder (default Strict).
  bool run(const std::vector<Patch>& patches, std::vector<Result>& results, std::string& error,
           const RunOptions& options = {});

  // True when the last run() failed because the driver does not emit in the reference order (Strict only: records
  // out of patch order, the TES not once per point in point order, a vertex id that does not match its point).
  bool orderMismatch() const;

  // Statistics of the last run().
  int drawCalls() const;
  // Domain points per draw (by pointBound): 60,000 on Mesa's software renderers (llvmpipe numbers a draw's vertices
  // with 16 bits), 200,000 on other drivers (as tests/tools/nvidia_compare on NVIDIA).
  int drawPointBudget() const;

  struct Impl;

private:
  GlOracle();
  std::unique_ptr<Impl> impl_;
  std::string renderer_;
  std::string version_;
};

// ---- batch format (shared with the CLI's `tessellate --format hex`; parsed here independently) ----

struct BatchLine {
  Patch patch;
  int lineNumber = 0;
};

// Parses the whole batch text. Blank lines and '#' comments are ignored. Only stage "hw" is accepted: a hardware
// oracle has no HLSL stage. On error returns false and sets 'error' to "line N: ..." naming the bad token.
bool parseBatch(const std::string& text, std::vector<BatchLine>& out, std::string& error);

// Appends one patch block in the golden .out format ("patch N points P indices I", P lines of "uuuuuuuu vvvvvvvv",
// then the indices: 3 per line for triangles, 2 for lines, 1 for points).
void writePatchBlock(std::string& out, int patchNumber, const Patch& patch, const Result& result);

const char* toString(Domain d);
const char* toString(Partitioning p);
const char* toString(Topology t);

// "quad integer triangle_cw hw 0x........ x6": the batch line for a patch (to reproduce a failure).
std::string batchLine(const Patch& patch);

// Number of indices per output line / per primitive in the format: 3 triangles, 2 lines (isoline line and quad/tri
// line), 1 points.
int indicesPerPrimitive(const Patch& patch);

// Conservative number of domain points of a patch, never underestimated: each edge's segments from its factor
// clamped to [.., 64] (NaN and +Inf as 64), +1 for the rounding of the fractional partitionings, at least 2; 0 for a
// patch GL must discard (a used outer factor <= 0 or NaN, GL 4.5 section 11.2.2). Sizes the draws of a capture.
int pointBound(const Patch& patch);

// The GL spacing a partitioning maps to at the hardware stage: 0 equal_spacing (integer, pow2: D3D11.3 spec 11.7),
// 1 fractional_odd_spacing, 2 fractional_even_spacing.
int glSpacing(Partitioning p);

// True when GL draws this patch's output primitives (quad/tri triangle_cw/ccw, isoline line); otherwise GL only
// gives the point array and the indices are derived from it.
bool hasGlPrimitives(const Patch& patch);

} // namespace oracle
} // namespace fftess
