// fftess driver-check: is the local OpenGL or Vulkan driver's tessellator D3D11-exact? Patches (a batch file, or seeded
// random ones) go through the driver (gl/: headless EGL, transform-feedback capture, llvmpipe by default; vk/: Vulkan,
// VK_EXT_transform_feedback, lavapipe by default) and the captures through the same comparison as `fftess compare`
// (compare/compare.h).
#include "common.h"
#include "options.h"
#include "compare_report.h"
#include "random_batch.h"
#include "port_bug.h"
#include "ci_compare.h"
#include "compare_svg.h"

#include <CLI/CLI.hpp>

#include "tessellator/batch.h"
#include "compare/compare.h"

#ifdef FFTESS_HAVE_GL
#include "gl/gl_capture.h"
#endif
#ifdef FFTESS_HAVE_VULKAN
#include "vk/vk_capture.h"
#endif

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iostream>

namespace fftess::cli {

CLI::App* addDriverCheck(CLI::App& app, DriverCheckArgs& a) {
  CLI::App* sub = app.add_subcommand("driver-check", "Run patches through the local OpenGL (or Vulkan) tessellator and "
                                                     "compare with the emulator (llvmpipe / lavapipe by default)");
  sub->add_option("patches", a.patches, "Batch file (hw or hlsl stage; - for stdin); none: --random patches");
  sub->add_option("--random", a.random, "Seeded random patches (with special factor values) when no batch is given")
      ->check(CLI::Range(1, 10000000));
  addSeedOption(sub, a.seed, "Seed of --random's patches");
  sub->add_flag("--hardware", a.hardware, "Prefer a GPU (EGL device, Vulkan device) over Mesa's software one");
  sub->add_option("--api", a.api, "The driver's API: gl (OpenGL 4.5, EGL) or vulkan (VK_EXT_transform_feedback)")
      ->check(choiceOf({"gl", "vulkan"}));
  sub->add_flag("--strict-order", a.strictOrder,
                "Capture and compare in the reference's order: same primitives in the same order with the same first "
                "vertex (needs a driver that emits in that order, llvmpipe)");
  sub->add_flag("--flush-denormals", a.flushDenormals, "Reference flushes denormal factors (as llvmpipe and GPUs do)");
  sub->add_flag("--json", a.json, "JSON report on stdout");
  addShowOption(sub, a.show, "Differing patches listed in full (all are counted)");
  sub->add_option("--write-batch", a.writeBatch, "The patches checked, as a batch file (--random: what fftess gen "
                                                 "writes for the same N and seed)");
  sub->add_option("--port-bug", a.portBug, "Run the driver as a port with this whole-patch bug (NAME[:FORM], "
                                           "docs/compare.md): its factors and coordinates moved around the driver");
  sub->add_option("--permute-capture", a.permuteCapture,
                  "Test: permute the driver's captured records (seeded, nonzero) and rotate its triangles before they "
                  "are grouped, as a driver with its own order would emit them")
      ->check(CLI::Range(uint64_t(1), UINT64_MAX));
  sub->add_option("--svg", a.svg, "SVG of the first differing patches: reference and capture over each other");
  sub->add_option("--sarif", a.sarif,
                  "Write every differing patch as SARIF 2.1.0 to FILE, at its line in PATCHES (or, with --random, in "
                  "the --write-batch file; docs/ci.md)")
      ->type_name("FILE");
  sub->add_option("--junit", a.junit, "Write JUnit XML to FILE: a failing test case per differing patch (docs/ci.md)")
      ->type_name("FILE");
  sub->footer(
      "Example:\n  fftess driver-check --random 2000 --seed 7\n  fftess driver-check docs/examples/compare_port.batch\n"
      "  fftess driver-check --api vulkan --hardware --random 2000\n"
      "Exit status: 0 same, 1 differs, 2 bad usage or input, 3 no GL/Vulkan driver, internal error, or --strict-order on a "
      "driver that emits in its own order.");
  return sub;
}

#ifndef FFTESS_HAVE_GL
int runDriverCheck(const DriverCheckArgs&) {
  throw UsageError("driver-check: this fftess was built without OpenGL/EGL (install libegl-dev libgl-dev, rebuild)");
}
#else
namespace {

// What the driver gave, as a capture: its primitives where GL draws them, else its point array.
CapturedPatch toCapture(const oracle::Result& r, int64_t index) {
  CapturedPatch c;
  c.patch = index;
  const bool prims = !r.primitives.empty();
  const std::vector<uint32_t>& words = prims ? r.primitives : r.points;
  for (size_t i = 0; i + 1 < words.size(); i += 2) c.vertices.push_back(CapturedVertex{words[i], words[i + 1]});
  c.verticesPerPrimitive = c.vertices.empty() ? 0 : prims ? r.verticesPerPrimitive : 1;
  if (prims && r.indices.size() == c.vertices.size()) c.indices = r.indices; // the driver's point numbering
  return c;
}

struct Item {
  Patch patch; // hardware-stage patch (an hlsl-stage line is preconditioned here, the driver gets the result)
  int line = 0; // its line in PATCHES, or (--random) in the batch `fftess gen` writes
};

// --write-batch: the patches checked; for --random the bytes `fftess gen` writes (its header names the command).
void writeBatch(const DriverCheckArgs& a, const std::vector<Item>& items) {
  BatchFileWriter out(a.writeBatch);
  out.text(a.patches.empty() ? genHeader(GenSpec{a.random, a.seed, false})
                             : "# the hardware-stage patches fftess driver-check checked from " +
                                   (a.patches == "-" ? std::string("standard input") : quotePath(a.patches)) + "\n");
  for (const Item& it : items) out.add(it.patch);
  out.commit();
}

} // namespace

// The driver of --api: GL (GlOracle) or Vulkan (VkOracle), the same patches in, the same results out. Vulkan's capture
// is always order-free (it keeps the driver's order within a patch: --strict-order then compares that order).
struct Driver {
  std::unique_ptr<oracle::GlOracle> gl;
#ifdef FFTESS_HAVE_VULKAN
  std::unique_ptr<oracle::VkOracle> vk;
#endif
  std::string renderer, version;
  bool software = false; // Mesa's llvmpipe / lavapipe
  bool run(const std::vector<oracle::Patch>& patches, std::vector<oracle::Result>& results, std::string& error,
           const oracle::RunOptions& options) {
#ifdef FFTESS_HAVE_VULKAN
    if (vk) return vk->run(patches, results, error);
#endif
    return gl->run(patches, results, error, options);
  }
  bool orderMismatch() const { return gl && gl->orderMismatch(); }
};

// Opens the driver of --api; false (the reason on stderr) when there is none.
bool openDriver(const DriverCheckArgs& a, Driver& d) {
  std::string error;
  if (a.api == "vulkan") {
#ifndef FFTESS_HAVE_VULKAN
    throw UsageError(
        "driver-check --api vulkan: this fftess was built without Vulkan (install libvulkan-dev, rebuild)");
#else
    d.vk = oracle::VkOracle::create(error, a.hardware);
    if (!d.vk) {
      std::fprintf(stderr, "fftess: error: driver-check --api vulkan: no Vulkan device for the capture: %s\n",
                   error.c_str());
      return false;
    }
    if (a.permuteCapture) d.vk->setRecordShuffle(a.permuteCapture);
    d.renderer = d.vk->renderer(), d.version = d.vk->version(), d.software = d.vk->isCpu();
    return true;
#endif
  }
  d.gl = oracle::GlOracle::create(error, a.hardware);
  if (!d.gl) {
    std::fprintf(stderr, "fftess: error: driver-check: no OpenGL 4.5 context: %s\n", error.c_str());
    return false;
  }
  d.renderer = d.gl->renderer(), d.version = d.gl->version(), d.software = d.gl->isLlvmpipe();
  return true;
}

int runDriverCheck(const DriverCheckArgs& a) {
  if (a.writeBatch == "-") throw UsageError("--write-batch '-': stdout carries the report; give a file");
  refuseSameFiles({{"--write-batch", a.writeBatch}, {"--svg", a.svg}, {"--sarif", a.sarif}, {"--junit", a.junit}},
                  {{"PATCHES", a.patches}});
  const SimulatedPortBug simulated(a.portBug);
  std::vector<Item> items;
  std::string source;
  if (!a.patches.empty()) {
    std::unique_ptr<std::ifstream> file;
    std::istream* in = &std::cin;
    if (a.patches != "-") {
      file = std::make_unique<std::ifstream>(a.patches);
      if (!*file) throw UsageError("PATCHES '" + a.patches + "': cannot open");
      in = file.get();
    }
    std::string s;
    for (int lineNo = 1; std::getline(*in, s); ++lineNo) {
      if (auto hash = s.find('#'); hash != std::string::npos) s.erase(hash);
      if (isBatchSkippable(s)) continue;
      Item it;
      BatchError be;
      if (!parseBatchLine(s, it.patch, be))
        throw UsageError(
            a.patches + ":" + std::to_string(lineNo) + ": " +
            (be.token.empty() ? "" : "token " + std::to_string(be.column) + " " + quoteToken(be.token) + ": ") +
            be.message);
      if (it.patch.stage.hlsl) {
        const HlslFactors h =
            processHlslFactors(it.patch.domain, it.patch.partitioning, it.patch.stage, it.patch.factors);
        std::memcpy(it.patch.factors, h.rounded, sizeof h.rounded);
        it.patch.stage = Stage{};
      }
      it.line = lineNo;
      items.push_back(it);
    }
    source = a.patches;
  } else {
    forEachGenPatch(GenSpec{a.random, a.seed, false},
                    [&](int64_t i, const Patch& p) { items.push_back(Item{p, genLineOf(i)}); });
    source = genCommand(GenSpec{a.random, a.seed, false});
  }
  CompareOptions opt;
  opt.strictOrder = a.strictOrder;
  opt.emulator.flushDenormals = a.flushDenormals;
  CompareSvg svg(a.svg, opt);
  // --sarif / --junit: results at the patches' lines in PATCHES, or (--random) in the --write-batch file
  CompareCi ci(a.sarif, a.junit, "driver-check", a.patches.empty() ? a.writeBatch : a.patches == "-" ? "" : a.patches);
  if (!a.writeBatch.empty()) writeBatch(a, items);
  std::string error;
  Driver driver;
  if (!openDriver(a, driver)) return kExitInternal;
  if (a.hardware && driver.software)
    std::fprintf(stderr, "fftess: note: driver-check --hardware: no GPU device gave %s context; running on %s\n",
                 a.api == "vulkan" ? "a Vulkan" : "an OpenGL 4.5", driver.renderer.c_str());
  oracle::RunOptions run;
  run.order = a.strictOrder ? oracle::CaptureOrder::Strict : oracle::CaptureOrder::Free;
  run.permuteSeed = a.permuteCapture;
  CompareReporter reporter(a.json, a.show, a.strictOrder, source, "driver_check");
  if (a.patches.empty()) reporter.setGenerated();
  if (simulated.active())
    reporter.addJsonField("port_bug", {{"name", toString(simulated.bug())}, {"form", simulated.form()}});
  Tessellator tess;
  constexpr size_t kChunk = 4096; // patches per capture round: bounded memory for any count
  std::vector<oracle::Patch> glPatches;
  std::vector<oracle::Result> results;
  for (size_t begin = 0; begin < items.size(); begin += kChunk) {
    const size_t end = std::min(items.size(), begin + kChunk);
    glPatches.clear();
    for (size_t i = begin; i < end; ++i) glPatches.push_back(toOracle(simulated.input(items[i].patch)));
    if (!driver.run(glPatches, results, error, run)) {
      if (driver.orderMismatch())
        std::fprintf(stderr, "fftess: error: driver-check: --strict-order needs a driver that emits in the reference "
                             "order (llvmpipe); %s does not%s (%s)\n", driver.renderer.c_str(),
                     a.permuteCapture ? " with --permute-capture" : "", error.c_str());
      else
        std::fprintf(stderr, "fftess: error: driver-check: the capture on %s failed: %s\n", driver.renderer.c_str(),
                     error.c_str());
      return kExitInternal;
    }
    for (size_t i = begin; i < end; ++i) {
      CapturedPatch c = toCapture(results[i - begin], int64_t(i));
      simulated.output(items[i].patch, c);
      const PatchComparison cmp = comparePatch(items[i].patch, &c, opt, tess);
      reporter.add(int64_t(i), items[i].line, items[i].patch, cmp);
      svg.add(int64_t(i), items[i].line, items[i].patch, &c, cmp);
      ci.add(int64_t(i), items[i].line, items[i].patch, cmp);
    }
  }
  svg.commit("fftess driver-check on " + driver.renderer + ": " + source, reporter.summary());
  ci.commit(reporter.summary(), reporter.summary().differing ? kExitFindings : kExitClean, driver.renderer + ": " + source);
  reporter.finish(a.api, "driver: " + driver.renderer + " (" + driver.version + "), " + std::to_string(items.size()) +
                             " patches from " + source + "\n" + simulated.header());
  return reporter.summary().differing ? kExitFindings : kExitClean;
}
#endif

} // namespace fftess::cli
