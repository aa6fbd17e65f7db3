// fftess compare PATCHES CAPTURE: another tessellator's output against the emulator, patch by patch, streamed
// (compare/compare.h does the comparing; this file reads the files, prints and picks the exit status).
#include "ci_compare.h"
#include "common.h"
#include "options.h"
#include "compare_report.h"
#include "compare_svg.h"

#include <CLI/CLI.hpp>

#include "tessellator/batch.h"
#include "compare/capture.h"
#include "compare/compare.h"
#include "tessellator/names.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <memory>

namespace fftess::cli {
namespace {

using json = nlohmann::ordered_json;
using nlohmann::ordered_json;

// Reads the batch file one patch at a time (blank lines and '#' comments skipped, as `tessellate` does).
class BatchReader {
public:
  BatchReader(std::istream& in, std::string source) : in_(in), source_(std::move(source)) {}
  bool next(Patch& p, int& line) {
    std::string s;
    while (std::getline(in_, s)) {
      ++lineNo_;
      if (auto hash = s.find('#'); hash != std::string::npos) s.erase(hash);
      if (isBatchSkippable(s)) continue;
      BatchError be;
      if (!parseBatchLine(s, p, be))
        throw UsageError(
            source_ + ":" + std::to_string(lineNo_) + ": " +
            (be.token.empty() ? "" : "token " + std::to_string(be.column) + " " + quoteToken(be.token) + ": ") +
            be.message);
      line = lineNo_;
      return true;
    }
    return false;
  }

private:
  std::istream& in_;
  std::string source_;
  int lineNo_ = 0;
};

std::istream& openInput(const std::string& path, std::unique_ptr<std::ifstream>& file, const char* what) {
  if (path == "-") return std::cin;
  file = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!*file) throw UsageError(std::string(what) + " '" + path + "': cannot open");
  return *file;
}

std::string vertexText(CapturedVertex v) {
  return "(" + formatFloat(floatOf(v.u)) + ", " + formatFloat(floatOf(v.v)) + ")";
}

json vertexJson(CapturedVertex v) {
  return json{
      {"u", floatOf(v.u)}, {"v", floatOf(v.v)}, {"u_bits", "0x" + hex8(v.u)}, {"v_bits", "0x" + hex8(v.v)}};
}

// Where a patch is: "FILE:LINE", or "COMMAND, line LINE" for a generated batch.
std::string placeOf(const std::string& batch, bool generated, int line) {
  if (line <= 0) return batch;
  return batch + (generated ? ", line " : ":") + std::to_string(line);
}

// A coordinate in 16.16 units (u * 65536: exact, a power-of-two scale), as the shortest decimal of that float.
std::string units16(uint32_t bits) {
  const float f = floatOf(bits), s = f * 65536.0f;
  return std::isinf(s) && !std::isinf(f) ? formatNumber(double(f) * 65536.0) : formatFloat(s);
}

json primitiveJson(const PrimitiveDifference& d) {
  json vs = json::array();
  for (CapturedVertex v : d.vertices) {
    json j = vertexJson(v);
    j["u_16_16"] = double(floatOf(v.u)) * 65536.0;
    j["v_16_16"] = double(floatOf(v.v)) * 65536.0;
    vs.push_back(j);
  }
  return json{{"primitive", d.primitive},
              {"vertices", vs},
              {"indices", d.indices},
              {"reference_indices", d.referenceIndices}};
}

// "triangles" (or "segments"): the primitives only in one side, counts and the first of each.
json primitivesJson(const PatchComparison& c) {
  json ref = json::array(), cap = json::array();
  for (const auto& d : c.onlyInReference) ref.push_back(primitiveJson(d));
  for (const auto& d : c.onlyInCapture) cap.push_back(primitiveJson(d));
  return json{{"only_in_reference_count", c.onlyInReferenceCount},
              {"only_in_capture_count", c.onlyInCaptureCount},
              {"only_in_reference", ref},
              {"only_in_capture", cap}};
}

std::string indexList(const std::vector<int32_t>& v) {
  std::string s;
  for (int32_t i : v) s += (s.empty() ? "" : " ") + (i < 0 ? std::string("-") : std::to_string(i));
  return s;
}

// Text: the listed primitives of one side, one per line: position, indices, coordinates as floats and in 16.16.
void describePrimitives(std::string& o, const char* side, int count, const std::vector<PrimitiveDifference>& list,
                        int arity) {
  if (count == 0) return;
  o += "  " + std::to_string(count) + (arity == 3 ? " triangles" : " segments") + " only in " + side +
       (int(list.size()) < count ? " (the first " + std::to_string(list.size()) + ")" : "") + ":\n";
  for (const auto& d : list) {
    std::string xy, fixed;
    for (CapturedVertex v : d.vertices) {
      xy += " " + vertexText(v);
      fixed += " (" + units16(v.u) + ", " + units16(v.v) + ")";
    }
    o += "    primitive " + std::to_string(d.primitive);
    if (!d.indices.empty() && d.indices != d.referenceIndices) o += ", indices " + indexList(d.indices);
    o += ", reference indices " + indexList(d.referenceIndices) + ":" + xy + "; 16.16:" + fixed + "\n";
  }
}

bool listsPrimitivesInText(DifferenceKind k) {
  return k == DifferenceKind::WindingOnly || k == DifferenceKind::Multiplicity ||
         k == DifferenceKind::TriangulationDiffers || k == DifferenceKind::PrimitivesDiffer;
}

void describePatch(std::string& o, ordered_json& list, int64_t index, const std::string& place, const Patch& patch,
                   int line, const PatchComparison& c, bool asJson) {
  if (asJson) {
    json j{{"patch", index},
           {"line", line},
           {"batch_line", formatBatchLine(patch)},
           {"kind", toString(c.kind)},
           {"reference_primitives", c.referencePrimitives},
           {"capture_primitives", c.capturePrimitives},
           {"vertices_per_primitive", c.verticesPerPrimitive},
           {"missing_points", c.missingPoints},
           {"extra_points", c.extraPoints},
           {"flipped_triangles", c.flippedTriangles}};
    json bugs = json::array();
    for (PortBug b : c.bugs) bugs.push_back(toString(b));
    j["bugs"] = bugs;
    j["bug_forms"] = c.bugVariants; // parallel to bugs: the form that reproduces ("" for bugs with one)
    json pts = json::array();
    for (const auto& d : c.points)
      pts.push_back(json{{"got", vertexJson(d.got)},
                         {"nearest", vertexJson(d.nearest)},
                         {"du", d.du},
                         {"dv", d.dv},
                         {"where", d.where},
                         {"step", d.step},
                         {"detail", d.detail}});
    j["points"] = pts;
    j["rotated_primitives"] = c.rotatedPrimitives;
    if (c.verticesPerPrimitive >= 2) j[c.verticesPerPrimitive == 3 ? "triangles" : "segments"] = primitivesJson(c);
    list.push_back(j);
    return;
  }
  o += "patch " + std::to_string(index) + " (" + place + "): " + toString(c.kind) + ": " +
       std::to_string(c.referencePrimitives) + " reference " + (c.verticesPerPrimitive == 1 ? "points" : "primitives") +
       ", " + std::to_string(c.capturePrimitives) + " in the capture";
  if (c.kind == DifferenceKind::PointsDiffer)
    o += "; " + std::to_string(c.missingPoints) + " reference points missing, " + std::to_string(c.extraPoints) +
         " points the reference lacks";
  if (c.kind == DifferenceKind::WindingOnly) o += "; " + std::to_string(c.flippedTriangles) + " triangles flipped";
  if (c.kind == DifferenceKind::Rotated)
    o += "; " + std::to_string(c.rotatedPrimitives) + " start at another vertex";
  o += "\n  batch line: " + formatBatchLine(patch) + "\n";
  if (listsPrimitivesInText(c.kind)) {
    describePrimitives(o, "the reference", c.onlyInReferenceCount, c.onlyInReference, c.verticesPerPrimitive);
    describePrimitives(o, "the capture", c.onlyInCaptureCount, c.onlyInCapture, c.verticesPerPrimitive);
  }
  for (const auto& d : c.points) {
    o += "  " + vertexText(d.got) + ": nearest reference point " + vertexText(d.nearest) + ", du " +
         formatNumber(d.du) + " dv " + formatNumber(d.dv) + " (16.16 units)\n";
    o += "    " + d.where + ": " + d.detail + "\n";
  }
  for (size_t i = 0; i < c.bugs.size(); ++i) {
    const std::string& form = i < c.bugVariants.size() ? c.bugVariants[i] : std::string();
    o += std::string("  reproduced by ") + toString(c.bugs[i]) + (form.empty() ? "" : " (" + form + ")") + ": " +
         describe(c.bugs[i]) + "\n";
  }
}

} // namespace

CompareReporter::CompareReporter(bool asJson, int show, bool strict, std::string batch, const char* kind)
    : json_(asJson), strict_(strict), kind_(kind), show_(show), batch_(std::move(batch)),
      listed_(ordered_json::array()) {}

void CompareReporter::add(int64_t index, int line, const Patch& patch, const PatchComparison& c) {
  sum_.add(c, c.referencePrimitives * c.verticesPerPrimitive);
  if (c.kind != DifferenceKind::Same && shown_ < show_) {
    ++shown_;
    describePatch(text_, listed_, index, placeOf(batch_, generated_, line), patch, line, c, json_);
  }
}

void CompareReporter::finish(const std::string& format, const std::string& header) {
  if (!json_) text_ = header + text_;
  const auto all = sum_.explainingAll();
  if (json_) {
    json j{{"version", kCompareReportVersion},
           {"kind", kind_},
           {"fftess_version", FFTESS_VERSION},
           {generated_ ? "generated_by" : "batch", batch_},
           {"patches", sum_.patches},     {"same", sum_.same},
           {"differing", sum_.differing}, {"points_compared", sum_.pointsCompared},
           {"strict_order", strict_},     {"format", format}};
    if (!header.empty()) j["source_text"] = header.substr(0, header.find('\n')); // the first header line, without '\n'
    for (const auto& [key, value] : extra_.items()) j[key] = value;
    json kinds = json::object();
    for (int k = 1; k < int(DifferenceKind::Count); ++k) kinds[toString(DifferenceKind(k))] = sum_.byKind[k];
    j["by_kind"] = kinds;
    json bugs = json::object();
    for (int b = 0; b < int(PortBug::Count); ++b) bugs[toString(PortBug(b))] = sum_.byBug[b];
    j["bugs"] = bugs;
    json ex = json::array();
    for (PortBug b : all) ex.push_back(toString(b));
    j["explained_by"] = ex;
    j["listed"] = listed_;
    if (sink_) *sink_ = j.dump(2) + "\n";
    else writeStdout(j.dump(2) + "\n");
  } else {
    text_ += "summary: " + std::to_string(sum_.patches) + " patches, " + std::to_string(sum_.same) + " same, " +
             std::to_string(sum_.differing) + " differ";
    std::string kinds;
    for (int k = 1; k < int(DifferenceKind::Count); ++k)
      if (sum_.byKind[k])
        kinds +=
            std::string(kinds.empty() ? "" : ", ") + toString(DifferenceKind(k)) + " " + std::to_string(sum_.byKind[k]);
    if (!kinds.empty()) text_ += " (" + kinds + ")";
    text_ += "; " + std::to_string(sum_.pointsCompared) + " reference vertices compared" +
             (strict_ ? " in strict order" : "") + "\n";
    for (int b = 0; b < int(PortBug::Count); ++b)
      if (sum_.byBug[b])
        text_ += std::string("typical port bug ") + toString(PortBug(b)) + " reproduces " +
                 std::to_string(sum_.byBug[b]) + " of " + std::to_string(sum_.differing) + " differing patches (" +
                 describe(PortBug(b)) + ")\n";
    if (sum_.differing == 0)
      text_ += "verdict: same: the capture is the D3D11 reference's output\n";
    else if (!all.empty())
      text_ += std::string("verdict: differs; every difference is reproduced by ") + toString(all.front()) + ": " +
               describe(all.front()) + " (step: " + stepOf(all.front()) + ")\n";
    else
      text_ += "verdict: differs\n";
    writeStdout(text_);
  }
}

CLI::App* addCompare(CLI::App& app, CompareArgs& a) {
  CLI::App* sub = app.add_subcommand("compare", "Compare a port's tessellator output (CAPTURE) with the emulator");
  sub->add_option("patches", a.patches, "Batch file the port was fed (tessellator/batch.h format; - for stdin)")
      ->required();
  sub->add_option("capture", a.capture, "The port's output: hex blocks or CSV patch,primitive,vertex,u,v[,w]")
      ->required();
  sub->add_option("--format", a.format, "Capture format: auto (default), hex, csv")
      ->check(choiceOf({"auto", "hex", "csv"}));
  sub->add_flag("--strict-order", a.strictOrder, "Same primitives in the same order with the same first vertex");
  sub->add_flag("--json", a.json, "JSON report on stdout");
  sub->add_flag("--flush-denormals", a.flushDenormals, "Reference flushes denormal factors (as llvmpipe and GPUs do)");
  addShowOption(sub, a.show, "Differing patches listed in full (all are counted)");
  sub->add_option("--details", a.details, "Differing points explained per patch (default 4)");
  sub->add_option("--svg", a.svg, "SVG of the first differing patches: reference and capture over each other");
  sub->add_option("--sarif", a.sarif, "Write every differing patch as SARIF 2.1.0 to FILE, at its batch line (docs/ci.md)")
      ->type_name("FILE");
  sub->add_option("--junit", a.junit, "Write JUnit XML to FILE: a failing test case per differing patch (docs/ci.md)")
      ->type_name("FILE");
  sub->footer("Example:\n  fftess compare docs/examples/compare_port.batch docs/examples/compare_port_bug.csv\n"
              "Exit status: 0 same, 1 differs, 2 bad usage or input (FILE:LINE), 3 internal error.");
  return sub;
}

int runCompare(const CompareArgs& a) {
  if (a.patches == "-" && a.capture == "-") throw UsageError("PATCHES and CAPTURE cannot both be stdin");
  if (a.show < 0) throw UsageError("--show " + std::to_string(a.show) + ": must be >= 0");
  if (a.details < 0) throw UsageError("--details " + std::to_string(a.details) + ": must be >= 0");
  refuseSameFiles({{"--svg", a.svg}, {"--sarif", a.sarif}, {"--junit", a.junit}},
                  {{"PATCHES", a.patches}, {"CAPTURE", a.capture}});
  std::unique_ptr<std::ifstream> pf, cf;
  std::istream& pin = openInput(a.patches, pf, "PATCHES");
  std::istream& cin = openInput(a.capture, cf, "CAPTURE");
  const CaptureFormat format = a.format == "hex"   ? CaptureFormat::Hex
                               : a.format == "csv" ? CaptureFormat::Csv
                                                   : CaptureFormat::Auto;
  BatchReader batch(pin, a.patches);
  CaptureReader capture(cin, a.capture, format);
  CompareOptions opt;
  opt.strictOrder = a.strictOrder;
  opt.emulator.flushDenormals = a.flushDenormals;
  opt.maxPointDetails = a.details;
  CompareSvg svg(a.svg, opt);
  CompareCi ci(a.sarif, a.junit, "compare", a.patches == "-" ? "" : a.patches); // --sarif / --junit
  Tessellator tess;
  CompareReporter reporter(a.json, a.show, a.strictOrder, a.patches);
  reporter.setJsonSink(a.jsonOut);
  CapturedPatch got;
  bool haveGot = false;
  try {
    haveGot = capture.next(got);
    Patch p;
    int line = 0;
    for (int64_t index = 0; batch.next(p, line); ++index) {
      const bool present = haveGot && got.patch == index;
      PatchComparison c;
      try {
        c = comparePatch(p, present ? &got : nullptr, opt, tess);
      } catch (const CaptureError& e) {
        throw CaptureError(a.capture + ":" + std::to_string(got.line) + ": " + e.what());
      }
      reporter.add(index, line, p, c);
      svg.add(index, line, p, present ? &got : nullptr, c);
      ci.add(index, line, p, c);
      if (present) haveGot = capture.next(got);
    }
    if (haveGot)
      throw CaptureError(a.capture + ":" + std::to_string(got.line) + ": patch " + std::to_string(got.patch) +
                         " is not in " + a.patches + " (it has " + std::to_string(reporter.summary().patches) +
                         " patches)");
  } catch (const CaptureError& e) {
    throw UsageError(e.what());
  }
  svg.commit("fftess compare " + a.patches + " " + a.capture, reporter.summary());
  ci.commit(reporter.summary(), reporter.summary().differing ? kExitFindings : kExitClean, a.patches + " " + a.capture);
  reporter.finish(capture.format() == CaptureFormat::Hex ? "hex" : "csv", "");
  return reporter.summary().differing ? kExitFindings : kExitClean;
}

} // namespace fftess::cli
