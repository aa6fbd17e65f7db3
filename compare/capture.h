// fftess capture: reading another tessellator's output ("a capture") patch by patch, in bounded memory.
//
// Two formats (docs/compare.md):
//   * hex blocks, exactly as `fftess tessellate --format hex` writes them and as shared/golden/*.out hold them:
//       patch N points P indices I / P lines "UUUUUUUU VVVVVVVV" / the I indices, 1, 2 or 3 per line (kept as
//       CapturedPatch::indices: the capture's own numbering, for the report);
//   * CSV, one vertex per row: patch,primitive,vertex,u,v[,w]
//       patch: 0-based patch number in the batch file; primitive: 0-based within the patch; vertex: 0-based within
//       the primitive (0..2 triangles, 0..1 segments, 0 points); u, v (and w, read and ignored): decimal floats or
//       0x + 8 hex digits (IEEE-754 bits). An optional header line (first field not a number), blank lines and
//       lines starting with '#' are skipped. Rows of one patch are contiguous, patches in increasing order; rows of
//       a patch may come in any order. A patch with no rows is a patch the port culled. A capture of point lists
//       (every vertex 0) may be compared with any topology: then the points are compared, not the primitives.
//
// Standard library only. Errors are thrown as CaptureError with "FILE:LINE: reason" (the caller's exit status 2).
#pragma once

#include <cstdint>
#include <istream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fftess {

struct CaptureError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class CaptureFormat : uint8_t { Auto, Hex, Csv };

// One vertex as float bits.
struct CapturedVertex {
  uint32_t u = 0;
  uint32_t v = 0;
};
inline bool operator==(CapturedVertex a, CapturedVertex b) { return a.u == b.u && a.v == b.v; }
inline bool operator!=(CapturedVertex a, CapturedVertex b) { return !(a == b); }
inline bool operator<(CapturedVertex a, CapturedVertex b) { return a.u != b.u ? a.u < b.u : a.v < b.v; }

// One patch of a capture: its primitives, verticesPerPrimitive vertices each, in the capture's order.
struct CapturedPatch {
  int64_t patch = -1;
  int verticesPerPrimitive = 0;         // 1 points, 2 segments, 3 triangles; 0 when the patch has no primitives
  std::vector<CapturedVertex> vertices; // primitive after primitive
  // The capture's own point numbering where it has one (hex blocks: vertices[i] is point indices[i] of the block);
  // empty for CSV and point-only blocks. Only used when indices.size() == vertices.size().
  std::vector<int32_t> indices;
  int line = 0;                         // line of the patch's first row / header in the capture
  int primitives() const { return verticesPerPrimitive ? int(vertices.size()) / verticesPerPrimitive : 0; }
};

// Streams a capture. The stream must outlive the reader. Reading is one patch at a time: memory is bounded by the
// largest patch (a quad at factor 64: 24,576 triangles).
class CaptureReader {
public:
  // source: the name used in error messages (a path, or "-"). format Auto: hex if the first line that is not blank
  // or a comment starts with "patch ", else CSV.
  CaptureReader(std::istream& in, std::string source, CaptureFormat format = CaptureFormat::Auto);

  // The next patch present in the capture (patch numbers increase; numbers skipped are patches the capture lacks).
  // Returns false at the end. Throws CaptureError on malformed input, naming the file and line.
  bool next(CapturedPatch& out);

  CaptureFormat format() const { return format_; }
  const std::string& source() const { return source_; }

private:
  struct Row {
    int64_t patch;
    int64_t primitive;
    int vertex;
    CapturedVertex value;
    int line;
  };
  bool readLine(std::string& line);
  [[noreturn]] void fail(int line, const std::string& why) const;
  bool nextHex(CapturedPatch& out);
  bool nextCsv(CapturedPatch& out);
  bool readCsvRow(Row& row);

  std::istream& in_;
  std::string source_;
  CaptureFormat format_;
  int lineNo_ = 0;
  bool havePending_ = false; // CSV: a row of the next patch already read
  Row pending_{};
  std::string pushedBack_; // Auto detection: the first meaningful line, read again by the parser
  bool havePushedBack_ = false;
  int64_t lastPatch_ = -1;
  bool sawRow_ = false; // CSV: a header line is allowed before the first row only
  std::vector<Row> rows_;
};

} // namespace fftess
