// fftess tessellate: batch tessellation, one patch per input line, in the exact golden format or human formats.
#include "commands.h"
#include "common.h"
#include "options.h"

#include <CLI/CLI.hpp>

#include "tessellator/batch.h"
#include "tessellator/names.h"
#include "tessellator/parallel.h"
#include "tessellator/tessellator.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>
#include <sys/stat.h>
#include <unistd.h>

namespace fftess::cli {
namespace {

// Longest input line read (a batch line is under 200 bytes).
constexpr size_t kMaxLineBytes = size_t(1) << 20;

struct BatchPatch {
  int line = 0;       // 1-based line number in the input
  int index = 0;      // 0-based patch number: counts every patch line, malformed ones included
  std::string text;   // the line with comments stripped and whitespace collapsed
  Patch patch;
};

// Parses one input line with the batch format's parser (tessellator/batch.h). The CLI also allows a trailing
// "# comment" after a patch. Returns false with err set on a malformed line; isPatch is false for blank and comment
// lines.
bool parseLine(const std::string& raw, int lineNo, const std::string& source, BatchPatch& bp, std::string& err,
               bool& isPatch) {
  std::string s = raw;
  if (auto hash = s.find('#'); hash != std::string::npos) s.erase(hash);
  isPatch = !isBatchSkippable(s);
  if (!isPatch) return true;
  Patch p;
  fftess::BatchError be;
  if (!parseBatchLine(s, p, be)) {
    err = source + ":" + std::to_string(lineNo) + ": " +
          (be.token.empty() ? "" : "token " + std::to_string(be.column) + " " + quoteToken(be.token) + ": ") + be.message;
    return false;
  }
  bp.line = lineNo;
  bp.patch = p;
  bp.text.clear();
  std::istringstream in(s);
  for (std::string t; in >> t;) bp.text += (bp.text.empty() ? "" : " ") + t;
  return true;
}

void formatTable(std::string& out, const BatchPatch& bp, const Tessellator& t) {
  const Patch& p = bp.patch;
  const int nf = p.domain == Domain::Quad ? 6 : p.domain == Domain::Tri ? 4 : 2;
  out += "patch " + std::to_string(bp.index) + " (line " + std::to_string(bp.line) + "): " + toString(p.domain) + " " +
         toString(p.partitioning) + " " + toString(p.primitive) + " " + toString(p.stage) + "\n";
  out += "  factors:";
  for (int i = 0; i < nf; ++i) {
    out += std::string("  ") + factorName(p.domain, i);
    if (p.stage.hlsl && ((p.domain == Domain::Quad && i >= 4) || (p.domain == Domain::Tri && i == 3)))
      out += "(scale)";
    out += "=" + formatFloat(p.factors[i]);
    if (!std::isfinite(p.factors[i]) || (p.factors[i] != 0 && std::fabs(p.factors[i]) < 1.17549435e-38f))
      out += " [" + hex8(bitsOf(p.factors[i])) + "]";
  }
  out += "\n";
  if (p.stage.hlsl) {
    const HlslFactors& h = t.hlslFactors();
    out += "  after HLSL stage (rounded / unrounded):";
    for (int i = 0; i < nf; ++i)
      out += std::string("  ") + factorName(p.domain, i) + "=" + formatFloat(h.rounded[i]) + "/" + formatFloat(h.unrounded[i]);
    out += "\n";
  }
  const auto& pts = t.points();
  const auto& idx = t.indices();
  if (pts.empty()) {
    out += "  culled: an outer factor is not > 0 (NaN, zero, negative or -inf): no points, no primitives\n\n";
    return;
  }
  const int per = indicesPerLine(p);
  const char* prim = per == 3 ? "triangles" : per == 2 ? "segments" : "points";
  out += "  " + std::to_string(pts.size()) + " points, " + std::to_string(idx.size() / static_cast<size_t>(per)) + " " +
         prim + " (" + std::to_string(idx.size()) + " indices)\n";
  char buf[160];
  std::snprintf(buf, sizeof buf, "  %6s  %-12s %-12s %-8s %-8s%s\n", "#", "u", "v", "u bits", "v bits",
                p.domain == Domain::Tri ? "  w = 1-u-v" : "");
  out += buf;
  for (size_t i = 0; i < pts.size(); ++i) {
    const DomainPoint& q = pts[i];
    std::snprintf(buf, sizeof buf, "  %6zu  %-12s %-12s %08x %08x", i, formatFloat(q.u).c_str(), formatFloat(q.v).c_str(),
                  bitsOf(q.u), bitsOf(q.v));
    out += buf;
    if (p.domain == Domain::Tri) out += "  " + formatFloat(1.0f - q.u - q.v);
    out += "\n";
  }
  if (per > 1) {
    out += std::string("  ") + prim + ":\n";
    for (size_t i = 0; i + static_cast<size_t>(per) <= idx.size(); i += static_cast<size_t>(per)) {
      std::snprintf(buf, sizeof buf, "  %6zu ", i / static_cast<size_t>(per));
      out += buf;
      for (int k = 0; k < per; ++k) {
        std::snprintf(buf, sizeof buf, " %6d", idx[i + static_cast<size_t>(k)]);
        out += buf;
      }
      out += "\n";
    }
  }
  out += "\n";
}

// Planar position of a domain point: quad/isoline: (u, v); tri: barycentric (u, v, w) on an equilateral triangle
// with the u = 1 corner on top, v = 1 bottom left, w = 1 bottom right.
void planar(const Patch& p, const DomainPoint& q, double& x, double& y) {
  if (p.domain == Domain::Tri) {
    const double u = q.u, v = q.v, w = 1.0 - u - v;
    x = u * 0.5 + v * 0.0 + w * 1.0;
    y = u * 0.0 + v * 0.8660254037844386 + w * 0.8660254037844386;
    y += (1.0 - 0.8660254037844386) / 2;
  } else {
    x = q.u;
    y = q.v;
  }
}

void formatObj(std::string& out, const BatchPatch& bp, const Tessellator& t, size_t& vertexBase) {
  const Patch& p = bp.patch;
  out += "o patch_" + std::to_string(bp.index) + "\n# " + bp.text + "\n";
  char buf[96];
  for (const DomainPoint& q : t.points()) {
    double x, y;
    planar(p, q, x, y);
    // quad/isoline: x = u, y = v; tri: equilateral layout (see docs/cli.md). 9 significant digits round-trip floats.
    std::snprintf(buf, sizeof buf, "v %.9g %.9g 0\n", x, y);
    out += buf;
  }
  const auto& idx = t.indices();
  const int per = indicesPerLine(p);
  const char* tag = per == 3 ? "f" : per == 2 ? "l" : "p";
  for (size_t i = 0; i + static_cast<size_t>(per) <= idx.size(); i += static_cast<size_t>(per)) {
    out += tag;
    for (int k = 0; k < per; ++k) out += " " + std::to_string(vertexBase + 1 + static_cast<size_t>(idx[i + static_cast<size_t>(k)]));
    out += "\n";
  }
  vertexBase += t.points().size();
}

constexpr int kSvgCell = 420;   // pixels per patch cell
constexpr int kSvgDomain = 360; // pixels of the unit domain
constexpr int kSvgColumns = 3;

void formatSvgPatch(std::string& out, const BatchPatch& bp, const Tessellator& t, int cell) {
  const Patch& p = bp.patch;
  const int cx = (cell % kSvgColumns) * kSvgCell, cy = (cell / kSvgColumns) * (kSvgCell + 40);
  const double ox = cx + (kSvgCell - kSvgDomain) / 2.0, oy = cy + 48;
  char buf[256];
  std::snprintf(buf, sizeof buf, "<g id=\"patch-%d\">\n<text x=\"%d\" y=\"%d\" class=\"t\">patch %d: %s</text>\n", bp.index,
                cx + 10, cy + 18, bp.index, xmlEscape(std::string(toString(p.domain)) + " " + toString(p.partitioning) +
                                                          " " + toString(p.primitive) + " " + toString(p.stage)).c_str());
  out += buf;
  std::string fac;
  const int nf = p.domain == Domain::Quad ? 6 : p.domain == Domain::Tri ? 4 : 2;
  for (int i = 0; i < nf; ++i) fac += std::string(i ? " " : "") + factorName(p.domain, i) + "=" + formatFloat(p.factors[i]);
  std::snprintf(buf, sizeof buf, "<text x=\"%d\" y=\"%d\" class=\"s\">%s</text>\n", cx + 10, cy + 34, xmlEscape(fac).c_str());
  out += buf;
  const auto& pts = t.points();
  const auto& idx = t.indices();
  auto X = [&](const DomainPoint& q) { double x, y; planar(p, q, x, y); return ox + x * kSvgDomain; };
  auto Y = [&](const DomainPoint& q) { double x, y; planar(p, q, x, y); return oy + y * kSvgDomain; };
  // The domain outline.
  if (p.domain == Domain::Tri) {
    DomainPoint a{1, 0}, b{0, 1}, c{0, 0};
    std::snprintf(buf, sizeof buf, "<polygon class=\"dom\" points=\"%.3f,%.3f %.3f,%.3f %.3f,%.3f\"/>\n", X(a), Y(a), X(b),
                  Y(b), X(c), Y(c));
  } else {
    std::snprintf(buf, sizeof buf, "<rect class=\"dom\" x=\"%.3f\" y=\"%.3f\" width=\"%d\" height=\"%d\"/>\n", ox, oy,
                  kSvgDomain, kSvgDomain);
  }
  out += buf;
  if (pts.empty()) {
    std::snprintf(buf, sizeof buf, "<text x=\"%.1f\" y=\"%.1f\" class=\"c\">culled</text>\n", ox + kSvgDomain / 2.0,
                  oy + kSvgDomain / 2.0);
    out += buf;
  }
  const int per = indicesPerLine(p);
  if (per == 3) {
    for (size_t i = 0; i + 3 <= idx.size(); i += 3) {
      const DomainPoint &a = pts[static_cast<size_t>(idx[i])], &b = pts[static_cast<size_t>(idx[i + 1])],
                        &c = pts[static_cast<size_t>(idx[i + 2])];
      std::snprintf(buf, sizeof buf, "<polygon class=\"tri\" points=\"%.3f,%.3f %.3f,%.3f %.3f,%.3f\"/>\n", X(a), Y(a),
                    X(b), Y(b), X(c), Y(c));
      out += buf;
    }
  } else if (per == 2) {
    for (size_t i = 0; i + 2 <= idx.size(); i += 2) {
      const DomainPoint &a = pts[static_cast<size_t>(idx[i])], &b = pts[static_cast<size_t>(idx[i + 1])];
      std::snprintf(buf, sizeof buf, "<line class=\"seg\" x1=\"%.3f\" y1=\"%.3f\" x2=\"%.3f\" y2=\"%.3f\"/>\n", X(a), Y(a),
                    X(b), Y(b));
      out += buf;
    }
  }
  for (const DomainPoint& q : pts) {
    std::snprintf(buf, sizeof buf, "<circle class=\"pt\" cx=\"%.3f\" cy=\"%.3f\" r=\"1.6\"/>\n", X(q), Y(q));
    out += buf;
  }
  std::snprintf(buf, sizeof buf, "<text x=\"%d\" y=\"%.1f\" class=\"s\">%zu points, %zu indices</text>\n</g>\n", cx + 10,
                oy + kSvgDomain + 18, pts.size(), idx.size());
  out += buf;
}

std::string svgHeader(int patches) {
  const int cols = patches < kSvgColumns ? (patches < 1 ? 1 : patches) : kSvgColumns;
  const int rows = (patches + kSvgColumns - 1) / kSvgColumns;
  const int w = cols * kSvgCell, h = (rows < 1 ? 1 : rows) * (kSvgCell + 40);
  char buf[1024];
  std::snprintf(buf, sizeof buf,
                "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\">\n"
                "<title>fftess tessellate</title>\n"
                "<style>.dom{fill:#f4f6fa;stroke:#223;stroke-width:1.5}.tri{fill:#cfe0f7;fill-opacity:0.35;"
                "stroke:#2a5599;stroke-width:0.6}.seg{stroke:#2a5599;stroke-width:0.8}.pt{fill:#b02020}"
                ".t{font:bold 13px sans-serif}.s{font:11px monospace}.c{font:bold 20px sans-serif;fill:#b02020;"
                "text-anchor:middle}</style>\n"
                "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n",
                w, h, w, h);
  return buf;
}

} // namespace

CLI::App* addTessellate(CLI::App& app, TessellateArgs& a) {
  CLI::App* sub = app.add_subcommand("tessellate", "Tessellate patches given one per line (batch format)");
  sub->footer(
      "Batch line: DOMAIN PARTITIONING TOPOLOGY STAGE f0 f1 f2 f3 f4 f5   (blank lines and # comments ignored)\n"
      "  DOMAIN " + joinNames(domainNames()) + "   PARTITIONING " + joinNames(partitioningNames()) + "\n"
      "  TOPOLOGY " + joinNames(outputPrimitiveNames()) + "   STAGE " + joinNames(stageNames()) + "\n"
      "  factor: decimal float, or 0x + 8 hex digits (IEEE-754 bits)\n"
      "Examples:\n"
      "  fftess tessellate -e 'quad fractional_odd triangle_cw hw 3.5 2 5 4 3 3'\n"
      "  fftess tessellate --format hex patches.txt > patches.out\n"
      "  fftess tessellate --format svg -e 'tri integer triangle_cw hw 4 4 4 4 0 0' -o tri.svg");
  sub->add_option("input", a.input, "Batch file ('-' or omitted: standard input)");
  sub->add_option("-e,--patch", a.patches, "A batch line given on the command line (repeatable; replaces INPUT)")
      ->allow_extra_args(false); // one line per -e: "-e LINE FILE" is LINE and INPUT, which exclude each other
  sub->add_option("-f,--format", a.format, "Output format")
      ->check(choiceOf({"hex", "table", "obj", "svg", "hashes"}))
      ->capture_default_str();
  sub->add_option("-o,--output", a.output, "Write to FILE (atomically: temp file + rename) instead of stdout");
  sub->add_flag("--flush-denormals", a.flushDenormals, "Flush denormal factors to zero first (as llvmpipe does)");
  addThreadsOption(sub, a.threads, "Tessellate and format hex/hashes output on N threads (the same bytes for any N)");
  sub->add_flag("--keep-going", a.keepGoing,
                "Print the well-formed patches even if some lines are malformed (exit status is still 2)");
  return sub;
}

namespace {

// Input lines, read twice: once to check every line (with a malformed line nothing is printed unless --keep-going),
// once to tessellate in chunks. Files are reread; standard input is spooled to a temporary file on the first pass;
// -e lines are kept in memory. So peak memory does not grow with the number of patches.
class LineSource {
public:
  explicit LineSource(const TessellateArgs& a) {
    if (!a.patches.empty()) {
      if (a.input != "-") throw UsageError("tessellate: give either INPUT or --patch lines, not both");
      memory_ = &a.patches;
      name_ = "--patch";
    } else if (a.input == "-") {
      file_ = stdin;
      name_ = "<stdin>";
      spool_ = std::tmpfile();
      if (!spool_) throw std::runtime_error(std::string("tessellate: no temporary file for standard input: ") +
                                            std::strerror(errno));
    } else {
      name_ = a.input;
      file_ = std::fopen(a.input.c_str(), "rb");
      if (!file_) throw UsageError("tessellate: cannot open input " + quotePath(a.input) + ": " + std::strerror(errno));
      owned_ = true;
    }
  }
  ~LineSource() {
    if (owned_ && file_) std::fclose(file_);
    if (spool_) std::fclose(spool_);
  }
  LineSource(const LineSource&) = delete;
  LineSource& operator=(const LineSource&) = delete;
  const std::string& name() const { return name_; }

  // Next line without its '\n' (as std::getline). False at the end. A read error, or a line longer than
  // kMaxLineBytes (no batch line comes close: /dev/zero, a binary file), is a UsageError naming the input and line:
  // never taken for the end of the input, and memory stays bounded.
  bool next(std::string& line) {
    if (memory_) {
      if (pos_ >= memory_->size()) return false;
      line = (*memory_)[pos_++];
      return true;
    }
    FILE* f = secondPass_ && spool_ ? spool_ : file_;
    line.clear();
    bool any = false;
    for (int c; (c = getc_unlocked(f)) != EOF;) {
      any = true;
      if (c == '\n') break;
      if (line.size() >= kMaxLineBytes)
        throw UsageError("tessellate: " + inputWords() + ":" + std::to_string(lines_ + 1) + ": line longer than " +
                         std::to_string(kMaxLineBytes) + " bytes (not a batch file?)");
      line += static_cast<char>(c);
    }
    if (std::ferror(f)) throw UsageError("tessellate: cannot read " + inputWords() + ": " + std::strerror(errno));
    if (any && !secondPass_ && spool_) {
      line += '\n';
      const bool ok = std::fwrite(line.data(), 1, line.size(), spool_) == line.size();
      line.pop_back();
      if (!ok) throw std::runtime_error(std::string("tessellate: spooling standard input failed: ") + std::strerror(errno));
    }
    if (!any) return false;
    ++lines_;
    return true;
  }
  void rewind() {
    secondPass_ = true;
    pos_ = 0;
    lines_ = 0;
    if (spool_) std::rewind(spool_);
    else if (file_) std::rewind(file_);
  }

private:
  const std::vector<std::string>* memory_ = nullptr;
  size_t pos_ = 0;
  FILE* file_ = nullptr;
  FILE* spool_ = nullptr;
  bool owned_ = false;
  bool secondPass_ = false;
  size_t lines_ = 0;
  std::string name_;
  std::string inputWords() const { return file_ == stdin ? std::string("standard input") : "input " + quotePath(name_); }
};

// Output written as it is produced: stdout, or FILE as AtomicFile writes it (a temporary file renamed over a regular
// FILE on commit(), a symlink followed, a FIFO or device written straight and never replaced; the path is checked
// before any work, and nothing is left behind on failure).
class StreamOutput {
public:
  explicit StreamOutput(const std::string& path) : file_(path) {}
  void write(std::string& s) {
    file_.stream(s);
    s.clear();
  }
  void commit() {
    file_.commit();
    if (file_.path() == "-") flushStdout();
  }

private:
  AtomicFile file_;
};

// A chunk is cut at this many patches or this much planned output (points + indices), whichever comes first.
constexpr size_t kChunkPatches = 4096;
constexpr int64_t kChunkElements = int64_t(1) << 23;

void appendHashLine(std::string& out, const BatchPatch& bp, const std::string& block) {
  char h[24];
  std::snprintf(h, sizeof h, " %016llx\n", static_cast<unsigned long long>(fnv1a64(block)));
  out += bp.text;
  out += h;
}

// Pass 1: every line checked; the first 20 malformed lines kept for the messages.
struct LineCheck {
  std::vector<std::string> errors; // the first 20
  size_t errorCount = 0;
  int patchCount = 0;
};

LineCheck checkLines(LineSource& source) {
  LineCheck c;
  std::string line;
  for (int lineNo = 1; source.next(line); ++lineNo) {
    BatchPatch bp;
    std::string err;
    bool isPatch = false;
    if (!parseLine(line, lineNo, source.name(), bp, err, isPatch)) {
      if (c.errors.size() < 20) c.errors.push_back(err);
      ++c.errorCount;
      continue;
    }
    if (isPatch) ++c.patchCount;
  }
  return c;
}

void printLineErrors(const LineCheck& c) {
  for (const std::string& e : c.errors) std::fprintf(stderr, "fftess: error: %s\n", printable(e, kMaxMessageBytes).c_str());
  if (c.errorCount > 20) std::fprintf(stderr, "fftess: error: ... and %zu more malformed lines\n", c.errorCount - 20);
}

// Pass 2's output: the patches tessellated and formatted chunk by chunk, written as they are produced. --threads
// applies to the bulk formats (hex, hashes: tessellateBatch, then each thread formats its range); table, obj and svg
// are for a few patches and run on this thread.
class PatchWriter {
public:
  PatchWriter(const TessellateArgs& a, StreamOutput& output)
      : a_(a), output_(output), parallel_(a.threads != 1 && (a.format == "hex" || a.format == "hashes")) {
    opt_.flushDenormals = a.flushDenormals;
  }
  void begin(int patchCount) {
    if (a_.format != "svg") return;
    block_ = svgHeader(patchCount);
    output_.write(block_);
  }
  void add(BatchPatch&& bp) {
    if (parallel_) {
      const OutputCounts c = outputCounts(bp.patch, opt_);
      if (!chunk_.empty() && chunkElements_ + c.points + c.indices > kChunkElements) flush();
      chunkElements_ += c.points + c.indices;
      chunkPatches_.push_back(bp.patch);
    }
    chunk_.push_back(std::move(bp));
    if (chunk_.size() >= kChunkPatches) flush();
  }
  void end() {
    flush();
    if (a_.format != "svg") return;
    block_ = "</svg>\n";
    output_.write(block_);
  }

private:
  void flush() {
    if (chunk_.empty()) return;
    if (parallel_) flushParallel();
    else flushSerial();
    chunk_.clear();
    chunkPatches_.clear();
    chunkElements_ = 0;
  }
  void flushParallel();
  void flushSerial();

  const TessellateArgs& a_;
  StreamOutput& output_;
  const bool parallel_;
  Options opt_;
  Tessellator tess_;
  std::string block_;
  size_t vertexBase_ = 0;
  int cell_ = 0;
  std::vector<BatchPatch> chunk_;
  std::vector<Patch> chunkPatches_;
  std::vector<BatchSlot> slots_;
  std::vector<DomainPoint> points_;
  std::vector<int32_t> indices_;
  std::vector<std::string> parts_;
  int64_t chunkElements_ = 0;
};

void PatchWriter::flushParallel() {
  slots_.resize(chunk_.size());
  const BatchTotals totals = planBatch(chunkPatches_.data(), chunkPatches_.size(), slots_.data(), opt_);
  if (points_.size() < size_t(totals.points)) points_.resize(size_t(totals.points));
  if (indices_.size() < size_t(totals.indices)) indices_.resize(size_t(totals.indices));
  tessellateBatch(chunkPatches_.data(), chunkPatches_.size(), slots_.data(), points_.data(), indices_.data(),
                  a_.threads, opt_);
  const int threads = a_.threads > 0 ? a_.threads : int(std::thread::hardware_concurrency());
  parts_.resize(size_t(threads > 0 ? threads : 1));
  forEachBatchRange(chunk_.size(), slots_.data(), a_.threads, [&](int t, size_t begin, size_t end) {
    std::string& out = parts_[size_t(t)];
    std::string b;
    for (size_t i = begin; i < end; ++i) {
      const BatchSlot& s = slots_[i];
      if (a_.format == "hex") {
        appendHexBlock(out, chunk_[i].index, chunk_[i].patch, points_.data() + s.firstPoint, s.points,
                       indices_.data() + s.firstIndex, s.indices);
      } else {
        b.clear();
        appendHexBlock(b, chunk_[i].index, chunk_[i].patch, points_.data() + s.firstPoint, s.points,
                       indices_.data() + s.firstIndex, s.indices);
        appendHashLine(out, chunk_[i], b);
      }
    }
  });
  for (std::string& part : parts_) output_.write(part);
}

void PatchWriter::flushSerial() {
  for (const BatchPatch& bp : chunk_) {
    tess_.tessellate(bp.patch, opt_);
    if (a_.format == "hex") {
      appendHexBlock(block_, bp.index, bp.patch, tess_);
    } else if (a_.format == "hashes") {
      std::string b;
      appendHexBlock(b, bp.index, bp.patch, tess_);
      appendHashLine(block_, bp, b);
    } else if (a_.format == "table") {
      formatTable(block_, bp, tess_);
    } else if (a_.format == "obj") {
      formatObj(block_, bp, tess_, vertexBase_);
    } else {
      formatSvgPatch(block_, bp, tess_, cell_++);
    }
    output_.write(block_);
  }
}

// Pass 2: tessellate and print, chunk by chunk (malformed lines were reported; they still count as patches).
void tessellateLines(LineSource& source, PatchWriter& writer) {
  source.rewind();
  std::string line;
  int patchIndex = 0;
  for (int lineNo = 1; source.next(line); ++lineNo) {
    BatchPatch bp;
    std::string err;
    bool isPatch = false;
    if (!parseLine(line, lineNo, source.name(), bp, err, isPatch)) {
      ++patchIndex;
      continue;
    }
    if (!isPatch) continue;
    bp.index = patchIndex++;
    writer.add(std::move(bp));
  }
}

} // namespace

int runTessellate(const TessellateArgs& a) {
  if (a.patches.empty() && a.input != "-") refuseSameFiles({{"-o", a.output}}, {{"INPUT", a.input}});
  LineSource source(a);
  const LineCheck check = checkLines(source);
  printLineErrors(check);
  if (check.errorCount > 0 && !a.keepGoing) return kExitUsage;
  StreamOutput output(a.output);
  PatchWriter writer(a, output);
  writer.begin(check.patchCount);
  tessellateLines(source, writer);
  writer.end();
  output.commit();
  return check.errorCount == 0 ? kExitClean : kExitUsage;
}

} // namespace fftess::cli
