// fftess bench: runs the Google Benchmark program built from bench/ (fftess_bench, installed next to fftess).
#include "commands.h"
#include "common.h"
#include "options.h"

#include <CLI/CLI.hpp>
#include "accuracy.h"

#include <memory>

#include <cerrno>
#include <climits>
#include <cstring>
#include <string>
#include <unistd.h>
#include <vector>

namespace fftess::cli {

CLI::App* addBench(CLI::App& app, BenchArgs& a) {
  CLI::App* sub = app.add_subcommand(
      "bench", "What accuracy costs in time: a table of accuracy levels and simulated GPU effects on one scene "
               "(--micro: the Google Benchmark micro-benchmarks)");
  sub->footer("Examples:\n"
              "  fftess bench                                   (the table for docs/examples/terrain.toml)\n"
              "  fftess bench --scene docs/examples/rings_small.toml --markdown table.md --json table.json --svg table.svg\n"
              "  fftess bench --set lod.adjacency_clamp=none --cameras 32\n"
              "  fftess bench --micro --benchmark_filter=Edge --benchmark_min_time=0.2\n"
              "--micro: the Google Benchmark program itself (fftess_bench); the arguments after it go to it.\n"
              "Rows, columns and what each row buys: docs/accuracy.md.");
  sub->allow_extras();
  sub->add_option("--scene", a.scene, "Scene file (default: docs/examples/terrain.toml)");
  sub->add_option("--set", a.overrides, "Override a scene key for every row: KEY=VALUE (repeatable)");
  sub->add_option("--cameras", a.cameras, "Random cameras (every row runs on the same ones)")->capture_default_str();
  addSeedOption(sub, a.seed, "Seed of the random cameras");
  sub->add_option("--mesh-cameras", a.meshCameras, "Cameras of the whole-mesh row (seconds each)")->capture_default_str();
  sub->add_option("--repeats", a.repeats, "Each camera of an edge-check row is timed as the fastest of this many runs")
      ->capture_default_str();
  // The table's own groups (benchGroups): the help lists every one ({...}), and any other is refused.
  sub->add_option("--group", a.group, "Only this group's rows")
      ->type_name("GROUP")
      ->check(choiceOf(benchGroups()));
  sub->add_option("--markdown", a.markdown, "Write the table as Markdown");
  sub->add_option("--json", a.json, "Write the table as JSON");
  sub->add_option("--svg", a.svg, "Write the relative costs as an SVG bar chart");
  sub->add_flag("-q,--quiet", a.quiet, "No table on stdout");
  return sub;
}

static std::string defaultScene() {
  const std::string local = "docs/examples/terrain.toml";
  if (::access(local.c_str(), R_OK) == 0) return local;
  return std::string(FFTESS_SOURCE_ROOT) + "/" + local;
}

static int runBenchReport(const BenchArgs& a) {
  for (const std::string& s : a.passThrough)
    throw UsageError("bench: unknown argument " + quoteToken(s) + " (Google Benchmark options need --micro)");
  if (a.cameras < 1) throw UsageError("--cameras " + std::to_string(a.cameras) + ": must be >= 1");
  if (a.meshCameras < 0) throw UsageError("--mesh-cameras " + std::to_string(a.meshCameras) + ": must be >= 0");
  BenchReportArgs r;
  r.scene = a.scene.empty() ? defaultScene() : a.scene;
  r.overrides = a.overrides;
  r.cameras = a.cameras;
  r.meshCameras = a.meshCameras;
  if (a.repeats < 1) throw UsageError("--repeats " + std::to_string(a.repeats) + ": must be >= 1");
  r.repeats = a.repeats;
  r.only = a.group;
  r.seed = parseSeed(a.seed);
  refuseSameFiles({{"--markdown", a.markdown}, {"--json", a.json}, {"--svg", a.svg}}, {{"--scene", a.scene}});
  std::unique_ptr<AtomicFile> md, js, svg; // paths checked before the work
  if (!a.markdown.empty()) md = std::make_unique<AtomicFile>(a.markdown);
  if (!a.json.empty()) js = std::make_unique<AtomicFile>(a.json);
  if (!a.svg.empty()) svg = std::make_unique<AtomicFile>(a.svg);
  const BenchTable t = runBenchTable(r);
  AtomicFile* files[3];
  size_t n = 0;
  if (md) md->buffer() = benchMarkdown(t), files[n++] = md.get();
  if (js) js->buffer() = benchJson(t), files[n++] = js.get();
  if (svg) svg->buffer() = benchSvg(t), files[n++] = svg.get();
  commitAll(files, n);
  if (!a.quiet) writeStdout(benchText(t));
  flushStdout();
  return kExitClean;
}

int runBench(const BenchArgs& a, const char* argv0) {
  bool micro = false;
  for (const std::string& s : a.passThrough) micro = micro || s == "--micro" || s.rfind("--benchmark_", 0) == 0;
  if (!micro) return runBenchReport(a);
  std::string dir;
  char self[PATH_MAX];
  ssize_t n = ::readlink("/proc/self/exe", self, sizeof self - 1);
  if (n > 0) {
    self[n] = '\0';
    dir = self;
  } else {
    dir = argv0;
  }
  dir = dir.substr(0, dir.find_last_of('/') == std::string::npos ? 0 : dir.find_last_of('/') + 1);
  const std::string prog = dir + "fftess_bench";
  if (::access(prog.c_str(), X_OK) != 0)
    throw UsageError("bench: " + prog + " not found: build it (cmake -DFFTESS_BENCHMARKS=ON; target fftess_bench)");
  std::vector<char*> args;
  args.push_back(const_cast<char*>(prog.c_str()));
  // --micro selects the Google Benchmark program (today also the default); it is not passed on.
  for (const std::string& s : a.passThrough)
    if (s != "--micro") args.push_back(const_cast<char*>(s.c_str()));
  args.push_back(nullptr);
  std::fflush(stdout);
  ::execv(prog.c_str(), args.data());
  throw std::runtime_error("bench: cannot run " + prog + ": " + std::strerror(errno));
}

} // namespace fftess::cli
