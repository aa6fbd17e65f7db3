// fftess bench: runs the Google Benchmark program built from bench/ (fftess_bench, installed next to fftess).
#include "commands.h"
#include "common.h"

#include <cerrno>
#include <climits>
#include <cstring>
#include <string>
#include <unistd.h>
#include <vector>

namespace fftess::cli {

CLI::App* addBench(CLI::App& app, BenchArgs& a) {
  CLI::App* sub = app.add_subcommand(
      "bench", "Run the benchmarks (Google Benchmark): what accuracy costs in time. Extra arguments go to the "
               "benchmark program (--benchmark_filter=REGEX, --benchmark_format=json, ...)");
  sub->footer("Examples:\n"
              "  fftess bench --micro\n"
              "  fftess bench --micro --benchmark_filter=case_   (issue 11's cases (a) and (b))\n"
              "  fftess bench --micro --benchmark_filter=Edge --benchmark_min_time=0.2\n"
              "--micro: the Google Benchmark program itself (fftess_bench); the arguments after it go to it.");
  sub->allow_extras();
  (void)a;
  return sub;
}

int runBench(const BenchArgs& a, const char* argv0) {
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
