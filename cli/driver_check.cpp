// fftess driver-check: is the local OpenGL driver's tessellator D3D11-exact? Patches (a batch file, or seeded random
// ones) go through the driver (gl/: headless EGL, transform-feedback capture; llvmpipe by default) and the
// captures through the same comparison as `fftess compare` (compare/compare.h).
#include "common.h"
#include "compare_report.h"

#include <CLI/CLI.hpp>

#include "tessellator/batch.h"
#include "compare/compare.h"

#ifdef FFTESS_HAVE_GL
#include "gl/gl_capture.h"
#include "gl/random_patches.h"
#endif
#ifdef FFTESS_HAVE_VULKAN
#include "vk/vk_capture.h"
#endif

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
  sub->add_option("--seed", a.seed, "Seed of --random (default 1)");
  sub->add_flag("--hardware", a.hardware, "Prefer a GPU (EGL device, Vulkan device) over Mesa's software one");
  sub->add_option("--api", a.api, "The driver's API: gl (OpenGL 4.5, EGL) or vulkan (VK_EXT_transform_feedback)")
      ->check(CLI::IsMember({"gl", "vulkan"}));
  sub->add_flag("--strict-order", a.strictOrder, "Same primitives in the same order with the same first vertex");
  sub->add_flag("--flush-denormals", a.flushDenormals, "Reference flushes denormal factors (as llvmpipe and GPUs do)");
  sub->add_flag("--json", a.json, "JSON report on stdout");
  sub->add_option("--show", a.show, "Differing patches listed in full (default 20)");
  sub->footer(
      "Example:\n  fftess driver-check --random 2000 --seed 7\n  fftess driver-check docs/examples/compare_port.batch\n"
      "  fftess driver-check --api vulkan --hardware --random 2000\n"
      "Exit status: 0 same, 1 differs, 2 bad usage or input, 3 no GL/Vulkan driver or internal error.");
  return sub;
}

#ifndef FFTESS_HAVE_GL
int runDriverCheck(const DriverCheckArgs&) {
  throw UsageError("driver-check: this fftess was built without OpenGL/EGL (install libegl-dev libgl-dev, rebuild)");
}
#else
namespace {

oracle::Patch toGl(const Patch& p) {
  oracle::Patch g;
  g.domain = static_cast<oracle::Domain>(static_cast<uint8_t>(p.domain));
  g.partitioning = static_cast<oracle::Partitioning>(static_cast<uint8_t>(p.partitioning));
  g.topology = static_cast<oracle::Topology>(static_cast<uint8_t>(p.primitive));
  std::memcpy(g.factorBits, p.factors, sizeof g.factorBits);
  return g;
}

Patch fromGl(const oracle::Patch& g) {
  Patch p;
  p.domain = static_cast<Domain>(static_cast<uint8_t>(g.domain));
  p.partitioning = static_cast<Partitioning>(static_cast<uint8_t>(g.partitioning));
  p.primitive = static_cast<OutputPrimitive>(static_cast<uint8_t>(g.topology));
  std::memcpy(p.factors, g.factorBits, sizeof p.factors);
  return p;
}

// What the driver gave, as a capture: its primitives where GL draws them, else its point array.
CapturedPatch toCapture(const oracle::Result& r, int64_t index) {
  CapturedPatch c;
  c.patch = index;
  const bool prims = !r.primitives.empty();
  const std::vector<uint32_t>& words = prims ? r.primitives : r.points;
  for (size_t i = 0; i + 1 < words.size(); i += 2) c.vertices.push_back(CapturedVertex{words[i], words[i + 1]});
  c.verticesPerPrimitive = c.vertices.empty() ? 0 : prims ? r.verticesPerPrimitive : 1;
  return c;
}

// The driver of --api: GL (GlOracle) or Vulkan (VkOracle), the same patches in, the same results out.
struct Driver {
  std::unique_ptr<oracle::GlOracle> gl;
#ifdef FFTESS_HAVE_VULKAN
  std::unique_ptr<oracle::VkOracle> vk;
#endif
  std::string renderer, version;
  bool run(const std::vector<oracle::Patch>& patches, std::vector<oracle::Result>& results, std::string& error) {
#ifdef FFTESS_HAVE_VULKAN
    if (vk) return vk->run(patches, results, error);
#endif
    return gl->run(patches, results, error);
  }
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
    d.renderer = d.vk->renderer(), d.version = d.vk->version();
    return true;
#endif
  }
  d.gl = oracle::GlOracle::create(error, a.hardware);
  if (!d.gl) {
    std::fprintf(stderr, "fftess: error: driver-check: no OpenGL 4.5 context: %s\n", error.c_str());
    return false;
  }
  d.renderer = d.gl->renderer(), d.version = d.gl->version();
  return true;
}

struct Item {
  Patch patch; // hardware-stage patch (an hlsl-stage line is preconditioned here, the driver gets the result)
  int line = 0;
};

} // namespace

int runDriverCheck(const DriverCheckArgs& a) {
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
    for (const oracle::Patch& g : oracle::generatePatches(a.random, a.seed, false)) items.push_back(Item{fromGl(g), 0});
    source = "random(seed " + std::to_string(a.seed) + ")";
  }
  std::string error;
  Driver driver;
  if (!openDriver(a, driver)) return kExitInternal;
  CompareOptions opt;
  opt.strictOrder = a.strictOrder;
  opt.emulator.flushDenormals = a.flushDenormals;
  CompareReporter reporter(a.json, a.show, a.strictOrder, source);
  Tessellator tess;
  constexpr size_t kChunk = 4096; // patches per capture round: bounded memory for any count
  std::vector<oracle::Patch> glPatches;
  std::vector<oracle::Result> results;
  for (size_t begin = 0; begin < items.size(); begin += kChunk) {
    const size_t end = std::min(items.size(), begin + kChunk);
    glPatches.clear();
    for (size_t i = begin; i < end; ++i) glPatches.push_back(toGl(items[i].patch));
    if (!driver.run(glPatches, results, error)) {
      std::fprintf(stderr, "fftess: error: driver-check: the capture on %s failed: %s\n", driver.renderer.c_str(),
                   error.c_str());
      return kExitInternal;
    }
    for (size_t i = begin; i < end; ++i) {
      const CapturedPatch c = toCapture(results[i - begin], int64_t(i));
      reporter.add(int64_t(i), items[i].line, comparePatch(items[i].patch, &c, opt, tess));
    }
  }
  reporter.finish(a.api, "driver: " + driver.renderer + " (" + driver.version + "), " + std::to_string(items.size()) +
                             " patches from " + source + "\n");
  return reporter.summary().differing ? kExitFindings : kExitClean;
}
#endif

} // namespace fftess::cli
